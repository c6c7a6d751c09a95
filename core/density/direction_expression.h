#pragma once
// A procedural anisotropy direction (paper fig. 12, issue 6): three expressions of the density
// language (expression.h), "ex, ey, ez", giving a world vector per face, e.g. "-y, x, 0" (a
// vortex around the z axis), "nz, 0, -nx" or "if(z > 1, 1, 0), 0, 1". The components are the
// expression language's own (all its variables but border, which needs the border distances
// only the density field computes), so the same safety limits hold: the whole text at most
// Expression::kMaxLength characters, each component at most Expression::kMaxDepth levels
// deep, the three together at most Expression::kMaxTerms terms.
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "core/density/expression.h"
#include "core/mesh/curvature.h"
#include "core/mesh/tri_mesh.h"

namespace ff {

struct DirectionExpression {
  std::array<Expression, 3> components;  // x, y, z
  // k1, k2, H, K or curv in any component: the caller has to estimate curvature.
  bool uses_curvature() const;
};

// Splits `text` at its top-level commas (not those inside function calls) into exactly three
// components and parses each. Throws InputError naming the component and the column in the
// whole text, e.g. "direction expression, component 2 (y): unknown name 'q' at column 5".
DirectionExpression parse_direction_expression(std::string_view text);

// The expression per face, evaluated at the face's centroid with its unit face normal as
// nx ny nz (u v w over the mesh's bounding box; k1 k2 H K curv the mean of its corners'), and
// normalised to unit length; a zero vector gives a zero direction (that face stays isotropic,
// as does one whose direction is along its normal: anisotropy.h projects into the face plane).
// `curvature` is needed (non-null) only when expr.uses_curvature(). Throws InputError naming
// the face, the component and the centroid where a value is not finite.
std::vector<Vec3> expression_face_directions(const TriMesh& mesh, const DirectionExpression& expr,
                                             const VertexCurvature* curvature);

}  // namespace ff
