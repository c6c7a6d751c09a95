#pragma once
// A part far from the rest (a stray fragment of a CAD export, a triangle typed 1e8 away) is
// refused by name. The solve works in one frame about the middle of the whole mesh, with
// tolerances relative to its bounding box: a part 1e6 times the model's size away leaves the
// model too few digits there and its panels end invalid (epcot.off with a triangle 3e6 away:
// exit 3 at 30 panels; 1e6 away: valid), with nothing to say why.
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff {

// Per vertex, the smallest vertex of its part: parts are connected through shared vertices
// (so two sheets touching at a vertex are one). Unused vertices are parts of their own. O(m).
std::vector<int> vertex_part_roots(const TriMesh& mesh);

// The mesh's bounding box may be at most this many times the largest part's (by diagonal).
constexpr double kMaxPartSpread = 1e5;

// Throws a LargestPartError naming the part farthest from the largest one (its triangles and
// where it is) when the whole mesh's bounding-box diagonal exceeds kMaxPartSpread times the
// largest connected part's; its numbers count the faces of the part of largest area, which
// CleanOptions::largest_manifold_part would keep. Parts are connected through shared
// vertices (mesh: cleaned, so also through edges). O(m), plus O(m log m) when refused.
void require_compact_parts(const TriMesh& mesh);
// The same with the mesh's vertex_part_roots() known (clean_mesh computes them once for both
// spread checks).
void require_compact_parts(const TriMesh& mesh, const std::vector<int>& roots);

}  // namespace ff
