#pragma once
// Solid panels: each panel as a closed prism (outer face, inner face, one quad per edge,
// the quads being the chamfer cuts), as an OBJ in the panel mesh's coordinates, so it
// overlays the panels OBJ. Panels do not share vertices: each is its own part.
#include <string>

#include "core/fabricate/thick_panels.h"

namespace ff {

// thickness > 0, in the panel mesh's units. Faces point out of each solid.
std::string solid_panels_obj(const PanelMesh& panels, double thickness, MaterialSide side = MaterialSide::Inside);

}  // namespace ff
