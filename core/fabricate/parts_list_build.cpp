// make_parts_list: the fabrication data per panel, laid out in each panel's own frame.
#include <cmath>
#include <string>

#include "core/fabricate/parts_list.h"
#include "core/fabricate/units.h"
#include "core/panels/polygon2d.h"
#include "core/util/angles.h"
#include "core/util/error.h"

namespace ff {

namespace {

// Interior angle at each corner of a counter-clockwise polygon, in (0, 360).
std::vector<double> corner_angles(const std::vector<Vec2>& poly) {
  std::vector<double> angles;
  const size_t k = poly.size();
  for (size_t i = 0; i < k; ++i) {
    const Vec2 in = poly[i] - poly[(i + k - 1) % k], out = poly[(i + 1) % k] - poly[i];
    // The turn from the incoming to the outgoing edge; a left turn makes a convex corner.
    const double turn = std::atan2(in.x() * out.y() - in.y() * out.x(), in.dot(out)) * kDegreesPerRadian;
    angles.push_back(180.0 - turn);
  }
  return angles;
}

// Whether the inner face, drawn one corner per outer corner, cannot be cut as drawn: offset by
// more than the panel can take, its edges pass each other. Then it turns clockwise or crosses
// itself (bunny.off at 58 panels, 2 cm thick: 36 of 58), or, on a thin panel, an inner edge
// runs against its outer edge while the face stays simple and counter-clockwise: a sliver
// triangle's inner face is itself turned half round (YasIsland.off at 120 panels in glass,
// 1 cm: the inner face of P74a 2.6 times its outer one), and one short edge of a larger panel
// can flip alone (hyperboloid_s4.off at 150 panels, 1 m outside: an inner corner 3 cm off).
// A reversed edge up to `tolerance` long is a crossing of that size at one corner, within what
// a cut is made to (a 0.26 mm edge of the helicoid at 40 panels, 20 mm thick: 0.5 mm).
bool inner_face_folds(const std::vector<Vec2>& outer, const std::vector<Vec2>& inner, double tolerance) {
  if (!(signed_area(inner) > 0.0) || !is_simple(inner, 0.0)) return true;
  const size_t k = outer.size();
  for (size_t i = 0; i < k; ++i) {
    const Vec2 along = inner[(i + 1) % k] - inner[i];
    if (!(along.dot(outer[(i + 1) % k] - outer[i]) > 0.0) && !(along.norm() <= tolerance)) return true;
  }
  return false;
}

// The crossing a reversed inner edge may have (inner_face_folds): 1 mm, a cutting tolerance.
constexpr double kFoldToleranceMm = 1.0;

bool is_piece_of(const std::string& label, const std::string& base) {
  if (label.size() <= base.size() || label.compare(0, base.size(), base) != 0) return false;
  for (size_t i = base.size(); i < label.size(); ++i)
    if (label[i] < 'a' || label[i] > 'z') return false;
  return true;
}

// Per panel thickness in the designer's units: the overrides by label (exact labels after
// base labels, so "P3a" wins over "P3"), else the default.
std::vector<double> resolve_thickness(const std::vector<PanelPart>& parts, const FabricationOptions& o,
                                      std::vector<std::string>& unmatched) {
  std::vector<double> t(parts.size(), o.thickness);
  for (const bool exact : {false, true})
    for (const auto& [label, value] : o.panel_thickness) {
      bool matched = false;
      for (size_t p = 0; p < parts.size(); ++p)
        if (exact ? parts[p].label == label : is_piece_of(parts[p].label, label)) {
          t[p] = value;
          matched = true;
        }
      if (exact && !matched) {
        bool piece = false;
        for (const PanelPart& part : parts) piece = piece || is_piece_of(part.label, label);
        if (!piece) unmatched.push_back(label);
      }
    }
  return t;
}

}  // namespace

PartsList make_parts_list(const PanelMesh& pm, const FabricationOptions& options) {
  if (!(options.thickness >= 0.0) || !std::isfinite(options.thickness))
    throw InputError("thickness: expected a positive number, got " + std::to_string(options.thickness));
  for (const auto& [label, value] : options.panel_thickness) {
    if (!(value > 0.0) || !std::isfinite(value))
      throw InputError("panel thickness of " + label + ": expected a positive number, got " + std::to_string(value));
    if (!(options.thickness > 0.0))
      throw InputError("panel thickness of " + label + ": set a thickness for the other panels too");
  }
  PartsList list;
  list.options = options;
  const double scale = unit_scale(options.mesh_units, options.units);  // mesh -> designer
  const PanelEdges edges = panel_edges(pm);
  const std::vector<PanelPart> basic = panel_parts(pm);
  const std::vector<double> thickness = resolve_thickness(basic, options, list.unmatched_labels);
  // Uniform thickness and square boundary cuts: the plain chamfers, bit for bit.
  const bool plain = options.panel_thickness.empty() && options.boundary.kind == BoundaryCut::Kind::Square;
  const std::vector<std::vector<EdgeChamfer>> chamfers =
      plain ? edge_chamfers(pm, edges) : edge_chamfers(pm, edges, thickness, options.boundary, options.side);
  ThickPanels thick;
  const bool has_thickness = options.thickness > 0.0;
  if (has_thickness) {
    ThickOptions to;
    to.thickness = options.thickness / scale;
    to.side = options.side;
    to.boundary = options.boundary;
    if (!options.panel_thickness.empty())
      for (const double t : thickness) to.panel_thickness.push_back(t / scale);
    thick = thicken_panels(pm, edges, to);
    list.max_node_spread = thick.max_spread * scale;
    list.straight_corners = thick.straight_corners;
    list.projected_corners = thick.projected_corners;
  }
  if (has_thickness) {
    for (size_t v = 0; v < pm.vertices.size(); ++v) {
      if (!(thick.node_spread[v] > 1e-9 * thick.thickness)) continue;
      NodeSpread node;
      node.vertex = static_cast<int>(v);
      node.position = pm.vertices[v] * scale;
      node.spread = thick.node_spread[v] * scale;
      for (const int p : edges.vertex_panels[v]) node.panels.push_back(basic[static_cast<size_t>(p)].label);
      list.spread_nodes.push_back(node);
    }
  }
  for (size_t p = 0; p < pm.panels.size(); ++p) {
    PartRow row;
    row.part = basic[p];
    row.part.area *= scale * scale;
    row.part.perimeter *= scale;
    row.part.offset *= scale;
    row.chamfers = chamfers[p];
    PanelOutline& o = row.outline;
    o.panel = row.part.panel;
    o.label = row.part.label;
    o.thickness = has_thickness ? thickness[p] : 0.0;
    const std::vector<int>& poly = pm.panels[p];
    // The frame sits at the first corner, its normal the panel's: counter-clockwise panels
    // stay counter-clockwise in 2D (PlaneFrame is right-handed).
    const PlaneFrame frame = make_plane_frame(pm.vertices[static_cast<size_t>(poly[0])], pm.plane_normals[p]);
    for (const int v : poly) o.outer.push_back(frame.to_2d(pm.vertices[static_cast<size_t>(v)]) * scale);
    // The inner face is parallel to the outer one: seen through the panel, it is its
    // projection onto the panel's plane.
    if (has_thickness) {
      for (const Vec3& x : thick.inner[p]) o.inner.push_back(frame.to_2d(x) * scale);
      const double tolerance = kFoldToleranceMm * unit_scale(LengthUnit::Millimetre, options.units);
      if (inner_face_folds(o.outer, o.inner, tolerance)) list.folded_inner_faces.push_back(o.label);
    }
    for (size_t i = 0; i < poly.size(); ++i) {
      OutlineEdge e;
      e.length = (o.outer[(i + 1) % poly.size()] - o.outer[i]).norm();
      e.chamfer_deg = row.chamfers[i].chamfer_deg;
      if (row.chamfers[i].neighbour >= 0) e.neighbour = basic[static_cast<size_t>(row.chamfers[i].neighbour)].label;
      o.edges.push_back(e);
    }
    row.corner_angles_deg = corner_angles(o.outer);
    list.total_area += row.part.area;
    list.total_perimeter += row.part.perimeter;
    list.rows.push_back(std::move(row));
  }
  return list;
}

std::vector<PanelOutline> panel_outlines(const PartsList& list) {
  std::vector<PanelOutline> outlines;
  for (const PartRow& row : list.rows) outlines.push_back(row.outline);
  return outlines;
}

}  // namespace ff
