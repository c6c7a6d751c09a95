// Plane relaxation: three planes around a corner whose normals are nearly coplanar (the
// cylinder-like case) meet far from it; relaxed, they meet near the corner while still
// fitting their faces. Planes already meeting at their corner stay where they are.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/cluster/metric.h"
#include "core/panels/plane_relax.h"
#include "core/panels/vertex_rule.h"
#include "core/util/angles.h"

namespace ff {
namespace {

// Exact moments of one triangle: integral of p p^T = (A / 12) (sum p_i p_i^T + 9 c c^T).
void add_triangle(ClusterMoments& m, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a);
  const double area = 0.5 * n.norm();
  const Vec3 centroid = (a + b + c) / 3.0;
  m.area += area;
  m.first += area * centroid;
  m.centroid_sq += area * centroid.squaredNorm();
  m.second +=
      area / 12.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + 9.0 * centroid * centroid.transpose());
  m.normal_sum += 0.5 * n;
  m.density_area += area;
}

// A small fan of four triangles (0.4 across) lying exactly in `plane` around its point
// nearest `around`, counter-clockwise about the normal.
ClusterMoments faces_on(const Plane& plane, const Vec3& around) {
  const Vec3 c = plane.project(around);
  const Vec3 u = plane.normal.cross(std::abs(plane.normal.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).normalized();
  const Vec3 v = plane.normal.cross(u);
  const Vec3 ring[4] = {c + 0.2 * u, c + 0.2 * v, c - 0.2 * u, c - 0.2 * v};
  ClusterMoments m;
  for (int i = 0; i < 4; ++i) add_triangle(m, c, ring[i], ring[(i + 1) % 4]);
  return m;
}

double rms_distance(const Plane& plane, const ClusterMoments& m) {
  // integral (n.p - d)^2 = n^T S n - 2 d n.first + d^2 area
  const Vec3& n = plane.normal;
  const double sq = n.dot(m.second * n) - 2.0 * plane.offset * n.dot(m.first) + plane.offset * plane.offset * m.area;
  return std::sqrt(std::max(0.0, sq) / m.area);  // cancellation can leave -0 for a perfect fit
}

struct Corner3 {
  Vec3 corner = Vec3(0.0, 0.0, 1.0);  // on top of a unit barrel along x
  std::vector<Plane> planes;
  std::vector<ClusterMoments> moments;
  std::vector<NodeConstraint> nodes;
};

// Clusters around the corner of a gently double-curved barrel: A on the left (theta < 0),
// B and C on the right, behind and ahead. Their normals are nearly coplanar (all nearly
// orthogonal to x); each plane misses the corner by offsets[i].
Corner3 barrel(const Vec3& offsets) {
  Corner3 s;
  const Vec3 normals[3] = {Vec3(0.004, std::sin(-0.15), std::cos(-0.15)).normalized(),
                           Vec3(-0.006, std::sin(0.15), std::cos(0.15)).normalized(),
                           Vec3(0.009, std::sin(0.17), std::cos(0.17)).normalized()};
  const Vec3 sectors[3] = {Vec3(0.0, -0.3, 1.0), Vec3(-0.3, 0.3, 1.0), Vec3(0.3, 0.3, 1.0)};
  for (int i = 0; i < 3; ++i) {
    s.planes.push_back(Plane{normals[i], normals[i].dot(s.corner) - offsets[i]});
    s.moments.push_back(faces_on(s.planes.back(), sectors[i]));
  }
  NodeConstraint node;
  node.corner = s.corner;
  node.planes = {{0, 1, 2}};
  node.count = 3;
  s.nodes.push_back(node);
  return s;
}

TEST(PlaneRelax, NearlyCoplanarNormalsMeetNearTheCornerAfterRelaxing) {
  const Corner3 s = barrel(Vec3(0.01, -0.01, 0.005));
  const VertexRuleResult before = closest_point_on_planes(s.planes, s.corner);
  ASSERT_TRUE(before.exact);
  const double d0 = (before.point - s.corner).norm();
  ASSERT_GT(d0, 1.0);  // far beyond the 0.4-wide clusters: a spike
  for (size_t i = 0; i < 3; ++i) ASSERT_LT(rms_distance(s.planes[i], s.moments[i]), 1e-6);  // a perfect fit
  const std::vector<Plane> relaxed = relax_planes(s.nodes, s.moments, s.planes);
  const VertexRuleResult after = closest_point_on_planes(relaxed, s.corner);
  ASSERT_TRUE(after.exact);
  const double d1 = (after.point - s.corner).norm();
  EXPECT_LT(d1, 0.1 * d0) << "before " << d0 << " after " << d1;
  EXPECT_LT(d1, 0.05);  // near the corner in absolute terms too
  for (size_t i = 0; i < 3; ++i) {
    // Still the same planes to within a small tilt, still fitting their faces closely.
    EXPECT_NEAR(relaxed[i].normal.norm(), 1.0, 1e-12);
    EXPECT_GT(relaxed[i].normal.dot(s.planes[i].normal), std::cos(3.0 * kRadiansPerDegree)) << i;
    EXPECT_LT(rms_distance(relaxed[i], s.moments[i]), 0.01) << i;
  }
}

TEST(PlaneRelax, PlanesThroughTheCornerStayPut) {
  const Corner3 s = barrel(Vec3::Zero());
  ASSERT_LT((closest_point_on_planes(s.planes, s.corner).point - s.corner).norm(), 1e-12);
  const std::vector<Plane> relaxed = relax_planes(s.nodes, s.moments, s.planes);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_LT((relaxed[i].normal - s.planes[i].normal).norm(), 1e-9) << i;
    EXPECT_NEAR(relaxed[i].offset, s.planes[i].offset, 1e-9) << i;
  }
}

