// Aiming one plane at one node (core/panels/aim_node_planes.cpp): at a node whose three
// planes put it far from its corner, one plane turns about its centre so the node comes back
// to the line of the other two near the corner; kept only when fewer panels are invalid.
#include <gtest/gtest.h>

#include <vector>

#include "core/mesh/topology.h"
#include "core/panels/panel_graph.h"
#include "core/panels/panel_layout.h"
#include "core/remesher.h"
#include "core/shapes/hard_cases.h"
#include "labelled_grid.h"
#include "panel_checks.h"
#include "synthetic_meshes.h"

namespace ff {
namespace {

// A flat 6 x 2 grid in three clusters: A (x < 3) and B (x > 3) above y = 1, C below; one
// interior corner at (3, 1), border corners at (3, 2), (0, 1) and (6, 1). A on z = 0, C on
// z = s (y - 1) (through A's line y = 1), B on z = a (x + y / 2 - 4): through (3, 2, 0) on
// A, and meeting A's and C's line at (3.5, 1, 0). With a = 0.01, s = 0.1 the three normals
// are nearly coplanar (triple product a s = 0.001): the interior node is half a unit from
// its corner, a spike at 0.3, while every border node is within 0.3 of its own.
struct Strip : test::LabelledGrid {
  Strip()
      : LabelledGrid(test::labelled_grid(test::grid(6, 2), 3,
                                         [](const Vec3& c) { return c.y() < 1.0 ? 2 : (c.x() < 3.0 ? 0 : 1); })) {}

  PanelLayout layout(double spike_distance) const {
    const double a = 0.01, s = 0.1;
    MasterPlanes m;
    m.master_of = {0, 1, 2};
    m.planes = {Plane::through(Vec3(0, 0, 0), Vec3(0, 0, 1)),
                Plane::through(Vec3(4, 0, 0), Vec3(-a, -0.5 * a, 1).normalized()),
                Plane::through(Vec3(0, 1, 0), Vec3(0, -s, 1).normalized())};
    m.centers = {Vec3(1.5, 1.5, 0), Vec3(4.5, 1.5, 1.25 * a), Vec3(3, 0.5, -0.5 * s)};
    m.count = {1, 1, 1};
    LayoutOptions options;
    options.diameter = 2.0;
    options.spike_distance = spike_distance;
    return PanelLayout(mesh, topology, labels, mesh.positions, graph, std::move(m), options);
  }
};

// Largest distance of a panel's node vertices from where they belong.
double farthest_node(const PanelLayout& layout, int cluster) {
  const PanelPolygon& poly = layout.polygon(cluster);
  double far = 0.0;
  for (size_t i = 0; i < poly.points.size(); ++i) {
    if (poly.node[i] >= 0) far = std::max(far, (poly.points[i] - poly.reference[i]).norm());
  }
  return far;
}

// Largest distance of a panel's vertices from its own plane.
double off_plane(const PanelLayout& layout, int cluster) {
  const Plane& plane = layout.planes().plane_of(cluster);
  double off = 0.0;
  for (const Vec3& p : layout.polygon(cluster).points) off = std::max(off, std::abs(plane.distance(p)));
  return off;
}

TEST(AimNodePlanes, NearlyParallelTripleComesBackToItsCorner) {
  const Strip s;
  PanelLayout layout = s.layout(0.3);
  // The spike spoils all three panels around it.
  for (int c = 0; c < 3; ++c) {
    ASSERT_NEAR(farthest_node(layout, c), 0.5, 1e-6) << c;
    ASSERT_FALSE(layout.issues()[static_cast<size_t>(c)].valid()) << c;
  }
  EXPECT_EQ(layout.aim_node_planes(), 1);
  EXPECT_EQ(layout.num_invalid(), 0);
  for (int c = 0; c < 3; ++c) {
    EXPECT_LE(farthest_node(layout, c), 0.3) << c;
    EXPECT_LT(off_plane(layout, c), 1e-9) << c;  // the vertex rule still holds: exactly planar
  }
}

TEST(AimNodePlanes, FixedPlanesStay) {
  const Strip s;
  PanelLayout layout = s.layout(0.3);
  const std::vector<Plane> before = layout.planes().planes;
  EXPECT_EQ(layout.aim_node_planes(std::vector<char>(3, 1)), 0);
  for (size_t m = 0; m < before.size(); ++m) {
    EXPECT_EQ(layout.planes().planes[m].normal, before[m].normal);
    EXPECT_EQ(layout.planes().planes[m].offset, before[m].offset);
  }
}

// No turn bigger than allowed: with a limit far below the needed turn nothing changes.
TEST(AimNodePlanes, TurnLimitHolds) {
  const Strip s;
  PanelLayout layout = s.layout(0.3);
  const int before = layout.num_invalid();
  EXPECT_EQ(layout.aim_node_planes({}, 1e-3), 0);
  EXPECT_EQ(layout.num_invalid(), before);
}

// Barrel vault, 50k triangles, 500 panels: the rounds and the other mends left one panel
// flipped where three planes along the axis meet; aiming one of them mends it.
TEST(AimNodePlanes, BarrelVaultAt500EndsValid) {
  RemeshParams p;
  p.panels = 500;
  Remesher r(make_barrel_vault(50000), p);
  r.run();
  EXPECT_TRUE(test::valid_panels(r, 500, 0.05));
}

}  // namespace
}  // namespace ff
