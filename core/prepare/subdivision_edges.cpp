#include "core/prepare/subdivision_edges.h"

#include <algorithm>
#include <string>

#include "core/mesh/half_edges.h"
#include "core/util/error.h"

namespace ff::detail {

int PolyEdges::find(int a, int b) const {
  const std::uint64_t key = edge_key(a, b);
  const auto it = std::lower_bound(keys.begin(), keys.end(), key);
  return it != keys.end() && *it == key ? static_cast<int>(it - keys.begin()) : -1;
}

namespace {

[[noreturn]] void edge_error(const PolyMesh& mesh, const char* what, int a, int b, const std::string& problem) {
  const Vec3 mid = 0.5 * (mesh.positions[static_cast<size_t>(a)] + mesh.positions[static_cast<size_t>(b)]);
  throw InputError(std::string(what) + ": edge between vertices " + std::to_string(std::min(a, b)) + " and " +
                   std::to_string(std::max(a, b)) + " at " + format_point(mid) + " " + problem);
}

void require_valid_faces(const PolyMesh& mesh, const char* what) {
  const int n = mesh.num_vertices();
  if (mesh.face_start.empty() || mesh.face_start.front() != 0 ||
      mesh.face_start.back() != static_cast<int>(mesh.corners.size()))
    throw InputError(std::string(what) + ": malformed face list");
  if (mesh.num_faces() == 0) throw InputError(std::string(what) + ": the mesh has no faces");
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const int k = mesh.face_size(f);
    if (k < 3) throw InputError(std::string(what) + ": face " + std::to_string(f) + " has fewer than 3 vertices");
    for (int i = 0; i < k; ++i) {
      const int v = mesh.corner(f, i);
      if (v < 0 || v >= n)
        throw InputError(std::string(what) + ": face " + std::to_string(f) + " uses vertex " + std::to_string(v) +
                         ", out of range [0, " + std::to_string(n) + ")");
      for (int j = 0; j < i; ++j)
        if (mesh.corner(f, j) == v)
          throw InputError(std::string(what) + ": face " + std::to_string(f) + " uses vertex " + std::to_string(v) +
                           " twice");
    }
  }
}

}  // namespace

PolyEdges build_poly_edges(const PolyMesh& mesh, const char* what) {
  require_valid_faces(mesh, what);
  const size_t num_half = mesh.corners.size();
  const size_t n = mesh.positions.size();
  std::vector<int> face_of(num_half), head(num_half);
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const int k = mesh.face_size(f), s = mesh.face_start[static_cast<size_t>(f)];
    for (int i = 0; i < k; ++i) {
      face_of[static_cast<size_t>(s + i)] = f;
      head[static_cast<size_t>(s + i)] = mesh.corner(f, (i + 1) % k);
    }
  }
  // Counting sort of the half-edges by their smaller vertex, then by (larger vertex, id).
  std::vector<size_t> start(n + 1, 0);
  for (size_t h = 0; h < num_half; ++h) ++start[static_cast<size_t>(std::min(mesh.corners[h], head[h])) + 1];
  for (size_t v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<std::uint64_t> keyed(num_half);
  {
    std::vector<size_t> cursor(start.begin(), start.end() - 1);
    for (size_t h = 0; h < num_half; ++h) {
      const int a = mesh.corners[h], b = head[h];
      keyed[cursor[static_cast<size_t>(std::min(a, b))]++] = (static_cast<std::uint64_t>(std::max(a, b)) << 32) | h;
    }
  }
  PolyEdges edges;
  edges.corner_edge.assign(num_half, -1);
  edges.keys.reserve(num_half / 2 + 1);
  edges.vertices.reserve(num_half / 2 + 1);
  edges.faces.reserve(num_half / 2 + 1);
  for (size_t v = 0; v < n; ++v) {
    std::sort(keyed.begin() + static_cast<std::ptrdiff_t>(start[v]), keyed.begin() + static_cast<std::ptrdiff_t>(start[v + 1]));
    for (size_t i = start[v]; i < start[v + 1];) {
      size_t j = i + 1;
      while (j < start[v + 1] && (keyed[j] >> 32) == (keyed[i] >> 32)) ++j;
      const int a = static_cast<int>(v), b = static_cast<int>(keyed[i] >> 32);
      if (j - i > 2) edge_error(mesh, what, a, b, "is shared by " + std::to_string(j - i) + " faces (non-manifold)");
      const auto h0 = static_cast<size_t>(keyed[i] & 0xffffffffu);
      const int e = static_cast<int>(edges.keys.size());
      std::array<int, 2> faces = {face_of[h0], -1};
      edges.corner_edge[h0] = e;
      if (j - i == 2) {
        const auto h1 = static_cast<size_t>(keyed[i + 1] & 0xffffffffu);
        if (mesh.corners[h0] == mesh.corners[h1])
          edge_error(mesh, what, a, b, "is traversed the same way by two faces (inconsistent orientation)");
        faces[1] = face_of[h1];
        edges.corner_edge[h1] = e;
      }
      edges.keys.push_back(edge_key(a, b));
      edges.vertices.push_back({a, b});
      edges.faces.push_back(faces);
      i = j;
    }
  }
  return edges;
}

std::vector<char> crease_flags(const PolyEdges& edges, const std::vector<std::uint64_t>& crease_keys) {
  std::vector<char> crease(edges.keys.size(), 0);
  for (int e = 0; e < edges.num_edges(); ++e) crease[static_cast<size_t>(e)] = edges.is_boundary(e) ? 1 : 0;
  // Both lists are sorted: one merge pass.
  size_t k = 0;
  for (size_t e = 0; e < edges.keys.size() && k < crease_keys.size(); ++e) {
    while (k < crease_keys.size() && crease_keys[k] < edges.keys[e]) ++k;
    if (k < crease_keys.size() && crease_keys[k] == edges.keys[e]) crease[e] = 1;
  }
  return crease;
}

std::vector<std::uint64_t> child_crease_keys(const PolyEdges& edges, const std::vector<char>& crease,
                                             int first_edge_vertex) {
  std::vector<std::uint64_t> out;
  for (int e = 0; e < edges.num_edges(); ++e) {
    // Boundary edges are creases anyway at the next level: only inner creases need carrying.
    if (!crease[static_cast<size_t>(e)] || edges.is_boundary(e)) continue;
    const int m = first_edge_vertex + e;
    out.push_back(edge_key(edges.vertices[static_cast<size_t>(e)][0], m));
    out.push_back(edge_key(m, edges.vertices[static_cast<size_t>(e)][1]));
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace ff::detail
