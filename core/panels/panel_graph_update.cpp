#include "core/panels/panel_graph_update.h"

#include <algorithm>

namespace ff {

namespace {

// Working memory of one update.
struct Scratch {
  std::vector<int> fan, cycle, sorted;
};

// Adds `sign` times the vertex's share (s.cycle) to the counts: one vertex for each cluster
// there, one pinch for each repeat of a cluster.
void count_vertex(Scratch& s, long long sign, PanelGraphState& state) {
  if (s.cycle.size() == 1) {
    if (s.cycle[0] != kBoundary) state.vertices[static_cast<size_t>(s.cycle[0])] += sign;
    return;
  }
  s.sorted.assign(s.cycle.begin(), s.cycle.end());
  std::sort(s.sorted.begin(), s.sorted.end());
  for (size_t k = 0; k < s.sorted.size(); ++k) {
    const int c = s.sorted[k];
    if (c == kBoundary) continue;
    if (k > 0 && c == s.sorted[k - 1]) {
      state.pinches[static_cast<size_t>(c)] += static_cast<int>(sign);
    } else {
      state.vertices[static_cast<size_t>(c)] += sign;
    }
  }
}

// Face f's half-edges on its cluster's boundary.
int border_of(const MeshTopology& topology, const std::vector<int>& labels, int f) {
  const int c = labels[static_cast<size_t>(f)];
  int count = 0;
  for (int i = 0; i < 3; ++i) count += PanelGraph::other_side(topology, labels, 3 * f + i) != c;
  return count;
}

// The counts of state.labels, from scratch.
void count_all(const TriMesh& mesh, const MeshTopology& topology, size_t n, PanelGraphState& state, Scratch& s) {
  state.vertices.assign(n, 0);
  state.faces.assign(n, 0);
  state.border.assign(n, 0);
  state.pinches.assign(n, 0);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    bool on_boundary = false;
    vertex_cycle(mesh, topology, state.labels, v, s.fan, s.cycle, on_boundary);
    count_vertex(s, 1, state);
  }
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const size_t c = static_cast<size_t>(state.labels[static_cast<size_t>(f)]);
    state.faces[c] += 1;
    state.border[c] += border_of(topology, state.labels, f);
  }
  state.vertex_mark.assign(static_cast<size_t>(mesh.num_vertices()), 0);
  state.face_mark.assign(static_cast<size_t>(mesh.num_faces()), 0);
  state.cluster_mark.assign(n, 0);
  state.seen.assign(static_cast<size_t>(3 * mesh.num_faces()), 0);
  state.next.assign(static_cast<size_t>(3 * mesh.num_faces()), -1);
  state.counted = true;
}

// The corners at the `affected` vertices (sorted) from `labels`, merged into the others in
// vertex order; counts their vertices' shares back in.
void update_corners(const TriMesh& mesh, const MeshTopology& topology, const std::vector<int>& labels,
                    const std::vector<int>& affected, PanelGraphState& state, Scratch& s) {
  PanelGraph& g = state.graph;
  std::vector<Corner> corners;
  corners.reserve(g.corners.size() + affected.size());
  size_t k = 0;
  for (int v : affected) {
    for (; k < g.corners.size() && g.corners[k].vertex < v; ++k) corners.push_back(std::move(g.corners[k]));
    if (k < g.corners.size() && g.corners[k].vertex == v) ++k;  // redone below
    bool on_boundary = false;
    vertex_cycle(mesh, topology, labels, v, s.fan, s.cycle, on_boundary);
    count_vertex(s, 1, state);
    g.corner_of_vertex[static_cast<size_t>(v)] = -1;
    if (s.cycle.size() >= 3) corners.push_back(Corner{v, on_boundary, s.cycle});
  }
  for (; k < g.corners.size(); ++k) corners.push_back(std::move(g.corners[k]));
  g.corners = std::move(corners);
  for (size_t i = 0; i < g.corners.size(); ++i)
    g.corner_of_vertex[static_cast<size_t>(g.corners[i].vertex)] = static_cast<int>(i);
}

// The loops and problems of the marked clusters (state.cluster_mark), as build_panel_graph()
// finds them: their boundary half-edges in face order, each loop from its first.
void redo_loops(const TriMesh& mesh, const MeshTopology& topology, const std::vector<int>& labels,
                const std::vector<int>& dirty, PanelGraphState& state) {
  PanelGraph& g = state.graph;
  std::vector<int> half_edges;
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const int c = labels[static_cast<size_t>(f)];
    if (!state.cluster_mark[static_cast<size_t>(c)]) continue;
    for (int i = 0; i < 3; ++i) {
      if (PanelGraph::other_side(topology, labels, 3 * f + i) != c) half_edges.push_back(3 * f + i);
    }
  }
  for (int h : half_edges) state.next[static_cast<size_t>(h)] = next_border_half_edge(mesh, topology, labels, h);
  std::vector<int> loop_count(g.problems.size(), 0);  // only the dirty ones are read
  for (int c : dirty) g.loops[static_cast<size_t>(c)].clear();
  trace_border_loops(half_edges, state.next, labels, state.seen, g.loops, loop_count);
  for (int h : half_edges) state.seen[static_cast<size_t>(h)] = 0, state.next[static_cast<size_t>(h)] = -1;

  std::vector<int> chain_neighbours;
  for (int ci : dirty) {
    const size_t c = static_cast<size_t>(ci);
    unsigned problems = state.pinches[c] > 0 ? unsigned{kPinch} : 0u;
    if (loop_count[c] > 1) problems |= kHole;
    const long long euler = state.vertices[c] + state.faces[c];
    const long long twice_edges = 3 * state.faces[c] + state.border[c];
    if (2 * euler - twice_edges != 2) problems |= kHandle;
    g.problems[c] = problems;
    std::vector<int>& loop = g.loops[c];
    if (problems != 0 || loop.empty()) {
      if (problems != 0) loop.clear();
      continue;
    }
    g.problems[c] |= start_loop_after_corner(mesh, topology, labels, g.corner_of_vertex, loop, chain_neighbours);
  }
}

}  // namespace

