#pragma once
// Glass mode (DESIGN.md 3): glass cannot be cut with inside corners, so each concave panel is
// cut at its reflex corners into convex pieces along diagonals between its own vertices. The
// pieces keep the panel's plane and vertices exactly (planarity unchanged); a diagonal adds
// one edge and one face, so the Euler characteristic and the boundary loops stay as they were.
#include <vector>

#include "core/mesh/tri_mesh.h"
#include "core/panels/panel_mesh.h"
#include "core/panels/polygon2d.h"

namespace ff {

// Convex pieces of a simple counter-clockwise polygon, as lists of its vertex indices, each
// counter-clockwise. Each step cuts one reflex corner by the diagonal that best keeps every
// new corner at or above min_deg, then resolves the reflex corner, then has the largest
// smallest new angle (the other end only loses angle, so no new reflex corner appears).
// Deterministic; a convex polygon comes back whole.
std::vector<std::vector<int>> convex_pieces(const std::vector<Vec2>& ccw_polygon, double min_deg);

// The corners (polygon indices, increasing) below min_deg once the polygon is cut as above
// when `glass` (the pieces' corners: a cut can make thin ones), else its own corners.
std::vector<int> acute_corners_after_split(const std::vector<Vec2>& ccw_polygon, double min_deg, bool glass);

// Splits every concave panel that is simple and not flipped into convex pieces in place:
// per-panel arrays follow, panel_source names each piece's original panel, face_panel moves
// each face to the piece over its centroid, and with min_deg > 0 each piece's acute_corner
// is checked again. mesh: the input the faces belong to (world coordinates). Returns the
// number of panels split.
int split_concave_panels(PanelMesh& panels, const TriMesh& mesh, double min_deg);

}  // namespace ff
