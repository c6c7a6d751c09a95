#pragma once
// Internal to core/prepare: the state isotropic_remesh() carries through its rounds, and the
// split / collapse / flip passes with their feature rules (isotropic_remesh.h says which).
#include <string>
#include <vector>

#include "core/prepare/edit_mesh.h"

namespace ff::prepare_detail {

struct RemeshState {
  explicit RemeshState(const TriMesh& input) : mesh(input) {}

  EditMesh mesh;
  std::vector<char> edge_feature;    // per edge: a crease or boundary curve
  std::vector<char> vertex_feature;  // per vertex: on a feature curve
  std::vector<char> vertex_locked;   // per vertex: a feature corner, never moved or removed
  std::vector<double> vertex_length;  // per vertex: the local target edge length
  std::vector<int> vertex_hint;      // per vertex: input element of its last projection, or -1
  std::vector<double> vertex_density;  // per vertex (empty when there is no density)

  // The target of edge e: the mean of its ends' targets.
  double target(int e) const;
  // Sizes the per-vertex and per-edge arrays to the mesh after it grew.
  void grow();
};

// Splits every edge longer than 4/3 of its target at its midpoint, the new halves too, so no
// edge stays too long. The new vertex inherits the edge's feature flag. Throws InputError
// when the mesh gets past max_faces triangles (> 0; 0: no limit).
void split_long_edges(RemeshState& s, long long max_faces = 0);

// "the edge from (x, y, z) to (x, y, z) is R times its target": the edge of the largest
// length / target, for messages; "" without edges.
std::string longest_edge_phrase(const RemeshState& s);
// Collapses edges shorter than 4/5 of their target into the end that keeps the rules.
void collapse_short_edges(RemeshState& s);
// Flips non-feature edges where the valence deviation goes down and no triangle folds.
void flip_edges(RemeshState& s);

// The unit normal of the triangle (a, b, c), zero when degenerate.
Vec3 triangle_normal(const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace ff::prepare_detail
