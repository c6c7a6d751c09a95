#include "core/fabricate/parts_list.h"

#include "core/fabricate/number_text.h"
#include "core/panels/polygon2d.h"

namespace ff {

namespace {

std::string exact_number(double v) { return number_text(v, 17); }

// "P12" for a whole panel; glass pieces of panel 12 are "P12a", "P12b", ... (they are
// consecutive), numbered after the panel they were cut from, so the labels match the design.
std::vector<std::string> panel_labels(const PanelMesh& pm) {
  const size_t n = pm.panels.size();
  std::vector<std::string> labels(n);
  if (pm.panel_source.size() != n) {
    for (size_t p = 0; p < n; ++p) labels[p] = "P" + std::to_string(p + 1);
    return labels;
  }
  for (size_t p = 0; p < n;) {
    size_t end = p + 1;
    while (end < n && pm.panel_source[end] == pm.panel_source[p]) ++end;
    const std::string base = "P" + std::to_string(pm.panel_source[p] + 1);
    for (size_t k = p; k < end; ++k) {
      const size_t i = k - p;  // a..z, then za, zb, ... (a panel rarely has many pieces)
      labels[k] = end - p == 1 ? base : base + std::string(i / 26, 'z') + static_cast<char>('a' + i % 26);
    }
    p = end;
  }
  return labels;
}

}  // namespace

std::vector<PanelPart> panel_parts(const PanelMesh& pm) {
  std::vector<PanelPart> parts;
  const std::vector<std::string> labels = panel_labels(pm);
  for (size_t p = 0; p < pm.panels.size(); ++p) {
    const std::vector<int>& panel = pm.panels[p];
    PanelPart part;
    part.panel = static_cast<int>(p);
    part.label = labels[p];
    part.sides = static_cast<int>(panel.size());
    std::vector<Vec3> points;
    for (const int v : panel) points.push_back(pm.vertices[static_cast<size_t>(v)]);
    for (size_t i = 0; i < points.size(); ++i) part.perimeter += (points[(i + 1) % points.size()] - points[i]).norm();
    // Newell's normal of a planar polygon is twice its area along the unit normal.
    part.area = 0.5 * newell_normal(points).norm();
    if (p < pm.plane_normals.size()) part.normal = pm.plane_normals[p];
    if (p < pm.plane_offsets.size()) part.offset = pm.plane_offsets[p];
    parts.push_back(part);
  }
  return parts;
}

std::string parts_list_csv(const PanelMesh& panels) {
  std::string csv = "panel,label,sides,area,perimeter,normal_x,normal_y,normal_z,offset\n";
  double area = 0.0, perimeter = 0.0;
  for (const PanelPart& part : panel_parts(panels)) {
    csv += std::to_string(part.panel) + "," + part.label + "," + std::to_string(part.sides) + "," +
           exact_number(part.area) + "," + exact_number(part.perimeter) + "," + exact_number(part.normal.x()) + "," +
           exact_number(part.normal.y()) + "," + exact_number(part.normal.z()) + "," + exact_number(part.offset) + "\n";
    area += part.area;
    perimeter += part.perimeter;
  }
  csv += ",total,," + exact_number(area) + "," + exact_number(perimeter) + ",,,,\n";
  return csv;
}

}  // namespace ff
