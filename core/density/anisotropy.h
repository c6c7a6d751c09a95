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
};

struct Anisotropy {
  AnisotropyDirection direction = AnisotropyDirection::None;
  Vec3 vector = Vec3::UnitX();  // Constant only; any non-zero length
  double stretch = 1.0;         // s, 1..10; 1 = isotropic

  static constexpr double kMaxStretch = 10.0;
  bool active() const { return direction != AnisotropyDirection::None && stretch != 1.0; }
  bool uses_curvature() const {
    return direction == AnisotropyDirection::MaxCurvature || direction == AnisotropyDirection::MinCurvature;
  }
  bool operator==(const Anisotropy& o) const {
    return direction == o.direction && vector == o.vector && stretch == o.stretch;
  }
  bool operator!=(const Anisotropy& o) const { return !(*this == o); }
};

// The names used by the page and the CLI: "none", "x", "y", "z", "maxCurvature",
// "minCurvature". Sets `a`'s direction (and vector) and returns true, or false for an unknown
// name. The name of a constant direction other than an axis is "vector".
bool set_anisotropy_direction(Anisotropy& a, const std::string& name);
const char* anisotropy_direction_name(const Anisotropy& a);

// Throws InputError for a stretch outside 1..10 or a zero / non-finite constant direction.
void validate_anisotropy(const Anisotropy& anisotropy);

// Per face: e_f = sqrt(1 - 1/s^2) * g_f * d_f, so M_f = I - e_f e_f^T. d_f is the direction
// projected into the face plane (shorter as the direction leaves the tangent plane, so the
// stretch fades smoothly instead of jumping); for curvature directions g_f in [0, 1] is how
// clearly the corners agree on one direction ((|k|max - |k|min) weighted coherence), so
// umbilic and flat regions stay isotropic. Empty when `anisotropy` is not active.
// `curvature` is needed (non-null) only for the curvature directions.
std::vector<Vec3> face_stretch_vectors(const TriMesh& mesh, const Anisotropy& anisotropy,
                                       const VertexCurvature* curvature);

}  // namespace ff
