// Master planes: neighbouring planes within a degree share one plane (the area-weighted
// normal through the area-weighted centre), a gently turning chain does not collapse into
// one, planes that meet between their clusters (a curved surface) do not snap, and planes
// that stay alone keep their plane bit for bit.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <utility>
#include <vector>

#include "core/panels/master_planes.h"
#include "core/util/angles.h"

namespace ff {
namespace {

// Normal tilted by `deg` degrees from +z about the x axis.
Vec3 tilted(double deg) { return Vec3(0.0, std::sin(deg * kRadiansPerDegree), std::cos(deg * kRadiansPerDegree)); }

double angle_deg(const Vec3& a, const Vec3& b) { return std::atan2(a.cross(b).norm(), a.dot(b)) / kRadiansPerDegree; }

TEST(MasterPlanes, PlanesWithinADegreeSnapToTheAreaWeightedMean) {
  const std::vector<Vec3> centers = {Vec3(0, 0, 0.01), Vec3(2, 0, -0.02)};
  const std::vector<Plane> planes = {Plane::through(centers[0], tilted(0.2)), Plane::through(centers[1], tilted(0.9))};
  const std::vector<double> areas = {1.0, 3.0};
  const MasterPlanes m = snap_master_planes(planes, centers, areas, {{0, 1}});
  ASSERT_EQ(m.planes.size(), 1u);
  EXPECT_EQ(m.master_of, (std::vector<int>{0, 0}));
  EXPECT_EQ(m.count, std::vector<int>{2});
  const Vec3 normal = (1.0 * planes[0].normal + 3.0 * planes[1].normal).normalized();
  const Vec3 center = (1.0 * centers[0] + 3.0 * centers[1]) / 4.0;
  EXPECT_LT((m.planes[0].normal - normal).norm(), 1e-12);
  EXPECT_NEAR(m.planes[0].normal.norm(), 1.0, 1e-14);
  EXPECT_NEAR(m.planes[0].distance(center), 0.0, 1e-12);
  EXPECT_LT((m.centers[0] - center).norm(), 1e-12);
  EXPECT_EQ(&m.plane_of(1), &m.planes[0]);
}

TEST(MasterPlanes, OnlyNeighboursSnap) {
  const std::vector<Plane> planes = {Plane{tilted(0.0), 0.0}, Plane{tilted(0.1), 0.5}};
  const MasterPlanes m = snap_master_planes(planes, {Vec3::Zero(), Vec3(0, 0, 0.5)}, {1.0, 1.0}, {});
  EXPECT_EQ(m.planes.size(), 2u);
  EXPECT_NE(m.master_of[0], m.master_of[1]);
}

TEST(MasterPlanes, PlanesTwoDegreesApartStaySeparateAndExact) {
  const std::vector<Vec3> centers = {Vec3(0.1, 0.2, 0.3), Vec3(1.7, -0.4, 0.9)};
  const std::vector<Plane> planes = {Plane::through(centers[0], tilted(0.0)), Plane::through(centers[1], tilted(2.0))};
  const MasterPlanes m = snap_master_planes(planes, centers, {2.0, 1.0}, {{0, 1}});
  ASSERT_EQ(m.planes.size(), 2u);
  ASSERT_NE(m.master_of[0], m.master_of[1]);
  for (int c = 0; c < 2; ++c) {
    const Plane& p = m.plane_of(c);
    // Bit for bit, not merely close.
    EXPECT_EQ(p.normal.x(), planes[static_cast<size_t>(c)].normal.x());
    EXPECT_EQ(p.normal.y(), planes[static_cast<size_t>(c)].normal.y());
    EXPECT_EQ(p.normal.z(), planes[static_cast<size_t>(c)].normal.z());
    EXPECT_EQ(p.offset, planes[static_cast<size_t>(c)].offset);
    EXPECT_EQ(m.count[static_cast<size_t>(m.master_of[static_cast<size_t>(c)])], 1);
  }
  // The threshold is the angle given: at 2.5 degrees they do snap.
  EXPECT_EQ(snap_master_planes(planes, centers, {2.0, 1.0}, {{0, 1}}, 2.5).planes.size(), 1u);
}

// On a smoothly curved surface neighbouring planes meet about halfway between their
// clusters, however small the angle: tangent planes of a sphere of radius 100 at points 1
// apart (0.57 degrees) stay separate. The same two normals with the second plane moved by
// 2 mm along its normal meet 0.2 away from the middle (a fifth of their distance): noise,
// not curvature, so they snap. Identical and parallel planes snap.
TEST(MasterPlanes, PlanesMeetingBetweenTheirClustersStaySeparate) {
  const double radius = 100.0;
  const Vec3 na = Vec3(-0.5, 0.0, radius).normalized(), nb = Vec3(0.5, 0.0, radius).normalized();
  const std::vector<Vec3> centers = {radius * na, radius * nb};
  const std::vector<Plane> tangent = {Plane::through(centers[0], na), Plane::through(centers[1], nb)};
  ASSERT_NEAR(angle_deg(na, nb), 0.573, 0.001);
  EXPECT_EQ(snap_master_planes(tangent, centers, {1.0, 1.0}, {{0, 1}}).planes.size(), 2u);
  const std::vector<Plane> moved = {tangent[0], Plane{nb, tangent[1].offset + 2e-3}};
  EXPECT_EQ(snap_master_planes(moved, centers, {1.0, 1.0}, {{0, 1}}).planes.size(), 1u);
  const std::vector<Plane> same = {tangent[0], tangent[0]};
  EXPECT_EQ(snap_master_planes(same, centers, {1.0, 1.0}, {{0, 1}}).planes.size(), 1u);
  const std::vector<Plane> parallel = {tangent[0], Plane{na, tangent[0].offset + 0.1}};
  EXPECT_EQ(snap_master_planes(parallel, centers, {1.0, 1.0}, {{0, 1}}).planes.size(), 1u);
}

TEST(MasterPlanes, AChainOfSmallTurnsDoesNotCollapse) {
  // Planes each 0.6 degree from the next (3 degrees end to end), neighbours in a chain.
  const int n = 6;
  std::vector<Plane> planes;
  std::vector<Vec3> centers;
  std::vector<std::pair<int, int>> neighbours;
  for (int i = 0; i < n; ++i) {
    centers.emplace_back(0.0, i, 0.0);
    planes.push_back(Plane::through(centers.back(), tilted(0.6 * i)));
    if (i > 0) neighbours.emplace_back(i - 1, i);
  }
  const MasterPlanes m = snap_master_planes(planes, centers, std::vector<double>(n, 1.0), neighbours);
  EXPECT_GE(m.planes.size(), 2u);
  EXPECT_LT(m.planes.size(), static_cast<size_t>(n));  // but some do snap
  for (int i = 0; i < n; ++i) {
    // No cluster is more than the degree from its master plane...
    EXPECT_LE(angle_deg(planes[static_cast<size_t>(i)].normal, m.plane_of(i).normal), 1.0) << i;
    for (int j = 0; j < n; ++j) {
      // ...and a group never spans the whole turn.
      if (m.master_of[static_cast<size_t>(i)] == m.master_of[static_cast<size_t>(j)]) {
        EXPECT_LT(angle_deg(planes[static_cast<size_t>(i)].normal, planes[static_cast<size_t>(j)].normal), 2.0);
      }
    }
  }
  // Masters are contiguous along the chain (a group is connected through neighbours).
  for (int i = 2; i < n; ++i) {
    if (m.master_of[static_cast<size_t>(i)] == m.master_of[static_cast<size_t>(i - 2)]) {
      EXPECT_EQ(m.master_of[static_cast<size_t>(i)], m.master_of[static_cast<size_t>(i - 1)]);
    }
  }
}

TEST(MasterPlanes, SingletonsKeepTheirPlaneAmongSnappedGroups) {
  // 0 and 1 snap (their line runs through 1's centre, half their distance from the middle);
  // 2 is 5 degrees off and keeps its plane exactly, whatever its area.
  const std::vector<Vec3> centers = {Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(2, 0, 0.3)};
  const std::vector<Plane> planes = {Plane::through(centers[0], tilted(0.0)), Plane::through(centers[1], tilted(0.3)),
                                     Plane::through(centers[2], Vec3(0.3, -0.1, 1.0).normalized())};
  const MasterPlanes m = snap_master_planes(planes, centers, {1.0, 1.0, 1e-9}, {{0, 1}, {1, 2}, {0, 2}});
  EXPECT_EQ(m.planes.size(), 2u);
  EXPECT_EQ(m.master_of[0], m.master_of[1]);
  const Plane& alone = m.plane_of(2);
  EXPECT_TRUE(alone.normal == planes[2].normal);
  EXPECT_EQ(alone.offset, planes[2].offset);
  EXPECT_EQ(m.count[static_cast<size_t>(m.master_of[2])], 1);
  EXPECT_EQ(m.count[static_cast<size_t>(m.master_of[0])], 2);
}

TEST(MasterPlanes, Deterministic) {
  std::vector<Plane> planes;
  std::vector<Vec3> centers;
  std::vector<std::pair<int, int>> neighbours;
  for (int i = 0; i < 10; ++i) {
    centers.emplace_back(i, 0.5 * i, 0.0);
    planes.push_back(Plane::through(centers.back(), tilted(0.4 * (i % 4))));
    if (i > 0) neighbours.emplace_back(i, i - 1);
  }
  const MasterPlanes a = snap_master_planes(planes, centers, std::vector<double>(10, 1.0), neighbours);
  const MasterPlanes b = snap_master_planes(planes, centers, std::vector<double>(10, 1.0), neighbours);
  EXPECT_EQ(a.master_of, b.master_of);
  for (size_t k = 0; k < a.planes.size(); ++k) EXPECT_TRUE(a.planes[k].normal == b.planes[k].normal);
}

// Settled clusters keep their planes from round to round: a group with a fixed plane takes
// it bit for bit, and two different fixed planes never join.
TEST(MasterPlanes, FixedPlanesAreKeptExactly) {
  const std::vector<Vec3> centers = {Vec3(0, 0, 0), Vec3(1, 0, 0.01), Vec3(2, 0, 0.02)};
  const std::vector<Plane> planes = {Plane::through(centers[0], tilted(0.0)), Plane::through(centers[1], tilted(0.3)),
                                     Plane::through(centers[2], tilted(0.6))};
  const std::vector<std::pair<int, int>> neighbours = {{0, 1}, {1, 2}};
  const MasterPlanes free = snap_master_planes(planes, centers, {1.0, 1.0, 1.0}, neighbours);
  ASSERT_EQ(free.planes.size(), 1u);
  const MasterPlanes kept = snap_master_planes(planes, centers, {1.0, 1.0, 1.0}, neighbours, 1.0, {0, 0, 1});
  ASSERT_EQ(kept.planes.size(), 1u);
  EXPECT_EQ(kept.planes[0].normal, planes[2].normal);
  EXPECT_EQ(kept.planes[0].offset, planes[2].offset);
  const MasterPlanes two = snap_master_planes(planes, centers, {1.0, 1.0, 1.0}, neighbours, 1.0, {1, 0, 1});
  ASSERT_EQ(two.planes.size(), 2u);
  EXPECT_NE(two.master_of[0], two.master_of[2]);
  EXPECT_EQ(two.plane_of(0).normal, planes[0].normal);
  EXPECT_EQ(two.plane_of(2).normal, planes[2].normal);
  EXPECT_TRUE(two.plane_of(1).normal == planes[0].normal || two.plane_of(1).normal == planes[2].normal);
}

// A cluster left alone keeps its own plane; the others still snap.
TEST(MasterPlanes, AloneClustersStayOutOfGroups) {
  const std::vector<Vec3> centers = {Vec3(0, 0, 0), Vec3(1, 0, 0.01), Vec3(2, 0, 0.02)};
  const std::vector<Plane> planes = {Plane::through(centers[0], tilted(0.0)), Plane::through(centers[1], tilted(0.1)),
                                     Plane::through(centers[2], tilted(0.2))};
  const MasterPlanes m =
      snap_master_planes(planes, centers, {1.0, 1.0, 1.0}, {{0, 1}, {1, 2}, {0, 2}}, 1.0, {}, {0, 0, 1});
  ASSERT_EQ(m.planes.size(), 2u);
  EXPECT_EQ(m.master_of[0], m.master_of[1]);
  EXPECT_EQ(m.count[static_cast<size_t>(m.master_of[2])], 1);
  EXPECT_EQ(m.plane_of(2).normal, planes[2].normal);
  EXPECT_EQ(m.plane_of(2).offset, planes[2].offset);
}

}  // namespace
}  // namespace ff
