#include "bench/cgal_panels.h"

#include <algorithm>
#include <vector>

#include "core/panels/polygon2d.h"

namespace ff::bench {

PanelMesh polygon_panels(const CgalVsaMesh& m, int faces) {
  ff::PanelMesh pm;
  pm.vertices = m.anchors;
  pm.panels = m.polygons;
  std::vector<int> proxy_panel(static_cast<size_t>(std::max(m.proxies, 0)), -1), cycles(proxy_panel.size(), 0);
  for (size_t p = 0; p < pm.panels.size(); ++p) {
    std::vector<ff::Vec3> points;
    ff::Vec3 centroid = ff::Vec3::Zero();
    for (int v : pm.panels[p]) {
      points.push_back(pm.vertices[static_cast<size_t>(v)]);
      centroid += points.back();
    }
    if (!points.empty()) centroid /= static_cast<double>(points.size());
    ff::Vec3 n = ff::newell_normal(points);
    n = n.norm() > 0.0 ? ff::Vec3(n.normalized()) : ff::Vec3::UnitZ();
    pm.plane_normals.push_back(n);
    pm.plane_offsets.push_back(n.dot(centroid));
    const int proxy = m.polygon_proxy[p];
    pm.panel_cluster.push_back(proxy);
    if (proxy >= 0 && proxy < m.proxies) {
      proxy_panel[static_cast<size_t>(proxy)] = static_cast<int>(p);
      ++cycles[static_cast<size_t>(proxy)];
    }
  }
  pm.issues.resize(pm.panels.size());
  pm.vertex_corner.assign(pm.vertices.size(), -1);
  pm.face_panel.assign(static_cast<size_t>(faces), -1);
  for (int f = 0; f < faces; ++f) {
    const int proxy = m.face_proxy[static_cast<size_t>(f)];
    if (proxy >= 0 && proxy < m.proxies && cycles[static_cast<size_t>(proxy)] == 1)
      pm.face_panel[static_cast<size_t>(f)] = proxy_panel[static_cast<size_t>(proxy)];
  }
  return pm;
}

// CGAL's actual output, its indexed triangles over the anchors, as one panel per triangle:
// for its Hausdorff distance and topology next to the polygons'.
PanelMesh triangle_panels(const CgalVsaMesh& m) {
  ff::PanelMesh pm;
  pm.vertices = m.anchors;
  for (const auto& t : m.triangles) {
    pm.panels.push_back({t[0], t[1], t[2]});
    const ff::Vec3 n = ff::newell_normal({m.anchors[static_cast<size_t>(t[0])], m.anchors[static_cast<size_t>(t[1])],
                                          m.anchors[static_cast<size_t>(t[2])]});
    pm.plane_normals.push_back(n.norm() > 0.0 ? ff::Vec3(n.normalized()) : ff::Vec3::UnitZ());
    pm.plane_offsets.push_back(pm.plane_normals.back().dot(m.anchors[static_cast<size_t>(t[0])]));
  }
  pm.issues.resize(pm.panels.size());
  pm.vertex_corner.assign(pm.vertices.size(), -1);
  return pm;
}

}  // namespace ff::bench
