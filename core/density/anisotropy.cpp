#include "core/density/anisotropy.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "core/density/direction_expression.h"
#include "core/util/error.h"

namespace ff {

bool set_anisotropy_direction(Anisotropy& a, const std::string& name) {
  if (name == "none") {
    a.direction = AnisotropyDirection::None;
  } else if (name == "x" || name == "y" || name == "z") {
    a.direction = AnisotropyDirection::Constant;
    a.vector = name == "x" ? Vec3::UnitX() : name == "y" ? Vec3::UnitY() : Vec3::UnitZ();
  } else if (name == "maxCurvature") {
    a.direction = AnisotropyDirection::MaxCurvature;
  } else if (name == "minCurvature") {
    a.direction = AnisotropyDirection::MinCurvature;
  } else if (name == "expression") {
    a.direction = AnisotropyDirection::Expression;
  } else {
    return false;
  }
  if (a.direction != AnisotropyDirection::Expression) a.expression.clear();
  return true;
}

const char* anisotropy_direction_name(const Anisotropy& a) {
  switch (a.direction) {
    case AnisotropyDirection::None:
      return "none";
    case AnisotropyDirection::Constant:
      if (a.vector == Vec3::UnitX()) return "x";
      if (a.vector == Vec3::UnitY()) return "y";
      if (a.vector == Vec3::UnitZ()) return "z";
      return "vector";
    case AnisotropyDirection::MaxCurvature:
      return "maxCurvature";
    case AnisotropyDirection::MinCurvature:
      return "minCurvature";
    case AnisotropyDirection::Expression:
      return "expression";
  }
  return "none";
}

bool Anisotropy::uses_curvature() const {
  if (direction == AnisotropyDirection::Expression) return parse_direction_expression(expression).uses_curvature();
  return direction == AnisotropyDirection::MaxCurvature || direction == AnisotropyDirection::MinCurvature;
}

void validate_anisotropy(const Anisotropy& a) {
  if (!(a.stretch >= 1.0 && a.stretch <= Anisotropy::kMaxStretch))
    throw InputError("the anisotropy stretch must be between 1 and 10");
  if (a.direction == AnisotropyDirection::Constant && (!a.vector.allFinite() || !(a.vector.norm() > 0.0)))
    throw InputError("the anisotropy direction must be a finite, non-zero vector");
  if (a.direction == AnisotropyDirection::Expression) parse_direction_expression(a.expression);
}

std::vector<Vec3> face_stretch_vectors(const TriMesh& mesh, const Anisotropy& a, const VertexCurvature* curvature) {
  validate_anisotropy(a);
  if (!a.active()) return {};
  const bool want_max = a.direction == AnisotropyDirection::MaxCurvature;
  const bool by_curvature = want_max || a.direction == AnisotropyDirection::MinCurvature;
  if (by_curvature && curvature == nullptr) throw InputError("anisotropy by curvature needs curvature");
  const double amount = std::sqrt(1.0 - 1.0 / (a.stretch * a.stretch));
  const Vec3 constant = a.vector.normalized();
  // Expression: unit vectors per face (zero where it gives none), then projected as `constant`.
  std::vector<Vec3> procedural;
  if (a.direction == AnisotropyDirection::Expression)
    procedural = expression_face_directions(mesh, parse_direction_expression(a.expression), curvature);
  // Curvatures below this (relative to the model size) count as flat.
  const double tiny = 1e-9 / std::max(bbox_diagonal(mesh), 1e-300);
  std::vector<Vec3> out(mesh.triangles.size(), Vec3::Zero());
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const Vec3& p0 = mesh.positions[static_cast<size_t>(t[0])];
    const Vec3 cross =
        (mesh.positions[static_cast<size_t>(t[1])] - p0).cross(mesh.positions[static_cast<size_t>(t[2])] - p0);
    const double len = cross.norm();
    if (!(len > 0.0) || !std::isfinite(len)) continue;
    const Vec3 n = cross / len;
    Vec3 d = procedural.empty() ? constant : procedural[f];
    double coherence = 1.0;
    if (by_curvature) {
      // Corners' direction lines (sign-free) summed as tensors, weighted by how much the two
      // curvatures differ there; the top eigenvector is the face's direction.
      Eigen::Matrix3d tensor = Eigen::Matrix3d::Zero();
      double total = 0.0;
      for (int v : t) {
        const size_t i = static_cast<size_t>(v);
        const double a1 = std::abs(curvature->k1[i]), a2 = std::abs(curvature->k2[i]);
        const Vec3& dir = (a1 >= a2) == want_max ? curvature->dir1[i] : curvature->dir2[i];
        const Vec3 in_plane = dir - dir.dot(n) * n;
        tensor += std::abs(a1 - a2) * in_plane * in_plane.transpose();
        total += a1 + a2;
      }
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(tensor);
      const Eigen::Vector3d lambda = eig.eigenvalues();  // ascending
      coherence = total > 3.0 * tiny ? std::clamp((lambda[2] - lambda[1]) / total, 0.0, 1.0) : 0.0;
      d = eig.eigenvectors().col(2);
    }
    out[f] = amount * coherence * (d - d.dot(n) * n);
  }
  return out;
}

int count_isotropic_faces(const std::vector<Vec3>& stretch, const Anisotropy& a) {
  if (stretch.empty() || !a.active()) return 0;
  const double full = std::sqrt(1.0 - 1.0 / (a.stretch * a.stretch));
  int n = 0;
  for (const Vec3& e : stretch) n += e.norm() < 0.01 * full ? 1 : 0;
  return n;
}

}  // namespace ff
