#pragma once
// Internal to clean_mesh(): the largest manifold part of a mesh with non-manifold edges.
// Not part of the public API.
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff::detail {

struct ManifoldPart {
  std::vector<int> faces;      // the part's faces (indices into tris), increasing
  int sheets = 0;              // parts after cutting the mesh at its non-manifold edges (if any)
  int nonmanifold_edges = 0;   // edges with three or more faces
  int most_faces_left_out = 0;  // the faces of the largest-by-count sheet not kept (0: none)
};

// Cuts the mesh at every edge with three or more faces (the faces of each fan there become
// their own sheets: faces are joined only across edges with exactly two faces) and keeps
// the sheet of largest area (ties: more faces, then the lowest face) among those at most
// kMaxPartSpread (part_spread.h) times the size of the sheet with the most faces, so that a
// stray triangle larger than the model is not taken for it. A mesh without such
// edges is split into its parts (joined by edges) the same way. Should that sheet still hold
// three faces of one edge (it wraps back onto it), the faces there beyond the first two are
// dropped and the cut repeated, so the result is always edge-manifold.
// tris: distinct, non-degenerate faces with valid indices.
ManifoldPart largest_manifold_part(const std::vector<Triangle>& tris, const std::vector<Vec3>& positions);

}  // namespace ff::detail