TEST(PlaneRelax, WellConditionedCornerKeepsItsFit) {
  // Three planes at clear angles that miss the corner slightly: their point is already
  // near it, and relaxing moves them by no more than about that.
  Corner3 s;
  s.corner = Vec3(0.0, 0.0, 0.0);
  const Vec3 normals[3] = {Vec3(1, 0.2, 0.1).normalized(), Vec3(-0.1, 1, 0.3).normalized(),
                           Vec3(0.2, -0.3, 1).normalized()};
  for (int i = 0; i < 3; ++i) {
    s.planes.push_back(Plane{normals[i], 0.003 * (i + 1)});
    s.moments.push_back(faces_on(s.planes.back(), 0.3 * normals[(i + 1) % 3] + 0.3 * normals[(i + 2) % 3]));
  }
  NodeConstraint node;
  node.planes = {{0, 1, 2}};
  node.count = 3;
  s.nodes.push_back(node);
  const double d0 = (closest_point_on_planes(s.planes, s.corner).point - s.corner).norm();
  const std::vector<Plane> relaxed = relax_planes(s.nodes, s.moments, s.planes);
  const double d1 = (closest_point_on_planes(relaxed, s.corner).point - s.corner).norm();
  EXPECT_LE(d1, d0);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_LT(std::abs(relaxed[i].offset - s.planes[i].offset), 2.0 * d0) << i;
    EXPECT_GT(relaxed[i].normal.dot(s.planes[i].normal), std::cos(2.0 * kRadiansPerDegree)) << i;
  }
}

TEST(PlaneRelax, FixedPlanesDoNotMove) {
  const Corner3 s = barrel(Vec3(0.01, -0.01, 0.005));
  const std::vector<Plane> relaxed = relax_planes(s.nodes, s.moments, s.planes, RelaxOptions{}, {1, 0, 0});
  EXPECT_TRUE(relaxed[0].normal == s.planes[0].normal);
  EXPECT_EQ(relaxed[0].offset, s.planes[0].offset);
  // The other two still bring the node in.
  const double d0 = (closest_point_on_planes(s.planes, s.corner).point - s.corner).norm();
  const double d1 = (closest_point_on_planes(relaxed, s.corner).point - s.corner).norm();
  EXPECT_LT(d1, 0.1 * d0);
}

