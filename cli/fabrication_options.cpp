#include "cli/fabrication_options.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <utility>

#include "core/fabricate/number_text.h"
#include "core/fabricate/solid_panels.h"
#include "core/fabricate/units.h"
#include "core/util/error.h"

namespace ff::cli {

namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  if (s.size() < tail.size()) return false;
  std::string end = s.substr(s.size() - tail.size());
  for (char& c : end) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return end == tail;
}

LengthUnit unit_option(const Args& args, const std::string& name, LengthUnit fallback) {
  if (!args.has(name)) return fallback;
  try {
    return parse_length_unit(args.get(name), "--" + name);
  } catch (const InputError& e) {
    throw UsageError(e.what());
  }
}

std::string file_option(const Args& args, const std::string& name) {
  const std::string path = args.get(name);
  if (args.has(name) && path.empty()) throw UsageError("--" + name + ": empty file name");
  return path;
}

// --panel-thickness P3=0.05,P7=0.03 (labels as the parts list writes them).
std::vector<std::pair<std::string, double>> panel_thickness_option(const std::string& text) {
  std::vector<std::pair<std::string, double>> out;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t comma = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, comma - start);
    const size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0 || item[0] != 'P')
      throw UsageError("--panel-thickness: expected LABEL=T,... (e.g. P3=0.05,P7=0.03), got '" + item + "'");
    const double t = parse_double(item.substr(eq + 1), "--panel-thickness " + item.substr(0, eq));
    if (!(t > 0.0)) throw UsageError("--panel-thickness: expected a positive thickness for " + item.substr(0, eq));
    for (const auto& [label, given] : out)
      if (label == item.substr(0, eq))
        throw UsageError("--panel-thickness: " + label + " is given twice (" + number_text(given, 6) + " and " +
                         number_text(t, 6) + ")");
    out.emplace_back(item.substr(0, eq), t);
    start = comma + 1;
  }
  return out;
}

// --boundary-cut square | plumb | DEG (a bevel from square, -60..60).
BoundaryCut boundary_option(const Args& args) {
  BoundaryCut cut;
  const std::string text = args.get("boundary-cut", "square");
  if (text == "plumb") {
    cut.kind = BoundaryCut::Kind::Plumb;
  } else if (text != "square") {
    cut.kind = BoundaryCut::Kind::Bevel;
    cut.bevel_deg = parse_double(text, "--boundary-cut");
    if (!(std::abs(cut.bevel_deg) <= 60.0))
      throw UsageError("--boundary-cut: expected square, plumb or degrees from -60 to 60, got '" + text + "'");
  }
  const std::string up = args.get("up", "z");
  if (up != "x" && up != "y" && up != "z") throw UsageError("--up: expected x, y or z, got '" + up + "'");
  cut.up = up == "x" ? Vec3::UnitX() : up == "y" ? Vec3::UnitY() : Vec3::UnitZ();
  if (args.has("up") && cut.kind != BoundaryCut::Kind::Plumb) throw UsageError("--up needs --boundary-cut plumb");
  return cut;
}

}  // namespace

const std::set<std::string>& fabrication_option_names() {
  static const std::set<std::string> names = {"thickness", "side",       "units",           "mesh-units",
                                              "parts",     "sheets",     "sheet-size",      "solid",
                                              "up",        "boundary-cut", "panel-thickness"};
  return names;
}

