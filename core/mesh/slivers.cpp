#include "core/mesh/slivers.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <iterator>

namespace ff::detail {

namespace {

constexpr double kHeight = 1e-9;  // of the bounding-box diagonal
constexpr double kArea = 1e-12;   // of its square
constexpr int kMaxPasses = 8;     // each pass only removes slivers; a few always suffice

// A manifold mesh under local edits: faces with an alive flag and the faces around each
// vertex (dead ones removed eagerly), enough for link conditions and flips.
class LocalMesh {
 public:
  LocalMesh(std::vector<Triangle>& tris, const std::vector<Vec3>& positions)
      : tris_(tris), pos_(positions), alive_(tris.size(), 1), around_(positions.size()) {
    for (size_t f = 0; f < tris.size(); ++f) {
      for (int v : tris[f]) around_[static_cast<size_t>(v)].push_back(static_cast<int>(f));
    }
    double diag = 0.0;
    if (!positions.empty()) {
      Vec3 lo = positions.front(), hi = positions.front();
      for (const Vec3& p : positions) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
      diag = (hi - lo).norm();
    }
    diag_ = diag;
  }

  double diag() const { return diag_; }
  bool alive(int f) const { return alive_[static_cast<size_t>(f)] != 0; }
  const Vec3& p(int v) const { return pos_[static_cast<size_t>(v)]; }
  const Triangle& tri(int f) const { return tris_[static_cast<size_t>(f)]; }

  // Faces using both a and b (0, 1 or 2 on a manifold).
  std::vector<int> edge_faces(int a, int b) const {
    std::vector<int> out;
    for (int f : around_[static_cast<size_t>(a)]) {
      const Triangle& t = tri(f);
      if (t[0] == b || t[1] == b || t[2] == b) out.push_back(f);
    }
    return out;
  }
  bool on_boundary(int v) const {
    for (int f : around_[static_cast<size_t>(v)]) {
      for (int w : tri(f)) {
        if (w != v && edge_faces(v, w).size() == 1) return true;
      }
    }
    return false;
  }
  std::vector<int> neighbours(int v) const {
    std::vector<int> out;
    for (int f : around_[static_cast<size_t>(v)]) {
      for (int w : tri(f)) {
        if (w != v) out.push_back(w);
      }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }
  bool sliver(const Vec3& a, const Vec3& b, const Vec3& c) const { return is_sliver(a, b, c, diag_); }

  void kill(int f) {
    alive_[static_cast<size_t>(f)] = 0;
    for (int v : tri(f)) detach(v, f);
  }
  void detach(int v, int f) {
    auto& list = around_[static_cast<size_t>(v)];
    list.erase(std::remove(list.begin(), list.end(), f), list.end());
  }
  void attach(int v, int f) { around_[static_cast<size_t>(v)].push_back(f); }
  void set(int f, const Triangle& t) { tris_[static_cast<size_t>(f)] = t; }
  // New corners for a live face.
  void replace(int f, const Triangle& t) {
    for (int v : tri(f)) detach(v, f);
    set(f, t);
    for (int v : t) attach(v, f);
  }
  const std::vector<int>& faces_at(int v) const { return around_[static_cast<size_t>(v)]; }

 private:
  std::vector<Triangle>& tris_;
  const std::vector<Vec3>& pos_;
  std::vector<char> alive_;
  std::vector<std::vector<int>> around_;
  double diag_ = 0.0;
};

// Rotates f's corners so corner `i` comes first (orientation unchanged).
Triangle rotated(const Triangle& t, int i) {
  return {t[static_cast<size_t>(i)], t[static_cast<size_t>((i + 1) % 3)], t[static_cast<size_t>((i + 2) % 3)]};
}

// Collapses u into w (w stays). Refused when it would change the topology or turn a face.
bool try_collapse(LocalMesh& m, int u, int w, std::vector<int>& vertex_target) {
  const std::vector<int> shared = m.edge_faces(u, w);
  if (shared.empty()) return false;
  const bool bu = m.on_boundary(u), bw = m.on_boundary(w);
  if (bu && !bw) std::swap(u, w);  // keep the boundary end where the boundary is
  if (bu && bw && shared.size() != 1) return false;  // an interior edge joining two boundaries
  // Link condition: the common neighbours are exactly the corners opposite the edge.
  std::vector<int> opposite;
  for (int f : shared) {
    for (int v : m.tri(f)) {
      if (v != u && v != w) opposite.push_back(v);
    }
  }
  std::sort(opposite.begin(), opposite.end());
  const std::vector<int> nu = m.neighbours(u), nw = m.neighbours(w);
  std::vector<int> common;
  std::set_intersection(nu.begin(), nu.end(), nw.begin(), nw.end(), std::back_inserter(common));
  common.erase(std::remove_if(common.begin(), common.end(), [&](int v) { return v == u || v == w; }), common.end());
  if (common != opposite) return false;
  // The faces that move: none may turn over or repeat one of w's faces.
  std::vector<int> moving;
  for (int f : m.faces_at(u)) {
    if (std::find(shared.begin(), shared.end(), f) == shared.end()) moving.push_back(f);
  }
  if (moving.empty() && m.faces_at(w).size() == shared.size()) return false;  // nothing would remain
  for (int f : moving) {
    Triangle t = m.tri(f);
    const Vec3 before = (m.p(t[1]) - m.p(t[0])).cross(m.p(t[2]) - m.p(t[0]));
    for (int& v : t) v = v == u ? w : v;
    const Vec3 after = (m.p(t[1]) - m.p(t[0])).cross(m.p(t[2]) - m.p(t[0]));
    if (before.dot(after) < 0.0) return false;
    std::array<int, 3> key = t;
    std::sort(key.begin(), key.end());
    for (int g : m.faces_at(w)) {
      std::array<int, 3> other = m.tri(g);
      std::sort(other.begin(), other.end());
      if (other == key) return false;
    }
  }
  for (int f : shared) m.kill(f);
  for (int f : moving) {
    Triangle t = m.tri(f);
    for (int& v : t) v = v == u ? w : v;
    m.set(f, t);
    m.attach(w, f);
  }
  for (int f : moving) m.detach(u, f);
  vertex_target[static_cast<size_t>(u)] = w;
  return true;
}

// f = (a, b, p) with p near the middle of a-b: flip a-b into p-q, or drop f on the boundary.
int try_flip(LocalMesh& m, int f, int longest) {
  const Triangle t = rotated(m.tri(f), longest);
  const int a = t[0], b = t[1], p = t[2];
  const std::vector<int> across = m.edge_faces(a, b);
  if (across.size() == 1) {
    // A boundary cap: without it the boundary runs a-p-b; needs p interior with two
    // interior edges, so p ends on one boundary fan.
    if (m.on_boundary(p) || m.edge_faces(a, p).size() != 2 || m.edge_faces(p, b).size() != 2) return 0;
    m.kill(f);
    return 2;
  }
  if (across.size() != 2) return 0;
  const int g = across[0] == f ? across[1] : across[0];
  int q = -1;
  for (int v : m.tri(g)) {
    if (v != a && v != b) q = v;
  }
  if (q < 0 || q == p || !m.edge_faces(p, q).empty()) return 0;
  if (m.sliver(m.p(a), m.p(q), m.p(p)) || m.sliver(m.p(q), m.p(b), m.p(p))) return 0;
  // f: a->b->p and g: b->a->q; the quad a->q->b->p becomes (a, q, p) and (q, b, p).
  m.replace(f, {a, q, p});
  m.replace(g, {q, b, p});
  return 1;
}

}  // namespace

bool is_sliver(const Vec3& a, const Vec3& b, const Vec3& c, double diag) {
  const double twice_area = (b - a).cross(c - a).norm();
  const double longest = std::sqrt(std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()}));
  return 0.5 * twice_area <= kArea * diag * diag || twice_area <= kHeight * diag * longest;
}

