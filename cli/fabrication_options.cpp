#include "cli/fabrication_options.h"

#include <cctype>
#include <cmath>

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

}  // namespace

const std::set<std::string>& fabrication_option_names() {
  static const std::set<std::string> names = {"thickness", "side",   "units",      "mesh-units",
                                              "parts",     "sheets", "sheet-size", "solid"};
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

std::vector<OutputFile> fabrication_outputs(const FabricationRequest& r, const PanelMesh& panels) {
  std::vector<OutputFile> files;
  if (!r.any()) return files;
  const PartsList list = make_parts_list(panels, r.options);
  if (!r.parts.empty())
    files.push_back({r.parts, ends_with(r.parts, ".json") ? parts_list_json(list) : parts_list_csv(list)});
  if (!r.sheets.empty()) {
    const std::vector<PanelOutline> outlines = panel_outlines(list);
    const SheetLayout layout = pack_outlines(outlines, r.sheet);
    files.push_back({r.sheets, ends_with(r.sheets, ".dxf") ? cut_sheets_dxf(outlines, layout, r.sheet)
                                                           : cut_sheets_svg(outlines, layout, r.sheet)});
  }
  if (!r.solid.empty()) {
    const double scale = unit_scale(r.options.units, r.options.mesh_units);  // thickness -> mesh units
    files.push_back({r.solid, solid_panels_obj(panels, r.options.thickness * scale, r.options.side)});
  }
  return files;
}

}  // namespace ff::cli
