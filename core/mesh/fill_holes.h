#pragma once
// Internal to clean_mesh(): filling small holes of an oriented edge-manifold mesh. Not part
// of the public API.
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff::detail {

// The most edges a hole may have to be filled (the triangulation is cubic in it).
constexpr int kMaxFillEdges = 500;

struct HoleFill {
  int holes_filled = 0;
  int faces_added = 0;
  int holes_left = 0;  // boundary loops left open (longer than asked, or no valid filling)
};

// Fills every boundary loop of at most max_edges edges with the triangulation of least
// total area among those that add no edge the mesh has already (an O(k^3) dynamic
// program over the loop's k corners; no new vertices, no fairing). The new faces follow
// the orientation of the faces around the hole and are appended to tris; face_origin gets
// appended, per new face, the index (in tris) of the face along the loop's first edge, so
// per-face data has a source.
// tris must be an oriented edge-manifold without non-manifold vertices (each vertex on at
// most one boundary loop), as clean_mesh() makes it.
HoleFill fill_holes(std::vector<Triangle>& tris, const std::vector<Vec3>& positions, int max_edges,
                    std::vector<int>& face_origin);

}  // namespace ff::detail
