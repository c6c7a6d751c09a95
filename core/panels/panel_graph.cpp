#include "core/panels/panel_graph.h"

#include <algorithm>

namespace ff {

std::vector<int> vertex_fan(const TriMesh& mesh, const MeshTopology& topology, int v, bool& on_boundary) {
  std::vector<int> fan;
  vertex_fan(mesh, topology, v, on_boundary, fan);
  return fan;
}

void vertex_fan(const TriMesh& mesh, const MeshTopology& topology, int v, bool& on_boundary, std::vector<int>& fan) {
  const int begin = topology.vertex_face_offsets[static_cast<size_t>(v)];
  const int end = topology.vertex_face_offsets[static_cast<size_t>(v) + 1];
  fan.clear();
  on_boundary = false;
  if (begin == end) return;
  // Start where the clockwise neighbour (across the edge v -> next) is missing, if anywhere.
  int start = topology.vertex_faces[static_cast<size_t>(begin)];
  for (int k = begin; k < end; ++k) {
    const int f = topology.vertex_faces[static_cast<size_t>(k)];
    const int i = local_index(mesh.triangles[static_cast<size_t>(f)], v);
    if (topology.face_neighbors[static_cast<size_t>(f)][static_cast<size_t>(i)] < 0) {
      start = f;
      on_boundary = true;
      break;
    }
  }
  int f = start;
  const int limit = end - begin;
  do {
    fan.push_back(f);
    const int i = local_index(mesh.triangles[static_cast<size_t>(f)], v);
    // Counter-clockwise next: across the edge from the previous vertex back to v.
    f = topology.face_neighbors[static_cast<size_t>(f)][static_cast<size_t>((i + 2) % 3)];
  } while (f >= 0 && f != start && static_cast<int>(fan.size()) < limit);
}

void vertex_cycle(const TriMesh& mesh, const MeshTopology& topology, const std::vector<int>& labels, int v,
                  std::vector<int>& fan, std::vector<int>& cycle, bool& on_boundary) {
  cycle.clear();
  on_boundary = false;
  // Most vertices lie inside one cluster: no fan to walk.
  const int begin = topology.vertex_face_offsets[static_cast<size_t>(v)];
  const int end = topology.vertex_face_offsets[static_cast<size_t>(v) + 1];
  if (begin == end) return;
  const int first_label = labels[static_cast<size_t>(topology.vertex_faces[static_cast<size_t>(begin)])];
  bool single = true;
  for (int k = begin + 1; k < end && single; ++k)
    single = labels[static_cast<size_t>(topology.vertex_faces[static_cast<size_t>(k)])] == first_label;
  if (single && !is_boundary_vertex(mesh, topology, v)) {
    cycle.push_back(first_label);
    return;
  }
  vertex_fan(mesh, topology, v, on_boundary, fan);
  if (fan.empty()) return;
  for (int f : fan) {
    const int c = labels[static_cast<size_t>(f)];
    if (cycle.empty() || cycle.back() != c) cycle.push_back(c);
  }
  if (!on_boundary && cycle.size() > 1 && cycle.front() == cycle.back()) cycle.pop_back();
  if (on_boundary) cycle.push_back(kBoundary);
}

int next_border_half_edge(const TriMesh& mesh, const MeshTopology& topology, const std::vector<int>& labels, int h) {
  const int c = labels[static_cast<size_t>(h / 3)];
  int f = h / 3;
  const int v = mesh.triangles[static_cast<size_t>(f)][static_cast<size_t>((h % 3 + 1) % 3)];
  for (;;) {
    const int j = local_index(mesh.triangles[static_cast<size_t>(f)], v);
    const int across = topology.face_neighbors[static_cast<size_t>(f)][static_cast<size_t>(j)];
    if (across < 0 || labels[static_cast<size_t>(across)] != c) return 3 * f + j;
    f = across;
  }
}

void trace_border_loops(const std::vector<int>& half_edges, const std::vector<int>& next,
                        const std::vector<int>& labels, std::vector<char>& seen, std::vector<std::vector<int>>& loops,
                        std::vector<int>& loop_count) {
  for (int h0 : half_edges) {
    if (seen[static_cast<size_t>(h0)]) continue;
    const int c = labels[static_cast<size_t>(h0 / 3)];
    std::vector<int> loop;
    for (int h = h0; !seen[static_cast<size_t>(h)]; h = next[static_cast<size_t>(h)]) {
      seen[static_cast<size_t>(h)] = 1;
      loop.push_back(h);
    }
    if (++loop_count[static_cast<size_t>(c)] == 1) loops[static_cast<size_t>(c)] = std::move(loop);
  }
}

unsigned start_loop_after_corner(const TriMesh& mesh, const MeshTopology& topology, const std::vector<int>& labels,
                                 const std::vector<int>& corner_of_vertex, std::vector<int>& loop,
                                 std::vector<int>& chain_neighbours) {
  const auto ends_chain = [&](int h) {
    const int head = mesh.triangles[static_cast<size_t>(h / 3)][static_cast<size_t>((h % 3 + 1) % 3)];
    return corner_of_vertex[static_cast<size_t>(head)] >= 0;
  };
  const auto it = std::find_if(loop.begin(), loop.end(), ends_chain);
  if (it == loop.end()) {
    // A whole open component as one panel is all border; otherwise the cluster is enclosed.
    if (PanelGraph::other_side(topology, labels, loop.front()) == kBoundary) return 0u;
    loop.clear();
    return kEnclosed;
  }
  std::rotate(loop.begin(), it + 1, loop.end());
  chain_neighbours.clear();
  for (int h : loop) {
    if (!ends_chain(h)) continue;
    const int other = PanelGraph::other_side(topology, labels, h);
    if (other != kBoundary) chain_neighbours.push_back(other);
  }
  std::sort(chain_neighbours.begin(), chain_neighbours.end());
  return std::adjacent_find(chain_neighbours.begin(), chain_neighbours.end()) != chain_neighbours.end() ? kTwoChains
                                                                                                        : 0u;
}

PanelGraph build_panel_graph(const TriMesh& mesh, const MeshTopology& topology, const std::vector<int>& labels,
                             int num_clusters) {
  const size_t n = static_cast<size_t>(num_clusters);
  PanelGraph g;
  g.corner_of_vertex.assign(static_cast<size_t>(mesh.num_vertices()), -1);
  g.problems.assign(n, 0u);
  g.loops.assign(n, {});

  // Corners, pinches, and the vertex count of every cluster (for its Euler characteristic).
  std::vector<long long> euler(n, 0);
  std::vector<int> cycle, fan, sorted;  // per vertex, reused
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    bool on_boundary = false;
    vertex_cycle(mesh, topology, labels, v, fan, cycle, on_boundary);
    if (cycle.empty()) continue;
    if (cycle.size() == 1 && !on_boundary) {  // inside one cluster
      euler[static_cast<size_t>(cycle[0])] += 1;
      continue;
    }
    sorted.assign(cycle.begin(), cycle.end());
    std::sort(sorted.begin(), sorted.end());
    for (size_t k = 0; k < sorted.size(); ++k) {
      if (sorted[k] == kBoundary) continue;
      if (k > 0 && sorted[k] == sorted[k - 1]) {
        g.problems[static_cast<size_t>(sorted[k])] |= kPinch;
      } else {
        euler[static_cast<size_t>(sorted[k])] += 1;
      }
    }
    if (cycle.size() >= 3) {
      g.corner_of_vertex[static_cast<size_t>(v)] = static_cast<int>(g.corners.size());
      g.corners.push_back(Corner{v, on_boundary, cycle});
    }
  }

