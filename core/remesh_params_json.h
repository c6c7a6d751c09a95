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

}  // namespace ff
