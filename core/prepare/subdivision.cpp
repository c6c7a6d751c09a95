#include "core/prepare/subdivision.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "core/prepare/subdivision_edges.h"
#include "core/util/angles.h"
#include "core/util/error.h"

namespace ff {

namespace {

using detail::PolyEdges;

// Index space: every vertex number must fit an int with room to spare.
constexpr long long kHardTriangleLimit = 1LL << 28;

// What each vertex's rule needs, summed over its edges and faces.
struct VertexStats {
  std::vector<int> valence, creases, faces;
  std::vector<char> on_boundary;
  std::vector<Vec3> neighbour_sum, crease_sum;
};

VertexStats vertex_stats(const PolyMesh& mesh, const PolyEdges& edges, const std::vector<char>& crease) {
  const size_t n = mesh.positions.size();
  VertexStats s;
  s.valence.assign(n, 0);
  s.creases.assign(n, 0);
  s.faces.assign(n, 0);
  s.on_boundary.assign(n, 0);
  s.neighbour_sum.assign(n, Vec3::Zero());
  s.crease_sum.assign(n, Vec3::Zero());
  for (int e = 0; e < edges.num_edges(); ++e) {
    const auto [a, b] = edges.vertices[static_cast<size_t>(e)];
    const Vec3& pa = mesh.positions[static_cast<size_t>(a)];
    const Vec3& pb = mesh.positions[static_cast<size_t>(b)];
    for (const auto& [v, other] : {std::pair<int, const Vec3*>{a, &pb}, std::pair<int, const Vec3*>{b, &pa}}) {
      const auto i = static_cast<size_t>(v);
      ++s.valence[i];
      s.neighbour_sum[i] += *other;
      if (crease[static_cast<size_t>(e)]) {
        ++s.creases[i];
        s.crease_sum[i] += *other;
      }
      if (edges.is_boundary(e)) s.on_boundary[i] = 1;
    }
  }
  for (const int v : mesh.corners) ++s.faces[static_cast<size_t>(v)];
  return s;
}

enum class VertexKind { Smooth, Crease, Corner };

// A vertex on three or more creases is a corner; on two it follows the curve; a boundary
// vertex of one face (valence-2 boundary corner) and an unused vertex stay too.
VertexKind vertex_kind(const VertexStats& s, size_t v) {
  if (s.valence[v] == 0 || s.creases[v] >= 3) return VertexKind::Corner;
  if (s.creases[v] == 2) return s.on_boundary[v] && s.faces[v] == 1 ? VertexKind::Corner : VertexKind::Crease;
  return VertexKind::Smooth;  // no crease or a dart (one crease edge ending here)
}

// The cubic B-spline vertex rule along a crease: (a + 6 v + b) / 8.
Vec3 crease_vertex(const VertexStats& s, const Vec3& p, size_t v) { return (s.crease_sum[v] + 6.0 * p) / 8.0; }

// The vertex of triangle f that is not on edge e.
int opposite_vertex(const PolyMesh& mesh, int f, const std::array<int, 2>& edge) {
  for (int i = 0; i < 3; ++i) {
    const int v = mesh.corner(f, i);
    if (v != edge[0] && v != edge[1]) return v;
  }
  return edge[0];  // unreachable: faces have distinct vertices
}

// One level of Loop subdivision: every triangle -> four.
PolyMesh loop_step(const PolyMesh& mesh, const PolyEdges& edges, const std::vector<char>& crease) {
  const int nv = mesh.num_vertices(), ne = edges.num_edges();
  const auto& p = mesh.positions;
  PolyMesh out;
  out.positions.resize(static_cast<size_t>(nv) + static_cast<size_t>(ne));
  for (int e = 0; e < ne; ++e) {
    const auto& ev = edges.vertices[static_cast<size_t>(e)];
    const Vec3 sum = p[static_cast<size_t>(ev[0])] + p[static_cast<size_t>(ev[1])];
    Vec3& q = out.positions[static_cast<size_t>(nv + e)];
    if (crease[static_cast<size_t>(e)]) {
      q = 0.5 * sum;
    } else {
      const auto& ef = edges.faces[static_cast<size_t>(e)];
      const Vec3& c = p[static_cast<size_t>(opposite_vertex(mesh, ef[0], ev))];
      const Vec3& d = p[static_cast<size_t>(opposite_vertex(mesh, ef[1], ev))];
      q = 0.375 * sum + 0.125 * (c + d);
    }
  }
  const VertexStats s = vertex_stats(mesh, edges, crease);
  for (size_t v = 0; v < static_cast<size_t>(nv); ++v) {
    switch (vertex_kind(s, v)) {
      case VertexKind::Corner:
        out.positions[v] = p[v];
        break;
      case VertexKind::Crease:
        out.positions[v] = crease_vertex(s, p[v], v);
        break;
      case VertexKind::Smooth: {
        // Loop's original weights: beta = (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n.
        const double n = s.valence[v], w = 0.375 + 0.25 * std::cos(2.0 * kPi / n);
        const double beta = (0.625 - w * w) / n;
        out.positions[v] = (1.0 - n * beta) * p[v] + beta * s.neighbour_sum[v];
        break;
      }
    }
  }
  out.corners.reserve(4 * mesh.corners.size());
  out.face_start.reserve(4 * static_cast<size_t>(mesh.num_faces()) + 1);
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const auto c = static_cast<size_t>(mesh.face_start[static_cast<size_t>(f)]);
    const int a = mesh.corners[c], b = mesh.corners[c + 1], d = mesh.corners[c + 2];
    const int ab = nv + edges.corner_edge[c], bd = nv + edges.corner_edge[c + 1], da = nv + edges.corner_edge[c + 2];
    out.add_face({a, ab, da});
    out.add_face({b, bd, ab});
    out.add_face({d, da, bd});
    out.add_face({ab, bd, da});
  }
  return out;
}

// One level of Catmull-Clark: an n-gon -> n quads around its face point.
PolyMesh catmull_clark_step(const PolyMesh& mesh, const PolyEdges& edges, const std::vector<char>& crease) {
  const int nv = mesh.num_vertices(), ne = edges.num_edges(), nf = mesh.num_faces();
  const auto& p = mesh.positions;
  PolyMesh out;
  out.positions.resize(static_cast<size_t>(nv) + static_cast<size_t>(ne) + static_cast<size_t>(nf));
  const auto face_point = [&](int f) -> Vec3& { return out.positions[static_cast<size_t>(nv + ne + f)]; };
  for (int f = 0; f < nf; ++f) {
    Vec3 sum = Vec3::Zero();
    for (int i = 0; i < mesh.face_size(f); ++i) sum += p[static_cast<size_t>(mesh.corner(f, i))];
    face_point(f) = sum / mesh.face_size(f);
  }
  for (int e = 0; e < ne; ++e) {
    const auto& ev = edges.vertices[static_cast<size_t>(e)];
    const Vec3 sum = p[static_cast<size_t>(ev[0])] + p[static_cast<size_t>(ev[1])];
    const auto& ef = edges.faces[static_cast<size_t>(e)];
    out.positions[static_cast<size_t>(nv + e)] =
        crease[static_cast<size_t>(e)] ? Vec3(0.5 * sum) : Vec3(0.25 * (sum + face_point(ef[0]) + face_point(ef[1])));
  }
  const VertexStats s = vertex_stats(mesh, edges, crease);
  std::vector<Vec3> face_sum(static_cast<size_t>(nv), Vec3::Zero());
  for (int f = 0; f < nf; ++f)
    for (int i = 0; i < mesh.face_size(f); ++i) face_sum[static_cast<size_t>(mesh.corner(f, i))] += face_point(f);
  for (size_t v = 0; v < static_cast<size_t>(nv); ++v) {
    switch (vertex_kind(s, v)) {
      case VertexKind::Corner:
        out.positions[v] = p[v];
        break;
      case VertexKind::Crease:
        out.positions[v] = crease_vertex(s, p[v], v);
        break;
      case VertexKind::Smooth: {
        // (Q + 2 R + (n - 3) S) / n: Q the mean face point, R the mean edge midpoint.
        const double n = s.valence[v];
        const Vec3 q = face_sum[v] / s.faces[v];
        const Vec3 r = 0.5 * (p[v] + s.neighbour_sum[v] / n);
        out.positions[v] = (q + 2.0 * r + (n - 3.0) * p[v]) / n;
        break;
      }
    }
  }
  out.corners.reserve(4 * mesh.corners.size());
  out.face_start.reserve(mesh.corners.size() + 1);
  for (int f = 0; f < nf; ++f) {
    const int k = mesh.face_size(f), start = mesh.face_start[static_cast<size_t>(f)];
    for (int i = 0; i < k; ++i) {
      const auto c = static_cast<size_t>(start + i), prev = static_cast<size_t>(start + (i + k - 1) % k);
      out.add_face({mesh.corners[c], nv + edges.corner_edge[c], nv + ne + f, nv + edges.corner_edge[prev]});
    }
  }
  return out;
}

// 4^levels * base, saturating at the largest long long / 8.
long long times_four_to_the(long long base, int levels) {
  constexpr long long kCap = std::numeric_limits<long long>::max() / 8;
  for (int i = 0; i < levels && base < kCap; ++i) base *= 4;
  return std::min(base, kCap);
}

void require_size_ok(const PolyMesh& mesh, SubdivisionScheme scheme, int levels, long long max_triangles) {
  const std::string name = scheme == SubdivisionScheme::Loop ? "Loop" : "Catmull-Clark";
  if (levels < 0) throw InputError("subdivision: levels must be 0 or more, got " + std::to_string(levels));
  const long long limit = std::min(max_triangles, kHardTriangleLimit);
  const long long count = subdivided_triangle_count(mesh, scheme, levels);
  if (count <= limit) return;
  int fits = 0;
  while (fits < levels && subdivided_triangle_count(mesh, scheme, fits + 1) <= limit) ++fits;
  throw InputError("subdivision: " + std::to_string(levels) + " level" + (levels == 1 ? "" : "s") + " of " + name +
                   " would make " + std::to_string(count) + " triangles from " + std::to_string(mesh.num_faces()) +
                   " faces, more than the limit of " + std::to_string(limit) + "; use at most " +
                   std::to_string(fits) + " level" + (fits == 1 ? "" : "s"));
}

// The crease pairs as sorted keys, each checked to be an edge of the control mesh.
std::vector<std::uint64_t> control_crease_keys(const PolyMesh& mesh, const PolyEdges& edges,
                                               const std::vector<VertexPair>& creases) {
  std::vector<std::uint64_t> keys;
  keys.reserve(creases.size());
  for (const VertexPair& c : creases) {
    const bool in_range = c[0] >= 0 && c[1] >= 0 && c[0] < mesh.num_vertices() && c[1] < mesh.num_vertices();
    if (!in_range || edges.find(c[0], c[1]) < 0)
      throw InputError("subdivision: crease (" + std::to_string(c[0]) + ", " + std::to_string(c[1]) +
                       ") is not an edge of the mesh");
    keys.push_back(detail::edge_key(c[0], c[1]));
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return keys;
}

template <typename Step>
PolyMesh subdivide(PolyMesh mesh, int levels, const std::vector<VertexPair>& creases, Step step) {
  PolyEdges edges = detail::build_poly_edges(mesh, "subdivision");
  std::vector<std::uint64_t> keys = control_crease_keys(mesh, edges, creases);
  for (int level = 0; level < levels; ++level) {
    if (level > 0) edges = detail::build_poly_edges(mesh, "subdivision");
    const std::vector<char> crease = detail::crease_flags(edges, keys);
    PolyMesh next = step(mesh, edges, crease);
    keys = detail::child_crease_keys(edges, crease, mesh.num_vertices());
    mesh = std::move(next);
  }
  return mesh;
}

}  // namespace

const char* scheme_name(SubdivisionScheme scheme) {
  return scheme == SubdivisionScheme::Loop ? "loop" : "catmull-clark";
}

long long subdivided_triangle_count(const PolyMesh& mesh, SubdivisionScheme scheme, int levels) {
  long long corners = 0, fan_triangles = 0;
  for (int f = 0; f < mesh.num_faces(); ++f) {
    corners += mesh.face_size(f);
    fan_triangles += std::max(mesh.face_size(f) - 2, 0);
  }
  if (levels <= 0) return fan_triangles;
  if (scheme == SubdivisionScheme::Loop) return times_four_to_the(fan_triangles, levels);
  return 2 * times_four_to_the(corners, levels - 1);  // n quads per n-gon, x4 after, 2 triangles a quad
}

std::vector<VertexPair> crease_edges(const PolyMesh& mesh, double angle_deg) {
  if (!(angle_deg >= 0.0)) throw InputError("crease angle must be 0 degrees or more");
  const PolyEdges edges = detail::build_poly_edges(mesh, "crease detection");
  std::vector<VertexPair> out;
  if (angle_deg >= 180.0) return out;
  std::vector<Vec3> normal(static_cast<size_t>(mesh.num_faces()));
  for (int f = 0; f < mesh.num_faces(); ++f) normal[static_cast<size_t>(f)] = polygon_normal(mesh, f);
  for (int e = 0; e < edges.num_edges(); ++e) {
    if (edges.is_boundary(e)) continue;
    const auto& ef = edges.faces[static_cast<size_t>(e)];
    const Vec3& a = normal[static_cast<size_t>(ef[0])];
    const Vec3& b = normal[static_cast<size_t>(ef[1])];
    if (a.isZero(0.0) || b.isZero(0.0)) continue;  // a degenerate face has no direction to compare
    const double angle = std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / kPi;
    if (angle > angle_deg) out.push_back(edges.vertices[static_cast<size_t>(e)]);
  }
  return out;
}

TriMesh loop_subdivide(const TriMesh& mesh, int levels, const std::vector<VertexPair>& creases,
                       long long max_triangles) {
  PolyMesh control = poly_mesh_from_triangles(mesh);
  require_size_ok(control, SubdivisionScheme::Loop, levels, max_triangles);
  const PolyMesh fine = subdivide(std::move(control), levels, creases, loop_step);
  TriMesh out;
  out.positions = fine.positions;
  out.triangles.reserve(static_cast<size_t>(fine.num_faces()));
  for (size_t c = 0; c + 2 < fine.corners.size(); c += 3)
    out.triangles.push_back({fine.corners[c], fine.corners[c + 1], fine.corners[c + 2]});
  return out;
}

PolyMesh catmull_clark_quads(const PolyMesh& mesh, int levels, const std::vector<VertexPair>& creases,
                             long long max_triangles) {
  require_size_ok(mesh, SubdivisionScheme::CatmullClark, levels, max_triangles);
  return subdivide(mesh, levels, creases, catmull_clark_step);
}

TriMesh catmull_clark(const PolyMesh& mesh, int levels, const std::vector<VertexPair>& creases,
                      long long max_triangles) {
  return triangulate(catmull_clark_quads(mesh, levels, creases, max_triangles));
}

ControlSubdivision subdivide_control_mesh(const TriMesh& mesh, const std::vector<int>& face_polygon, int levels,
                                          double crease_angle_deg) {
  const PolyMesh control = merge_polygons(mesh, face_polygon);
  const bool loop = control.all_triangles();
  const std::vector<VertexPair> creases = crease_edges(control, crease_angle_deg);
  ControlSubdivision out;
  out.mesh = loop ? loop_subdivide(mesh, levels, creases) : catmull_clark(control, levels, creases);
  out.scheme = loop ? SubdivisionScheme::Loop : SubdivisionScheme::CatmullClark;
  out.control_vertices = control.num_vertices();
  out.control_faces = control.num_faces();
  out.crease_edges = static_cast<int>(creases.size());
  return out;
}

}  // namespace ff
