#pragma once
// Who touches whom in a panel mesh: the panel across each panel edge and the panels around
// each vertex, from the shared vertex indices alone (the fabrication data needs nothing else).
#include <vector>

#include "core/panels/panel_mesh.h"

namespace ff {

struct PanelEdges {
  // Per panel, per edge i (from corner i to corner i + 1): the panel across it, -1 on the
  // boundary (or where more than two panels share the edge: not a surface there).
  std::vector<std::vector<int>> neighbour;
  // Per vertex: the panels having it as a corner, increasing.
  std::vector<std::vector<int>> vertex_panels;
};

PanelEdges panel_edges(const PanelMesh& panels);

}  // namespace ff
