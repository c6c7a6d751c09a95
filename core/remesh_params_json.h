#pragma once
// RemeshParams from the JSON the browser sends (wasm/flatfacet.d.ts, RemeshParams): camelCase
// names, missing fields keep the values of `base`. Every field's type and range is checked
// here, by name, because the text may come from a share link someone else made.
#include <string_view>

#include "core/remesher.h"

namespace ff {

// Throws InputError naming the field for a wrong type, a non-integer count, a value out of
// range or an unknown field; the Remesher checks what depends on the mesh (panels vs faces).
RemeshParams remesh_params_from_json(std::string_view json, const RemeshParams& base = {});

// Per-panel edits, the `edits` field's array on its own (`flatfacet remesh --edits FILE`):
// [{"op": "split", "face": 12}, {"op": "merge", "face": 3, "with": 40}, {"op": "lock",
// "face": 7}, {"op": "unlock", "face": 7}], at most kMaxEdits. Face ids are checked against
// the mesh when the edits are applied (Remesher).
constexpr int kMaxEdits = 10000;
std::vector<PanelEdit> panel_edits_from_json(std::string_view json);

}  // namespace ff
