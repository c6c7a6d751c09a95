#pragma once
// Anisotropic panels (paper fig. 12, "snake skin"): the euclidean term of the metric measures
// distance with M_f = I - (1 - 1/s^2) d_f d_f^T instead of I, d_f the preferred direction in
// face f's tangent plane, so reaching along d_f costs 1/s^2 as much and panels grow about
// s times longer along it than across (cluster/metric.h).
#include <string>
#include <vector>

#include "core/mesh/curvature.h"
#include "core/mesh/topology.h"
#include "core/mesh/tri_mesh.h"

namespace ff {

enum class AnisotropyDirection {
  None,
  Constant,      // a fixed world direction (`vector`), e.g. x
  MaxCurvature,  // the principal direction of larger |curvature| (around a cylinder)
  MinCurvature,  // the principal direction of smaller |curvature| (along a cylinder)
  Expression,    // procedural: `expression` "ex, ey, ez" per face (direction_expression.h)
};

struct Anisotropy {
  AnisotropyDirection direction = AnisotropyDirection::None;
  Vec3 vector = Vec3::UnitX();  // Constant only; any non-zero length
  double stretch = 1.0;         // s, 1..10; 1 = isotropic
  std::string expression;       // Expression only, e.g. "-y, x, 0"

  static constexpr double kMaxStretch = 10.0;
  bool active() const { return direction != AnisotropyDirection::None && stretch != 1.0; }
  // The curvature directions, or an expression using k1, k2, H, K or curv (parses it).
  bool uses_curvature() const;
  bool operator==(const Anisotropy& o) const {
    return direction == o.direction && vector == o.vector && stretch == o.stretch && expression == o.expression;
  }
  bool operator!=(const Anisotropy& o) const { return !(*this == o); }
};

// The names used by the page and the CLI: "none", "x", "y", "z", "maxCurvature",
// "minCurvature", "expression" (the expression text is set apart). Sets `a`'s direction (and
// vector) and returns true, or false for an unknown name. The name of a constant direction
// other than an axis is "vector".
bool set_anisotropy_direction(Anisotropy& a, const std::string& name);
const char* anisotropy_direction_name(const Anisotropy& a);

// Throws InputError for a stretch outside 1..10, a zero / non-finite constant direction or a
// direction expression that does not parse (parse_direction_expression's message).
void validate_anisotropy(const Anisotropy& anisotropy);

// Per face: e_f = sqrt(1 - 1/s^2) * g_f * d_f, so M_f = I - e_f e_f^T. d_f is the direction
// projected into the face plane (shorter as the direction leaves the tangent plane, so the
// stretch fades smoothly instead of jumping); for curvature directions g_f in [0, 1] is how
// clearly the corners agree on one direction ((|k|max - |k|min) weighted coherence), so
// umbilic and flat regions stay isotropic. An expression's unit vector per face is projected
// like a constant direction (so "1, 0, 0" is exactly direction x); where it is zero or along
// the normal the face stays isotropic. Empty when `anisotropy` is not active. `curvature` is
// needed (non-null) only when anisotropy.uses_curvature().
std::vector<Vec3> face_stretch_vectors(const TriMesh& mesh, const Anisotropy& anisotropy,
                                       const VertexCurvature* curvature);

// Faces left (nearly) isotropic by an active anisotropy: those whose stretch vector is under
// 1% of the full stretch (a direction along the normal, a zero expression value, a flat or
// umbilic region for the curvature directions). 0 when `stretch` is empty.
int count_isotropic_faces(const std::vector<Vec3>& stretch, const Anisotropy& anisotropy);

}  // namespace ff
