#include "core/panels/vertex_rule.h"

#include <Eigen/Dense>
#include <cmath>

namespace ff {

namespace {

// Below this 1 - cos^2 (an angle of 1e-4 rad) the Gram form below loses too many digits to
// the cancellation in 1 - cos^2: its point is 2e-10 of the offsets off the planes at 1e-4 rad
// and 3e-6 at 2e-6 rad (test_vertex_rule.cpp), against a planarity target of 1e-9. Such pairs
// are rare (trial layouts: the outputs of bench/sweep_validity.sh at seed 1 are the same to
// the bit either way), so the Gram form stays above it: every other vertex keeps the bits the
// chaotic panel phase was validated with.
constexpr double kCancellingDet = 1e-8;

// The same point from the line's direction u = a x b, whose length sin(angle) has no
// cancellation: x - corner = (ra (b x u) + rb (u x a)) / |u|^2 lies on both planes and is
// perpendicular to u; one Newton step then removes the rounding of the large terms.
bool solve_two_nearly_parallel(const Plane& a, const Plane& b, const Vec3& corner, Vec3& out) {
  const Vec3 u = a.normal.cross(b.normal);
  const double uu = u.squaredNorm();
  const Vec3 across_a = b.normal.cross(u) / uu, across_b = u.cross(a.normal) / uu;
  out = corner + (a.offset - a.normal.dot(corner)) * across_a + (b.offset - b.normal.dot(corner)) * across_b;
  out += (a.offset - a.normal.dot(out)) * across_a + (b.offset - b.normal.dot(out)) * across_b;
  return out.allFinite();
}

// Lagrange form: x = corner + sum lambda_i n_i with Gram matrix G lambda = d - N corner.
// The nearest point to `corner` on the line of a and b; false (and the projection onto a)
// when they are (nearly) parallel and have no usable line.
bool solve_two(const Plane& a, const Plane& b, const Vec3& corner, Vec3& out) {
  const double c = a.normal.dot(b.normal);
  const double det = 1.0 - c * c;
  if (!(det > 1e-12)) {
    out = a.project(corner);
    return false;
  }
  if (det < kCancellingDet) return solve_two_nearly_parallel(a, b, corner, out);
  const double ra = a.offset - a.normal.dot(corner);
  const double rb = b.offset - b.normal.dot(corner);
  const double la = (ra - c * rb) / det;
  const double lb = (rb - c * ra) / det;
  out = corner + la * a.normal + lb * b.normal;
  return out.allFinite();
}

}  // namespace

VertexRuleResult closest_point_on_planes(const std::vector<Plane>& planes, const Vec3& corner) {
  VertexRuleResult r;
  if (planes.empty()) {
    r.point = corner;
  } else if (planes.size() == 1) {
    r.point = planes[0].project(corner);
  } else if (planes.size() == 2) {
    r.exact = solve_two(planes[0], planes[1], corner, r.point);
  } else {
    const Vec3& n0 = planes[0].normal;
    const Vec3& n1 = planes[1].normal;
    const Vec3& n2 = planes[2].normal;
    const double det = n0.dot(n1.cross(n2));
    if (std::abs(det) > 1e-12) {
      // Cramer's rule in the triple-product form: exact on all three planes.
      r.point =
          (planes[0].offset * n1.cross(n2) + planes[1].offset * n2.cross(n0) + planes[2].offset * n0.cross(n1)) / det;
      // One Newton step on the residuals removes the rounding the division left behind.
      Eigen::Matrix3d N;
      N.row(0) = n0.transpose();
      N.row(1) = n1.transpose();
      N.row(2) = n2.transpose();
      const Vec3 residual(planes[0].distance(r.point), planes[1].distance(r.point), planes[2].distance(r.point));
      r.point -= N.partialPivLu().solve(residual);
    } else {
      // No common point: the best-conditioned pair's line (flagged, never silently used).
      int best_i = 0, best_j = 1;
      double best = -1.0;
      for (int i = 0; i < 3; ++i) {
        for (int j = i + 1; j < 3; ++j) {
          const double s =
              planes[static_cast<size_t>(i)].normal.cross(planes[static_cast<size_t>(j)].normal).squaredNorm();
          if (s > best) best = s, best_i = i, best_j = j;
        }
      }
      solve_two(planes[static_cast<size_t>(best_i)], planes[static_cast<size_t>(best_j)], corner, r.point);
      r.exact = false;
    }
  }
  return r;
}

}  // namespace ff
