#pragma once
// A PanelMesh as plain geometry for files and displays: the polygons on the vertices they
// use (what the panels OBJ holds), the panels triangulated in their own planes (what a
// viewer draws; concave panels included), and the OBJ text with its comment lines.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/panels/panel_mesh.h"

namespace ff {

struct PolygonMesh {
  std::vector<Vec3> vertices;
  std::vector<std::vector<int>> faces;
};

// The panels on the vertices they use, in their original order, so the OBJ has exactly the
// report's `vertices` v-lines. Panel indices must be in range (measure_quality checks them).
PolygonMesh used_vertices_only(const PanelMesh& panels);

struct PanelTriangles {
  std::vector<std::array<int, 3>> triangles;  // indices into PanelMesh::vertices
  std::vector<int> panel;                     // per triangle: its panel
};

// Each panel triangulated in its own plane (ear clipping; a fan for a non-simple one), oriented
// like the panel. Panels with fewer than 3 vertices give none.
PanelTriangles triangulate_panels(const PanelMesh& panels);

// The comment block of a panels OBJ: tool and version, input, panel counts, seed; nothing that
// varies between identical runs, so identical runs give identical bytes.
std::string panels_obj_comment(const std::string& input_name, int panels, int requested_panels, int vertices,
                               std::uint64_t seed, int invalid_panels);

// The panels OBJ (DESIGN.md 4): comment lines, used vertices at %.17g, one face per panel.
std::string panels_obj(const PanelMesh& panels, const std::string& comment);

}  // namespace ff