SliverResult remove_slivers(std::vector<Triangle>& tris, const std::vector<Vec3>& positions,
                            std::vector<int>& face_origin, std::vector<int>& vertex_target) {
  SliverResult result;
  vertex_target.resize(positions.size());
  for (size_t v = 0; v < positions.size(); ++v) vertex_target[v] = static_cast<int>(v);
  LocalMesh m(tris, positions);
  const int faces = static_cast<int>(tris.size());
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    bool changed = false;
    for (int f = 0; f < faces; ++f) {
      if (!m.alive(f)) continue;
      const Triangle& t = m.tri(f);
      if (!m.sliver(m.p(t[0]), m.p(t[1]), m.p(t[2]))) continue;
      int shortest = 0, longest = 0;
      double lo = 0.0, hi = 0.0;
      for (int i = 0; i < 3; ++i) {
        const double len = (m.p(t[static_cast<size_t>((i + 1) % 3)]) - m.p(t[static_cast<size_t>(i)])).norm();
        if (i == 0 || len < lo) lo = len, shortest = i;
        if (i == 0 || len > hi) hi = len, longest = i;
      }
      bool done = false;
      if (lo <= 0.1 * hi) {
        const int u = t[static_cast<size_t>(shortest)], w = t[static_cast<size_t>((shortest + 1) % 3)];
        done = try_collapse(m, std::max(u, w), std::min(u, w), vertex_target);
        result.collapsed += done ? 1 : 0;
      } else {
        const int flip = try_flip(m, f, longest);
        result.flipped += flip == 1 ? 1 : 0;
        result.dropped += flip == 2 ? 1 : 0;
        done = flip != 0;
      }
      changed = changed || done;
    }
    if (!changed) break;
  }
  std::vector<Triangle> kept;
  std::vector<int> origin;
  for (int f = 0; f < faces; ++f) {
    if (!m.alive(f)) continue;
    kept.push_back(m.tri(f));
    origin.push_back(f);
    if (m.sliver(m.p(m.tri(f)[0]), m.p(m.tri(f)[1]), m.p(m.tri(f)[2]))) ++result.kept;
  }
  tris = std::move(kept);
  face_origin = std::move(origin);
  return result;
}

}  // namespace ff::detail
