#pragma once
// Internal to clean_mesh(): removal of sliver faces (zero-area and needle triangles) from an
// oriented edge-manifold mesh without changing its topology. Not part of the public API.
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff::detail {

struct SliverResult {
  int collapsed = 0;  // slivers removed by collapsing their shortest edge
  int flipped = 0;    // slivers removed by flipping their longest edge
  int dropped = 0;    // boundary caps removed (their long edge was on the boundary)
  int kept = 0;       // slivers no local operation could remove (left as they are)
  int removed() const { return collapsed + flipped + dropped; }
};

// A face is a sliver when its area is below 1e-12 diag^2 or a corner lies within 1e-9 diag
// of the line of the opposite edge (diag: the bounding-box diagonal).
bool is_sliver(const Vec3& a, const Vec3& b, const Vec3& c, double diag);

// Removes slivers in face order, in passes until none can be removed:
// - a needle (shortest edge below a tenth of the longest) collapses its shortest edge into
//   one of its ends (a boundary end is kept, else the lower index), when the link condition
//   holds, no face turns over and no duplicate face appears;
// - a cap (a corner near the middle of the opposite edge) flips that edge when it is
//   interior and the two new faces are no slivers; on the boundary the cap is dropped when
//   its corner is interior (the boundary then runs through it).
// Each keeps the Euler characteristic and the boundary loops. Positions never move.
// tris: oriented edge-manifold faces, rewritten (removed faces erased). face_origin: per
// output face, the input face it was (a flip's two faces keep their own). vertex_target:
// per vertex, the vertex it was collapsed into (itself when kept).
SliverResult remove_slivers(std::vector<Triangle>& tris, const std::vector<Vec3>& positions,
                            std::vector<int>& face_origin, std::vector<int>& vertex_target);

}  // namespace ff::detail
