// Turning a plane through two points (core/panels/plane.cpp), the step both panel mends
// (aim_node_planes, aim_edge_order) take: the new plane holds both points, its normal is the
// old one with the part along the line removed, and too large or undefined turns are refused.
#include <gtest/gtest.h>

#include <cmath>

#include "core/panels/plane.h"
#include "core/util/angles.h"

namespace ff {
namespace {

TEST(TurnPlaneThrough, HoldsBothPointsWithTheNearestNormal) {
  const Plane flat = Plane::through(Vec3(0, 0, 0), Vec3(0, 0, 1));
  const Vec3 p(0, 0, 0), q(1, 0, 0.1);  // a 5.7 degree rise along x
  Plane out;
  ASSERT_TRUE(turn_plane_through(flat, p, q, 1.0, 10.0, out));
  EXPECT_NEAR(out.distance(p), 0.0, 1e-15);
  EXPECT_NEAR(out.distance(q), 0.0, 1e-15);
  EXPECT_NEAR(out.normal.norm(), 1.0, 1e-15);
  EXPECT_NEAR(out.normal.y(), 0.0, 1e-15);  // the turn is about the y axis only
  EXPECT_NEAR(std::acos(out.normal.dot(flat.normal)), std::atan(0.1), 1e-12);
}

TEST(TurnPlaneThrough, ALineInThePlaneLeavesItAsItIs) {
  const Plane tilted = Plane::through(Vec3(1, 2, 3), Vec3(1, 1, 1).normalized());
  const Vec3 p = tilted.project(Vec3(0, 0, 0)), q = tilted.project(Vec3(3, -1, 2));
  Plane out;
  ASSERT_TRUE(turn_plane_through(tilted, p, q, 1.0, 1e-6, out));
  EXPECT_NEAR((out.normal - tilted.normal).norm(), 0.0, 1e-12);
  EXPECT_NEAR(out.offset, tilted.offset, 1e-12);
}

TEST(TurnPlaneThrough, RefusesTurnsPastTheLimit) {
  const Plane flat = Plane::through(Vec3(0, 0, 0), Vec3(0, 0, 1));
  const Plane before = Plane::through(Vec3(7, 7, 7), Vec3(1, 0, 0));
  Plane out = before;
  const Vec3 q(1, 0, std::tan(20 * kRadiansPerDegree));  // needs a 20 degree turn
  EXPECT_FALSE(turn_plane_through(flat, Vec3(0, 0, 0), q, 1.0, 19.0, out));
  EXPECT_EQ(out.normal, before.normal);  // untouched on refusal
  EXPECT_TRUE(turn_plane_through(flat, Vec3(0, 0, 0), q, 1.0, 21.0, out));
}

TEST(TurnPlaneThrough, RefusesCoincidentPointsAndLinesAlongTheNormal) {
  const Plane flat = Plane::through(Vec3(0, 0, 0), Vec3(0, 0, 1));
  Plane out;
  EXPECT_FALSE(turn_plane_through(flat, Vec3(0, 0, 0), Vec3(1e-8, 0, 0), 1.0, 90.0, out));  // within 1e-6 length
  EXPECT_TRUE(turn_plane_through(flat, Vec3(0, 0, 0), Vec3(1e-8, 0, 0), 1e-3, 90.0, out));  // a small model
  EXPECT_FALSE(turn_plane_through(flat, Vec3(0, 0, 0), Vec3(0, 0, 1), 1.0, 90.0, out));     // no plane holds it
}

}  // namespace
}  // namespace ff
