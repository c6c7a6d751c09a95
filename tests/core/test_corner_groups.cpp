// Node groups: two corners joined by a short chain become one group whose clusters are the
// contracted chain's k-gon in counter-clockwise order; long chains and groups that would put
// two clusters on one master plane stay apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "core/mesh/topology.h"
#include "core/panels/corner_groups.h"
#include "core/panels/panel_graph.h"
#include "synthetic_meshes.h"

namespace ff {
namespace {

constexpr int kA = 0, kB = 1, kC = 2, kD = 3;

// A 4-wide grid: C the bottom two rows, then `band` rows with A left of x = 2 and B right of
// it, then D the top row. A | B is a vertical chain of `band` edges from (2, 2) up to
// (2, 2 + band), between the corners A B C (below) and A B D (above).
struct Layout {
  int band;
  TriMesh mesh;
  MeshTopology topology;
  std::vector<int> labels;
  PanelGraph graph;

  explicit Layout(int b) : band(b), mesh(test::grid(4, 3 + b)), topology(build_topology(mesh)) {
    for (int j = 0; j < 3 + band; ++j) {
      for (int i = 0; i < 4; ++i) {
        const int c = j < 2 ? kC : (j < 2 + band ? (i < 2 ? kA : kB) : kD);
        labels.push_back(c);
        labels.push_back(c);
      }
    }
    graph = build_panel_graph(mesh, topology, labels, 4);
  }
  int vertex(int i, int j) const { return 5 * j + i; }
  int corner(int i, int j) const { return graph.corner_of_vertex[static_cast<size_t>(vertex(i, j))]; }
  NodeGroups group(double max_chain_length, const std::vector<int>& master_of = {0, 1, 2, 3}) const {
    return group_corners(mesh, topology, labels, graph, mesh.positions, master_of, max_chain_length);
  }
};

bool same_cycle(std::vector<int> cycle, const std::vector<int>& expected) {
  for (size_t r = 0; r < cycle.size(); ++r) {
    if (cycle == expected) return true;
    std::rotate(cycle.begin(), cycle.begin() + 1, cycle.end());
  }
  return false;
}

// Every corner is in exactly one group, and each group lists its corners back.
void expect_partition(const Layout& layout, const NodeGroups& g) {
  ASSERT_EQ(g.group_of_corner.size(), layout.graph.corners.size());
  size_t listed = 0;
  for (size_t k = 0; k < g.groups.size(); ++k) {
    for (int c : g.groups[k].corners) EXPECT_EQ(g.group_of_corner[static_cast<size_t>(c)], static_cast<int>(k));
    listed += g.groups[k].corners.size();
    // kBoundary at most once, and then as the group's boundary flag.
    const auto boundary = std::count(g.groups[k].clusters.begin(), g.groups[k].clusters.end(), kBoundary);
    EXPECT_LE(boundary, 1);
    EXPECT_EQ(boundary == 1, g.groups[k].on_boundary);
  }
  EXPECT_EQ(listed, layout.graph.corners.size());
}

TEST(CornerGroups, LayoutHasTheCornersItClaims) {
  const Layout layout(1);
  ASSERT_GE(layout.corner(2, 2), 0);
  ASSERT_GE(layout.corner(2, 3), 0);
  EXPECT_TRUE(same_cycle(layout.graph.corners[static_cast<size_t>(layout.corner(2, 2))].clusters, {kC, kB, kA}));
  EXPECT_TRUE(same_cycle(layout.graph.corners[static_cast<size_t>(layout.corner(2, 3))].clusters, {kA, kB, kD}));
  for (unsigned p : layout.graph.problems) EXPECT_EQ(p, 0u);
}

TEST(CornerGroups, ShortChainJoinsTwoCornersIntoAFourClusterGroup) {
  const Layout layout(1);
  const NodeGroups g = layout.group(1.5);
  expect_partition(layout, g);
  const int lower = layout.corner(2, 2), upper = layout.corner(2, 3);
  ASSERT_EQ(g.group_of_corner[static_cast<size_t>(lower)], g.group_of_corner[static_cast<size_t>(upper)]);
  const NodeGroup& group = g.groups[static_cast<size_t>(g.group_of_corner[static_cast<size_t>(lower)])];
  EXPECT_EQ(std::set<int>(group.corners.begin(), group.corners.end()), (std::set<int>{lower, upper}));
  // The chain contracted to a point: C below, B right, D above, A left, counter-clockwise.
  EXPECT_TRUE(same_cycle(group.clusters, {kC, kB, kD, kA}));
  EXPECT_FALSE(group.on_boundary);
  EXPECT_LT((group.reference - Vec3(2.0, 2.5, 0.0)).norm(), 1e-12);
  // Every other corner (all on the boundary) stands alone with its own clusters.
  for (size_t k = 0; k < layout.graph.corners.size(); ++k) {
    if (static_cast<int>(k) == lower || static_cast<int>(k) == upper) continue;
    const NodeGroup& single = g.groups[static_cast<size_t>(g.group_of_corner[k])];
    EXPECT_EQ(single.corners, std::vector<int>{static_cast<int>(k)});
    EXPECT_EQ(single.clusters, layout.graph.corners[k].clusters);
    EXPECT_EQ(single.reference, layout.mesh.positions[static_cast<size_t>(layout.graph.corners[k].vertex)]);
  }
  EXPECT_EQ(g.groups.size(), layout.graph.corners.size() - 1);
}

TEST(CornerGroups, LongChainsDoNotJoin) {
  // The same 1-edge chain with a limit below its length, and a 2-edge chain with the old limit.
  for (const auto& [band, limit] : {std::pair<int, double>{1, 0.99}, std::pair<int, double>{2, 1.5}}) {
    const Layout layout(band);
    const NodeGroups g = layout.group(limit);
    expect_partition(layout, g);
    EXPECT_EQ(g.groups.size(), layout.graph.corners.size()) << "band " << band;
    for (const NodeGroup& group : g.groups) {
      EXPECT_EQ(group.corners.size(), 1u);
      EXPECT_EQ(group.clusters, layout.graph.corners[static_cast<size_t>(group.corners[0])].clusters);
    }
  }
  // And the 2-edge chain does join once the limit covers it (x stretched so that the
  // horizontal chains, also 2 edges long, are longer).
  const Layout layout(2);
  std::vector<Vec3> stretched = layout.mesh.positions;
  for (Vec3& p : stretched) p.x() *= 2.0;
  const NodeGroups g =
      group_corners(layout.mesh, layout.topology, layout.labels, layout.graph, stretched, {0, 1, 2, 3}, 2.01);
  EXPECT_EQ(g.group_of_corner[static_cast<size_t>(layout.corner(2, 2))],
            g.group_of_corner[static_cast<size_t>(layout.corner(2, 4))]);
}

TEST(CornerGroups, BoundaryCornerJoinsWithKBoundaryOnce) {
  // x squeezed: the chains along y = 2 (A | C from the left border, B | C to the right border)
  // are the shortest; the first joins (2, 2) with the boundary corner (0, 2).
  const Layout layout(2);
  std::vector<Vec3> squeezed = layout.mesh.positions;
  for (Vec3& p : squeezed) p.x() *= 0.25;
  const NodeGroups g =
      group_corners(layout.mesh, layout.topology, layout.labels, layout.graph, squeezed, {0, 1, 2, 3}, 0.6);
  expect_partition(layout, g);
  const int inner = layout.corner(2, 2);
  const NodeGroup& group = g.groups[static_cast<size_t>(g.group_of_corner[static_cast<size_t>(inner)])];
  ASSERT_EQ(group.corners.size(), 2u);
  EXPECT_TRUE(group.on_boundary);
  const int other = group.corners[0] == inner ? group.corners[1] : group.corners[0];
  if (other == layout.corner(0, 2)) {
    EXPECT_TRUE(same_cycle(group.clusters, {kC, kB, kA, kBoundary}));  // A | C contracted
  } else {
    ASSERT_EQ(other, layout.corner(4, 2));
    EXPECT_TRUE(same_cycle(group.clusters, {kC, kBoundary, kB, kA}));  // B | C contracted
  }
}

TEST(CornerGroups, ForcedPairsJoinWhateverTheirLength) {
  const Layout layout(2);
  const int lower = layout.corner(2, 2), upper = layout.corner(2, 4);
  const NodeGroups g = group_corners(layout.mesh, layout.topology, layout.labels, layout.graph, layout.mesh.positions,
                                     {0, 1, 2, 3}, 0.5, {{std::min(lower, upper), std::max(lower, upper)}});
  expect_partition(layout, g);
  EXPECT_EQ(g.group_of_corner[static_cast<size_t>(lower)], g.group_of_corner[static_cast<size_t>(upper)]);
  const NodeGroup& group = g.groups[static_cast<size_t>(g.group_of_corner[static_cast<size_t>(lower)])];
  EXPECT_TRUE(same_cycle(group.clusters, {kC, kB, kD, kA}));
  EXPECT_LT((group.reference - Vec3(2.0, 3.0, 0.0)).norm(), 1e-12);
}

// A lock holds its corners' grouping by mesh vertex (HeldGrouping): a pair together whatever
// its chain's length, and a corner apart though its chain is short enough.
TEST(CornerGroups, HeldGroupingKeepsCornersTogetherOrApart) {
  const Layout layout(2);
  const int lower = layout.corner(2, 2), upper = layout.corner(2, 4);
  const int lv = layout.vertex(2, 2), uv = layout.vertex(2, 4);
  HeldGrouping together;
  together.together = {{std::min(lv, uv), std::max(lv, uv)}};
  const NodeGroups g = group_corners(layout.mesh, layout.topology, layout.labels, layout.graph, layout.mesh.positions,
                                     {0, 1, 2, 3}, 0.5, {}, together);
  expect_partition(layout, g);
  EXPECT_EQ(g.group_of_corner[static_cast<size_t>(lower)], g.group_of_corner[static_cast<size_t>(upper)]);
  HeldGrouping apart;
  apart.apart = {uv};
  const NodeGroups h = group_corners(layout.mesh, layout.topology, layout.labels, layout.graph, layout.mesh.positions,
                                     {0, 1, 2, 3}, 10.0, {}, apart);
  expect_partition(layout, h);
  EXPECT_NE(h.group_of_corner[static_cast<size_t>(lower)], h.group_of_corner[static_cast<size_t>(upper)]);
  EXPECT_EQ(h.groups[static_cast<size_t>(h.group_of_corner[static_cast<size_t>(upper)])].corners.size(), 1u);
}

TEST(CornerGroups, BoundaryGroupsStandOnTheBordersWall) {
  // The wall at a boundary corner contains the border's direction and the surface normal.
  const Layout layout(1);
  const NodeGroups g = layout.group(1.5);
  int walls = 0;
  for (const NodeGroup& group : g.groups) {
    if (!group.on_boundary || !group.has_wall) continue;
    ++walls;
    const Corner& c = layout.graph.corners[static_cast<size_t>(group.corners[0])];
    const Vec3& p = layout.mesh.positions[static_cast<size_t>(c.vertex)];
    const Vec3 border = p.x() == 0.0 || p.x() == 4.0 ? Vec3::UnitY() : Vec3::UnitX();
    EXPECT_NEAR(group.wall.distance(p), 0.0, 1e-12);
    EXPECT_NEAR(group.wall.normal.dot(border), 0.0, 1e-12);
    EXPECT_NEAR(group.wall.normal.dot(Vec3::UnitZ()), 0.0, 1e-12);
  }
  EXPECT_EQ(walls, 4);  // (0, 2), (0, 3), (4, 2), (4, 3)
}

TEST(CornerGroups, NoGroupWithTwoClustersOnOneMasterPlane) {
  const Layout layout(1);
  // C and D share a master plane: the group C B D A would have two nodes on it.
  const NodeGroups g = layout.group(1.5, {0, 1, 2, 2});
  expect_partition(layout, g);
  EXPECT_NE(g.group_of_corner[static_cast<size_t>(layout.corner(2, 2))],
            g.group_of_corner[static_cast<size_t>(layout.corner(2, 3))]);
  for (const NodeGroup& group : g.groups) {
    std::set<int> masters;
    const std::vector<int> master_of = {0, 1, 2, 2};
    for (int c : group.clusters) {
      if (c != kBoundary) {
        EXPECT_TRUE(masters.insert(master_of[static_cast<size_t>(c)]).second);
      }
    }
  }
  // Nor when the shared masters are the chain's own two sides.
  const NodeGroups ab = layout.group(1.5, {0, 0, 1, 2});
  EXPECT_NE(ab.group_of_corner[static_cast<size_t>(layout.corner(2, 2))],
            ab.group_of_corner[static_cast<size_t>(layout.corner(2, 3))]);
  // Control: with four distinct masters the same layout does join.
  const NodeGroups distinct = layout.group(1.5, {3, 2, 1, 0});
  EXPECT_EQ(distinct.group_of_corner[static_cast<size_t>(layout.corner(2, 2))],
            distinct.group_of_corner[static_cast<size_t>(layout.corner(2, 3))]);
}

}  // namespace
}  // namespace ff
