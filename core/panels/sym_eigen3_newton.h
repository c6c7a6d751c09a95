#pragma once
// The eigenvector of the smallest eigenvalue of a symmetric 3x3 matrix from its
// characteristic cubic: Newton's method for the smallest root, then the eigenvector as the
// longest cross product of two rows of A - lambda I. Why: the plane relaxation (plane_relax.h)
// solves one such problem per plane and iteration, and Eigen's iterative QR (sym_eigen3.h,
// its bit-exact copy) cost ~1900 instructions a solve, a third of a small mesh's whole run;
// this costs a fraction of that. Only +, -, *, / and sqrt (IEEE exact), no trigonometry:
// the same bits native and in WebAssembly. Not the same bits as Eigen: the two agree to
// rounding (~1e-13 for well separated eigenvalues). When the smallest eigenvalue is (nearly)
// double, or the matrix is not finite, it hands over to smallest_eigenvector (sym_eigen3.h).
#include <Eigen/Core>

#include "core/mesh/tri_mesh.h"

namespace ff {

// a: symmetric (only its lower triangle is read). Returns a unit vector (Eigen's result,
// unit too, on the fallback); its sign is arbitrary. guess (optional): a vector near the
// answer, e.g. the last iteration's; it moves Newton's start closer to the root (fewer
// steps) when its Rayleigh quotient allows, and otherwise changes nothing. The result is
// the same to rounding with or without it, not the same bits.
Vec3 smallest_eigenvector_newton(const Eigen::Matrix3d& a, const Vec3* guess = nullptr);

// Two at once, the same bits as two calls: the Newton loops run side by side, so that one's
// division fills the other's wait (each step of one loop depends on its last).
void smallest_eigenvectors_newton(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b, Vec3& va, Vec3& vb,
                                  const Vec3* guess_a = nullptr, const Vec3* guess_b = nullptr);

}  // namespace ff
