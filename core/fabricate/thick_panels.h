#pragma once
// Thick panels (paper 1.1, fig. 3; DESIGN.md 3): every panel plane offset by the material
// thickness t, and each panel's inner face (the face away from the designed surface).
//
// Each edge of panel p is cut on a plane through the edge: against a neighbour q, the
// bisector plane of p and q (the chamfer cut, chamfers.h), on the boundary the plane
// perpendicular to p (a square cut). The inner vertex of p at a corner is where its offset
// plane meets the cut planes of its two edges there. The line where p's offset plane meets
// the bisector of p and q is also on q's offset plane, so:
//  - at a valence-3 node the three panels' inner vertices are the one point where the three
//    offset planes meet (computed once, shared exactly);
//  - at a node of 4+ panels each panel gets the point of its own plane and its two edge
//    neighbours' (a consecutive triple), so every inner edge still lies on both offset
//    planes and the panels meet flush along their edges; only at the node do the triples
//    disagree, and how far apart they are (the node's spread) is the extra chamfering the
//    node needs (fig. 3). Least squares over all the planes would spread that error along
//    the edges instead, where it shows as gaps.
// Coplanar neighbours make the bisector degenerate; it tends to the square cut, which is
// used below kParallel. Where a corner's two cut planes are near parallel (a straight
// corner: collinear edges) the plane through the corner perpendicular to the edges stands
// in for one; where even that fails (a panel folded back onto its neighbour), the corner is
// projected onto the offset plane and counted in `projected_corners`.
//
// Per-panel thickness (chamfers.h): between panels of different thickness the cut plane holds
// the outer edge and the line where the two offset planes meet, which is still on both, so
// valence-3 nodes still get the one point of the three offset planes. Boundary edges may be
// cut other than square (BoundaryCut, chamfers.h).
#include <vector>

#include "core/fabricate/chamfers.h"
#include "core/fabricate/panel_edges.h"
#include "core/panels/panel_mesh.h"
#include "core/panels/plane.h"

namespace ff {

struct ThickOptions {
  double thickness = 0.0;  // > 0, in the panel mesh's units
  MaterialSide side = MaterialSide::Inside;
  std::vector<double> panel_thickness;  // empty, or one per panel (> 0, mesh units) instead of `thickness`
  BoundaryCut boundary;
};

struct ThickPanels {
  double thickness = 0.0;  // in the panel mesh's units (the default of ThickOptions)
  MaterialSide side = MaterialSide::Inside;
  std::vector<double> panel_thickness;   // per panel, mesh units
  std::vector<Plane> offset_planes;      // per panel: its plane moved by its t towards the material
  std::vector<std::vector<Vec3>> inner;  // per panel, per corner (the panel's order)
  // Per panel, per corner: 0 solved exactly, 1 straight corner (see above), 2 projected.
  std::vector<std::vector<char>> corner_fallback;
  // Per panel-mesh vertex: max distance between the inner vertices of the panels meeting
  // there (only panels whose both edges at the vertex are interior and solved exactly);
  // 0 at valence-3 nodes, positive at 4+ nodes whose offset planes miss one point.
  std::vector<double> node_spread;
  double max_spread = 0.0;
  int straight_corners = 0;
  int projected_corners = 0;
};

// thickness > 0 (throws InputError otherwise), in the units of the panel mesh.
ThickPanels thicken_panels(const PanelMesh& panels, const PanelEdges& edges, double thickness,
                           MaterialSide side = MaterialSide::Inside);
// The same with per-panel thicknesses and a boundary cut (each thickness checked likewise).
ThickPanels thicken_panels(const PanelMesh& panels, const PanelEdges& edges, const ThickOptions& options);

// The cut plane of panel edge a -> b (see above): the bisector with the neighbour's unit
// normal, or the square cut when `neighbour` is null or (near) parallel. Exposed for tests.
Plane edge_cut_plane(const Vec3& normal, const Vec3* neighbour, const Vec3& a, const Vec3& b);

// The cut plane of edge a -> b of a panel (unit `normal`, offset plane `own_offset`) against
// a neighbour of another thickness (offset plane `other_offset`): through the edge and the
// line where the offset planes meet; the square cut where they do not (coplanar).
Plane unequal_cut_plane(const Vec3& normal, const Plane& own_offset, const Plane& other_offset, const Vec3& a,
                        const Vec3& b);

}  // namespace ff
