// The typed arrays the page draws from (wasm/flatfacet.d.ts): the cleaned (and prepared)
// mesh, its clustering, and the panels as polygons, as triangles and by corner. Each getter
// returns a fresh copy (bindings.cpp hands it to JavaScript as it is). Without a solve the
// panel arrays are empty (panel_offsets: just 0) and cluster_ids is -1 per triangle.
#include <cstdint>
#include <vector>

#include "core/panels/panel_export.h"
#include "core/quality/panel_deviation.h"
#include "core/quality/planarity.h"
#include "wasm/session.h"

namespace ff::wasm {

std::vector<float> Session::input_positions() const {
  std::vector<float> out;
  out.reserve(mesh_.positions.size() * 3);
  for (const Vec3& p : mesh_.positions)
    for (int k = 0; k < 3; ++k) out.push_back(static_cast<float>(p[k]));
  return out;
}

std::vector<std::uint32_t> Session::input_indices() const {
  std::vector<std::uint32_t> out;
  out.reserve(mesh_.triangles.size() * 3);
  for (const auto& t : mesh_.triangles)
    for (const int v : t) out.push_back(static_cast<std::uint32_t>(v));
  return out;
}

std::vector<std::int32_t> Session::cluster_ids() const {
  if (!remesher_ || remesher_->clustering().labels.empty())
    return std::vector<std::int32_t>(mesh_.triangles.size(), -1);
  const std::vector<int>& labels = remesher_->clustering().labels;
  return std::vector<std::int32_t>(labels.begin(), labels.end());
}

std::vector<double> Session::panel_positions() const {
  std::vector<double> out;
  if (!remesher_) return out;
  for (const Vec3& p : remesher_->panels().vertices)
    for (int k = 0; k < 3; ++k) out.push_back(p[k]);
  return out;
}

std::vector<std::uint32_t> Session::panel_offsets() const {
  std::vector<std::uint32_t> out{0};
  if (!remesher_) return out;
  for (const std::vector<int>& panel : remesher_->panels().panels)
    out.push_back(out.back() + static_cast<std::uint32_t>(panel.size()));
  return out;
}

std::vector<std::uint32_t> Session::panel_indices() const {
  std::vector<std::uint32_t> out;
  if (!remesher_) return out;
  for (const std::vector<int>& panel : remesher_->panels().panels)
    for (const int v : panel) out.push_back(static_cast<std::uint32_t>(v));
  return out;
}

std::vector<std::uint32_t> Session::panel_triangles() const {
  std::vector<std::uint32_t> out;
  if (!remesher_) return out;
  for (const auto& t : triangulate_panels(remesher_->panels()).triangles)
    for (const int v : t) out.push_back(static_cast<std::uint32_t>(v));
  return out;
}

std::vector<std::uint32_t> Session::panel_triangle_ids() const {
  if (!remesher_) return {};
  const std::vector<int> panel = triangulate_panels(remesher_->panels()).panel;
  return std::vector<std::uint32_t>(panel.begin(), panel.end());
}

std::vector<double> Session::corner_positions() const {
  std::vector<double> out;
  if (!remesher_) return out;
  const PanelMesh& pm = remesher_->panels();
  for (size_t v = 0; v < pm.vertices.size(); ++v) {
    const int corner = v < pm.vertex_corner.size() ? pm.vertex_corner[v] : -1;
    const Vec3& p =
        corner >= 0 && corner < mesh_.num_vertices() ? mesh_.positions[static_cast<size_t>(corner)] : pm.vertices[v];
    for (int k = 0; k < 3; ++k) out.push_back(p[k]);
  }
  return out;
}

std::vector<double> Session::corner_planarity() const {
  if (!remesher_) return {};
  return corner_polygon_planarity(mesh_, remesher_->panels());
}

std::vector<double> Session::panel_deviation() const {
  if (!remesher_) return {};
  return ff::panel_deviation(mesh_, remesher_->panels());
}

}  // namespace ff::wasm