  // Boundary half-edges of every cluster, and the next one along its loop: rotate about the
  // head vertex through the cluster's own faces until an edge leaves the cluster.
  const int faces = mesh.num_faces();
  std::vector<int> next(static_cast<size_t>(3 * faces), -1);
  std::vector<int> boundary_half_edges;
  for (int f = 0; f < faces; ++f) {
    const int c = labels[static_cast<size_t>(f)];
    euler[static_cast<size_t>(c)] += 1;  // V + F here, E below
    for (int i = 0; i < 3; ++i) {
      const int h = 3 * f + i;
      if (PanelGraph::other_side(topology, labels, h) != c) boundary_half_edges.push_back(h);
    }
  }
  // E = (3 F + B) / 2 per cluster: subtract it as (3 per face + 1 per boundary half-edge) / 2.
  std::vector<long long> twice_edges(n, 0);
  for (int f = 0; f < faces; ++f) twice_edges[static_cast<size_t>(labels[static_cast<size_t>(f)])] += 3;
  for (int h : boundary_half_edges) twice_edges[static_cast<size_t>(labels[static_cast<size_t>(h / 3)])] += 1;
  for (int h : boundary_half_edges) next[static_cast<size_t>(h)] = next_border_half_edge(mesh, topology, labels, h);

  // Loops per cluster.
  std::vector<char> seen(next.size(), 0);
  std::vector<int> loop_count(n, 0);
  trace_border_loops(boundary_half_edges, next, labels, seen, g.loops, loop_count);

  std::vector<int> chain_neighbours;
  for (size_t c = 0; c < n; ++c) {
    if (loop_count[c] > 1) g.problems[c] |= kHole;
    if (2 * euler[c] - twice_edges[c] != 2) g.problems[c] |= kHandle;
    std::vector<int>& loop = g.loops[c];
    if (g.problems[c] != 0 || loop.empty()) {
      if (g.problems[c] != 0) loop.clear();
      continue;
    }
    g.problems[c] |= start_loop_after_corner(mesh, topology, labels, g.corner_of_vertex, loop, chain_neighbours);
  }
  return g;
}

}  // namespace ff
