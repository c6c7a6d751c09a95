#pragma once
// The vertex rule (DESIGN.md 3): a panel vertex is the point closest to its mesh corner on
// the intersection of the distinct planes around it. 3 planes: their common point; 2: the
// nearest point on their line (boundary vertices, coplanar seams); 1: the projection.
// Because the point lies on every plane exactly (up to rounding), every panel stays planar
// whatever else happens.
#include <vector>

#include "core/panels/plane.h"

namespace ff {

struct VertexRuleResult {
  Vec3 point = Vec3::Zero();
  // False when the planes have no common point (three planes whose normals are coplanar
  // with a determinant below 1e-12, or two parallel planes): `point` is then the nearest
  // point on the line of the best-conditioned pair (or a projection), and the caller must
  // treat the vertex as a spike to fix.
  bool exact = true;
};

// Minimises |x - corner|^2 subject to n_i.x = d_i for 1 to 3 planes (more is a caller bug:
// four planes meet in one point only when made to: PanelLayout::make_single_point_nodes). Planes must be
// pairwise distinct (master planes at least a degree apart); `planes` may be empty (returns
// the corner).
VertexRuleResult closest_point_on_planes(const std::vector<Plane>& planes, const Vec3& corner);

}  // namespace ff