// The free planes depend on the fixed planes their nodes touch, and on nothing else that is
// fixed: a node among fixed planes only and a fixed plane no free node touches change no bit
// of the result (relax_planes loops over the planes it needs only), while moving a fixed
// plane that a free node touches moves the free planes.
TEST(PlaneRelax, FreePlanesIgnoreWhatNoFreeNodeTouches) {
  const Corner3 s = barrel(Vec3(0.01, -0.01, 0.005));
  const std::vector<Plane> alone = relax_planes(s.nodes, s.moments, s.planes, RelaxOptions{}, {1, 0, 0});
  Corner3 more = s;
  const Plane far = Plane::through(Vec3(5.0, 0.0, 0.0), Vec3(1.0, 0.2, 0.1).normalized());
  more.planes.push_back(far);
  more.moments.push_back(faces_on(far, Vec3(5.0, 0.0, 0.0)));
  NodeConstraint fixed_only;
  fixed_only.corner = Vec3(2.0, 0.0, 1.0);
  fixed_only.planes = {{0, 3, -1}};
  fixed_only.count = 2;
  more.nodes.insert(more.nodes.begin(), fixed_only);
  const std::vector<Plane> with = relax_planes(more.nodes, more.moments, more.planes, RelaxOptions{}, {1, 0, 0, 1});
  ASSERT_EQ(with.size(), 4u);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_TRUE(with[i].normal == alone[i].normal) << i;
    EXPECT_EQ(with[i].offset, alone[i].offset) << i;
  }
  EXPECT_TRUE(with[3].normal == far.normal);
  EXPECT_EQ(with[3].offset, far.offset);
  Corner3 moved = s;
  moved.planes[0] = Plane::through(moved.planes[0].project(s.corner) + 0.05 * moved.planes[0].normal,
                                   moved.planes[0].normal);
  const std::vector<Plane> shifted = relax_planes(moved.nodes, moved.moments, moved.planes, RelaxOptions{}, {1, 0, 0});
  EXPECT_GT(std::abs(shifted[1].offset - alone[1].offset) + std::abs(shifted[2].offset - alone[2].offset), 1e-4);
}

// The settled stop (RelaxOptions::settled_step) ends the relaxation early with the rest of
// the planes' geometric tail added: it lands where all iterations go, far closer than
// stopping at the same point without the tail would.
TEST(PlaneRelax, SettledStopLandsWhereAllIterationsGo) {
  const Corner3 s = barrel(Vec3(0.01, -0.01, 0.005));
  RelaxOptions all;
  all.settled_step = 0.0;
  const std::vector<Plane> full = relax_planes(s.nodes, s.moments, s.planes, all);
  const std::vector<Plane> settled = relax_planes(s.nodes, s.moments, s.planes);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(settled[i].normal.norm(), 1.0, 1e-12) << i;
    EXPECT_LT((settled[i].normal - full[i].normal).lpNorm<Eigen::Infinity>(), 1e-8) << i;
    EXPECT_LT(std::abs(settled[i].offset - full[i].offset), 1e-8) << i;
  }
  // The iteration it stopped at: the fewest iterations that give the same planes to the bit.
  int stop = all.iterations;
  for (int k = 1; k < all.iterations; ++k) {
    RelaxOptions upto;
    upto.iterations = k;
    const std::vector<Plane> r = relax_planes(s.nodes, s.moments, s.planes, upto);
    bool same = true;
    for (size_t i = 0; i < 3; ++i) same = same && r[i].normal == settled[i].normal && r[i].offset == settled[i].offset;
    if (same) {
      stop = k;
      break;
    }
  }
  EXPECT_LT(stop, 60);
  // Stopping there without the tail would land ten times farther off, or more.
  RelaxOptions fewer = all;
  fewer.iterations = stop;
  const std::vector<Plane> truncated = relax_planes(s.nodes, s.moments, s.planes, fewer);
  double off_truncated = 0.0, off_settled = 0.0;
  for (size_t i = 0; i < 3; ++i) {
    off_truncated = std::max(off_truncated, (truncated[i].normal - full[i].normal).lpNorm<Eigen::Infinity>());
    off_settled = std::max(off_settled, (settled[i].normal - full[i].normal).lpNorm<Eigen::Infinity>());
  }
  RecordProperty("stop", stop);
  EXPECT_GT(off_truncated, 10.0 * off_settled) << "stopped at " << stop;
}

// Nothing pins a plane without nodes, so its fit is done in one step: the stop must judge the
// offset too (the normal of this fit does not move at all, its offset does), else it would
// extrapolate the one step's offset change as a tail.
TEST(PlaneRelax, SettledStopJudgesTheOffsetToo) {
  const Plane surface = Plane::through(Vec3(0.0, 0.0, 0.3), Vec3::UnitZ());
  const std::vector<ClusterMoments> moments = {faces_on(surface, Vec3::Zero())};
  const std::vector<Plane> relaxed = relax_planes({}, moments, {Plane::through(Vec3::Zero(), Vec3::UnitZ())});
  EXPECT_LT((relaxed[0].normal - Vec3::UnitZ()).norm(), 1e-12);
  EXPECT_NEAR(relaxed[0].offset, 0.3, 1e-12);
}

