// update_panel_graph(): after random face moves on real meshes (closed, open, with handles),
// and after splits-like relabelling of whole neighbourhoods, the incremental graph equals
// build_panel_graph() of the same labels exactly: corners (vertex, boundary flag, clusters in
// order), corner_of_vertex, every loop (same half-edges from the same start) and the problems.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "core/mesh/clean.h"
#include "core/mesh/mesh_io.h"
#include "core/mesh/topology.h"
#include "core/panels/panel_graph.h"
#include "core/panels/panel_graph_update.h"
#include "core/util/random.h"
#include "synthetic_meshes.h"
#include "test_meshes.h"

namespace ff {
namespace {

void expect_same_graph(const PanelGraph& a, const PanelGraph& b, const std::string& where) {
  ASSERT_EQ(a.corner_of_vertex, b.corner_of_vertex) << where;
  ASSERT_EQ(a.corners.size(), b.corners.size()) << where;
  for (size_t k = 0; k < a.corners.size(); ++k) {
    ASSERT_EQ(a.corners[k].vertex, b.corners[k].vertex) << where;
    ASSERT_EQ(a.corners[k].on_boundary, b.corners[k].on_boundary) << where;
    ASSERT_EQ(a.corners[k].clusters, b.corners[k].clusters) << where << " corner " << k;
  }
  ASSERT_EQ(a.problems, b.problems) << where;
  ASSERT_EQ(a.loops, b.loops) << where;
}

// n connected clusters grown breadth-first from random seeds, in turn one face at a time.
std::vector<int> grown_labels(const MeshTopology& topology, int faces, int n, SplitMix64& rng) {
  std::vector<int> labels(static_cast<size_t>(faces), -1);
  std::vector<std::vector<int>> fronts;
  for (int c = 0; c < n; ++c) {
    int f = static_cast<int>(rng.below(static_cast<uint64_t>(faces)));
    while (labels[static_cast<size_t>(f)] >= 0) f = (f + 1) % faces;
    labels[static_cast<size_t>(f)] = c;
    fronts.push_back({f});
  }
  for (bool grew = true; grew;) {
    grew = false;
    for (int c = 0; c < n; ++c) {
      std::vector<int> next;
      for (int f : fronts[static_cast<size_t>(c)]) {
        for (int g : topology.face_neighbors[static_cast<size_t>(f)]) {
          if (g >= 0 && labels[static_cast<size_t>(g)] < 0)
            labels[static_cast<size_t>(g)] = c, next.push_back(g), grew = true;
        }
      }
      fronts[static_cast<size_t>(c)] = std::move(next);
    }
  }
  for (int& l : labels) l = std::max(l, 0);  // faces of components without a seed
  return labels;
}

// Moves `moves` random faces to the cluster of a random neighbour (never emptying a cluster):
// the boundary-term Lloyd iteration's kind of change, pinches, holes and handles included.
void move_faces(const MeshTopology& topology, std::vector<int>& labels, int n, int moves, SplitMix64& rng) {
  std::vector<int> size(static_cast<size_t>(n), 0);
  for (int l : labels) ++size[static_cast<size_t>(l)];
  for (int m = 0; m < moves; ++m) {
    const size_t f = static_cast<size_t>(rng.below(labels.size()));
    const int g = topology.face_neighbors[f][static_cast<size_t>(rng.below(3))];
    if (g < 0 || labels[static_cast<size_t>(g)] == labels[f] || size[static_cast<size_t>(labels[f])] <= 1) continue;
    --size[static_cast<size_t>(labels[f])];
    labels[f] = labels[static_cast<size_t>(g)];
    ++size[static_cast<size_t>(labels[f])];
  }
}

// Relabels every face within `rings` face steps of a random face with that face's cluster
// (a split's reflood), keeping every cluster non-empty.
void flood_patch(const MeshTopology& topology, std::vector<int>& labels, int n, int rings, SplitMix64& rng) {
  const size_t start = static_cast<size_t>(rng.below(labels.size()));
  const int c = labels[start];
  std::vector<int> size(static_cast<size_t>(n), 0);
  for (int l : labels) ++size[static_cast<size_t>(l)];
  std::vector<int> front{static_cast<int>(start)};
  for (int r = 0; r < rings; ++r) {
    std::vector<int> next;
    for (int f : front) {
      for (int g : topology.face_neighbors[static_cast<size_t>(f)]) {
        if (g < 0 || labels[static_cast<size_t>(g)] == c ||
            size[static_cast<size_t>(labels[static_cast<size_t>(g)])] <= 1)
          continue;
        --size[static_cast<size_t>(labels[static_cast<size_t>(g)])];
        labels[static_cast<size_t>(g)] = c;
        next.push_back(g);
      }
    }
    front = std::move(next);
  }
}

class PanelGraphUpdateMeshes : public ::testing::TestWithParam<std::string> {};

TEST_P(PanelGraphUpdateMeshes, EqualsAFreshBuildAfterRandomMoves) {
  const TriMesh mesh = clean_mesh(read_mesh_file(test::shared_mesh(GetParam())).mesh).mesh;
  const MeshTopology topology = build_topology(mesh);
  SplitMix64 rng(7);
  const int n = 60;
  std::vector<int> labels = grown_labels(topology, mesh.num_faces(), n, rng);
  PanelGraphState state;
  expect_same_graph(update_panel_graph(mesh, topology, labels, n, state), build_panel_graph(mesh, topology, labels, n),
                    "first");
  int with_problems = 0;
  for (int step = 0; step < 40; ++step) {
    if (step % 5 == 4) {
      flood_patch(topology, labels, n, 1 + static_cast<int>(rng.below(6)), rng);
    } else {
      move_faces(topology, labels, n, 1 + static_cast<int>(rng.below(400)), rng);
    }
    const PanelGraph fresh = build_panel_graph(mesh, topology, labels, n);
    expect_same_graph(update_panel_graph(mesh, topology, labels, n, state), fresh, "step " + std::to_string(step));
    with_problems += std::any_of(fresh.problems.begin(), fresh.problems.end(), [](unsigned p) { return p != 0; });
  }
  // The moves made clusters with problems (pinches, holes...), so those paths were compared too.
  EXPECT_GT(with_problems, 0);
  // No change: the same graph; another cluster count: built afresh.
  expect_same_graph(update_panel_graph(mesh, topology, labels, n, state), build_panel_graph(mesh, topology, labels, n),
                    "unchanged");
  std::vector<int> fewer = labels;
  for (int& l : fewer) l = l == n - 1 ? 0 : l;
  expect_same_graph(update_panel_graph(mesh, topology, fewer, n - 1, state),
                    build_panel_graph(mesh, topology, fewer, n - 1), "fewer");
  expect_same_graph(update_panel_graph(mesh, topology, labels, n, state), build_panel_graph(mesh, topology, labels, n),
                    "back");
}

INSTANTIATE_TEST_SUITE_P(Shared, PanelGraphUpdateMeshes,
                         ::testing::Values("bunny.off", "inspired_mesh.obj", "3holes.off", "YasIsland.off"));

// A torus whose clusters are rings around it (handles, enclosed, two chains): every problem
// kind, updated one face at a time.
TEST(PanelGraphUpdate, TorusRingsOneFaceAtATime) {
  const TriMesh mesh = test::torus(24, 12);
  const MeshTopology topology = build_topology(mesh);
  SplitMix64 rng(3);
  const int n = 6;
  std::vector<int> labels = grown_labels(topology, mesh.num_faces(), n, rng);
  PanelGraphState state;
  update_panel_graph(mesh, topology, labels, n, state);
  for (int step = 0; step < 300; ++step) {
    move_faces(topology, labels, n, 1, rng);
    expect_same_graph(update_panel_graph(mesh, topology, labels, n, state),
                      build_panel_graph(mesh, topology, labels, n), "step " + std::to_string(step));
  }
}

}  // namespace
}  // namespace ff
