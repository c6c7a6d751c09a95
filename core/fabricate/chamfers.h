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
//
// Panels of different thickness (the paper's future work, 6): the cut plane then holds the
// outer edge line and the line where the two offset planes meet, so the inner surface stays
// crisp and each side gets its own bevel. In the section across the edge the cut runs from
// the edge to the point d with n_p . d = -t_p and n_q . d = -t_q, so panel p's bevel (from
// square, towards q) satisfies
//     tan(bevel_p) = (t_q - t_p cos phi) / (t_p sin phi),     bevel_p + bevel_q = phi,
// which is phi / 2 for t_p = t_q; a negative bevel leans the other way (a thin panel against
// a much thicker one at a sharp angle).
#include <vector>

#include "core/fabricate/panel_edges.h"
#include "core/panels/panel_mesh.h"

namespace ff {

// The material side of thick panels (thick_panels.h). Inside: the material lies behind the
// panels' normals (for a closed, outward-oriented shape: inwards), the outer faces are the
// designed surface. Outside: in front of them.
enum class MaterialSide { Inside, Outside };

// How the boundary edges (no neighbour) are cut. Square: perpendicular to the panel (the
// default). Bevel: leaning `bevel_deg` from square about the edge, positive making the inner
// face smaller than the outer one (the way a ridge chamfer leans), |bevel| < 80. Plumb: the
// cut holds the edge and the `up` axis (a vertical fascia); where that is within 10 deg of the
// panel's own plane (or the edge runs along `up`) the edge is cut square.
struct BoundaryCut {
  enum class Kind { Square, Bevel, Plumb };
  Kind kind = Kind::Square;
  double bevel_deg = 0.0;
  Vec3 up = Vec3::UnitZ();  // unit, in mesh coordinates
};

// The direction the cut of a boundary edge runs from the outer face into the material: a
// unit vector perpendicular to the unit edge direction `e` (counter-clockwise around `n`).
Vec3 boundary_cut_direction(const Vec3& n, const Vec3& e, const BoundaryCut& cut, MaterialSide side);

// The signed bevel (degrees from square, positive: inner face smaller) of such a cut.
double boundary_bevel_deg(const Vec3& n, const Vec3& e, const BoundaryCut& cut, MaterialSide side);

// bevel_p above for the angle phi (degrees) between the two panels' normals.
double unequal_chamfer_deg(double phi_deg, double t_p, double t_q);

struct EdgeChamfer {
  int neighbour = -1;           // panel across the edge, -1 on the boundary
  double dihedral_deg = 180.0;  // between the panels, behind their normals: < 180 at a ridge
  double chamfer_deg = 0.0;     // from a square cut, see above
  bool convex = true;
};

// Per panel, per edge i (corner i to corner i + 1), using the panels' plane normals.
std::vector<std::vector<EdgeChamfer>> edge_chamfers(const PanelMesh& panels, const PanelEdges& edges);

// The same with per-panel thicknesses (one per panel, any units) and a boundary cut: edges
// between panels of different thickness get unequal_chamfer_deg, boundary edges
// boundary_bevel_deg; everything else is as above, bit for bit.
std::vector<std::vector<EdgeChamfer>> edge_chamfers(const PanelMesh& panels, const PanelEdges& edges,
                                                    const std::vector<double>& thickness, const BoundaryCut& boundary,
                                                    MaterialSide side);

// The same for one pair of unit normals; `edge` runs along the shared edge as the first
// panel's counter-clockwise boundary goes (it decides convex from concave).
EdgeChamfer chamfer_between(const Vec3& normal, const Vec3& neighbour_normal, const Vec3& edge);

}  // namespace ff
