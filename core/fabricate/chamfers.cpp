#include "core/fabricate/chamfers.h"

#include <Eigen/Geometry>
#include <cmath>

namespace ff {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = 180.0 / kPi;
}  // namespace

EdgeChamfer chamfer_between(const Vec3& n, const Vec3& m, const Vec3& edge) {
  EdgeChamfer c;
  const Vec3 cross = n.cross(m);
  // atan2 keeps small and near-180 angles accurate, where acos of the dot loses digits.
  const double phi = std::atan2(cross.norm(), n.dot(m)) * kDeg;
  // With the edge running counter-clockwise around n, n x m points along it at a ridge.
  c.convex = cross.dot(edge) >= 0.0;
  c.dihedral_deg = c.convex ? 180.0 - phi : 180.0 + phi;
  c.chamfer_deg = 0.5 * phi;
  return c;
}

std::vector<std::vector<EdgeChamfer>> edge_chamfers(const PanelMesh& pm, const PanelEdges& edges) {
  std::vector<std::vector<EdgeChamfer>> out(pm.panels.size());
  for (size_t p = 0; p < pm.panels.size(); ++p) {
    const std::vector<int>& poly = pm.panels[p];
    out[p].resize(poly.size());
    for (size_t i = 0; i < poly.size(); ++i) {
      const int q = edges.neighbour[p][i];
      if (q < 0) continue;  // boundary: square cut
      const Vec3 edge =
          pm.vertices[static_cast<size_t>(poly[(i + 1) % poly.size()])] - pm.vertices[static_cast<size_t>(poly[i])];
      out[p][i] = chamfer_between(pm.plane_normals[p], pm.plane_normals[static_cast<size_t>(q)], edge);
      out[p][i].neighbour = q;
    }
  }
  return out;
}

}  // namespace ff
