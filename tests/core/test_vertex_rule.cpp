// The vertex rule: the point closest to a corner on the intersection of 0 to 3 planes.
// Checked against its definition (on every plane, and the offset from the corner orthogonal
// to what the planes leave free), including far from the origin and nearly parallel planes.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/panels/vertex_rule.h"
#include "core/util/random.h"

namespace ff {
namespace {

Vec3 random_unit(SplitMix64& rng) {
  for (;;) {
    const Vec3 v(rng.uniform() * 2 - 1, rng.uniform() * 2 - 1, rng.uniform() * 2 - 1);
    if (v.norm() > 0.2 && v.norm() <= 1.0) return v.normalized();
  }
}

double max_residual(const std::vector<Plane>& planes, const Vec3& p) {
  double worst = 0.0;
  for (const Plane& plane : planes) worst = std::max(worst, std::abs(plane.distance(p)));
  return worst;
}

TEST(VertexRule, ThreePlanesGiveTheirCommonPoint) {
  SplitMix64 rng(11);
  int tested = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 target(rng.uniform() * 4 - 2, rng.uniform() * 4 - 2, rng.uniform() * 4 - 2);
    std::vector<Plane> planes;
    for (int i = 0; i < 3; ++i) planes.push_back(Plane::through(target, random_unit(rng)));
    const double det = planes[0].normal.dot(planes[1].normal.cross(planes[2].normal));
    if (std::abs(det) < 0.1) continue;  // well conditioned here; the hard cases below
    ++tested;
    const Vec3 corner = target + Vec3(rng.uniform(), rng.uniform(), rng.uniform());
    const VertexRuleResult r = closest_point_on_planes(planes, corner);
    EXPECT_TRUE(r.exact);
    EXPECT_LT(max_residual(planes, r.point), 1e-12) << "trial " << trial;
    EXPECT_LT((r.point - target).norm(), 1e-11) << "trial " << trial;
  }
  EXPECT_GT(tested, 50);
}

TEST(VertexRule, ThreePlanesFarFromTheOrigin) {
  SplitMix64 rng(5);
  for (double far : {1e4, 1e6, 1e8}) {
    for (int trial = 0; trial < 30; ++trial) {
      const Vec3 target = far * Vec3(1.0, -0.7, 0.3) + Vec3(rng.uniform(), rng.uniform(), rng.uniform());
      std::vector<Plane> planes;
      do {
        planes.clear();
        for (int i = 0; i < 3; ++i) planes.push_back(Plane::through(target, random_unit(rng)));
      } while (std::abs(planes[0].normal.dot(planes[1].normal.cross(planes[2].normal))) < 0.1);
      const VertexRuleResult r = closest_point_on_planes(planes, target + Vec3(0.5, 0.5, 0.5));
      EXPECT_TRUE(r.exact);
      // Offsets are ~far: relative to the size of the coordinates.
      EXPECT_LT(max_residual(planes, r.point), 1e-9 * 1e-3 * far) << far << " trial " << trial;
      EXPECT_LT((r.point - target).norm(), 1e-12 * far * 10) << far << " trial " << trial;
    }
  }
}

TEST(VertexRule, NearlyParallelPlanesStillMeetExactly) {
  // Normals tilted by eps from a common plane (det ~ eps): the point is far away, but on
  // all three planes to rounding relative to its size.
  for (double eps : {1e-3, 1e-5, 1e-7, 1e-9}) {
    const std::vector<Plane> planes = {
        Plane{Vec3(0, 0, 1), 1.0},
        Plane{Vec3(0, std::sin(0.3), std::cos(0.3)), 1.0},
        Plane{Vec3(eps, std::sin(-0.3), std::cos(-0.3)).normalized(), 1.0},
    };
    const double det = planes[0].normal.dot(planes[1].normal.cross(planes[2].normal));
    ASSERT_GT(std::abs(det), 1e-12);
    const VertexRuleResult r = closest_point_on_planes(planes, Vec3(0, 0, 1));
    EXPECT_TRUE(r.exact) << eps;
    ASSERT_TRUE(r.point.allFinite());
    EXPECT_GT(r.point.norm(), 0.01 / eps);  // really far: the planes nearly share a line
    EXPECT_LT(max_residual(planes, r.point), 1e-9 * r.point.norm()) << eps;
    // Planes 0/1 meet in the line z = 1, y = y0 along x; the third plane picks x on it.
    const double y0 = (1.0 - std::cos(0.3)) / std::sin(0.3);
    const double x = (std::sqrt(1.0 + eps * eps) + std::sin(0.3) * y0 - std::cos(0.3)) / eps;
    EXPECT_LT((r.point - Vec3(x, y0, 1.0)).norm(), 1e-9 * std::abs(x)) << eps;
  }
}

TEST(VertexRule, TwoPlanesGiveTheNearestPointOnTheirLine) {
  SplitMix64 rng(21);
  for (int trial = 0; trial < 100; ++trial) {
    const Vec3 on_line(rng.uniform() * 10 - 5, rng.uniform() * 10 - 5, rng.uniform() * 10 - 5);
    Vec3 n0 = random_unit(rng), n1 = random_unit(rng);
    if (n0.cross(n1).norm() < 0.05) continue;
    const std::vector<Plane> planes = {Plane::through(on_line, n0), Plane::through(on_line, n1)};
    const Vec3 corner = on_line + 3.0 * Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
    const VertexRuleResult r = closest_point_on_planes(planes, corner);
    EXPECT_TRUE(r.exact);
    EXPECT_LT(max_residual(planes, r.point), 1e-12 * 10) << trial;
    const Vec3 direction = n0.cross(n1).normalized();
    EXPECT_LT(std::abs((r.point - corner).dot(direction)), 1e-11) << trial;
    // And it is the minimum: any other point on the line is farther.
    for (double t : {-1e-3, 1e-3, 0.5}) {
      EXPECT_LT((r.point - corner).norm(), (r.point + t * direction - corner).norm()) << trial;
    }
  }
}

// Two planes at a small angle still have their line (a boundary vertex between two nearly
// coplanar panels): exact down to an angle of about 1e-6 rad, where 1 - cos^2 reaches the
// 1e-12 floor; below it (and for parallel planes) there is no usable line, the vertex is not
// exact and falls back to the projection onto the first plane, never a point far away.
TEST(VertexRule, TwoNearlyParallelPlanes) {
  const Vec3 corner(0.4, -0.3, 0.2);
  for (double angle : {1e-2, 1e-4, 2e-6}) {
    // Both planes contain the x axis; the second is turned by `angle` about it.
    const std::vector<Plane> planes = {Plane{Vec3(0, 0, 1), 0.0},
                                       Plane{Vec3(0, -std::sin(angle), std::cos(angle)), 0.0}};
    const VertexRuleResult r = closest_point_on_planes(planes, corner);
    EXPECT_TRUE(r.exact) << angle;
    EXPECT_LT(max_residual(planes, r.point), 1e-12) << angle;
    EXPECT_LT((r.point - Vec3(corner.x(), 0.0, 0.0)).norm(), 1e-9) << angle;  // the nearest point of the x axis
  }
  for (double angle : {1e-7, 0.0}) {
    const std::vector<Plane> planes = {Plane{Vec3(0, 0, 1), 0.0},
                                       Plane{Vec3(0, -std::sin(angle), std::cos(angle)), 0.5}};
    const VertexRuleResult r = closest_point_on_planes(planes, corner);
    EXPECT_FALSE(r.exact) << angle;
    ASSERT_TRUE(r.point.allFinite()) << angle;
    EXPECT_LT((r.point - planes[0].project(corner)).norm(), 1e-15) << angle;
  }
}

TEST(VertexRule, OnePlaneProjectsAndNoPlaneKeepsTheCorner) {
  const Plane plane{Vec3(1, 2, 2) / 3.0, 4.0};
  const Vec3 corner(10, -3, 7);
  const VertexRuleResult one = closest_point_on_planes({plane}, corner);
  EXPECT_TRUE(one.exact);
  EXPECT_LT(std::abs(plane.distance(one.point)), 1e-12);
  EXPECT_LT((one.point - corner).cross(plane.normal).norm(), 1e-12);  // moved along the normal
  EXPECT_NEAR((one.point - corner).norm(), std::abs(plane.distance(corner)), 1e-12);
  const VertexRuleResult none = closest_point_on_planes({}, corner);
  EXPECT_TRUE(none.exact);
  EXPECT_EQ(none.point, corner);
}

TEST(VertexRule, CoplanarNormalsAreNotExact) {
  // Three planes all containing the z direction: no common point (inconsistent offsets) or
  // a whole line of them (consistent); either way not a vertex.
  const Vec3 corner(0.3, -0.2, 5.0);
  for (double third_offset : {0.0, 1.0}) {
    const std::vector<Plane> planes = {
        Plane{Vec3(0.6, 0.8, 0), 0.5},
        Plane{Vec3(0, 1, 0), 0.2},
        Plane{Vec3(1, 1, 0).normalized(), third_offset},
    };
    const VertexRuleResult r = closest_point_on_planes(planes, corner);
    EXPECT_FALSE(r.exact);
    ASSERT_TRUE(r.point.allFinite());
    // The best-conditioned pair is 0/2 (|n0 x n2| = 0.14) vs 0/1 (0.6) vs 1/2 (0.71): 1/2.
    EXPECT_LT(std::abs(planes[1].distance(r.point)), 1e-12);
    EXPECT_LT(std::abs(planes[2].distance(r.point)), 1e-12);
    EXPECT_NEAR(r.point.z(), corner.z(), 1e-12);  // nearest on a line along z
  }
}

TEST(VertexRule, ThreePlanesAreExactlyTheIntersectionNotTheCorner) {
  // The 3-plane point does not depend on the corner at all.
  const std::vector<Plane> planes = {Plane{Vec3(1, 0, 0), 1}, Plane{Vec3(0, 1, 0), 2}, Plane{Vec3(0, 0, 1), 3}};
  for (const Vec3& corner : {Vec3(0, 0, 0), Vec3(100, -50, 7)}) {
    const VertexRuleResult r = closest_point_on_planes(planes, corner);
    EXPECT_EQ(r.point, Vec3(1, 2, 3));
  }
}

}  // namespace
}  // namespace ff
