#include "core/panels/vertex_rule.h"

#include <Eigen/Dense>
#include <cmath>

namespace ff {

namespace {

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
