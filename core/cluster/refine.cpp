#include "core/cluster/refine.h"

#include <algorithm>

namespace ff {

namespace {

// Whether face f can leave its cluster without splitting it: its same-cluster edge
// neighbours must stay connected through same-cluster faces of f's vertex rings (a local,
// sufficient test).
bool can_leave(const MeshTopology& topology, const std::vector<int>& labels, int f, const Triangle& corners,
               std::vector<int>& ring, std::vector<int>& stack) {
  const int a = labels[static_cast<size_t>(f)];
  int same = 0, first = -1;
  for (int g : topology.face_neighbors[static_cast<size_t>(f)]) {
    if (g >= 0 && labels[static_cast<size_t>(g)] == a) {
      ++same;
      if (first < 0) first = g;
    }
  }
  if (same == 0) return false;  // the only face of its cluster
  if (same == 1) return true;   // a leaf: the rest stays connected through its one neighbour
  ring.clear();
  for (int v : corners) {
    for (int k = topology.vertex_face_offsets[static_cast<size_t>(v)];
         k < topology.vertex_face_offsets[static_cast<size_t>(v) + 1]; ++k) {
      const int g = topology.vertex_faces[static_cast<size_t>(k)];
      if (g != f && labels[static_cast<size_t>(g)] == a) ring.push_back(g);
    }
  }
  std::sort(ring.begin(), ring.end());
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  std::vector<char> reached(ring.size(), 0);
  const auto index_of = [&](int g) {
    const auto it = std::lower_bound(ring.begin(), ring.end(), g);
    return it != ring.end() && *it == g ? static_cast<int>(it - ring.begin()) : -1;
  };
  stack.assign(1, first);
  reached[static_cast<size_t>(index_of(first))] = 1;
  while (!stack.empty()) {
    const int g = stack.back();
    stack.pop_back();
    for (int h : topology.face_neighbors[static_cast<size_t>(g)]) {
      const int k = h >= 0 ? index_of(h) : -1;
      if (k >= 0 && !reached[static_cast<size_t>(k)]) {
        reached[static_cast<size_t>(k)] = 1;
        stack.push_back(h);
      }
    }
  }
  for (int g : topology.face_neighbors[static_cast<size_t>(f)]) {
    if (g >= 0 && labels[static_cast<size_t>(g)] == a && !reached[static_cast<size_t>(index_of(g))]) return false;
  }
  return true;
}

// The three vertices of face f, from its edges (the topology stores no triangles).
Triangle corners_of(const MeshTopology& topology, int f) {
  const auto& e0 = topology.edge_vertices[static_cast<size_t>(topology.face_edges[static_cast<size_t>(f)][0])];
  const auto& e1 = topology.edge_vertices[static_cast<size_t>(topology.face_edges[static_cast<size_t>(f)][1])];
  const int third = (e1[0] != e0[0] && e1[0] != e0[1]) ? e1[0] : e1[1];
  return {e0[0], e0[1], third};
}

}  // namespace

int refine_boundaries(const Metric& metric, const MeshTopology& topology, Clustering& c, int max_passes) {
  const std::vector<Metric::Terms> terms = metric.terms(c.proxies);
  const size_t faces = c.labels.size();
  std::vector<char> is_seed(faces, 0);
  for (int s : c.seeds) is_seed[static_cast<size_t>(s)] = 1;

  // Only border faces can move: start from them in face order, and queue the neighbours of
  // every face that moves. Each move lowers the energy, so this ends; the budget of
  // max_passes visits per border face keeps it short.
  std::vector<int> queue;
  std::vector<char> queued(faces, 0);
  for (size_t f = 0; f < faces; ++f) {
    for (int g : topology.face_neighbors[f]) {
      if (g >= 0 && c.labels[static_cast<size_t>(g)] != c.labels[f]) {
        queue.push_back(static_cast<int>(f));
        queued[f] = 1;
        break;
      }
    }
  }
  const size_t budget = static_cast<size_t>(std::max(1, max_passes)) * queue.size();
  std::vector<int> ring, stack;
  int moves = 0;
  for (size_t head = 0; head < queue.size() && head < budget; ++head) {
    const int f = queue[head];
    queued[static_cast<size_t>(f)] = 0;
    if (is_seed[static_cast<size_t>(f)]) continue;
    const int a = c.labels[static_cast<size_t>(f)];
    double best = metric.cost(f, terms[static_cast<size_t>(a)]);
    int target = -1;
    for (int g : topology.face_neighbors[static_cast<size_t>(f)]) {
      if (g < 0) continue;
      const int b = c.labels[static_cast<size_t>(g)];
      if (b == a || b == target) continue;
      const double cost = metric.cost(f, terms[static_cast<size_t>(b)]);
      if (cost < best) {
        best = cost;
        target = b;
      }
    }
    if (target < 0 || !can_leave(topology, c.labels, f, corners_of(topology, f), ring, stack)) continue;
    c.labels[static_cast<size_t>(f)] = target;
    ++moves;
    for (int g : topology.face_neighbors[static_cast<size_t>(f)]) {
      if (g >= 0 && !queued[static_cast<size_t>(g)]) {
        queued[static_cast<size_t>(g)] = 1;
        queue.push_back(g);
      }
    }
  }
  return moves;
}

}  // namespace ff
