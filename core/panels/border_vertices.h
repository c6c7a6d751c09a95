#pragma once
// Extra border vertices (paper 2.5): a panel on the mesh boundary follows the border with
// as few extra vertices as keep it within a tolerance (Douglas-Peucker on the border
// vertices projected onto the panel's plane), so boundary panels keep their area.
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff {

// The indices (increasing) of `points` to keep between the fixed ends `from` and `to`: every
// dropped point lies within `tolerance` of the kept polyline, except a first or last point
// that would make a corner below kNeedleCornerDeg (panel_check.h) with its end (the end landed
// short of it: the border would run out and back). At least `min_keep` (0 or 1) when there
// are points at all.
std::vector<int> thin_border(const Vec3& from, const std::vector<Vec3>& points, const Vec3& to, double tolerance,
                             int min_keep);

// The same for a closed border with no fixed vertex (a whole open component as one panel):
// at least 3 points when there are 3.
std::vector<int> thin_closed_border(const std::vector<Vec3>& points, double tolerance);

}  // namespace ff
