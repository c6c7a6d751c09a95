#include "core/prepare/remesh_ops.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>
#include <vector>

#include "core/mesh/half_edges.h"
#include "core/util/error.h"
#include "core/util/index.h"
#include "core/util/short_number.h"

namespace ff::prepare_detail {

namespace {

// A collapse or flip must not turn a triangle over or squash it: the new normal stays
// within about 75 degrees of the old one.
constexpr double kMinNormalCos = 0.25;

// Would moving vertex v to p (with the faces of the collapsing edge h gone) keep every other
// face around v unfolded, non-degenerate, and every edge from v within `max_length`?
bool move_ok(const EditMesh& m, int v, const Vec3& p, int h, double max_length) {
  const int f_skip0 = m.face(h), f_skip1 = m.face(h ^ 1);
  const int other = m.to(h);
  const int h0 = m.out(v);
  int g = h0;
  do {
    const int w = m.to(g);
    if (w != other && (m.position(w) - p).norm() > max_length) return false;
    const int f = m.face(g);
    if (f >= 0 && f != f_skip0 && f != f_skip1) {
      const Vec3& b = m.position(m.to(g));
      const Vec3& c = m.position(m.to(m.next(g)));
      const Vec3 before = triangle_normal(m.position(v), b, c);
      const Vec3 after = triangle_normal(p, b, c);
      if (after.isZero() || after.dot(before) < kMinNormalCos) return false;
    }
    g = m.rotate(g);
  } while (g != h0);
  return true;
}

}  // namespace

Vec3 triangle_normal(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a);
  const double len = n.norm();
  return len > 0.0 ? Vec3(n / len) : Vec3::Zero();
}

double RemeshState::target(int e) const {
  const int a = mesh.to(2 * e), b = mesh.to(2 * e + 1);
  return 0.5 * (vertex_length[at(a)] + vertex_length[at(b)]);
}

void RemeshState::grow() {
  const size_t nv = at(mesh.num_vertices()), ne = at(mesh.num_edges());
  edge_feature.resize(ne, 0);
  vertex_feature.resize(nv, 0);
  vertex_locked.resize(nv, 0);
  vertex_length.resize(nv, 0.0);
  vertex_hint.resize(nv, -1);
  if (!vertex_density.empty()) vertex_density.resize(nv, 0.0);
}

std::string longest_edge_phrase(const RemeshState& s) {
  const EditMesh& m = s.mesh;
  int worst = -1;
  double worst_ratio = 0.0;
  for (int e = 0; e < m.num_edges(); ++e) {
    if (m.edge_removed(e)) continue;
    const double ratio = m.edge_length(e) / s.target(e);
    if (worst < 0 || ratio > worst_ratio) worst = e, worst_ratio = ratio;
  }
  if (worst < 0) return "";
  return "the edge from " + detail::format_point(m.position(m.to(2 * worst + 1))) + " to " +
         detail::format_point(m.position(m.to(2 * worst))) + " is " + short_number(worst_ratio) + " times its target";
}

void split_long_edges(RemeshState& s, long long max_faces) {
  EditMesh& m = s.mesh;
  // Passes of longest-first splits (Rivara's longest-edge bisection terminates and keeps
  // the shapes; splitting in index order can chase the same long edge forever). Each pass
  // sorts the edges still too long by length, ties by index.
  for (;;) {
    std::vector<std::pair<double, int>> queue;
    for (int e = 0; e < m.num_edges(); ++e) {
      if (m.edge_removed(e)) continue;
      const double ratio = m.edge_length(e) / s.target(e);
      if (ratio > 4.0 / 3.0) queue.emplace_back(-ratio, e);
    }
    if (queue.empty()) return;
    std::sort(queue.begin(), queue.end());
    for (const auto& item : queue) {
      const int e = item.second;
      if (m.edge_length(e) <= 4.0 / 3.0 * s.target(e)) continue;
      // Slivers many targets long (a stray vertex) would split without end: stop in time.
      if (max_faces > 0 && m.num_faces() > max_faces)
        throw InputError("remeshing: splitting the long edges went past " + std::to_string(max_faces) +
                         " triangles; " + longest_edge_phrase(s) + " (a vertex far from the rest of the mesh?)");
      const int a = m.to(2 * e + 1), b = m.to(2 * e);
      const int first_new_edge = m.num_edges();
      const int v = m.split(e, 0.5 * (m.position(a) + m.position(b)));
      s.grow();
      const char feature = s.edge_feature[at(e)];
      s.edge_feature[at(first_new_edge)] = feature;  // the second half of e
      s.vertex_feature[at(v)] = feature;
      s.vertex_length[at(v)] = 0.5 * (s.vertex_length[at(a)] + s.vertex_length[at(b)]);
      if (!s.vertex_density.empty())
        s.vertex_density[at(v)] = 0.5 * (s.vertex_density[at(a)] + s.vertex_density[at(b)]);
      // A hint refers to a triangle for surface vertices and a segment for feature vertices.
      int hint = -1;
      if (s.vertex_feature[at(a)] == feature)
        hint = s.vertex_hint[at(a)];
      else if (s.vertex_feature[at(b)] == feature)
        hint = s.vertex_hint[at(b)];
      s.vertex_hint[at(v)] = hint;
    }
  }
}