FabricationRequest parse_fabrication(const Args& args) {
  FabricationRequest r;
  FabricationOptions& o = r.options;
  // The mesh is in metres unless said otherwise; the output in the mesh's units unless said
  // otherwise, so a plain --parts keeps the numbers of the mesh file.
  o.mesh_units = unit_option(args, "mesh-units", LengthUnit::Metre);
  o.units = unit_option(args, "units", o.mesh_units);
  if (args.has("thickness")) {
    o.thickness = parse_double(args.get("thickness"), "--thickness");
    if (!(o.thickness > 0.0))
      throw UsageError("--thickness: expected a positive thickness, got '" + args.get("thickness") + "'");
  }
  const std::string side = args.get("side", "inside");
  if (side == "outside")
    o.side = MaterialSide::Outside;
  else if (side != "inside")
    throw UsageError("--side: expected inside or outside, got '" + side + "'");
  r.parts = file_option(args, "parts");
  r.sheets = file_option(args, "sheets");
  r.solid = file_option(args, "solid");
  if (!r.sheets.empty() && !ends_with(r.sheets, ".svg") && !ends_with(r.sheets, ".dxf"))
    throw UsageError("--sheets: expected a .svg or .dxf file name, got '" + r.sheets + "'");
  if (!r.solid.empty() && o.thickness <= 0.0) throw UsageError("--solid needs --thickness");
  if (args.has("thickness") && !r.any())
    throw UsageError("--thickness: nothing to use it for (add --parts, --sheets or --solid)");
  for (const char* name : {"side", "units", "mesh-units"})
    if (args.has(name) && !r.any())
      throw UsageError(std::string("--") + name + ": nothing to use it for (add --parts, --sheets or --solid)");
  if (args.has("sheet-size") && r.sheets.empty()) throw UsageError("--sheet-size needs --sheets");
  if (args.has("panel-thickness")) {
    if (o.thickness <= 0.0) throw UsageError("--panel-thickness needs --thickness (for the other panels)");
    o.panel_thickness = panel_thickness_option(args.get("panel-thickness"));
  }
  o.boundary = boundary_option(args);
  if (args.has("boundary-cut") && !r.any())
    throw UsageError("--boundary-cut: nothing to use it for (add --parts, --sheets or --solid)");

  // Sheet defaults: a 2440 x 1220 mm board, 10 mm margin, 5 mm between parts, in the
  // designer's units.
  const double mm = unit_scale(LengthUnit::Millimetre, o.units);
  r.sheet.width = 2440.0 * mm;
  r.sheet.height = 1220.0 * mm;
  r.sheet.margin = 10.0 * mm;
  r.sheet.spacing = 5.0 * mm;
  r.sheet.units = unit_name(o.units);
  if (args.has("sheet-size")) {
    const std::string text = args.get("sheet-size");
    const size_t comma = text.find(',');
    if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos)
      throw UsageError("--sheet-size: expected W,H (in the --units), got '" + text + "'");
    r.sheet.width = parse_double(text.substr(0, comma), "--sheet-size W");
    r.sheet.height = parse_double(text.substr(comma + 1), "--sheet-size H");
    if (!(r.sheet.width > 0.0) || !(r.sheet.height > 0.0))
      throw UsageError("--sheet-size: expected two positive numbers, got '" + text + "'");
  }
  return r;
}

std::vector<OutputFile> fabrication_outputs(const FabricationRequest& r, const PanelMesh& panels,
                                            std::vector<std::string>* folded) {
  std::vector<OutputFile> files;
  if (!r.any()) return files;
  const PartsList list = make_parts_list(panels, r.options);
  if (!list.unmatched_labels.empty())
    throw InputError("--panel-thickness: no panel labelled " + list.unmatched_labels.front());
  if (folded) *folded = list.folded_inner_faces;
  if (!r.parts.empty())
    files.push_back({r.parts, ends_with(r.parts, ".json") ? parts_list_json(list) : parts_list_csv(list)});
  if (!r.sheets.empty()) {
    const std::vector<PanelOutline> outlines = panel_outlines(list);
    const SheetLayout layout = pack_outlines(outlines, r.sheet);
    files.push_back({r.sheets, ends_with(r.sheets, ".dxf") ? cut_sheets_dxf(outlines, layout, r.sheet)
                                                           : cut_sheets_svg(outlines, layout, r.sheet)});
  }
  if (!r.solid.empty()) {
    // Thicknesses in mesh units; the file in the designer's units like the other outputs.
    const double scale = unit_scale(r.options.units, r.options.mesh_units);
    ThickOptions thick;
    thick.thickness = r.options.thickness * scale;
    thick.side = r.options.side;
    thick.boundary = r.options.boundary;
    if (!r.options.panel_thickness.empty())
      for (const PartRow& row : list.rows) thick.panel_thickness.push_back(row.outline.thickness * scale);
    files.push_back({r.solid, solid_panels_obj(panels, thick, unit_scale(r.options.mesh_units, r.options.units),
                                               unit_name(r.options.units))});
  }
  return files;
}

}  // namespace ff::cli