const PanelGraph& update_panel_graph(const TriMesh& mesh, const MeshTopology& topology, const std::vector<int>& labels,
                                     int num_clusters, PanelGraphState& state) {
  const size_t n = static_cast<size_t>(num_clusters);
  if (state.labels.size() != labels.size() || state.graph.problems.size() != n ||
      state.graph.corner_of_vertex.size() != static_cast<size_t>(mesh.num_vertices())) {
    state = PanelGraphState{};
    state.graph = build_panel_graph(mesh, topology, labels, num_clusters);
    state.labels = labels;
    return state.graph;
  }
  Scratch s;
  // The counts only from the second call on: a single round needs none.
  if (!state.counted) count_all(mesh, topology, n, state, s);

  std::vector<int> changed;
  for (size_t f = 0; f < labels.size(); ++f) {
    if (labels[f] != state.labels[f]) changed.push_back(static_cast<int>(f));
  }
  if (changed.empty()) return state.graph;

  // The vertices of changed faces (their corners and shares change) and the faces whose
  // boundary half-edges can change (the changed ones and their neighbours).
  std::vector<int> affected, touched;
  for (int f : changed) {
    for (int v : mesh.triangles[static_cast<size_t>(f)]) {
      if (!state.vertex_mark[static_cast<size_t>(v)])
        state.vertex_mark[static_cast<size_t>(v)] = 1, affected.push_back(v);
    }
    if (!state.face_mark[static_cast<size_t>(f)]) state.face_mark[static_cast<size_t>(f)] = 1, touched.push_back(f);
    for (int g : topology.face_neighbors[static_cast<size_t>(f)]) {
      if (g >= 0 && !state.face_mark[static_cast<size_t>(g)])
        state.face_mark[static_cast<size_t>(g)] = 1, touched.push_back(g);
    }
  }
  std::sort(affected.begin(), affected.end());
  // Dirty: every cluster with a face at an affected vertex, before or after. Any other keeps
  // its faces, its neighbours across its boundary and the corner status of its boundary
  // vertices, so its loop and problems stay as they were.
  std::vector<int> dirty;
  const auto mark = [&](int c) {
    if (!state.cluster_mark[static_cast<size_t>(c)]) state.cluster_mark[static_cast<size_t>(c)] = 1, dirty.push_back(c);
  };
  for (int v : affected) {
    for (int k = topology.vertex_face_offsets[static_cast<size_t>(v)];
         k < topology.vertex_face_offsets[static_cast<size_t>(v) + 1]; ++k) {
      const size_t f = static_cast<size_t>(topology.vertex_faces[static_cast<size_t>(k)]);
      mark(state.labels[f]);
      mark(labels[f]);
    }
  }
  std::sort(dirty.begin(), dirty.end());

  // Out with the old shares, in with the new.
  for (int v : affected) {
    bool on_boundary = false;
    vertex_cycle(mesh, topology, state.labels, v, s.fan, s.cycle, on_boundary);
    count_vertex(s, -1, state);
  }
  for (int f : touched)
    state.border[static_cast<size_t>(state.labels[static_cast<size_t>(f)])] -= border_of(topology, state.labels, f);
  for (int f : changed) {
    state.faces[static_cast<size_t>(state.labels[static_cast<size_t>(f)])] -= 1;
    state.faces[static_cast<size_t>(labels[static_cast<size_t>(f)])] += 1;
    state.labels[static_cast<size_t>(f)] = labels[static_cast<size_t>(f)];
  }
  for (int f : touched)
    state.border[static_cast<size_t>(labels[static_cast<size_t>(f)])] += border_of(topology, labels, f);
  update_corners(mesh, topology, labels, affected, state, s);
  redo_loops(mesh, topology, labels, dirty, state);

  for (int v : affected) state.vertex_mark[static_cast<size_t>(v)] = 0;
  for (int f : touched) state.face_mark[static_cast<size_t>(f)] = 0;
  for (int c : dirty) state.cluster_mark[static_cast<size_t>(c)] = 0;
  return state.graph;
}

}  // namespace ff
