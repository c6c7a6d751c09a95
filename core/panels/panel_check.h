#pragma once
// The checks a panel must pass in its own plane (paper 2.2-2.3, DESIGN.md 3): at least three
// vertices, simple, counter-clockwise like its cluster, star-shaped (non-empty kernel, so no
// edge is flipped with respect to a kernel point), and no vertex farther than the spike
// distance from the mesh vertex it stands for; with a minimum corner angle (degrees, 0 =
// off), no convex corner below it (reflex corners are split in glass mode, so only corners
// under 180 degrees are judged); in glass mode, the corners of its convex pieces
// (glass_split.h), simple counter-clockwise panels only.
#include <vector>

#include "core/panels/panel_mesh.h"
#include "core/panels/plane.h"
#include "core/panels/polygon2d.h"

namespace ff {

// A panel whose area (on its plane) is below this share of its cluster's faces' area
// projected on that plane has collapsed: its planes nearly meet in a line or a point, and its
// faces lie under its neighbours' panels. The paper's checks let it through (a thin triangle
// is simple, star-shaped and has no spike when its cluster is small), but it is no part to
// cut, and its cluster is better spent elsewhere (cow.off, 61 panels, seed 2: a 1.5 mm
// triangle for a cluster of 91 faces). The quality report counts them (collapsed_panels).
constexpr double kMinCoveredShare = 0.1;

// A panel corner below this (degrees) is a needle, not a design corner: a border run drops
// an end point that would make one (border_vertices.cpp), and the finish widens those at
// split nodes (widen_needle_corners.cpp).
constexpr double kNeedleCornerDeg = 5.0;

// Whether a panel of signed area `panel_area` on its plane, whose cluster's faces have the
// area `faces_area` projected on that plane, has collapsed. Any one scale for both (the
// layout passes them doubled, as sums of cross products).
inline bool is_collapsed(double panel_area, double faces_area) {
  return faces_area > 0.0 && panel_area < kMinCoveredShare * faces_area;
}

// points: the panel's vertices (on `plane`); references[i]: where points[i] belongs (its
// mesh corner). tolerance: lengths below it count as zero (edges, kernel width).
PanelIssues check_panel(const std::vector<Vec3>& points, const std::vector<Vec3>& references, const Plane& plane,
                        double spike_distance, double tolerance, double min_corner_angle_deg = 0.0, bool glass = false);

// Indices of the corners whose interior angle (counter-clockwise polygon) is below min_deg.
std::vector<int> acute_corners(const std::vector<Vec2>& ccw_polygon, double min_deg);

// Corners turning the wrong way (interior angle above 180 degrees plus a rounding slack of
// 1e-6 degrees): a panel with one is concave. Collinear border vertices are not reflex.
constexpr double kReflexSlackDeg = 1e-6;
std::vector<int> reflex_corners(const std::vector<Vec2>& ccw_polygon);

// Interior angle at b (degrees, [0, 360)) of a counter-clockwise polygon a -> b -> c.
double corner_angle_deg(const Vec2& a, const Vec2& b, const Vec2& c);

}  // namespace ff
