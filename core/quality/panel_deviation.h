#pragma once
// How far each panel is from the design near it: the largest distance between the panel and
// the input surface, sampled both ways, relative to the input's bounding-box diagonal (as the
// report's Hausdorff distance). The page colours panels by it, so a designer sees where the
// panel surface leaves the design and can paint density there.
#include <vector>

#include "core/mesh/tri_mesh.h"
#include "core/panels/panel_mesh.h"

namespace ff {

// Per panel of `panels`: the maximum over
//  - points of the panel (its triangulation, sample_surface) of the distance to the input, and
//  - points of the input triangles the panel stands for (PanelMesh::face_panel) of the
//    distance to the nearest panel (any panel: where a neighbour is closer, the surface is
//    covered there).
// About samples_per_side points a side (sample_surface: every vertex and centroid at least;
// deterministic). A panel with neither kind of sample
// gets 0. The maximum over panels approximates the two-sided Hausdorff distance at this
// sampling. Throws InputError for an input without triangles or extent, a face_panel that does
// not match the input's triangles, or a negative sample count.
std::vector<double> panel_deviation(const TriMesh& input, const PanelMesh& panels, int samples_per_side = 20000);

}  // namespace ff