void collapse_short_edges(RemeshState& s) {
  EditMesh& m = s.mesh;
  const int edges = m.num_edges();
  for (int e = 0; e < edges; ++e) {
    if (m.edge_removed(e)) continue;
    const double t = s.target(e);
    if (m.edge_length(e) >= 0.8 * t) continue;
    const double max_length = 4.0 / 3.0 * t;
    // h removes from(h) and keeps to(h).
    auto allowed = [&](int h) {
      const int gone = m.from(h), kept = m.to(h);
      if (s.vertex_locked[at(gone)]) return false;
      // A vertex on a feature curve only slides along it.
      if (s.vertex_feature[at(gone)] && !s.edge_feature[at(e)]) return false;
      if (!m.is_collapse_ok(h)) return false;
      return move_ok(m, gone, m.position(kept), h, max_length);
    };
    const int h0 = 2 * e, h1 = 2 * e + 1;
    const bool ok0 = allowed(h0), ok1 = allowed(h1);
    int h = -1;
    if (ok0 && ok1)
      h = m.valence(m.from(h0)) < m.valence(m.from(h1)) ? h0 : h1;
    else if (ok0)
      h = h0;
    else if (ok1)
      h = h1;
    if (h < 0) continue;
    m.collapse(h);
    for (const auto& [gone, kept] : m.merged_edges())
      s.edge_feature[at(kept)] = static_cast<char>(s.edge_feature[at(kept)] | s.edge_feature[at(gone)]);
  }
}

void flip_edges(RemeshState& s) {
  EditMesh& m = s.mesh;
  auto ideal = [&](int v) { return m.is_boundary_vertex(v) ? 4 : 6; };
  for (int e = 0; e < m.num_edges(); ++e) {
    if (m.edge_removed(e) || s.edge_feature[at(e)] || !m.is_flip_ok(e)) continue;
    const int h0 = 2 * e, h1 = 2 * e + 1;
    const int a = m.to(h0), b = m.to(h1);  // the edge's ends
    const int c = m.to(m.next(h0)), d = m.to(m.next(h1));  // the opposite vertices
    const int va = m.valence(a), vb = m.valence(b), vc = m.valence(c), vd = m.valence(d);
    const int before = std::abs(va - ideal(a)) + std::abs(vb - ideal(b)) + std::abs(vc - ideal(c)) +
                       std::abs(vd - ideal(d));
    const int after = std::abs(va - 1 - ideal(a)) + std::abs(vb - 1 - ideal(b)) + std::abs(vc + 1 - ideal(c)) +
                      std::abs(vd + 1 - ideal(d));
    if (after >= before) continue;
    // Valences 3 (2 on the boundary) would be left at a or b: never go below.
    if (va - 1 < (m.is_boundary_vertex(a) ? 2 : 3) || vb - 1 < (m.is_boundary_vertex(b) ? 2 : 3)) continue;
    // Geometry: face (b, a, c) and (a, b, d) become (c, d, a)... check both new triangles.
    const Vec3 &pa = m.position(a), &pb = m.position(b), &pc = m.position(c), &pd = m.position(d);
    const Vec3 old_sum = triangle_normal(pb, pa, pc) + triangle_normal(pa, pb, pd);
    const Vec3 n1 = triangle_normal(pc, pd, pa), n2 = triangle_normal(pd, pc, pb);
    if (n1.isZero() || n2.isZero() || old_sum.isZero()) continue;
    const Vec3 mean = old_sum.normalized();
    if (n1.dot(mean) < kMinNormalCos || n2.dot(mean) < kMinNormalCos || n1.dot(n2) < kMinNormalCos) continue;
    m.flip(e);
  }
}

}  // namespace ff::prepare_detail
