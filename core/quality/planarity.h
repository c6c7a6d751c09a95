#pragma once
// Planarity of polygons: how far a polygon's vertices are from their least-squares plane,
// relative to its size. For the panels (exact by construction: ~1e-15) and for the polygons
// through their mesh corners, i.e. the panels before the planes are intersected: what a
// plain cluster-corner remeshing (like VSA's extraction) would have to bend.
#include <algorithm>
#include <vector>

#include "core/mesh/tri_mesh.h"
#include "core/panels/panel_mesh.h"

namespace ff {

// Max distance of the points to their least-squares plane / their diameter; 0 for fewer than
// four points.
double polygon_planarity(const std::vector<Vec3>& points);

// The planarity the points' own rounding allows: the spacing of doubles at their largest
// coordinate (DBL_EPSILON * max |x - origin|) / their diameter; 0 for fewer than four points.
// Far from the origin (georeferenced models, a stray offset; or, with the point the panels
// were solved about as `origin`, a far-off part of the mesh) it exceeds 1e-9 and no solver can
// write exactly flat panels there: polygon_planarity measures about this much.
double planarity_rounding_floor(const std::vector<Vec3>& points, const Vec3& origin = Vec3::Zero());

// DESIGN.md 5: the panels are flat to this, relative to their size (exact by construction).
constexpr double kPlanarityTarget = 1e-9;

// Planarity within this many times what the coordinates' rounding allows
// (planarity_rounding_floor) is the coordinates', not the solve's.
constexpr double kRoundingAllowance = 100.0;

// Whether a panel of this polygon_planarity is off its plane by more than its coordinates can
// explain: above kPlanarityTarget and over kRoundingAllowance times the larger of its
// planarity_rounding_floor about the origin (`floor`) and about the solve's origin
// (`floor_solve`). A valid panel never is: only a vertex whose planes have no common point
// (a spike) or an error of the solver puts one there.
inline bool off_its_plane(double planarity, double floor, double floor_solve) {
  return planarity > kPlanarityTarget && planarity > kRoundingAllowance * std::max(floor, floor_solve);
}

// Per panel: polygon_planarity of its vertices moved back to their mesh corners
// (PanelMesh::vertex_corner; a vertex without a corner keeps its position). Empty when the
// panel mesh has no vertex_corner.
std::vector<double> corner_polygon_planarity(const TriMesh& mesh, const PanelMesh& panels);

}  // namespace ff
