#pragma once
// A triangle mesh from the flat arrays JavaScript hands over (xyz per vertex, three indices per
// triangle), checked, so a bad array is refused with a message instead of reading out of range.
#include <cstdint>
#include <string>
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff::wasm {

// positions: x, y, z per vertex, each finite; indices: three vertex indices per triangle, each
// below the vertex count. Throws InputError whose message starts with `prefix` (the file's
// name and what the arrays are, e.g. "roof.3dm: mesh ") and names the first bad vertex or
// triangle.
TriMesh mesh_from_arrays(const std::string& prefix, const std::vector<double>& positions,
                         const std::vector<std::uint32_t>& indices);

}  // namespace ff::wasm
