#include "core/fabricate/fabrication_params_json.h"

#include <cmath>
#include <string>

#include "core/fabricate/units.h"
#include "core/util/error.h"
#include "core/util/json_reader.h"

namespace ff {

namespace {

constexpr double kMaxLength = 1e9;  // in any unit: far beyond any sheet or panel

double length(const JsonValue& v, const std::string& name, bool zero_ok) {
  if (v.type != JsonValue::Type::Number) throw InputError("fabrication '" + name + "' must be a number");
  const double x = v.number;
  if (!std::isfinite(x) || x < 0.0 || (!zero_ok && x == 0.0) || x > kMaxLength)
    throw InputError("fabrication '" + name + "' must be " + (zero_ok ? "at least 0" : "above 0") + " and at most 1e9");
  return x;
}

std::string text(const JsonValue& v, const std::string& name) {
  if (v.type != JsonValue::Type::String) throw InputError("fabrication '" + name + "' must be a string");
  return v.string;
}

LengthUnit unit(const JsonValue& v, const std::string& name) {
  const std::string s = text(v, name);
  if (s != "mm" && s != "cm" && s != "m" && s != "in" && s != "ft")
    throw InputError("fabrication '" + name + "' must be one of mm, cm, m, in, ft");
  return parse_length_unit(s, name);
}

// {"P3": 0.05, ...}: labels as the parts list writes them (P<n>, glass pieces P<n><letters>).
void read_panel_thickness(const JsonValue& v, FabricationOptions& o) {
  if (v.type != JsonValue::Type::Object) throw InputError("fabrication 'panelThickness' must be an object");
  if (v.object.size() > 100000) throw InputError("fabrication 'panelThickness': at most 100000 panels");
  for (const auto& [label, value] : v.object) {
    bool ok = label.size() >= 2 && label.size() <= 20 && label[0] == 'P' && label[1] >= '1' && label[1] <= '9';
    size_t i = 1;
    while (ok && i < label.size() && label[i] >= '0' && label[i] <= '9') ++i;
    for (; ok && i < label.size(); ++i) ok = label[i] >= 'a' && label[i] <= 'z';
    if (!ok) throw InputError("fabrication 'panelThickness': '" + label.substr(0, 20) + "' is not a panel label (P1, P2, P3a, ...)");
    o.panel_thickness.emplace_back(label, length(value, "panelThickness." + label, false));
  }
}

Vec3 axis(const JsonValue& v) {
  const std::string s = text(v, "upAxis");
  if (s != "x" && s != "y" && s != "z") throw InputError("fabrication 'upAxis' must be \"x\", \"y\" or \"z\"");
  return s == "x" ? Vec3::UnitX() : s == "y" ? Vec3::UnitY() : Vec3::UnitZ();
}

}  // namespace

FabricationSettings fabrication_settings_from_json(std::string_view json) {
  const JsonValue root = parse_json(json, 4, 64 * 1024);
  if (root.type != JsonValue::Type::Object) throw InputError("fabrication settings must be a JSON object");
  const JsonValue* units = nullptr;
  const JsonValue* mesh_units = nullptr;
  const JsonValue* thickness = nullptr;
  const JsonValue* side = nullptr;
  const JsonValue* width = nullptr;
  const JsonValue* height = nullptr;
  const JsonValue* panel_thickness = nullptr;
  const JsonValue* boundary = nullptr;
  const JsonValue* bevel = nullptr;
  const JsonValue* up = nullptr;
  for (const auto& [name, value] : root.object) {
    if (name == "units")
      units = &value;
    else if (name == "meshUnits")
      mesh_units = &value;
    else if (name == "thickness")
      thickness = &value;
    else if (name == "side")
      side = &value;
    else if (name == "sheetWidth")
      width = &value;
    else if (name == "sheetHeight")
      height = &value;
    else if (name == "panelThickness")
      panel_thickness = &value;
    else if (name == "boundaryCut")
      boundary = &value;
    else if (name == "boundaryBevelDeg")
      bevel = &value;
    else if (name == "upAxis")
      up = &value;
    else
      throw InputError("unknown fabrication setting '" + name + "'");
  }
  FabricationSettings s;
  FabricationOptions& o = s.options;
  o.mesh_units = mesh_units ? unit(*mesh_units, "meshUnits") : LengthUnit::Metre;
  o.units = units ? unit(*units, "units") : o.mesh_units;
  if (thickness) o.thickness = length(*thickness, "thickness", true);
  if (side) {
    const std::string v = text(*side, "side");
    if (v != "inside" && v != "outside") throw InputError("fabrication 'side' must be \"inside\" or \"outside\"");
    o.side = v == "outside" ? MaterialSide::Outside : MaterialSide::Inside;
  }
  if (panel_thickness) read_panel_thickness(*panel_thickness, o);
  if (boundary) {
    const std::string v = text(*boundary, "boundaryCut");
    if (v != "square" && v != "plumb" && v != "bevel")
      throw InputError("fabrication 'boundaryCut' must be \"square\", \"plumb\" or \"bevel\"");
    o.boundary.kind = v == "plumb"   ? BoundaryCut::Kind::Plumb
                      : v == "bevel" ? BoundaryCut::Kind::Bevel
                                     : BoundaryCut::Kind::Square;
  }
  if (bevel) {
    if (bevel->type != JsonValue::Type::Number || !(std::abs(bevel->number) <= 60.0))
      throw InputError("fabrication 'boundaryBevelDeg' must be a number from -60 to 60");
    o.boundary.bevel_deg = bevel->number;
  }
  if (up) o.boundary.up = axis(*up);
  const double mm = unit_scale(LengthUnit::Millimetre, o.units);
  s.sheet.width = width ? length(*width, "sheetWidth", false) : 2440.0 * mm;
  s.sheet.height = height ? length(*height, "sheetHeight", false) : 1220.0 * mm;
  s.sheet.margin = 10.0 * mm;
  s.sheet.spacing = 5.0 * mm;
  s.sheet.units = unit_name(o.units);
  return s;
}

}  // namespace ff
