#pragma once
// The basic parts list: one row per panel with what a fabricator needs first (how many
// sides, how big, which plane). The fabrication issue extends it (thickness, chamfers,
// outlines, units); the columns here keep their names and meaning.
#include <string>
#include <vector>

#include "core/panels/panel_mesh.h"

namespace ff {

struct PanelPart {
  int panel = 0;
  std::string label;  // "P1", "P2", ... (1-based, as people count)
  int sides = 0;
  double area = 0.0;       // in the mesh's units squared
  double perimeter = 0.0;  // in the mesh's units
  Vec3 normal = Vec3::Zero();
  double offset = 0.0;  // plane: normal . x = offset
};

std::vector<PanelPart> panel_parts(const PanelMesh& panels);

// CSV with a header row: panel,label,sides,area,perimeter,normal_x,normal_y,normal_z,offset;
// numbers at full precision; a last row labelled "total" sums area and perimeter.
std::string parts_list_csv(const PanelMesh& panels);

}  // namespace ff
