#pragma once
// The panel graph of a clustering that changes a little at a time (the panel rounds: between
// two rounds the boundary-term Lloyd iteration moves some faces, splits reflood a
// neighbourhood). update_panel_graph() keeps the last graph with the per-cluster counts of
// its Euler characteristic and redoes only what the changed faces can reach: the corners at
// their vertices and the loops and problems of the clusters around those vertices. The
// result equals build_panel_graph() of the same labels exactly (tests/core/test_panel_graph_update.cpp).
#include <vector>

#include "core/panels/panel_graph.h"

namespace ff {

// What update_panel_graph() keeps between calls. Default-constructed: empty (the first call
// builds from scratch). Valid only for one mesh and topology.
struct PanelGraphState {
  std::vector<int> labels;  // the clustering `graph` is of
  PanelGraph graph;
  // Per cluster, as build_panel_graph() counts them (filled on the first incremental call):
  // vertices, faces, boundary half-edges (Euler characteristic V + F - (3 F + B) / 2), and
  // vertices where it touches itself (kPinch while above zero).
  bool counted = false;
  std::vector<long long> vertices, faces, border;
  std::vector<int> pinches;
  // Working memory, all zero / -1 between calls.
  std::vector<char> vertex_mark, face_mark, cluster_mark, seen;
  std::vector<int> next;
};

// The panel graph of `labels` (as build_panel_graph(mesh, topology, labels, num_clusters)),
// from the one in `state` when it is of the same mesh and cluster count: O(changed faces and
// the faces of the clusters around them) plus a pass over the labels. Updates `state`.
const PanelGraph& update_panel_graph(const TriMesh& mesh, const MeshTopology& topology, const std::vector<int>& labels,
                                     int num_clusters, PanelGraphState& state);

}  // namespace ff
