// Putting a short edge's two nodes back in order (core/panels/aim_edge_order.cpp): the plane
// whose trace is the edge turns so the trace passes the point of the two neighbouring lines
// on the right side; kept only when fewer panels are invalid.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "cluster_checks.h"
#include "core/mesh/topology.h"
#include "core/panels/panel_graph.h"
#include "core/panels/panel_layout.h"
#include "labelled_grid.h"
#include "panel_checks.h"
#include "synthetic_meshes.h"

namespace ff {
namespace {

// A flat 6 x 4 grid (cells of 0.5) in four clusters: P below y = 2, and above it A (x < 2), Q (2 < x < 4)
// and B (x > 4). P on z = 0; A and B meet it along the lines y = 2 - x / 3 and
// y = 2 + (x - 6) / 3, which cross at X = (3, 1); Q on z = s (y - y0) meets it along y = y0.
// The node of P, A and Q is where Q's trace crosses A's line, the node of P, Q and B where it
// crosses B's. With y0 below X (0.9) the two come out swapped: P's edge along Q runs the
// wrong way (P not simple, Q flipped), each node still within the spike distance of its
// corner. Above X (1.2) every panel is valid.
struct Notch : test::LabelledGrid {
  Notch() : LabelledGrid(test::notch_grid()) {}

  PanelLayout layout(double y0) const {
    const double t = 0.3, s = 0.253, r = std::sqrt(10.0);
    MasterPlanes m;
    m.master_of = {0, 1, 2, 3};
    m.planes = {Plane::through(Vec3(0, 0, 0), Vec3(0, 0, 1)),
                Plane::through(Vec3(0, 2, 0), Vec3(-t / r, -3 * t / r, 1).normalized()),
                Plane::through(Vec3(0, y0, 0), Vec3(0, -s, 1).normalized()),
                Plane::through(Vec3(6, 2, 0), Vec3(t / r, -3 * t / r, 1).normalized())};
    const std::vector<Vec3> near{Vec3(3, 1, 0), Vec3(1, 3, 0), Vec3(3, 3, 0), Vec3(5, 3, 0)};
    for (size_t c = 0; c < near.size(); ++c) m.centers.push_back(m.planes[c].project(near[c]));
    m.count = {1, 1, 1, 1};
    LayoutOptions options;
    options.diameter = 2.0;
    options.spike_distance = 1.9;  // below the chains (2.0): every corner its own node
    return PanelLayout(mesh, topology, labels, mesh.positions, graph, std::move(m), options);
  }
};

// The x of P's vertex standing for the mesh corner (x, 2): the node of P, Q and A (x = 2) or
// of P, Q and B (x = 4).
double node_x(const PanelLayout& layout, int corner_x) {
  const PanelPolygon& poly = layout.polygon(0);
  for (size_t i = 0; i < poly.points.size(); ++i) {
    if (poly.node[i] >= 0 && std::abs(poly.reference[i].x() - corner_x) < 1e-9 &&
        std::abs(poly.reference[i].y() - 2.0) < 1e-9)
      return poly.points[i].x();
  }
  return NAN;
}

TEST(AimEdgeOrder, SwappedNodesComeBackInOrder) {
  const Notch n;
  PanelLayout layout = n.layout(0.9);
  ASSERT_GT(node_x(layout, 2), node_x(layout, 4));  // swapped: A's node right of B's
  ASSERT_TRUE(layout.issues()[0].not_simple);
  ASSERT_TRUE(layout.issues()[2].flipped && layout.issues()[2].not_simple);
  for (int c = 0; c < 4; ++c) ASSERT_EQ(layout.issues()[static_cast<size_t>(c)].spike_vertices, 0);  // no spikes
  const Vec3 old_q = layout.planes().planes[2].normal;
  EXPECT_GE(layout.aim_edge_order(), 1);
  EXPECT_EQ(layout.num_invalid(), 0);
  EXPECT_LT(node_x(layout, 2), node_x(layout, 4));
  test::expect_planar(layout, 1e-9);  // the vertex rule still holds: exactly planar
  // Only Q moved (its trace lies along x, so holding both spots is a shift, no turn).
  EXPECT_NEAR(layout.planes().planes[2].normal.dot(old_q), 1.0, 1e-9);
  EXPECT_EQ(layout.planes().planes[0].offset, 0.0);
}

TEST(AimEdgeOrder, FixedPlanesStay) {
  const Notch n;
  PanelLayout layout = n.layout(0.9);
  const std::vector<Plane> before = layout.planes().planes;
  const int invalid = layout.num_invalid();
  EXPECT_EQ(layout.aim_edge_order(std::vector<char>(4, 1)), 0);
  EXPECT_EQ(layout.num_invalid(), invalid);
  for (size_t m = 0; m < before.size(); ++m) {
    EXPECT_EQ(layout.planes().planes[m].normal, before[m].normal);
    EXPECT_EQ(layout.planes().planes[m].offset, before[m].offset);
  }
}

// Nothing to do where the order is right: a valid layout stays as it is.
TEST(AimEdgeOrder, ValidLayoutUnchanged) {
  const Notch n;
  PanelLayout layout = n.layout(1.2);
  ASSERT_EQ(layout.num_invalid(), 0);
  EXPECT_EQ(layout.aim_edge_order(), 0);
}

// cow.off at 46 panels (the sweep's hardest case, bench/README.md): where the rounds and the
// other mends leave a panel flipped with every node well conditioned and near its corner,
// turning the neighbour plane of the offending edge mends it. Seed 12: valid on the first
// solve, and invalid without aim_edge_order (checked when the seed was chosen). The panel
// phase is chaotic, so the seed is re-chosen when the rounds change (it was seed 1 until the
// first round stopped re-relaxing for the tilt, panel_attempt.cpp).
TEST(AimEdgeOrder, CowAt46EndsValid) {
  const std::unique_ptr<Remesher> r = test::remeshed("cow.off", 46, 12);
  EXPECT_TRUE(test::valid_panels(*r, 46, 0.15));
  EXPECT_EQ(r->retries_done(), 0);
}

}  // namespace
}  // namespace ff
