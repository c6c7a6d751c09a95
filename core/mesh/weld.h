#pragma once
// Internal to clean_mesh(): which vertices to weld. Not part of the public API.
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff::detail {

// For each vertex, the vertex it is welded into. First the lowest-index vertex at the
// same position; then, when tolerance > 0, visiting those first vertices in index order,
// each joins the nearest earlier representative within tolerance (ties: lower index), or
// stays one itself. Representatives map to themselves, so welding never chains: of three
// points in a row 0.6 tolerance apart, the last stays apart. Only vertices with
// weldable[v] != 0 take part (all when weldable is empty). Positions must be finite and
// tolerance finite and >= 0.
std::vector<int> weld_representatives(const std::vector<Vec3>& positions, double tolerance,
                                      const std::vector<char>& weldable = {});

}  // namespace ff::detail
