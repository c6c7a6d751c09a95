#pragma once
// The generated examples the page offers by name (the paper's hard cases and a freeform roof),
// so a share link can name one instead of carrying a mesh.
#include <string>
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff {

std::vector<std::string> example_shape_names();

// About `triangles` triangles (100 .. 4,000,000). Throws InputError for an unknown name or a
// count out of range.
TriMesh make_example_shape(const std::string& name, int triangles);

}  // namespace ff
