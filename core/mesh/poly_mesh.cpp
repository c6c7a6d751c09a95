#include "core/mesh/poly_mesh.h"

#include <algorithm>
#include <numeric>
#include <utility>

namespace ff {

void PolyMesh::add_face(const std::vector<int>& loop) {
  corners.insert(corners.end(), loop.begin(), loop.end());
  face_start.push_back(static_cast<int>(corners.size()));
}

bool PolyMesh::all_triangles() const {
  if (num_faces() == 0) return false;
  for (int f = 0; f < num_faces(); ++f)
    if (face_size(f) != 3) return false;
  return true;
}

PolyMesh poly_mesh_from_triangles(const TriMesh& mesh) {
  PolyMesh pm;
  pm.positions = mesh.positions;
  pm.corners.reserve(3 * mesh.triangles.size());
  pm.face_start.reserve(mesh.triangles.size() + 1);
  for (const Triangle& t : mesh.triangles) pm.add_face({t[0], t[1], t[2]});
  return pm;
}

namespace {

using DirectedEdge = std::pair<int, int>;

// The outer loop of a group of triangles, or an empty vector when they do not form a disk
// without inner vertices (see merge_polygons).
std::vector<int> outer_loop(const TriMesh& mesh, const int* faces, size_t count) {
  std::vector<DirectedEdge> edges;
  edges.reserve(3 * count);
  for (size_t i = 0; i < count; ++i) {
    const Triangle& t = mesh.triangles[static_cast<size_t>(faces[i])];
    for (size_t k = 0; k < 3; ++k) edges.emplace_back(t[k], t[(k + 1) % 3]);
  }
  std::vector<DirectedEdge> sorted = edges;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return {};  // inconsistent orientation
  const auto has = [&](const DirectedEdge& e) { return std::binary_search(sorted.begin(), sorted.end(), e); };
  // Outer edges: those whose reverse is not in the group; at most one leaves each vertex.
  std::vector<DirectedEdge> outer;  // in face order: the first one starts the loop
  for (const DirectedEdge& e : edges)
    if (!has({e.second, e.first})) outer.push_back(e);
  if (outer.size() != count + 2) return {};  // k sides <-> k - 2 triangles when no inner vertex
  std::vector<DirectedEdge> by_tail = outer;
  std::sort(by_tail.begin(), by_tail.end());
  for (size_t i = 1; i < by_tail.size(); ++i)
    if (by_tail[i].first == by_tail[i - 1].first) return {};  // a vertex visited twice
  std::vector<int> loop;
  loop.reserve(outer.size());
  int v = outer.front().first;
  for (size_t step = 0; step < outer.size(); ++step) {
    loop.push_back(v);
    const auto it = std::lower_bound(by_tail.begin(), by_tail.end(), DirectedEdge{v, -1});
    if (it == by_tail.end() || it->first != v) return {};
    v = it->second;
  }
  if (v != loop.front()) return {};  // more than one loop
  return loop;
}

}  // namespace

std::vector<int> cleaned_face_polygons(const std::vector<int>& face_source, const std::vector<int>& source_polygon) {
  std::vector<int> polygon(face_source.size());
  for (size_t f = 0; f < polygon.size(); ++f) {
    const auto source = static_cast<size_t>(face_source[f]);
    polygon[f] = source < source_polygon.size() ? source_polygon[source] : static_cast<int>(source);
  }
  return polygon;
}

PolyMesh merge_polygons(const TriMesh& mesh, const std::vector<int>& face_polygon) {
  PolyMesh pm;
  pm.positions = mesh.positions;
  std::vector<int> order(mesh.triangles.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return face_polygon[static_cast<size_t>(a)] < face_polygon[static_cast<size_t>(b)];
  });
  for (size_t begin = 0; begin < order.size();) {
    size_t end = begin + 1;
    const int polygon = face_polygon[static_cast<size_t>(order[begin])];
    while (end < order.size() && face_polygon[static_cast<size_t>(order[end])] == polygon) ++end;
    std::vector<int> loop = end - begin > 1 ? outer_loop(mesh, order.data() + begin, end - begin) : std::vector<int>{};
    if (!loop.empty()) {
      pm.add_face(loop);
    } else {
      for (size_t i = begin; i < end; ++i) {
        const Triangle& t = mesh.triangles[static_cast<size_t>(order[i])];
        pm.add_face({t[0], t[1], t[2]});
      }
    }
    begin = end;
  }
  return pm;
}

TriMesh triangulate(const PolyMesh& mesh) {
  TriMesh out;
  out.positions = mesh.positions;
  out.triangles.reserve(mesh.corners.size());
  const auto p = [&](int v) -> const Vec3& { return mesh.positions[static_cast<size_t>(v)]; };
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const int n = mesh.face_size(f);
    if (n == 4) {
      const int a = mesh.corner(f, 0), b = mesh.corner(f, 1), c = mesh.corner(f, 2), d = mesh.corner(f, 3);
      if ((p(a) - p(c)).squaredNorm() <= (p(b) - p(d)).squaredNorm()) {
        out.triangles.push_back({a, b, c});
        out.triangles.push_back({a, c, d});
      } else {
        out.triangles.push_back({a, b, d});
        out.triangles.push_back({b, c, d});
      }
      continue;
    }
    for (int i = 1; i + 1 < n; ++i) out.triangles.push_back({mesh.corner(f, 0), mesh.corner(f, i), mesh.corner(f, i + 1)});
  }
  return out;
}

Vec3 polygon_normal(const PolyMesh& mesh, int f) {
  Vec3 n = Vec3::Zero();
  const int k = mesh.face_size(f);
  for (int i = 0; i < k; ++i) {
    const Vec3& a = mesh.positions[static_cast<size_t>(mesh.corner(f, i))];
    const Vec3& b = mesh.positions[static_cast<size_t>(mesh.corner(f, (i + 1) % k))];
    n += Vec3((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()), (a.x() - b.x()) * (a.y() + b.y()));
  }
  const double len = n.norm();
  return len > 0.0 ? Vec3(n / len) : Vec3::Zero();
}

}  // namespace ff