// The hinge of the tests below: the x axis (the line the locked plane z = 0 and the start
// plane share).
PlaneHinge x_axis_hinge() {
  PlaneHinge hinge;
  hinge.on = true;
  hinge.point = Vec3(0.5, 0.0, 0.0);
  hinge.direction = Vec3::UnitX();
  return hinge;
}

// A hinged plane (the neighbour of a locked panel) fits its faces only among the planes
// through its hinge's line: it keeps containing the line exactly, however far its faces lie
// from any such plane, and is the best fit of that pencil; a plane without a hinge fits its
// faces exactly.
TEST(PlaneRelax, HingedPlaneTurnsOnlyAboutItsLine) {
  const Plane locked = Plane::through(Vec3::Zero(), Vec3::UnitZ());
  const Plane start = Plane::through(Vec3::Zero(), Vec3(0.0, -0.3, 1.0).normalized());  // through the x axis
  const Plane surface = Plane::through(Vec3(0.0, 0.0, 0.3), Vec3(0.0, -0.7, 1.0).normalized());
  const std::vector<ClusterMoments> moments = {faces_on(locked, Vec3(0.0, -1.0, 0.0)),
                                               faces_on(surface, Vec3(0.0, 1.0, 1.0))};
  const PlaneHinge hinge = x_axis_hinge();
  const std::vector<char> fixed{1, 0};
  const std::vector<Plane> hinged = relax_planes({}, moments, {locked, start}, {}, fixed, {PlaneHinge{}, hinge});
  const std::vector<Plane> free = relax_planes({}, moments, {locked, start}, {}, fixed);
  EXPECT_EQ(hinged[0].normal, locked.normal);
  for (double x : {-50.0, 0.0, 3.0, 50.0}) EXPECT_LT(std::abs(hinged[1].distance(Vec3(x, 0.0, 0.0))), 1e-12) << x;
  EXPECT_GT(hinged[1].normal.dot(start.normal), 0.0);  // the same side
  EXPECT_LT(rms_distance(free[1], moments[1]), 1e-9);
  const double best = rms_distance(hinged[1], moments[1]);
  EXPECT_GT(best, 1e-3);  // the surface is not in the pencil: the hinge held
  for (double turn : {-0.01, 0.01}) {
    const Vec3 n = Eigen::AngleAxisd(turn, Vec3::UnitX()) * hinged[1].normal;
    EXPECT_GE(rms_distance(Plane::through(Vec3::Zero(), n), moments[1]), best) << turn;
  }
}

// The settled stop's tail keeps a hinged plane on its hinge: the extrapolation combines two
// planes through the hinge's line, so the result contains it too. A node pulls the hinged
// plane (so it moves until the stop, and the tail is not zero).
TEST(PlaneRelax, SettledStopKeepsAHingedPlaneOnItsLine) {
  const Plane locked = Plane::through(Vec3::Zero(), Vec3::UnitZ());
  const Plane start = Plane::through(Vec3::Zero(), Vec3(0.0, -0.3, 1.0).normalized());
  const std::vector<ClusterMoments> moments = {faces_on(locked, Vec3(0.0, -1.0, 0.0)),
                                               faces_on(start, Vec3(0.0, 1.0, 0.3))};
  const PlaneHinge hinge = x_axis_hinge();
  NodeConstraint node;
  node.corner = Vec3(0.5, 1.0, 0.6);  // above the start plane: the node pulls it up
  node.planes = {{0, 1, -1}};
  node.count = 2;
  const std::vector<char> fixed{1, 0};
  RelaxOptions all;
  all.settled_step = 0.0;
  const std::vector<Plane> full = relax_planes({node}, moments, {locked, start}, all, fixed, {PlaneHinge{}, hinge});
  const std::vector<Plane> settled = relax_planes({node}, moments, {locked, start}, {}, fixed, {PlaneHinge{}, hinge});
  EXPECT_GT(full[1].normal.dot(start.normal), 0.0);
  // It turned, and the stop came before the last iteration.
  EXPECT_GT((full[1].normal - start.normal).norm(), 1e-3);
  EXPECT_FALSE(settled[1].normal == full[1].normal && settled[1].offset == full[1].offset);
  EXPECT_LT((settled[1].normal - full[1].normal).norm(), 1e-8);
  for (double x : {-50.0, 0.0, 3.0, 50.0}) EXPECT_LT(std::abs(settled[1].distance(Vec3(x, 0.0, 0.0))), 1e-12) << x;
}

}  // namespace
}  // namespace ff
