// The fabrication parts list as CSV and JSON.
#include <string>

#include "core/fabricate/number_text.h"
#include "core/fabricate/parts_list.h"

namespace ff {

namespace {

// 12 significant digits: far below any cutting tolerance, and readable in a spreadsheet.
std::string num(double v) { return number_text(v, 12); }

template <typename T, typename F>
std::string joined(const std::vector<T>& items, const char* sep, F format) {
  std::string s;
  for (size_t i = 0; i < items.size(); ++i) s += (i ? sep : "") + format(items[i]);
  return s;
}

std::string point_csv(const Vec2& p) { return num(p.x()) + " " + num(p.y()); }
std::string point_json(const Vec2& p) { return "[" + num(p.x()) + "," + num(p.y()) + "]"; }
std::string quoted(const std::string& s) { return "\"" + s + "\""; }  // labels and units: no escapes needed

const char* side_name(MaterialSide side) { return side == MaterialSide::Inside ? "inside" : "outside"; }

}  // namespace

std::string parts_list_csv(const PartsList& list) {
  std::string csv =
      "panel,label,sides,area,perimeter,normal_x,normal_y,normal_z,offset,units,thickness,edge_lengths,"
      "edge_chamfers_deg,edge_neighbours,edge_dihedrals_deg,corner_angles_deg,outer_2d,inner_2d\n";
  const std::string units = unit_name(list.options.units);
  for (const PartRow& row : list.rows) {
    const PanelPart& p = row.part;
    const PanelOutline& o = row.outline;
    csv += std::to_string(p.panel) + "," + p.label + "," + std::to_string(p.sides) + "," + num(p.area) + "," +
           num(p.perimeter) + "," + num(p.normal.x()) + "," + num(p.normal.y()) + "," + num(p.normal.z()) + "," +
           num(p.offset) + "," + units + "," + num(o.thickness) + ",";
    csv += joined(o.edges, ";", [](const OutlineEdge& e) { return num(e.length); }) + ",";
    csv += joined(o.edges, ";", [](const OutlineEdge& e) { return num(e.chamfer_deg); }) + ",";
    csv += joined(o.edges, ";", [](const OutlineEdge& e) { return e.neighbour.empty() ? "-" : e.neighbour; }) + ",";
    csv += joined(row.chamfers, ";", [](const EdgeChamfer& c) { return num(c.dihedral_deg); }) + ",";
    csv += joined(row.corner_angles_deg, ";", num) + ",";
    csv += joined(o.outer, ";", point_csv) + "," + joined(o.inner, ";", point_csv) + "\n";
  }
  csv += std::to_string(list.rows.size()) + ",total,," + num(list.total_area) + "," + num(list.total_perimeter) +
         ",,,,," + units + "," + num(list.options.thickness) + ",,,,,,,\n";
  return csv;
}

std::string parts_list_json(const PartsList& list) {
  const FabricationOptions& opt = list.options;
  std::string j =
      "{\n  \"units\": " + quoted(unit_name(opt.units)) + ",\n  \"mesh_units\": " + quoted(unit_name(opt.mesh_units)) +
      ",\n  \"thickness\": " + num(opt.thickness) + ",\n  \"side\": " + quoted(side_name(opt.side)) +
      ",\n  \"totals\": {\"panels\": " + std::to_string(list.rows.size()) + ", \"area\": " + num(list.total_area) +
      ", \"perimeter\": " + num(list.total_perimeter) + "},\n  \"max_node_spread\": " + num(list.max_node_spread) +
      ",\n  \"straight_corners\": " + std::to_string(list.straight_corners) +
      ",\n  \"projected_corners\": " + std::to_string(list.projected_corners) +
      ",\n  \"folded_inner_faces\": [" + joined(list.folded_inner_faces, ",", quoted) + "],\n  \"panels\": [";
  for (size_t r = 0; r < list.rows.size(); ++r) {
    const PartRow& row = list.rows[r];
    const PanelPart& p = row.part;
    const PanelOutline& o = row.outline;
    j += std::string(r ? "," : "") + "\n    {\"panel\": " + std::to_string(p.panel) +
         ", \"label\": " + quoted(p.label) + ", \"sides\": " + std::to_string(p.sides) + ", \"area\": " + num(p.area) +
         ", \"perimeter\": " + num(p.perimeter) + ", \"normal\": [" + num(p.normal.x()) + "," + num(p.normal.y()) +
         "," + num(p.normal.z()) + "], \"offset\": " + num(p.offset) + ", \"thickness\": " + num(o.thickness) +
         ",\n     \"edges\": [";
    for (size_t i = 0; i < o.edges.size(); ++i) {
      const OutlineEdge& e = o.edges[i];
      const EdgeChamfer& c = row.chamfers[i];
      j += std::string(i ? ", " : "") + "{\"length\": " + num(e.length) + ", \"chamfer_deg\": " + num(e.chamfer_deg) +
           ", \"dihedral_deg\": " + num(c.dihedral_deg) + ", \"convex\": " + (c.convex ? "true" : "false") +
           ", \"neighbour\": " + (e.neighbour.empty() ? std::string("null") : quoted(e.neighbour)) + "}";
    }
    j += "],\n     \"corner_angles_deg\": [" + joined(row.corner_angles_deg, ",", num) + "],\n     \"outer\": [" +
         joined(o.outer, ",", point_json) + "],\n     \"inner\": [" + joined(o.inner, ",", point_json) + "]}";
  }
  j += "\n  ],\n  \"spread_nodes\": [";
  for (size_t i = 0; i < list.spread_nodes.size(); ++i) {
    const NodeSpread& n = list.spread_nodes[i];
    j += std::string(i ? "," : "") + "\n    {\"vertex\": " + std::to_string(n.vertex) + ", \"position\": [" +
         num(n.position.x()) + "," + num(n.position.y()) + "," + num(n.position.z()) +
         "], \"spread\": " + num(n.spread) + ", \"panels\": [" + joined(n.panels, ",", quoted) + "]}";
  }
  j += std::string(list.spread_nodes.empty() ? "" : "\n  ") + "]\n}\n";
  return j;
}

}  // namespace ff
