#pragma once
// A panel laid flat: what cut sheets draw and what the parts list describes per edge. Shared
// by the parts list (which makes them from a panel mesh) and the cut sheets (which pack them).
#include <string>
#include <vector>

#include "core/panels/polygon2d.h"

namespace ff {

struct OutlineEdge {
  double length = 0.0;       // in the chosen units
  double chamfer_deg = 0.0;  // bevel angle of the cut at this edge (0 = square cut)
  std::string neighbour;     // label of the panel across the edge, empty on the boundary
};

struct PanelOutline {
  int panel = 0;
  std::string label;  // "P1", ...
  // Counter-clockwise outline of the outer face in the panel's own frame (units chosen by
  // the designer), edge i from outer[i] to outer[i + 1]; the inner face (offset by the
  // thickness) likewise, empty without thickness.
  std::vector<Vec2> outer;
  std::vector<Vec2> inner;
  std::vector<OutlineEdge> edges;  // one per outer edge
  double thickness = 0.0;
};

}  // namespace ff
