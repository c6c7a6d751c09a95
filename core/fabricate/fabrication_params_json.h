#pragma once
// Fabrication settings from the JSON the browser sends (wasm/flatfacet.d.ts,
// FabricationParams): thickness, material side, units, mesh units and sheet size. Checked by
// name here, like core/remesh_params_json.h, because the text may come from a share link.
#include <string_view>

#include "core/fabricate/cut_sheets.h"
#include "core/fabricate/parts_list.h"

namespace ff {

struct FabricationSettings {
  FabricationOptions options;  // thickness in options.units
  SheetOptions sheet;          // in options.units
};

// Missing fields: mesh units "m", units = the mesh units, thickness 0 (no inner faces),
// side "inside", a 2440 x 1220 mm sheet with a 10 mm margin and 5 mm spacing (as the CLI),
// no panel thicknesses, square boundary cuts. "panelThickness": {"P3": 12, ...} (labels,
// in the units), "boundaryCut": "square" | "plumb" | "bevel", "boundaryBevelDeg": -60..60
// (for "bevel"), "upAxis": "x" | "y" | "z" (for "plumb", default "z").
// Throws InputError naming the field for a wrong type, a value out of range or an unknown
// field.
FabricationSettings fabrication_settings_from_json(std::string_view json);

}  // namespace ff
