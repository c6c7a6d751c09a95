#pragma once
// Two-sided sampled Hausdorff distance between the input surface and the panels, in units
// of the input's bounding-box diagonal (DESIGN.md 5). Sampling is deterministic: every
// referenced vertex, every triangle centroid, then jittered-stratified area-proportional
// points (SplitMix64) up to about samples_per_side points per side.
#include <cstdint>
#include <vector>

#include "core/mesh/tri_mesh.h"
#include "core/panels/panel_mesh.h"
#include "core/panels/polygon2d.h"

namespace ff {

struct HausdorffResult {
  double input_to_panels = 0.0;  // max over input samples of the distance to the panels
  double panels_to_input = 0.0;  // max over panel samples of the distance to the input
  double two_sided = 0.0;        // the larger of the two
  // World coordinates of the worst samples, for visualisation.
  Vec3 input_worst_point = Vec3::Zero();   // on the input, farthest from the panels
  Vec3 panels_worst_point = Vec3::Zero();  // on the panels, farthest from the input
  Vec3 worst_point = Vec3::Zero();         // whichever of the two gives two_sided
};

// The plane frame a panel is checked and triangulated in: its plane_normals entry when
// there is a usable one (non-empty, finite, non-zero), else its Newell normal (else +z for
// a degenerate polygon); origin at the vertex average. Indices must be valid.
PlaneFrame panel_frame(const PanelMesh& panels, int panel);
// The panel's vertices in that frame, in panel order.
std::vector<Vec2> panel_polygon_2d(const PanelMesh& panels, int panel, const PlaneFrame& frame);

// Every panel with >= 3 vertices triangulated in its own plane (triangulate_polygon),
// sharing the PanelMesh's vertex array, oriented like the panels. triangle_panel (optional)
// receives each triangle's panel. Throws InputError on a vertex index out of range.
TriMesh triangulate_panels(const PanelMesh& panels, std::vector<int>* triangle_panel = nullptr);

// The deterministic sample set described above (at least every referenced vertex and every
// centroid, even beyond target). `triangle` (optional) receives, per sample, the triangle it
// lies on (for a vertex: the first triangle that refers to it).
std::vector<Vec3> sample_surface(const TriMesh& mesh, int target, std::uint64_t seed,
                                 std::vector<int>* triangle = nullptr);

// The points' indices along a Morton (Z-order) curve over their bounding box, 10 bits per
// axis (a three-pass radix sort; equal codes keep their order). Queried in this order,
// consecutive points are near each other, so each query's answer is a good hint for the next.
// Empty for no points.
std::vector<int> morton_order(const std::vector<Vec3>& points);

// Directed distances between two triangle meshes, absolute (not divided by anything).
// A side with no triangles is infinitely far; an empty sample set contributes 0.
HausdorffResult hausdorff_distance(const TriMesh& a, const TriMesh& b, int samples_per_side = 200000);

// The product's measure: input vs triangulate_panels(panels), divided by
// bbox_diagonal(input). Throws InputError for an input without triangles or extent, or a
// negative sample count.
HausdorffResult hausdorff_distance(const TriMesh& input, const PanelMesh& panels, int samples_per_side = 200000);

}  // namespace ff
