#include "core/panels/panel_export.h"

#include "core/mesh/mesh_io.h"
#include "core/panels/polygon2d.h"
#include "core/version.h"

namespace ff {

PolygonMesh used_vertices_only(const PanelMesh& pm) {
  std::vector<int> index(pm.vertices.size(), -1);
  for (const std::vector<int>& panel : pm.panels)
    for (const int v : panel) index[static_cast<size_t>(v)] = 0;
  PolygonMesh out;
  for (size_t v = 0; v < index.size(); ++v) {
    if (index[v] < 0) continue;
    index[v] = static_cast<int>(out.vertices.size());
    out.vertices.push_back(pm.vertices[v]);
  }
  out.faces = pm.panels;
  for (std::vector<int>& face : out.faces)
    for (int& v : face) v = index[static_cast<size_t>(v)];
  return out;
}

PanelTriangles triangulate_panels(const PanelMesh& pm) {
  PanelTriangles out;
  for (size_t p = 0; p < pm.panels.size(); ++p) {
    const std::vector<int>& panel = pm.panels[p];
    if (panel.size() < 3) continue;
    std::vector<Vec3> points;
    for (const int v : panel) points.push_back(pm.vertices[static_cast<size_t>(v)]);
    // The panel's own plane when it has one, else its Newell normal (both orient it like the
    // surface); a degenerate panel falls back to any frame so it still gets triangles.
    Vec3 normal = p < pm.plane_normals.size() ? pm.plane_normals[p] : newell_normal(points);
    if (!(normal.squaredNorm() > 0.0) || !normal.allFinite()) normal = Vec3::UnitZ();
    const PlaneFrame frame = make_plane_frame(points[0], normal);
    std::vector<Vec2> polygon;
    for (const Vec3& q : points) polygon.push_back(frame.to_2d(q));
    for (const std::array<int, 3>& t : triangulate_polygon(polygon)) {
      out.triangles.push_back(
          {panel[static_cast<size_t>(t[0])], panel[static_cast<size_t>(t[1])], panel[static_cast<size_t>(t[2])]});
      out.panel.push_back(static_cast<int>(p));
    }
  }
  return out;
}

std::string panels_obj_comment(const std::string& input_name, int panels, int requested_panels, int vertices,
                               std::uint64_t seed, int invalid_panels) {
  return std::string("flatfacet ") + kVersion + " remesh\n" + "input: " + input_name + "\n" +
         "panels: " + std::to_string(panels) + " (requested " + std::to_string(requested_panels) +
         "), vertices: " + std::to_string(vertices) + ", seed: " + std::to_string(seed) +
         ", invalid panels: " + std::to_string(invalid_panels) + "\n";
}

std::string panels_obj(const PanelMesh& panels, const std::string& comment) {
  const PolygonMesh mesh = used_vertices_only(panels);
  return write_polygon_obj(mesh.vertices, mesh.faces, comment);
}

}  // namespace ff
