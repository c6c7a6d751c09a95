#pragma once
// The panel graph of a clustering (paper 2.1, DESIGN.md 3): corners are mesh vertices where
// three or more clusters meet (the mesh boundary counts as the NULL cluster kBoundary);
// each cluster's boundary is one loop of half-edges, cut into chains at its corners. It
// also finds the clusters that cannot become one panel (paper 2.4, fig. 10): a hole, a
// handle, a pinch, enclosed by a single neighbour, or two separate chains with one neighbour.
#include <vector>

#include "core/mesh/topology.h"

namespace ff {

constexpr int kBoundary = -1;  // the NULL cluster beyond the mesh boundary

struct Corner {
  int vertex = -1;
  bool on_boundary = false;
  // The clusters around the vertex in counter-clockwise order (seen from the side the
  // normals point to), consecutive repeats removed; on the boundary the last is kBoundary.
  std::vector<int> clusters;
};

// Why a cluster cannot be a panel as it is; bit flags.
enum ClusterProblem : unsigned {
  kHole = 1u,        // more than one boundary loop
  kHandle = 2u,      // one loop but not a disk (Euler characteristic != 1)
  kPinch = 4u,       // touches itself at a vertex
  kEnclosed = 8u,    // one neighbour all around, no corner
  kTwoChains = 16u,  // two or more separate chains with the same neighbour
};

struct PanelGraph {
  std::vector<int> corner_of_vertex;  // per mesh vertex: index into corners, or -1
  std::vector<Corner> corners;
  // Per cluster: its boundary half-edges (h = 3 f + i, from triangles[f][i] to [f][(i+1)%3],
  // the cluster on its left) as one loop starting just after a corner when it has one.
  // Empty for a cluster with problems other than kTwoChains.
  std::vector<std::vector<int>> loops;
  std::vector<unsigned> problems;  // per cluster, ClusterProblem flags

  // The cluster across half-edge h (kBoundary on the mesh boundary).
  static int other_side(const MeshTopology& topology, const std::vector<int>& labels, int h) {
    const int g = topology.face_neighbors[static_cast<size_t>(h / 3)][static_cast<size_t>(h % 3)];
    return g < 0 ? kBoundary : labels[static_cast<size_t>(g)];
  }
};

// The half-edge after border half-edge h along its cluster's border: about h's head vertex
// through the cluster's own faces until an edge leaves the cluster.
int next_border_half_edge(const TriMesh& mesh, const MeshTopology& topology, const std::vector<int>& labels, int h);

// Follows `next` (next_border_half_edge) from each of `half_edges` not yet `seen`, marking
// them: the first loop of a cluster c goes to loops[c], and loop_count[c] counts its loops.
void trace_border_loops(const std::vector<int>& half_edges, const std::vector<int>& next,
                        const std::vector<int>& labels, std::vector<char>& seen, std::vector<std::vector<int>>& loops,
                        std::vector<int>& loop_count);

// The border loop of a cluster with no other problem, rotated to start just after a corner.
// Returns kEnclosed (the loop cleared) when it has no corner and does not run along the mesh
// boundary, kTwoChains when it meets a neighbour in two chains, else 0. corner_of_vertex: as
// PanelGraph's; chain_neighbours: working memory.
unsigned start_loop_after_corner(const TriMesh& mesh, const MeshTopology& topology, const std::vector<int>& labels,
                                 const std::vector<int>& corner_of_vertex, std::vector<int>& loop,
                                 std::vector<int>& chain_neighbours);

// O(m). labels in [0, num_clusters), every cluster non-empty.
PanelGraph build_panel_graph(const TriMesh& mesh, const MeshTopology& topology, const std::vector<int>& labels,
                             int num_clusters);

// The faces around vertex v in counter-clockwise order; on the boundary, from the face on
// one boundary edge to the face on the other. Sets `on_boundary`.
std::vector<int> vertex_fan(const TriMesh& mesh, const MeshTopology& topology, int v, bool& on_boundary);
// The same into `fan` (cleared first), reusing its memory: build_panel_graph() walks the fan
// of every vertex where clusters meet, every panel round.
void vertex_fan(const TriMesh& mesh, const MeshTopology& topology, int v, bool& on_boundary, std::vector<int>& fan);

// The clusters around vertex v into `cycle` (cleared first), as a corner lists them:
// counter-clockwise, repeats in a row removed, kBoundary last on the boundary. A vertex
// inside one cluster is that cluster alone (its fan is not walked); an isolated vertex gives
// none. `fan`: working memory. Sets `on_boundary` (false for a vertex inside one cluster).
void vertex_cycle(const TriMesh& mesh, const MeshTopology& topology, const std::vector<int>& labels, int v,
                  std::vector<int>& fan, std::vector<int>& cycle, bool& on_boundary);

}  // namespace ff
