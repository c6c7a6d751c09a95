#pragma once
// Internal to clean_mesh(): consistent orientation. Not part of the public API.
#include <vector>

#include "core/mesh/half_edges.h"
#include "core/mesh/tri_mesh.h"

namespace ff::detail {

struct OrientResult {
  int faces_flipped = 0;
  int components = 0;  // edge-connected
};

// Flips faces (swapping their last two corners) so that the two faces of every interior
// edge use it in opposite directions, one breadth-first search per edge-connected
// component. Each component then keeps the orientation of the larger share (by area) of
// its input faces, except that a closed one gets a positive signed volume when
// closed_outward. `groups` must come from `tris` (renumbering vertices since is fine) and
// list at most two half-edges per edge; a flip renumbers a face's half-edges, so they no
// longer fit afterwards. Throws InputError when a component is not orientable, naming a
// vertex there through vertex_name.
OrientResult orient_faces(std::vector<Triangle>& tris, const HalfEdgeGroups& groups, const std::vector<Vec3>& positions,
                          const std::vector<int>& vertex_name, bool closed_outward);

}  // namespace ff::detail
