#include "core/fabricate/chamfers.h"

#include <Eigen/Geometry>
#include <cmath>

#include "core/util/angles.h"

namespace ff {

namespace {}  // namespace

EdgeChamfer chamfer_between(const Vec3& n, const Vec3& m, const Vec3& edge) {
  EdgeChamfer c;
  const Vec3 cross = n.cross(m);
  // atan2 keeps small and near-180 angles accurate, where acos of the dot loses digits.
  const double phi = std::atan2(cross.norm(), n.dot(m)) * kDegreesPerRadian;
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

Vec3 boundary_cut_direction(const Vec3& n, const Vec3& e, const BoundaryCut& cut, MaterialSide side) {
  const Vec3 depth = side == MaterialSide::Inside ? Vec3(-n) : n;
  const Vec3 inward = n.cross(e);  // in the panel's plane, towards its inside
  if (cut.kind == BoundaryCut::Kind::Bevel) {
    const double b = cut.bevel_deg / kDegreesPerRadian;
    return (std::cos(b) * depth + std::sin(b) * inward).normalized();
  }
  if (cut.kind == BoundaryCut::Kind::Plumb) {
    Vec3 c = cut.up - cut.up.dot(e) * e;  // the up axis seen across the edge
    if (c.norm() > 1e-6) {
      c.normalize();
      if (c.dot(depth) < 0.0) c = -c;
      // Within 10 deg of the panel's plane the cut would slice the panel lengthwise.
      if (c.dot(depth) > std::sin(10.0 / kDegreesPerRadian)) return c;
    }
  }
  return depth;
}

double boundary_bevel_deg(const Vec3& n, const Vec3& e, const BoundaryCut& cut, MaterialSide side) {
  if (cut.kind == BoundaryCut::Kind::Square) return 0.0;
  const Vec3 c = boundary_cut_direction(n, e, cut, side);
  const Vec3 depth = side == MaterialSide::Inside ? Vec3(-n) : n;
  return std::atan2(c.dot(n.cross(e)), c.dot(depth)) * kDegreesPerRadian;
}

double unequal_chamfer_deg(double phi_deg, double t_p, double t_q) {
  const double phi = phi_deg / kDegreesPerRadian;
  return std::atan2(t_q - t_p * std::cos(phi), t_p * std::sin(phi)) * kDegreesPerRadian;
}

std::vector<std::vector<EdgeChamfer>> edge_chamfers(const PanelMesh& pm, const PanelEdges& edges,
                                                    const std::vector<double>& thickness, const BoundaryCut& boundary,
                                                    MaterialSide side) {
  std::vector<std::vector<EdgeChamfer>> out = edge_chamfers(pm, edges);
  for (size_t p = 0; p < pm.panels.size(); ++p) {
    const std::vector<int>& poly = pm.panels[p];
    for (size_t i = 0; i < poly.size(); ++i) {
      const int q = edges.neighbour[p][i];
      const Vec3 edge =
          pm.vertices[static_cast<size_t>(poly[(i + 1) % poly.size()])] - pm.vertices[static_cast<size_t>(poly[i])];
      if (q < 0) {
        out[p][i].chamfer_deg = boundary_bevel_deg(pm.plane_normals[p], edge.normalized(), boundary, side);
      } else if (p < thickness.size() && static_cast<size_t>(q) < thickness.size() &&
                 thickness[p] != thickness[static_cast<size_t>(q)]) {
        // (Nearly) coplanar neighbours of different thickness: their offset planes do not
        // meet, a step, cut square (as thick_panels.cpp, which needs sin phi >= 1e-6).
        const double phi = 2.0 * out[p][i].chamfer_deg;
        out[p][i].chamfer_deg = std::sin(phi / kDegreesPerRadian) < 1e-6
                                    ? 0.0
                                    : unequal_chamfer_deg(phi, thickness[p], thickness[static_cast<size_t>(q)]);
      }
    }
  }
  return out;
}

}  // namespace ff
