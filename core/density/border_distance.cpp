#include "core/density/border_distance.h"

#include <algorithm>
#include <limits>

#include "core/cluster/quad_heap.h"

namespace ff {

namespace {

double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

}  // namespace

std::vector<double> border_distance(const TriMesh& mesh, const MeshTopology& topology) {
  const size_t n = mesh.positions.size();
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<int> source(n, -1);  // the boundary edge each vertex is measured to
  // Each vertex's edges (CSR): the topology lists edges, not vertex rings.
  std::vector<int> first(n + 1, 0), other(2 * static_cast<size_t>(topology.num_edges()));
  for (const std::array<int, 2>& e : topology.edge_vertices) {
    ++first[static_cast<size_t>(e[0]) + 1];
    ++first[static_cast<size_t>(e[1]) + 1];
  }
  for (size_t v = 0; v < n; ++v) first[v + 1] += first[v];
  {
    std::vector<int> at(first.begin(), first.end() - 1);
    for (const std::array<int, 2>& e : topology.edge_vertices) {
      other[static_cast<size_t>(at[static_cast<size_t>(e[0])]++)] = e[1];
      other[static_cast<size_t>(at[static_cast<size_t>(e[1])]++)] = e[0];
    }
  }
  // Per vertex, its boundary edges (two on a manifold border): the border as a graph.
  std::vector<int> first_border(n + 1, 0), border_edges;
  for (int e = 0; e < topology.num_edges(); ++e) {
    if (!topology.is_boundary_edge(e)) continue;
    for (int v : topology.edge_vertices[static_cast<size_t>(e)]) ++first_border[static_cast<size_t>(v) + 1];
  }
  for (size_t v = 0; v < n; ++v) first_border[v + 1] += first_border[v];
  border_edges.resize(static_cast<size_t>(first_border[n]));
  {
    std::vector<int> at(first_border.begin(), first_border.end() - 1);
    for (int e = 0; e < topology.num_edges(); ++e) {
      if (!topology.is_boundary_edge(e)) continue;
      for (int v : topology.edge_vertices[static_cast<size_t>(e)])
        border_edges[static_cast<size_t>(at[static_cast<size_t>(v)]++)] = e;
    }
  }
  const auto segment_distance = [&](const Vec3& p, int e) {
    const std::array<int, 2>& ends = topology.edge_vertices[static_cast<size_t>(e)];
    return distance_to_segment(p, mesh.positions[static_cast<size_t>(ends[0])],
                               mesh.positions[static_cast<size_t>(ends[1])]);
  };
  // The edge a front carries is the nearest for the vertex it came from; for the next vertex
  // the nearest may be further along the border (round a corner, along a curved rim): walk
  // the border from it while the next edge is nearer.
  const auto nearest_from = [&](const Vec3& p, int e, double& d) {
    d = segment_distance(p, e);
    for (bool nearer = true; nearer;) {
      nearer = false;
      for (int end : topology.edge_vertices[static_cast<size_t>(e)]) {
        for (int k = first_border[static_cast<size_t>(end)]; k < first_border[static_cast<size_t>(end) + 1]; ++k) {
          const int f = border_edges[static_cast<size_t>(k)];
          const double df = segment_distance(p, f);
          if (df < d) d = df, e = f, nearer = true;
        }
      }
    }
    return e;
  };
  // (distance, vertex) orders the queue strictly, so the result does not depend on the heap.
  QuadHeap<KeyedItem, KeyedBefore> queue;
  for (int e = 0; e < topology.num_edges(); ++e) {
    if (!topology.is_boundary_edge(e)) continue;
    for (int v : topology.edge_vertices[static_cast<size_t>(e)]) {
      if (source[static_cast<size_t>(v)] >= 0) continue;
      dist[static_cast<size_t>(v)] = 0.0;
      source[static_cast<size_t>(v)] = e;
      queue.push({order_key(0.0), v});
    }
  }
  while (!queue.empty()) {
    const KeyedItem item = queue.pop();
    const size_t v = static_cast<size_t>(item.id);
    if (key_value(item.key) > dist[v]) continue;  // superseded
    for (int k = first[v]; k < first[v + 1]; ++k) {
      const size_t w = static_cast<size_t>(other[static_cast<size_t>(k)]);
      // Strictly nearer only: every update lowers a distance, so the front ends.
      double d;
      const int e = nearest_from(mesh.positions[w], source[v], d);
      if (d < dist[w]) {
        dist[w] = d;
        source[w] = e;
        queue.push({order_key(d), static_cast<int>(w)});
      }
    }
  }
  return dist;
}

}  // namespace ff
