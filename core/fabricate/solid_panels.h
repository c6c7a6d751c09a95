#pragma once
// Solid panels: each panel as a closed prism (outer face, inner face, one quad per edge,
// the quads being the chamfer cuts), as an OBJ in the panel mesh's coordinates (times
// `scale`, to write it in the designer's units; a comment line names them), so it overlays
// the panels OBJ. Panels do not share vertices: each is its own part, named by its label.
#include <string>

#include "core/fabricate/thick_panels.h"

namespace ff {

// thickness > 0, in the panel mesh's units. Faces point out of each solid.
std::string solid_panels_obj(const PanelMesh& panels, double thickness, MaterialSide side = MaterialSide::Inside);
// With per-panel thicknesses and a boundary cut (thick_panels.h, mesh units); coordinates
// multiplied by `scale` and, when `units` is not empty, a "# units: <units>" line.
std::string solid_panels_obj(const PanelMesh& panels, const ThickOptions& options, double scale,
                             const std::string& units);

}  // namespace ff
