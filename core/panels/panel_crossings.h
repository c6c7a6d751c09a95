#pragma once
// Panels that pass through each other in space. Each panel is checked in its own plane
// (panel_check.h) and the panel mesh's topology in the quality report, but two panels can
// still cross: where a panel is concave, or runs on past a node, its interior can meet the
// line where its plane crosses another panel's, and a point inside both panels is a point
// where they pass through each other (cow.off at 40-150 panels: up to a fifth of a panel's
// size deep; bench/README.md, "Panels that pass through each other").
//
// Two non-parallel planar panels meet only on the line of their planes, so each pair of
// panels whose bounding boxes overlap is checked exactly on that line: the stretches of it
// inside each panel (an even-odd scan of its edges), and where stretches of both overlap,
// how deep the overlap reaches inside both (the distance to the nearer outline). Panels in
// one plane (parallel) are not compared.
#include <string>
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff {

struct PanelCrossing {
  int a = -1, b = -1;  // the two panels, a < b
  // The deepest point found inside both (world coordinates), and how far it is from the nearer
  // of the two outlines.
  Vec3 point = Vec3::Zero();
  double depth = 0.0;
  double depth_share = 0.0;  // depth over the smaller panel's diameter
};

// A crossing counts when its depth exceeds this share of the smaller panel's diameter (0.1 mm
// on a panel 1 m across; the vertices' own rounding is about 1e-13 of it).
constexpr double kCrossingDepthShare = 1e-4;

// vertices, panels: the panel mesh (PanelMesh::vertices and panels); normals and offsets: each
// panel's plane (n.x = offset, unit n). Pairs in increasing (a, b) order. O(P log P) for the
// box sweep plus O(n_a + n_b) per pair of overlapping boxes.
std::vector<PanelCrossing> panel_crossings(const std::vector<Vec3>& vertices,
                                           const std::vector<std::vector<int>>& panels,
                                           const std::vector<Vec3>& normals, const std::vector<double>& offsets);

// The surface passing through itself: pairs of its triangles that cross (the same check, each
// triangle a panel; degenerate ones are not compared, neighbours sharing an edge or a corner
// do not count). Panels made from such a surface cross there too, whatever their count
// (cow.off: its tail goes into its rump, 83 pairs). About 0.1 s for 50k triangles, 2 s for 1M
// (native). `checked` false (and no pairs) when the triangles' boxes overlap so much that the
// check would take more than kSurfaceTestsPerTriangle box tests a triangle (plus 1e7): a
// fan of long thin triangles around one point, all of whose boxes hold it, costs the square
// of their number (a 100k-triangle disc as a fan: minutes). Shared meshes take 6-30.
struct SurfaceCrossings {
  std::vector<PanelCrossing> pairs;
  bool checked = true;
  // The separate places where it crosses: pairs joined when they share a triangle or their
  // triangles share a corner (the triangles along one crossing curve do). The cow's 83 pairs
  // lie in a few places along its back, which a count of pairs does not say.
  int places = 0;
  // What the report and the page tell: how many pairs cross (-1: not checked), and the first
  // pair's deepest point (the origin when none).
  int count() const { return checked ? static_cast<int>(pairs.size()) : -1; }
  Vec3 first_point() const { return pairs.empty() ? Vec3::Zero() : pairs.front().point; }
};
constexpr double kSurfaceTestsPerTriangle = 400.0;
SurfaceCrossings surface_crossings(const TriMesh& mesh);

// Where a surface crosses itself, for a message: "in one place, near (x, y, z)", "in 3 places,
// one near (x, y, z)" (`point`: one of its crossings), or "near (x, y, z)" when the places were
// not counted (0).
std::string crossing_where(int places, const Vec3& point);

}  // namespace ff
