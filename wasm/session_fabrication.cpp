// The Session's fabrication outputs (session.h): the parts list, cut sheets, solid panels and
// the thick-panel view, all from the current panels and the fabrication settings.
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "core/fabricate/cut_sheets.h"
#include "core/fabricate/panel_edges.h"
#include "core/fabricate/parts_list.h"
#include "core/fabricate/solid_panels.h"
#include "core/fabricate/thick_panels.h"
#include "core/fabricate/units.h"
#include "core/util/error.h"
#include "core/util/json_writer.h"
#include "wasm/guarded.h"
#include "wasm/session.h"

namespace ff::wasm {

namespace {

// The thickness in mesh units (the settings hold it in the designer's units).
double mesh_thickness(const FabricationSettings& f) {
  return f.options.thickness * unit_scale(f.options.units, f.options.mesh_units);
}

bool same_outlines(const std::vector<PanelOutline>& a, const std::vector<PanelOutline>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    const PanelOutline &x = a[i], &y = b[i];
    if (x.panel != y.panel || x.label != y.label || x.outer != y.outer || x.inner != y.inner ||
        x.thickness != y.thickness || x.edges.size() != y.edges.size())
      return false;
    for (size_t k = 0; k < x.edges.size(); ++k)
      if (x.edges[k].length != y.edges[k].length || x.edges[k].chamfer_deg != y.edges[k].chamfer_deg ||
          x.edges[k].neighbour != y.edges[k].neighbour)
        return false;
  }
  return true;
}

bool same_sheet(const SheetOptions& a, const SheetOptions& b) {
  return a.width == b.width && a.height == b.height && a.margin == b.margin && a.spacing == b.spacing &&
         a.units == b.units;
}

// The thick-panel options in mesh units, per-panel thicknesses resolved as the parts list does.
ThickOptions thick_options(const PanelMesh& pm, const FabricationSettings& f) {
  const double scale = unit_scale(f.options.units, f.options.mesh_units);
  ThickOptions o;
  o.thickness = mesh_thickness(f);
  o.side = f.options.side;
  o.boundary = f.options.boundary;
  if (!f.options.panel_thickness.empty())
    for (const PartRow& row : make_parts_list(pm, f.options).rows)
      o.panel_thickness.push_back(row.outline.thickness * scale);
  return o;
}

}  // namespace

// Packing is the slow part: reuse the last layout when outlines and sheet are the same.
const SheetLayout& Session::sheet_layout(const std::vector<PanelOutline>& outlines) const {
  SheetCache& c = sheet_cache_;
  if (!c.valid || !same_sheet(c.sheet, fabrication_.sheet) || !same_outlines(c.outlines, outlines)) {
    c.valid = false;
    c.layout = pack_outlines(outlines, fabrication_.sheet);  // may throw: the cache stays invalid
    c.outlines = outlines;
    c.sheet = fabrication_.sheet;
    c.valid = true;
  }
  return c.layout;
}

std::string Session::set_fabrication(const std::string& json) {
  return guarded([&] {
    fabrication_ = fabrication_settings_from_json(json);
    return status_json(true, "");
  });
}

void Session::keep_panels() {
  PanelMesh kept = remesher_ ? remesher_->panels() : PanelMesh{};  // a failed copy keeps the old
  kept_panels_ = std::move(kept);
}

std::string Session::parts_csv() const {
  return guarded([&] { return parts_list_csv(make_parts_list(kept_panels_, fabrication_.options)); });
}

std::string Session::parts_json() const {
  return guarded([&] { return parts_list_json(make_parts_list(kept_panels_, fabrication_.options)); });
}

std::string Session::sheets_svg() const {
  return guarded([&] {
    const std::vector<PanelOutline> outlines = panel_outlines(make_parts_list(kept_panels_, fabrication_.options));
    return cut_sheets_svg(outlines, sheet_layout(outlines), fabrication_.sheet);
  });
}

std::string Session::sheets_dxf() const {
  return guarded([&] {
    const std::vector<PanelOutline> outlines = panel_outlines(make_parts_list(kept_panels_, fabrication_.options));
    return cut_sheets_dxf(outlines, sheet_layout(outlines), fabrication_.sheet);
  });
}

std::string Session::sheet_stats() const {
  return guarded([&] {
    const std::vector<PanelOutline> outlines = panel_outlines(make_parts_list(kept_panels_, fabrication_.options));
    const SheetLayout& layout = sheet_layout(outlines);
    JsonWriter j;
    j.begin_object().value("ok", true).value("message", "");
    j.value("sheets", layout.sheets).value("materialUse", layout.material_use).end_object();
    return j.str();
  });
}

std::string Session::solid_obj() const {
  return guarded([&] {
    if (!(fabrication_.options.thickness > 0.0))
      throw InputError("solid panels need a thickness: set one under Fabrication");
    if (kept_panels_.num_panels() == 0) throw InputError("solid panels need panels: remesh first");
    // In mesh coordinates, to overlay the panels in the page and in the panels OBJ.
    return solid_panels_obj(kept_panels_, thick_options(kept_panels_, fabrication_), 1.0, "");
  });
}

std::vector<double> Session::inner_positions() const {
  std::vector<double> out;
  const PanelMesh& pm = kept_panels_;
  if (pm.num_panels() == 0 || !(fabrication_.options.thickness > 0.0)) return out;
  const ThickPanels thick = thicken_panels(pm, panel_edges(pm), thick_options(pm, fabrication_));
  for (const std::vector<Vec3>& panel : thick.inner)
    for (const Vec3& p : panel)
      for (int k = 0; k < 3; ++k) out.push_back(p[k]);
  return out;
}

std::string Session::spread_nodes() const {
  return guarded([&] {
    const PanelMesh& pm = kept_panels_;
    const PartsList list = make_parts_list(pm, fabrication_.options);
    JsonWriter j;
    j.begin_object().value("ok", true).value("message", "");
    j.value("units", unit_name(fabrication_.options.units)).value("thickness", fabrication_.options.thickness);
    j.value("maxSpread", list.max_node_spread);
    j.begin_array("nodes");
    for (const NodeSpread& n : list.spread_nodes) {
      j.begin_object(nullptr).value("vertex", n.vertex);
      j.begin_array("position");
      for (int k = 0; k < 3; ++k) j.value(nullptr, pm.vertices[static_cast<size_t>(n.vertex)][k]);
      j.end_array();
      j.value("spread", n.spread);
      j.begin_array("panels");
      for (const std::string& label : n.panels) j.value(nullptr, label);
      j.end_array().end_object();
    }
    j.end_array();
    j.begin_array("folded");
    for (const std::string& label : list.folded_inner_faces) j.value(nullptr, label);
    j.end_array();
    // The same parts by panel index, for the view to outline them.
    j.begin_array("foldedPanels");
    for (const PartRow& row : list.rows)
      if (std::find(list.folded_inner_faces.begin(), list.folded_inner_faces.end(), row.part.label) !=
          list.folded_inner_faces.end())
        j.value(nullptr, row.part.panel);
    j.end_array().end_object();
    return j.str();
  });
}

}  // namespace ff::wasm
