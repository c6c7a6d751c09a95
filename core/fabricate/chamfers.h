#pragma once
// Chamfer (bevel) angles of the panel edges (paper 1.1: "the exact chamfer angle is defined
// per edge as one half the angle between the pair of panels").
//
// The angle between two panels is read as the angle between their planes' normals, phi =
// 180 deg - the dihedral angle through the material. Cutting both edges on the bisector
// plane of the two panels makes them meet flush; that cut leans away from a square cut
// (perpendicular to the panel) by
//     chamfer = phi / 2 = (180 deg - dihedral) / 2,
// so a cube's edges (dihedral 90) get 45 deg, a regular dodecahedron's (116.565) 31.72 deg,
// coplanar neighbours 0 (a square butt joint). Boundary edges are cut square (0).
// Convex edges (a ridge, seen from the side the normals point to) and concave ones (a
// valley) have the same angle but lean opposite ways; `convex` tells them apart.
#include <vector>

#include "core/fabricate/panel_edges.h"
#include "core/panels/panel_mesh.h"

namespace ff {

struct EdgeChamfer {
  int neighbour = -1;           // panel across the edge, -1 on the boundary
  double dihedral_deg = 180.0;  // between the panels, behind their normals: < 180 at a ridge
  double chamfer_deg = 0.0;     // from a square cut, see above
  bool convex = true;
};

// Per panel, per edge i (corner i to corner i + 1), using the panels' plane normals.
std::vector<std::vector<EdgeChamfer>> edge_chamfers(const PanelMesh& panels, const PanelEdges& edges);

// The same for one pair of unit normals; `edge` runs along the shared edge as the first
// panel's counter-clockwise boundary goes (it decides convex from concave).
EdgeChamfer chamfer_between(const Vec3& normal, const Vec3& neighbour_normal, const Vec3& edge);

}  // namespace ff
