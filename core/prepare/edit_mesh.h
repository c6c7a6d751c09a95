#pragma once
// EditMesh: an editable half-edge triangle mesh for the remesher (isotropic_remesh.h), with
// explicit boundary half-edges (pmp-library / OpenMesh layout). Internal to core/prepare.
//
// Half-edges come in pairs: h and h ^ 1 are opposite, edge e is half-edges 2e and 2e + 1.
// Elements are never reused: removed ones are flagged and dropped by to_tri_mesh(), and new
// ones are appended, so iterating by index is deterministic.
#include <utility>
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff::prepare_detail {

class EditMesh {
 public:
  // The mesh must be clean (clean_mesh): edge-manifold, vertex-manifold, consistently
  // oriented. Throws InputError otherwise.
  explicit EditMesh(const TriMesh& mesh);

  // Live triangles in face order, vertices renumbered in index order. vertex_of_new
  // (optional) receives, per output vertex, its index here.
  TriMesh to_tri_mesh(std::vector<int>* vertex_of_new = nullptr) const;

  int num_vertices() const { return static_cast<int>(vpos_.size()); }
  int num_edges() const { return static_cast<int>(hto_.size() / 2); }
  int num_faces() const { return static_cast<int>(fhe_.size()); }

  // Half-edge navigation.
  static int opposite(int h) { return h ^ 1; }
  static int halfedge(int e, int i) { return 2 * e + i; }
  static int edge(int h) { return h / 2; }
  int to(int h) const { return hto_[idx(h)]; }
  int from(int h) const { return hto_[idx(h ^ 1)]; }
  int next(int h) const { return hnext_[idx(h)]; }
  int prev(int h) const { return hprev_[idx(h)]; }
  int face(int h) const { return hface_[idx(h)]; }
  bool is_boundary_halfedge(int h) const { return hface_[idx(h)] < 0; }
  bool is_boundary_edge(int e) const { return face(2 * e) < 0 || face(2 * e + 1) < 0; }
  // An outgoing half-edge of v; a boundary one when v is on the boundary; -1 if isolated.
  int out(int v) const { return vout_[idx(v)]; }
  bool is_boundary_vertex(int v) const { return out(v) >= 0 && is_boundary_halfedge(out(v)); }
  // The next outgoing half-edge around from(h).
  int rotate(int h) const { return next(h ^ 1); }
  int face_halfedge(int f) const { return fhe_[idx(f)]; }

  bool vertex_removed(int v) const { return vdead_[idx(v)] != 0; }
  bool edge_removed(int e) const { return edead_[idx(e)] != 0; }
  bool face_removed(int f) const { return fdead_[idx(f)] != 0; }

  const Vec3& position(int v) const { return vpos_[idx(v)]; }
  void set_position(int v, const Vec3& p) { vpos_[idx(v)] = p; }
  int valence(int v) const;
  // The half-edge from a to b, or -1.
  int find_halfedge(int a, int b) const;
  Vec3 face_normal(int f) const;  // unit, zero for degenerate faces
  double edge_length(int e) const { return (position(to(2 * e)) - position(to(2 * e + 1))).norm(); }

  // pmp's link condition and boundary rules: collapsing h (removing from(h), keeping to(h))
  // keeps the mesh a manifold with the same topology. Also refuses collapses that would
  // leave a vertex of valence < 3 (interior) or < 2 (boundary): tetrahedra and the like.
  bool is_collapse_ok(int h) const;
  // Removes from(h) and the faces on both sides of h; to(h) stays where it is.
  void collapse(int h);
  // During collapse(), an edge removed as a duplicate passes its flag to the edge kept in
  // its place: callers read this list of (removed edge, kept edge) after each collapse.
  const std::vector<std::pair<int, int>>& merged_edges() const { return merged_; }

  bool is_flip_ok(int e) const;
  void flip(int e);

  // Splits edge e at point p; returns the new vertex. New edges are appended: the second
  // half of e first, then the edges to the opposite vertices (face side of 2e, then 2e+1).
  int split(int e, const Vec3& p);

 private:
  static size_t idx(int i) { return static_cast<size_t>(i); }
  int new_edge(int a, int b);  // half-edge a->b, its opposite b->a
  int new_face(int h);
  int new_vertex(const Vec3& p);
  void set_next(int h, int n) {
    hnext_[idx(h)] = n;
    hprev_[idx(n)] = h;
  }
  void adjust_outgoing(int v);
  void remove_edge_helper(int h);
  void remove_loop_helper(int h);

  std::vector<Vec3> vpos_;
  std::vector<int> vout_;
  std::vector<char> vdead_;
  std::vector<int> hto_, hnext_, hprev_, hface_;
  std::vector<char> edead_;
  std::vector<int> fhe_;
  std::vector<char> fdead_;
  std::vector<std::pair<int, int>> merged_;
};

}  // namespace ff::prepare_detail
