#pragma once
// The checks a panel must pass in its own plane (paper 2.2-2.3, DESIGN.md 3): at least three
// vertices, simple, counter-clockwise like its cluster, star-shaped (non-empty kernel, so no
// edge is flipped with respect to a kernel point), and no vertex farther than the spike
// distance from the mesh vertex it stands for.
#include <vector>

#include "core/panels/panel_mesh.h"
#include "core/panels/plane.h"

namespace ff {

// points: the panel's vertices (on `plane`); references[i]: where points[i] belongs (its
// mesh corner). tolerance: lengths below it count as zero (edges, kernel width).
PanelIssues check_panel(const std::vector<Vec3>& points, const std::vector<Vec3>& references, const Plane& plane,
                        double spike_distance, double tolerance);

}  // namespace ff
