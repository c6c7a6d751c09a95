#include "core/mesh/topology.h"

#include <algorithm>

#include "core/mesh/half_edges.h"
#include "core/util/error.h"

namespace ff {

namespace {

using detail::HalfEdgeGroups;

// The other edge of face f that touches vertex v (f has distinct vertices, one is v).
int other_edge_at(const TriMesh& mesh, const MeshTopology& topo, int f, int edge, int v) {
  const auto& edges = topo.face_edges[static_cast<size_t>(f)];
  const Triangle& t = mesh.triangles[static_cast<size_t>(f)];
  for (int i = 0; i < 3; ++i) {
    const int e = edges[static_cast<size_t>(i)];
    if (e != edge && (t[static_cast<size_t>(i)] == v || t[static_cast<size_t>((i + 1) % 3)] == v)) {
      return e;
    }
  }
  return -1;  // unreachable for a valid triangle
}

// Pairs the boundary edges at each vertex by walking the fan of faces between them. This
// is what keeps loops apart at a pinched vertex (two boundary loops, or one loop touching
// itself): partner[e][k] is the boundary edge that continues e's loop at
// edge_vertices[e][k], found from the faces and independent of their orientation.
std::vector<std::array<int, 2>> pair_boundary_edges(const TriMesh& mesh, const MeshTopology& topo) {
  std::vector<std::array<int, 2>> partner(topo.edge_vertices.size(), {-1, -1});
  const auto end_index = [&](int e, int v) { return topo.edge_vertices[static_cast<size_t>(e)][0] == v ? 0 : 1; };
  const int max_steps = static_cast<int>(topo.face_edges.size()) + 1;
  for (int e = 0; e < topo.num_edges(); ++e) {
    if (!topo.is_boundary_edge(e)) continue;
    for (int k = 0; k < 2; ++k) {
      if (partner[static_cast<size_t>(e)][static_cast<size_t>(k)] >= 0) continue;
      const int v = topo.edge_vertices[static_cast<size_t>(e)][static_cast<size_t>(k)];
      int f = topo.edge_faces[static_cast<size_t>(e)][0];
      int cur = e;
      // The faces around v that touch a boundary edge form a path; walk it to its end.
      for (int step = 0; step < max_steps; ++step) {
        cur = other_edge_at(mesh, topo, f, cur, v);
        const auto& ef = topo.edge_faces[static_cast<size_t>(cur)];
        if (ef[1] < 0) break;
        f = ef[0] == f ? ef[1] : ef[0];
      }
      partner[static_cast<size_t>(e)][static_cast<size_t>(k)] = cur;
      partner[static_cast<size_t>(cur)][static_cast<size_t>(end_index(cur, v))] = e;
    }
  }
  return partner;
}

void build_boundary_loops(const TriMesh& mesh, MeshTopology& topo) {
  bool any = false;
  for (int e = 0; e < topo.num_edges() && !any; ++e) any = topo.is_boundary_edge(e);
  if (!any) return;

  const auto partner = pair_boundary_edges(mesh, topo);
  std::vector<char> visited(topo.edge_vertices.size(), 0);
  // In (min, max) edge order the first unvisited edge of a loop holds the loop's smallest
  // vertex, so loops come out ordered by it and can start there.
  for (int e0 = 0; e0 < topo.num_edges(); ++e0) {
    if (!topo.is_boundary_edge(e0) || visited[static_cast<size_t>(e0)]) continue;
    const int f = topo.edge_faces[static_cast<size_t>(e0)][0];
    int tail = -1;
    for (int i = 0; i < 3; ++i) {
      if (topo.face_edges[static_cast<size_t>(f)][static_cast<size_t>(i)] == e0) {
        tail = mesh.triangles[static_cast<size_t>(f)][static_cast<size_t>(i)];
      }
    }
    std::vector<int> loop;
    int e = e0, v = tail;
    do {
      loop.push_back(v);
      visited[static_cast<size_t>(e)] = 1;
      const auto& ev = topo.edge_vertices[static_cast<size_t>(e)];
      const int k = ev[0] == v ? 1 : 0;  // leave e at its other end
      v = ev[static_cast<size_t>(k)];
      e = partner[static_cast<size_t>(e)][static_cast<size_t>(k)];
    } while (e != e0 && e >= 0 && loop.size() <= topo.edge_vertices.size());
    // Start at the smallest vertex: when e0 runs into it, it is the second vertex.
    if (tail != topo.edge_vertices[static_cast<size_t>(e0)][0]) {
      std::rotate(loop.begin(), loop.begin() + 1, loop.end());
    }
    topo.boundary_loops.push_back(std::move(loop));
  }
}

void build_components(MeshTopology& topo) {
  const size_t m = topo.face_neighbors.size();
  topo.face_component.assign(m, -1);
  std::vector<int> queue;
  queue.reserve(m);
  for (size_t seed = 0; seed < m; ++seed) {
    if (topo.face_component[seed] >= 0) continue;
    const int c = topo.num_components++;
    topo.face_component[seed] = c;
    queue.assign(1, static_cast<int>(seed));
    for (size_t q = 0; q < queue.size(); ++q) {
      for (int g : topo.face_neighbors[static_cast<size_t>(queue[q])]) {
        if (g >= 0 && topo.face_component[static_cast<size_t>(g)] < 0) {
          topo.face_component[static_cast<size_t>(g)] = c;
          queue.push_back(g);
        }
      }
    }
  }
}

}  // namespace

MeshTopology build_topology(const TriMesh& mesh) {
  detail::require_valid_indices(mesh.triangles, mesh.num_vertices(), /*require_distinct=*/true);
  const HalfEdgeGroups groups = detail::group_half_edges(mesh.triangles, mesh.num_vertices());
  detail::require_edge_manifold(groups, mesh.triangles, mesh.positions);

  MeshTopology topo;
  const size_t m = mesh.triangles.size();
  const size_t num_edges = static_cast<size_t>(groups.num_groups());
  topo.edge_vertices.resize(num_edges);
  topo.edge_faces.resize(num_edges);
  for (size_t g = 0; g < num_edges; ++g) {
    const int gi = static_cast<int>(g);
    const int h = groups.first(gi);
    const int a = detail::tail_of(mesh.triangles, h), b = detail::head_of(mesh.triangles, h);
    topo.edge_vertices[g] = {std::min(a, b), std::max(a, b)};
    topo.edge_faces[g] = {h / 3, groups.group_size(gi) == 2 ? groups.second(gi) / 3 : -1};
  }

  topo.face_edges.resize(m);
  topo.face_neighbors.resize(m);
  for (size_t f = 0; f < m; ++f) {
    for (size_t i = 0; i < 3; ++i) {
      const int e = groups.edge_of[3 * f + i];
      const auto& ef = topo.edge_faces[static_cast<size_t>(e)];
      topo.face_edges[f][i] = e;
      topo.face_neighbors[f][i] = ef[0] == static_cast<int>(f) ? ef[1] : ef[0];
    }
  }

  // Vertex -> faces, filled in face order so each list is sorted.
  const size_t n = mesh.positions.size();
  topo.vertex_face_offsets.assign(n + 1, 0);
  for (const Triangle& t : mesh.triangles) {
    for (int v : t) ++topo.vertex_face_offsets[static_cast<size_t>(v) + 1];
  }
  for (size_t v = 0; v < n; ++v) topo.vertex_face_offsets[v + 1] += topo.vertex_face_offsets[v];
  topo.vertex_faces.resize(3 * m);
  {
    std::vector<int> cursor(topo.vertex_face_offsets.begin(), topo.vertex_face_offsets.end() - 1);
    for (size_t f = 0; f < m; ++f) {
      for (int v : mesh.triangles[f]) {
        topo.vertex_faces[static_cast<size_t>(cursor[static_cast<size_t>(v)]++)] = static_cast<int>(f);
      }
    }
  }

  build_boundary_loops(mesh, topo);
  build_components(topo);
  return topo;
}

int euler_characteristic(const TriMesh& mesh, const MeshTopology& topology) {
  int referenced = 0;
  for (size_t v = 0; v + 1 < topology.vertex_face_offsets.size(); ++v) {
    referenced += topology.vertex_face_offsets[v + 1] > topology.vertex_face_offsets[v] ? 1 : 0;
  }
  return referenced - topology.num_edges() + mesh.num_faces();
}

std::vector<char> closed_components(const MeshTopology& topology) {
  std::vector<char> closed(static_cast<size_t>(topology.num_components), 1);
  for (int e = 0; e < topology.num_edges(); ++e) {
    if (!topology.is_boundary_edge(e)) continue;
    const int f = topology.edge_faces[static_cast<size_t>(e)][0];
    closed[static_cast<size_t>(topology.face_component[static_cast<size_t>(f)])] = 0;
  }
  return closed;
}

std::vector<PartShape> part_shapes(const MeshTopology& topology) {
  std::vector<PartShape> shapes(static_cast<size_t>(topology.num_components));
  if (topology.num_components == 1) {  // most meshes: counts the topology has, and used vertices
    int used = 0;
    for (size_t v = 0; v + 1 < topology.vertex_face_offsets.size(); ++v)
      used += topology.vertex_face_offsets[v + 1] > topology.vertex_face_offsets[v] ? 1 : 0;
    shapes[0].euler = used - topology.num_edges() + static_cast<int>(topology.face_component.size());
    shapes[0].boundary_loops = static_cast<int>(topology.boundary_loops.size());
    shapes[0].closed = topology.boundary_loops.empty();
    return shapes;
  }
  const std::vector<char> closed = closed_components(topology);
  for (size_t c = 0; c < shapes.size(); ++c) shapes[c].closed = closed[c] != 0;
  const auto component = [&](int f) { return topology.face_component[static_cast<size_t>(f)]; };
  for (size_t f = 0; f < topology.face_component.size(); ++f)
    ++shapes[static_cast<size_t>(component(static_cast<int>(f)))].euler;
  for (int e = 0; e < topology.num_edges(); ++e)
    --shapes[static_cast<size_t>(component(topology.edge_faces[static_cast<size_t>(e)][0]))].euler;
  // A vertex counts once in each component it is in: one, unless two sheets touch at it. No
  // sort (cluster_floors() asks for this at every teleport).
  std::vector<int> seen;
  const size_t n = topology.vertex_face_offsets.empty() ? 0 : topology.vertex_face_offsets.size() - 1;
  std::vector<int> vertex_component(n, -1);
  for (size_t v = 0; v < n; ++v) {
    const int begin = topology.vertex_face_offsets[v], end = topology.vertex_face_offsets[v + 1];
    if (begin == end) continue;
    const int first = component(topology.vertex_faces[static_cast<size_t>(begin)]);
    vertex_component[v] = first;
    ++shapes[static_cast<size_t>(first)].euler;
    seen.assign(1, first);
    for (int k = begin + 1; k < end; ++k) {
      const int c = component(topology.vertex_faces[static_cast<size_t>(k)]);
      if (c == first || std::find(seen.begin(), seen.end(), c) != seen.end()) continue;
      seen.push_back(c);
      ++shapes[static_cast<size_t>(c)].euler;
    }
  }
  for (const std::vector<int>& loop : topology.boundary_loops) {
    const int c = loop.empty() ? -1 : vertex_component[static_cast<size_t>(loop[0])];
    if (c >= 0) ++shapes[static_cast<size_t>(c)].boundary_loops;
  }
  return shapes;
}

int fewest_panels(const PartShape& shape) {
  const long long euler = shape.euler;
  for (long long panels = 1;; ++panels) {
    // The most shared sides that many panels can have; more sides only make it easier.
    const long long sides = std::min(panels * (panels - 1) / 2, 3 * panels - 3 * euler);
    const long long nodes = euler + sides - panels;  // a closed part's nodes; an open part's inner ones
    const bool fits =
        shape.closed ? 3 * panels <= 2 * sides && nodes >= 1 && sides <= nodes * (nodes - 1) / 2 : nodes >= 0;
    if (fits) return static_cast<int>(panels);
  }
}

std::vector<int> fewest_panels(const MeshTopology& topology) {
  std::vector<int> fewest;
  for (const PartShape& shape : part_shapes(topology)) fewest.push_back(fewest_panels(shape));
  return fewest;
}

std::vector<int> cluster_floors(const MeshTopology& topology, int n) {
  std::vector<int> floors = fewest_panels(topology);
  long long sum = 0;
  for (int f : floors) sum += f;
  if (n < sum) std::fill(floors.begin(), floors.end(), 1);
  return floors;
}

bool is_boundary_vertex(const TriMesh& mesh, const MeshTopology& topology, int v) {
  for (int k = topology.vertex_face_offsets[static_cast<size_t>(v)];
       k < topology.vertex_face_offsets[static_cast<size_t>(v) + 1]; ++k) {
    const int f = topology.vertex_faces[static_cast<size_t>(k)];
    const int i = local_index(mesh.triangles[static_cast<size_t>(f)], v);
    if (topology.face_neighbors[static_cast<size_t>(f)][static_cast<size_t>(i)] < 0 ||
        topology.face_neighbors[static_cast<size_t>(f)][static_cast<size_t>((i + 2) % 3)] < 0)
      return true;
  }
  return false;
}

}  // namespace ff
