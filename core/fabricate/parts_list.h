#pragma once
// The parts list. The basic one (panel_parts / the one-argument parts_list_csv): one row per
// panel with what a fabricator needs first (sides, size, plane), in mesh units; the page and
// the wasm module use it as it is. The fabrication one (make_parts_list): the same first
// columns with the same meaning, in the designer's units, plus thickness, per-edge lengths,
// chamfers and neighbours, corner angles and the outer and inner outlines laid flat.
#include <string>
#include <utility>
#include <vector>

#include "core/fabricate/chamfers.h"
#include "core/fabricate/panel_outline.h"
#include "core/fabricate/thick_panels.h"
#include "core/fabricate/units.h"
#include "core/panels/panel_mesh.h"

namespace ff {

struct PanelPart {
  int panel = 0;
  std::string label;  // "P1", "P2", ... (1-based, as people count)
  int sides = 0;
  double area = 0.0;       // in the mesh's units squared (the designer's in a PartsList)
  double perimeter = 0.0;  // in the mesh's units (the designer's in a PartsList)
  Vec3 normal = Vec3::Zero();
  double offset = 0.0;  // plane: normal . x = offset
};

std::vector<PanelPart> panel_parts(const PanelMesh& panels);

// CSV with a header row: panel,label,sides,area,perimeter,normal_x,normal_y,normal_z,offset;
// numbers at full precision; a last row labelled "total" sums area and perimeter.
std::string parts_list_csv(const PanelMesh& panels);

struct FabricationOptions {
  LengthUnit mesh_units = LengthUnit::Metre;  // what one mesh coordinate unit is
  LengthUnit units = LengthUnit::Metre;       // what the parts list is written in
  double thickness = 0.0;                     // in `units`; 0: no inner faces
  MaterialSide side = MaterialSide::Inside;
  // Panels thicker or thinner than `thickness` (which must then be > 0), by label, in
  // `units`: "P3" also covers the glass pieces "P3a", "P3b", ...; an exact label wins.
  std::vector<std::pair<std::string, double>> panel_thickness;
  BoundaryCut boundary;  // how boundary edges are cut (chamfers.h); `up` in mesh coordinates
};

struct PartRow {
  PanelPart part;                         // lengths in the designer's units
  PanelOutline outline;                   // outer (and inner) faces in the panel's own frame, designer's units
  std::vector<EdgeChamfer> chamfers;      // per edge, as outline.edges
  std::vector<double> corner_angles_deg;  // interior angle at each corner of the outer face
};

// A node whose panels' inner vertices do not meet in one point (thick_panels.h).
struct NodeSpread {
  int vertex = 0;                   // in the panel mesh
  Vec3 position = Vec3::Zero();     // the node on the outer surface, designer's units
  double spread = 0.0;              // designer's units
  std::vector<std::string> panels;  // labels of the panels meeting there
};

struct PartsList {
  FabricationOptions options;
  std::vector<PartRow> rows;
  double total_area = 0.0, total_perimeter = 0.0;  // designer's units
  // With thickness: the largest node spread (thick_panels.h), in the designer's units,
  // and the corners that needed a fallback.
  double max_node_spread = 0.0;
  int straight_corners = 0, projected_corners = 0;
  std::vector<NodeSpread> spread_nodes;  // spread above 1e-9 of the thickness, by vertex
  // With thickness: labels of the panels whose inner face folds over (clockwise, of no area,
  // or crossing itself): the thickness is too large for the panel's size and chamfers, and the
  // part cannot be made as drawn. Empty when every inner face is a proper polygon.
  std::vector<std::string> folded_inner_faces;
  std::vector<std::string> unmatched_labels;  // panel_thickness labels no panel has
};

// Throws InputError for a negative or non-finite thickness, a panel thickness not above 0, or
// panel thicknesses without a thickness.
PartsList make_parts_list(const PanelMesh& panels, const FabricationOptions& options);

// CSV: header row; the nine basic columns (lengths in the designer's units, `area` in them
// squared), then units, thickness, edge_lengths, edge_chamfers_deg, edge_neighbours,
// edge_dihedrals_deg, corner_angles_deg, outer_2d, inner_2d. Per-edge and per-corner data
// are ';'-separated lists; a 2D point is "x y"; a boundary edge's neighbour is "-". A last
// row labelled "total" holds the number of panels in `panel` and sums area and perimeter.
std::string parts_list_csv(const PartsList& list);
// JSON: {"units", "mesh_units", "thickness", "side", "totals": {"panels", "area",
// "perimeter"}, "max_node_spread", "straight_corners", "projected_corners", "panels": [...],
// "spread_nodes": [{"vertex", "position", "spread", "panels"}]}.
std::string parts_list_json(const PartsList& list);

// What the cut sheets draw: the rows' outlines, in order.
std::vector<PanelOutline> panel_outlines(const PartsList& list);

}  // namespace ff
