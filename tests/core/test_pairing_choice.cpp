// The pairing of a four-cluster corner (paper fig. 6): split into two valence-3 nodes, one of
// the two pairings leaves every panel valid and the other flips the short edge between the
// nodes. The layout's first choice is the pairing whose nodes stay nearest the corner;
// switch_pairings() must then find the one that flips nothing. And the designer's option,
// four planes through one point (make_single_point_nodes), keeps every panel planar.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/panels/panel_layout.h"
#include "labelled_grid.h"
#include "synthetic_meshes.h"

namespace ff {
namespace {

// A flat 4 x 4 square (cells of 0.5) in four quadrants around the corner C = (2, 2), counter-
// clockwise: 0 lower left, 1 lower right, 2 upper right, 3 upper left. Plane i is the height
// field z = s g_i . (x - P) + b_i, each rising away from the corner towards its own quadrant
// (g_0 = (-1, -1), g_1 = (1, -1), ...), about P = C + delta (1, 1). Raising planes 0 and 2
// by e makes them the top pair at P: on the convex surface z = max_i h_i they share an edge
// of length 2 sqrt(2) a along x + y = const (a = e / 2s), so the valid pairing has nodes
// (0 1 2) at P + a (1, -1) and (0 2 3) at P - a (1, -1). The other pairing puts its nodes at
// P +- a (1, 1): with delta along (1, 1) their distances to C sum to 2 sqrt(2) a, less than
// the valid pairing's 2 sqrt(2) sqrt(a^2 + delta^2), so it is the first choice, and it is
// wrong: panel 1 runs from the node of the right chain through the far corner of the edge
// back to the bottom chain.
struct FourQuadrants : test::LabelledGrid {
  static constexpr double s = 0.2, e = 0.02, delta = 0.02;
  static constexpr double a = e / (2 * s);

  FourQuadrants()
      : LabelledGrid(test::labelled_grid(test::half_grid(8, 8), 4, [](const Vec3& c) {
          return c.y() < 2.0 ? (c.x() < 2.0 ? 0 : 1) : (c.x() < 2.0 ? 3 : 2);
        })) {}

  static Vec3 p() { return Vec3(2.0 + delta, 2.0 + delta, 0.0); }

  PanelLayout layout() const {
    const double g[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    const double b[4] = {e, 0.0, e, 0.0};
    MasterPlanes m;
    m.master_of = {0, 1, 2, 3};
    for (int i = 0; i < 4; ++i) {
      // z = s g . (x - P) + b: normal (-s g, 1), through (P, b).
      const Vec3 normal = Vec3(-s * g[i][0], -s * g[i][1], 1.0).normalized();
      m.planes.push_back(Plane::through(p() + Vec3(0, 0, b[i]), normal));
      m.centers.push_back(m.planes.back().project(Vec3(2.0 + g[i][0], 2.0 + g[i][1], 0.0)));
      m.count.push_back(1);
    }
    LayoutOptions options;
    options.diameter = 2.0;
    options.spike_distance = 1.0;  // below the chains (2.0): the corner is one group of four
    return PanelLayout(mesh, topology, labels, mesh.positions, graph, std::move(m), options);
  }
};

// The points of a panel on nodes of the corner's group (those within `reach` of C in x, y).
std::vector<Vec3> centre_nodes(const PanelLayout& layout, int cluster, double reach = 0.5) {
  std::vector<Vec3> out;
  const PanelPolygon& poly = layout.polygon(cluster);
  for (size_t i = 0; i < poly.points.size(); ++i) {
    const Vec3 d = poly.points[i] - Vec3(2.0, 2.0, poly.points[i].z());
    if (poly.node[i] >= 0 && d.norm() < reach) out.push_back(poly.points[i]);
  }
  return out;
}

bool near_xy(const Vec3& u, const Vec3& v, double tolerance = 1e-9) {
  return std::hypot(u.x() - v.x(), u.y() - v.y()) < tolerance;
}

TEST(PairingChoice, NearestPairingFlipsAndTheSwitchFindsTheOneThatDoesNot) {
  const FourQuadrants q;
  PanelLayout layout = q.layout();
  // First choice: the nodes at P +- a (1, 1), on the edge panels 1 and 3 share.
  const std::vector<Vec3> first = centre_nodes(layout, 1);
  ASSERT_EQ(first.size(), 2u);
  const Vec3 diagonal = FourQuadrants::a * Vec3(1, 1, 0);
  EXPECT_TRUE(near_xy(first[0], q.p() + diagonal) || near_xy(first[1], q.p() + diagonal));
  EXPECT_TRUE(near_xy(first[0], q.p() - diagonal) || near_xy(first[1], q.p() - diagonal));
  EXPECT_GT(layout.num_invalid(), 0);
  EXPECT_FALSE(layout.issues()[1].valid());
  EXPECT_FALSE(layout.issues()[3].valid());

  EXPECT_EQ(layout.switch_pairings(), 1);
  EXPECT_EQ(layout.num_invalid(), 0);
  // Now panels 0 and 2 share the edge from P + a (1, -1) to P - a (1, -1); 1 and 3 each
  // touch one of its ends.
  const Vec3 across = FourQuadrants::a * Vec3(1, -1, 0);
  for (int c : {0, 2}) {
    const std::vector<Vec3> nodes = centre_nodes(layout, c);
    ASSERT_EQ(nodes.size(), 2u) << c;
    EXPECT_TRUE(near_xy(nodes[0], q.p() + across) || near_xy(nodes[1], q.p() + across)) << c;
    EXPECT_TRUE(near_xy(nodes[0], q.p() - across) || near_xy(nodes[1], q.p() - across)) << c;
  }
  ASSERT_EQ(centre_nodes(layout, 1).size(), 1u);
  EXPECT_TRUE(near_xy(centre_nodes(layout, 1)[0], q.p() + across));
  ASSERT_EQ(centre_nodes(layout, 3).size(), 1u);
  EXPECT_TRUE(near_xy(centre_nodes(layout, 3)[0], q.p() - across));
  test::expect_planar(layout, 1e-12);
  // A second pass has nothing left to switch.
  EXPECT_EQ(layout.switch_pairings(), 0);
}

// The designer's alternative (paper 2.2): the four planes turned through one point, which
// every panel then has as its vertex at the corner; still exactly planar and valid.
TEST(PairingChoice, SinglePointNodeJoinsAllFourPanelsAtOnePoint) {
  const FourQuadrants q;
  PanelLayout layout = q.layout();
  EXPECT_EQ(layout.make_single_point_nodes(), 1);
  std::vector<Vec3> points;
  for (int c = 0; c < 4; ++c) {
    const std::vector<Vec3> nodes = centre_nodes(layout, c);
    ASSERT_EQ(nodes.size(), 1u) << c;
    points.push_back(nodes[0]);
  }
  for (const Vec3& v : points) EXPECT_LT((v - points[0]).norm(), 1e-12);
  EXPECT_LT((points[0] - q.p()).head<2>().norm(), 0.1);
  EXPECT_EQ(layout.num_invalid(), 0);
  test::expect_planar(layout, 1e-12);
}

}  // namespace
}  // namespace ff
