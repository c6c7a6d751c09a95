#pragma once
// Internal to clean_mesh(): its last stage, local repairs on the cleaned, oriented mesh
// (sliver removal, hole filling) keeping every map of CleanMesh in step. Not public API.
#include "core/mesh/clean.h"

namespace ff::detail {

// Removes slivers (options.remove_slivers) and fills holes (options.fill_holes_max_edges),
// counting both in out.report; re-orients when a filling closed a part. out must be what
// clean_mesh() built so far (edge-manifold, no non-manifold vertices, oriented). Leaves out
// untouched, bit for bit, when there is nothing to do.
void repair_locally(CleanMesh& out, const CleanOptions& options);

}  // namespace ff::detail
