#include "core/prepare/edit_mesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <string>

#include "core/util/error.h"

namespace ff::prepare_detail {

EditMesh::EditMesh(const TriMesh& mesh) {
  const int nv = mesh.num_vertices();
  const int nf = mesh.num_faces();
  vpos_ = mesh.positions;
  vout_.assign(idx(nv), -1);
  vdead_.assign(idx(nv), 0);
  // Pair the corners by undirected edge: sort (min, max, corner) so edge numbers depend on
  // the triangles only.
  std::vector<std::array<int, 3>> corners;
  corners.reserve(idx(nf) * 3);
  for (int f = 0; f < nf; ++f) {
    for (int i = 0; i < 3; ++i) {
      const int a = mesh.triangles[idx(f)][idx(i)], b = mesh.triangles[idx(f)][idx((i + 1) % 3)];
      if (a < 0 || b < 0 || a >= nv || b >= nv || a == b) throw InputError("remeshing: invalid triangle " + std::to_string(f));
      corners.push_back({std::min(a, b), std::max(a, b), 3 * f + i});
    }
  }
  std::sort(corners.begin(), corners.end());
  std::vector<int> corner_he(corners.size(), -1);
  for (size_t i = 0; i < corners.size();) {
    size_t j = i + 1;
    while (j < corners.size() && corners[j][0] == corners[i][0] && corners[j][1] == corners[i][1]) ++j;
    const int c1 = corners[i][2];
    const int a = mesh.triangles[idx(c1 / 3)][idx(c1 % 3)];
    const int b = mesh.triangles[idx(c1 / 3)][idx((c1 % 3 + 1) % 3)];
    if (j - i > 2) throw InputError("remeshing: an edge is shared by more than two triangles (clean the mesh first)");
    const int h = new_edge(a, b);
    corner_he[idx(c1)] = h;
    hface_[idx(h)] = c1 / 3;
    if (j - i == 2) {
      const int c2 = corners[i + 1][2];
      if (mesh.triangles[idx(c2 / 3)][idx(c2 % 3)] != b)
        throw InputError("remeshing: inconsistent face orientation (clean the mesh first)");
      corner_he[idx(c2)] = h ^ 1;
      hface_[idx(h ^ 1)] = c2 / 3;
    }
    i = j;
  }
  fhe_.resize(idx(nf));
  fdead_.assign(idx(nf), 0);
  for (int f = 0; f < nf; ++f) {
    fhe_[idx(f)] = corner_he[idx(3 * f)];
    for (int i = 0; i < 3; ++i) {
      const int h = corner_he[idx(3 * f + i)];
      set_next(h, corner_he[idx(3 * f + (i + 1) % 3)]);
      vout_[idx(from(h))] = h;
    }
  }
  // Boundary half-edges: at a manifold vertex at most one leaves, and it follows the one
  // that arrives.
  std::vector<int> boundary_out(idx(nv), -1);
  for (int h = 0; h < static_cast<int>(hto_.size()); ++h) {
    if (hface_[idx(h)] >= 0) continue;
    if (boundary_out[idx(from(h))] >= 0)
      throw InputError("remeshing: a vertex joins two separate fans of triangles (clean the mesh first)");
    boundary_out[idx(from(h))] = h;
  }
  for (int h = 0; h < static_cast<int>(hto_.size()); ++h)
    if (hface_[idx(h)] < 0) set_next(h, boundary_out[idx(to(h))]);
  std::vector<int> degree(idx(nv), 0);
  for (int h = 0; h < static_cast<int>(hto_.size()); ++h) ++degree[idx(from(h))];
  for (int v = 0; v < nv; ++v) {
    if (boundary_out[idx(v)] >= 0) vout_[idx(v)] = boundary_out[idx(v)];
    if (vout_[idx(v)] >= 0 && valence(v) != degree[idx(v)])
      throw InputError("remeshing: a vertex joins two separate fans of triangles (clean the mesh first)");
  }
}

TriMesh EditMesh::to_tri_mesh(std::vector<int>* vertex_of_new) const {
  TriMesh out;
  std::vector<int> new_index(vpos_.size(), -1);
  for (int v = 0; v < num_vertices(); ++v) {
    if (vdead_[idx(v)] || vout_[idx(v)] < 0) continue;
    new_index[idx(v)] = out.num_vertices();
    out.positions.push_back(vpos_[idx(v)]);
    if (vertex_of_new) vertex_of_new->push_back(v);
  }
  for (int f = 0; f < num_faces(); ++f) {
    if (fdead_[idx(f)]) continue;
    const int h = fhe_[idx(f)];
    out.triangles.push_back({new_index[idx(from(h))], new_index[idx(to(h))], new_index[idx(to(next(h)))]});
  }
  return out;
}

int EditMesh::valence(int v) const {
  const int h0 = out(v);
  if (h0 < 0) return 0;
  int n = 0, h = h0;
  do {
    ++n;
    h = rotate(h);
  } while (h != h0 && n <= num_edges());
  return n;
}

int EditMesh::find_halfedge(int a, int b) const {
  const int h0 = out(a);
  if (h0 < 0) return -1;
  int h = h0;
  do {
    if (to(h) == b) return h;
    h = rotate(h);
  } while (h != h0);
  return -1;
}

Vec3 EditMesh::face_normal(int f) const {
  const int h = fhe_[idx(f)];
  const Vec3& a = position(from(h));
  const Vec3& b = position(to(h));
  const Vec3& c = position(to(next(h)));
  const Vec3 n = (b - a).cross(c - a);
  const double len = n.norm();
  return len > 0.0 ? Vec3(n / len) : Vec3::Zero();
}

int EditMesh::new_vertex(const Vec3& p) {
  vpos_.push_back(p);
  vout_.push_back(-1);
  vdead_.push_back(0);
  return num_vertices() - 1;
}

int EditMesh::new_edge(int a, int b) {
  const int h = static_cast<int>(hto_.size());
  hto_.push_back(b);
  hto_.push_back(a);
  hnext_.push_back(-1);
  hnext_.push_back(-1);
  hprev_.push_back(-1);
  hprev_.push_back(-1);
  hface_.push_back(-1);
  hface_.push_back(-1);
  edead_.push_back(0);
  return h;
}

int EditMesh::new_face(int h) {
  fhe_.push_back(h);
  fdead_.push_back(0);
  return num_faces() - 1;
}

void EditMesh::adjust_outgoing(int v) {
  const int h0 = out(v);
  if (h0 < 0) return;
  int h = h0;
  do {
    if (is_boundary_halfedge(h)) {
      vout_[idx(v)] = h;
      return;
    }
    h = rotate(h);
  } while (h != h0);
}

bool EditMesh::is_collapse_ok(int v0v1) const {
  const int v1v0 = v0v1 ^ 1;
  const int v0 = to(v1v0), v1 = to(v0v1);
  int vl = -1, vr = -1;
  // The edges v1-vl and vl-v0 must not both be boundary edges (likewise for vr).
  if (!is_boundary_halfedge(v0v1)) {
    const int h1 = next(v0v1), h2 = next(h1);
    vl = to(h1);
    if (is_boundary_halfedge(h1 ^ 1) && is_boundary_halfedge(h2 ^ 1)) return false;
  }
  if (!is_boundary_halfedge(v1v0)) {
    const int h1 = next(v1v0), h2 = next(h1);
    vr = to(h1);
    if (is_boundary_halfedge(h1 ^ 1) && is_boundary_halfedge(h2 ^ 1)) return false;
  }
  if (vl == vr) return false;
  // An edge between two boundary vertices must be a boundary edge.
  const bool b0 = is_boundary_vertex(v0), b1 = is_boundary_vertex(v1);
  if (b0 && b1 && !is_boundary_halfedge(v0v1) && !is_boundary_halfedge(v1v0)) return false;
  // Link condition: the one-rings of v0 and v1 share only vl and vr.
  const int h0 = out(v0);
  int h = h0;
  do {
    const int vv = to(h);
    if (vv != v1 && vv != vl && vv != vr && find_halfedge(vv, v1) >= 0) return false;
    h = rotate(h);
  } while (h != h0);
  // Valences that stay >= 3 inside and >= 2 on the boundary (no tetrahedron or lone
  // triangle collapses into a degenerate pair of faces).
  for (const int w : {vl, vr}) {
    if (w < 0) continue;
    if (valence(w) - 1 < (is_boundary_vertex(w) ? 2 : 3)) return false;
  }
  const int sides = (vl >= 0 ? 1 : 0) + (vr >= 0 ? 1 : 0);
  const int kept = valence(v0) + valence(v1) - 2 - sides;
  return kept >= ((b0 || b1) ? 2 : 3);
}

void EditMesh::collapse(int h) {
  merged_.clear();
  const int h1 = prev(h);
  const int o1 = next(h ^ 1);
  remove_edge_helper(h);
  if (next(next(h1)) == h1) remove_loop_helper(h1);
  if (next(next(o1)) == o1) remove_loop_helper(o1);
}

void EditMesh::remove_edge_helper(int h) {
  const int hn = next(h), hp = prev(h);
  const int o = h ^ 1, on = next(o), op = prev(o);
  const int fh = face(h), fo = face(o);
  const int vh = to(h), vo = to(o);
  // Every half-edge arriving at vo now arrives at vh.
  const int start = out(vo);
  int hc = start;
  do {
    hto_[idx(hc ^ 1)] = vh;
    hc = rotate(hc);
  } while (hc != start);
  set_next(hp, hn);
  set_next(op, on);
  if (fh >= 0) fhe_[idx(fh)] = hn;
  if (fo >= 0) fhe_[idx(fo)] = on;
  if (out(vh) == o) vout_[idx(vh)] = hn;
  adjust_outgoing(vh);
  vout_[idx(vo)] = -1;
  vdead_[idx(vo)] = 1;
  edead_[idx(edge(h))] = 1;
}

void EditMesh::remove_loop_helper(int h) {
  const int h0 = h, h1 = next(h0);
  const int o0 = h0 ^ 1, o1 = h1 ^ 1;
  const int v0 = to(h0), v1 = to(h1);
  const int fh = face(h0), fo = face(o0);
  set_next(h1, next(o0));
  set_next(prev(o0), h1);
  hface_[idx(h1)] = fo;
  vout_[idx(v0)] = h1;
  adjust_outgoing(v0);
  vout_[idx(v1)] = o1;
  adjust_outgoing(v1);
  if (fo >= 0 && fhe_[idx(fo)] == o0) fhe_[idx(fo)] = h1;
  if (fh >= 0) fdead_[idx(fh)] = 1;
  edead_[idx(edge(h0))] = 1;
  merged_.emplace_back(edge(h0), edge(h1));
}

bool EditMesh::is_flip_ok(int e) const {
  const int h0 = 2 * e, h1 = 2 * e + 1;
  if (is_boundary_halfedge(h0) || is_boundary_halfedge(h1)) return false;
  const int v0 = to(next(h0)), v1 = to(next(h1));
  if (v0 == v1) return false;
  return find_halfedge(v0, v1) < 0;
}

void EditMesh::flip(int e) {
  const int a0 = 2 * e, b0 = 2 * e + 1;
  const int a1 = next(a0), a2 = next(a1);
  const int b1 = next(b0), b2 = next(b1);
  const int va0 = to(a0), va1 = to(a1);
  const int vb0 = to(b0), vb1 = to(b1);
  const int fa = face(a0), fb = face(b0);
  hto_[idx(a0)] = va1;
  hto_[idx(b0)] = vb1;
  set_next(a0, a2);
  set_next(a2, b1);
  set_next(b1, a0);
  set_next(b0, b2);
  set_next(b2, a1);
  set_next(a1, b0);
  hface_[idx(a1)] = fb;
  hface_[idx(b1)] = fa;
  fhe_[idx(fa)] = a0;
  fhe_[idx(fb)] = b0;
  if (out(va0) == b0) vout_[idx(va0)] = a1;
  if (out(vb0) == a0) vout_[idx(vb0)] = b1;
}

int EditMesh::split(int e, const Vec3& p) {
  const int v = new_vertex(p);
  const int h0 = 2 * e, o0 = 2 * e + 1;
  const int v2 = to(o0);
  const int e1 = new_edge(v, v2), t1 = e1 ^ 1;
  const int f0 = face(h0), f3 = face(o0);
  vout_[idx(v)] = h0;
  hto_[idx(o0)] = v;
  if (f0 >= 0) {
    const int h1 = next(h0), h2 = next(h1);
    const int v1 = to(h1);
    const int e0 = new_edge(v, v1), t0 = e0 ^ 1;
    const int f1 = new_face(h2);
    fhe_[idx(f0)] = h0;
    hface_[idx(h1)] = f0;
    hface_[idx(t0)] = f0;
    hface_[idx(h0)] = f0;
    hface_[idx(h2)] = f1;
    hface_[idx(t1)] = f1;
    hface_[idx(e0)] = f1;
    set_next(h0, h1);
    set_next(h1, t0);
    set_next(t0, h0);
    set_next(e0, h2);
    set_next(h2, t1);
    set_next(t1, e0);
  } else {
    set_next(prev(h0), t1);
    set_next(t1, h0);
  }
  if (f3 >= 0) {
    const int o1 = next(o0), o2 = next(o1);
    const int v3 = to(o1);
    const int e2 = new_edge(v, v3), t2 = e2 ^ 1;
    const int f2 = new_face(o1);
    fhe_[idx(f3)] = o0;
    hface_[idx(o1)] = f2;
    hface_[idx(t2)] = f2;
    hface_[idx(e1)] = f2;
    hface_[idx(o2)] = f3;
    hface_[idx(o0)] = f3;
    hface_[idx(e2)] = f3;
    set_next(e1, o1);
    set_next(o1, t2);
    set_next(t2, e1);
    set_next(o0, e2);
    set_next(e2, o2);
    set_next(o2, o0);
  } else {
    set_next(e1, next(o0));
    set_next(o0, e1);
    vout_[idx(v)] = e1;
  }
  if (out(v2) == h0) vout_[idx(v2)] = t1;
  return v;
}

}  // namespace ff::prepare_detail
