#include "core/density/border_distance.h"

#include <limits>

#include "core/cluster/quad_heap.h"
#include "core/mesh/segment.h"

namespace ff {

namespace {

// Each vertex's edges, or only its boundary edges (two per vertex on a manifold border), in
// edge order (CSR: vertex v's are edges[first[v]..first[v+1]]); the topology lists edges,
// not vertex rings.
struct EdgesByVertex {
  std::vector<int> first, edges;
};

EdgesByVertex edges_by_vertex(const MeshTopology& topology, size_t num_vertices, bool boundary_only) {
  EdgesByVertex out;
  out.first.assign(num_vertices + 1, 0);
  const auto kept = [&](int e) { return !boundary_only || topology.is_boundary_edge(e); };
  for (int e = 0; e < topology.num_edges(); ++e)
    if (kept(e))
      for (int v : topology.edge_vertices[static_cast<size_t>(e)]) ++out.first[static_cast<size_t>(v) + 1];
  for (size_t v = 0; v < num_vertices; ++v) out.first[v + 1] += out.first[v];
  out.edges.resize(static_cast<size_t>(out.first[num_vertices]));
  std::vector<int> at(out.first.begin(), out.first.end() - 1);
  for (int e = 0; e < topology.num_edges(); ++e)
    if (kept(e))
      for (int v : topology.edge_vertices[static_cast<size_t>(e)]) out.edges[static_cast<size_t>(at[static_cast<size_t>(v)]++)] = e;
  return out;
}

}  // namespace

std::vector<double> border_distance(const TriMesh& mesh, const MeshTopology& topology) {
  const size_t n = mesh.positions.size();
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<int> source(n, -1);  // the boundary edge each vertex is measured to
  const EdgesByVertex ring = edges_by_vertex(topology, n, false);
  const EdgesByVertex border = edges_by_vertex(topology, n, true);  // the border as a graph
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
        for (int k = border.first[static_cast<size_t>(end)]; k < border.first[static_cast<size_t>(end) + 1]; ++k) {
          const int f = border.edges[static_cast<size_t>(k)];
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
    for (int k = ring.first[v]; k < ring.first[v + 1]; ++k) {
      const std::array<int, 2>& ends = topology.edge_vertices[static_cast<size_t>(ring.edges[static_cast<size_t>(k)])];
      const size_t w = static_cast<size_t>(ends[0] == item.id ? ends[1] : ends[0]);
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
