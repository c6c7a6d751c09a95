#pragma once
// The eigenvector of the smallest eigenvalue of a symmetric 3x3 matrix, bit for bit what
// Eigen 3.4's SelfAdjointEigenSolver<Matrix3d>(A).eigenvectors().col(0) gives, at a fraction
// of its cost. Why: the plane relaxation (plane_relax.h) solves one such problem per plane and
// iteration (80 per relaxation), and the generic solver's dynamic-size QR steps were a quarter
// of the panel phase. Same bits matter: the panel rounds are chaotic, so any change in the
// last bit of a plane moves the whole result. The relaxation now uses the cheaper
// smallest_eigenvector_newton (sym_eigen3_newton.h), which falls back to this one on
// near-double eigenvalues and non-finite input.
#include <Eigen/Core>

#include "core/mesh/tri_mesh.h"

namespace ff {

// a: symmetric (only its lower triangle is read, as Eigen does). Non-finite entries go to
// Eigen's solver itself.
Vec3 smallest_eigenvector(const Eigen::Matrix3d& a);

}  // namespace ff
