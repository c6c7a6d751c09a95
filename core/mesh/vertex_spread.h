#pragma once
// A vertex far from all the others (a mistyped or corrupted coordinate: 3e38 where 0.3 was
// meant) is refused by name. Its triangles become slivers as long as the mesh is wide, the
// solve's tolerances (relative to the bounding box) lose the model, and the run ended after
// every retry with half its panels invalid, advising another seed. Found by fuzz_cli.py
// (3holes.off with one vertex at x = 3e38: 8 retries, 5 s, 50 of 32 panels invalid).
// A far-off *part* is part_spread.h's; this one catches a stray vertex inside a part.
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff {

// How many times farther from its part's middle than 90% of the part's vertices one may lie.
// The shared meshes reach 1.0-1.7; a spire 100 times its building's height passes.
constexpr double kMaxVertexSpread = 1e5;

// Throws an InputError naming the vertex farthest out (its number in the input, via
// vertex_source, and its place) when it lies more than kMaxVertexSpread times as far from
// its part's middle (the per-axis median) as 90% of that part's vertices do. Parts are
// connected through shared vertices; parts of fewer than 4 vertices, and parts whose
// vertices mostly coincide, are left to other checks (a far-off small part: part_spread.h).
// vertex_source maps mesh vertices to input vertex numbers (CleanMesh::vertex_source);
// empty: numbered as in mesh. O(n).
void require_no_stray_vertex(const TriMesh& mesh, const std::vector<int>& vertex_source);
// The same with the mesh's vertex_part_roots() (part_spread.h) known.
void require_no_stray_vertex(const TriMesh& mesh, const std::vector<int>& vertex_source,
                             const std::vector<int>& roots);

}  // namespace ff
