#pragma once
// Isotropic remeshing to a target edge length (Botsch & Kobbelt 2004, as in pmp-library):
// repeat { split edges longer than 4/3 L at their midpoint; collapse edges shorter than
// 4/5 L where that creates no edge longer than 4/3 L, keeps the topology (link condition)
// and flips no triangle; flip edges where that brings valences closer to 6 (4 on the
// boundary); tangential area-weighted smoothing; projection back onto the input }.
//
// Features: boundary edges and edges whose dihedral angle exceeds feature_angle_deg are
// kept as curves: they are split but never flipped, vertices on them collapse and slide
// only along them and are projected onto the input's feature curves, and feature corners
// (vertices on 1 or 3+ feature edges, or where a curve turns by more than the feature angle)
// never move or go away. Deterministic: every pass runs in element order.
//
// Density: an optional per-input-vertex density (> 0; higher = smaller triangles) makes the
// local target L * sqrt(mean density / density), the mean being area-weighted, clamped to
// [L / 8, 8 L]; it is carried to the new vertices by interpolation at their projection.
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff {

struct IsotropicRemeshOptions {
  double target_edge_length = 0.0;  // L, required: finite and > 0
  int iterations = 10;              // remeshing rounds (pmp's default)
  int smoothing_steps = 2;          // smoothing + projection steps per round
  double feature_angle_deg = 44.0;  // dihedral angle above which an edge is a crease; >= 180: none
  std::vector<double> vertex_density;  // empty (uniform) or one value > 0 per input vertex
  // The most triangles the remeshing may make at any time (memory): a target that needs more,
  // by area or by the splits of the longest edges, is refused up front, and the splitting
  // stops with an InputError if it gets past this anyway.
  long long max_triangles = 4'000'000;
};

struct IsotropicRemeshResult {
  TriMesh mesh;
  std::vector<double> vertex_density;  // per output vertex, when the options had one
  int feature_edges = 0;               // input edges kept as curves (creases + boundary)
  int feature_corners = 0;             // input vertices that stayed fixed
};

// mesh: clean (clean_mesh: manifold, consistently oriented). Throws InputError for a bad
// target length, a density of the wrong size or with values <= 0, a mesh that is not a
// clean manifold, or more than max_triangles (naming the longest edge for the target: a
// vertex far from the rest makes huge slivers that no target suits).
IsotropicRemeshResult isotropic_remesh(const TriMesh& mesh, const IsotropicRemeshOptions& options);

// A per-input-vertex field carried to arbitrary points by interpolation at their closest
// point on the input (e.g. a density onto a remeshed surface). field: one value per vertex.
std::vector<double> transfer_vertex_field(const TriMesh& input, const std::vector<double>& field,
                                          const std::vector<Vec3>& points);
// A per-input-face field carried to the faces of `target` (value of the input face nearest
// to each target face's centroid).
std::vector<double> transfer_face_field(const TriMesh& input, const std::vector<double>& field,
                                        const TriMesh& target);

}  // namespace ff
