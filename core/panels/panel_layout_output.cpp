// What a PanelLayout gives out once its planes and pairings are settled: the panel mesh in
// world coordinates, and the per-node constraints and spike flags the plane relaxation reads.
// Kept apart from panel_layout.cpp, which builds and checks the panels.
#include "core/panels/panel_layout.h"

namespace ff {

std::vector<NodeConstraint> PanelLayout::node_constraints() const {
  std::vector<NodeConstraint> out(node_point_.size());
  for (size_t node = 0; node < node_point_.size(); ++node) {
    NodeConstraint& nc = out[node];
    nc.corner = groups_.groups[static_cast<size_t>(node_group_[node])].reference;
    for (int m : masters_of_node(node)) {
      if (nc.count < 3) nc.planes[static_cast<size_t>(nc.count++)] = m;
    }
  }
  return out;
}

std::vector<char> PanelLayout::spike_nodes() const {
  std::vector<char> out(node_point_.size(), 0);
  for (size_t node = 0; node < node_point_.size(); ++node) {
    const Vec3& at = groups_.groups[static_cast<size_t>(node_group_[node])].reference;
    const double limit = node_limit_.empty() ? options_.spike_distance : node_limit_[node];
    out[node] = !node_exact_[node] || !((node_point_[node] - at).norm() <= limit);
  }
  return out;
}

PanelMesh PanelLayout::to_panel_mesh(const FaceData& frame) const {
  PanelMesh out;
  out.spike_distance = frame.scale * options_.spike_distance;
  out.solve_origin = frame.origin;
  std::vector<int> node_vertex(node_point_.size(), -1);
  const size_t n = polygons_.size();
  std::vector<int> panel_of_cluster(n, -1);
  const auto add_vertex = [&](const PanelPolygon& poly, size_t i, int planes, int cluster) {
    if (!node_limit_.empty()) out.vertex_spike_distance.push_back(frame.scale * spike_limit(poly, i, cluster));
    out.vertices.push_back(frame.to_world(poly.points[i]));
    out.vertex_corner.push_back(poly.corner[i]);
    out.vertex_reference.push_back(frame.to_world(poly.reference[i]));
    out.vertex_planes.push_back(planes);
    return static_cast<int>(out.vertices.size()) - 1;
  };
  for (size_t c = 0; c < n; ++c) {
    const PanelPolygon& poly = polygons_[c];
    if (poly.points.size() < 3) {
      out.unbuilt_clusters.push_back(static_cast<int>(c));
      continue;
    }
    std::vector<int> face;
    for (size_t i = 0; i < poly.points.size(); ++i) {
      const int node = poly.node[i];
      if (node < 0) {
        face.push_back(add_vertex(poly, i, 1, static_cast<int>(c)));
        continue;
      }
      int& id = node_vertex[static_cast<size_t>(node)];
      if (id < 0) id = add_vertex(poly, i, node_planes_[static_cast<size_t>(node)], static_cast<int>(c));
      face.push_back(id);
    }
    panel_of_cluster[c] = out.num_panels();
    out.panels.push_back(std::move(face));
    const Plane& plane = planes_.plane_of(static_cast<int>(c));
    out.plane_normals.push_back(plane.normal);
    out.plane_offsets.push_back(plane.normal.dot(frame.origin) + frame.scale * plane.offset);
    out.panel_cluster.push_back(static_cast<int>(c));
    out.issues.push_back(issues_[c]);
  }
  out.face_panel.resize(labels_.size());
  for (size_t f = 0; f < labels_.size(); ++f) out.face_panel[f] = panel_of_cluster[static_cast<size_t>(labels_[f])];
  return out;
}

}  // namespace ff
