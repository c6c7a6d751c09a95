#include "core/panels/sym_eigen3.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace ff {

namespace {

// Eigen 3.4 step for step (SelfAdjointEigenSolver.h, Tridiagonalization.h, Jacobi.h), with
// the same operations in the same order; q is column-major like Eigen's eigenvector matrix.
struct Givens {
  double c = 1.0, s = 0.0;
};

// JacobiRotation<double>::makeGivens(p, q) without r.
Givens make_givens(double p, double q) {
  Givens g;
  if (q == 0.0) {
    g.c = p < 0.0 ? -1.0 : 1.0;
    g.s = 0.0;
  } else if (p == 0.0) {
    g.c = 0.0;
    g.s = q < 0.0 ? 1.0 : -1.0;
  } else if (std::abs(p) > std::abs(q)) {
    const double t = q / p;
    double u = std::sqrt(1.0 + t * t);
    if (p < 0.0) u = -u;
    g.c = 1.0 / u;
    g.s = -t * g.c;
  } else {
    const double t = p / q;
    double u = std::sqrt(1.0 + t * t);
    if (q < 0.0) u = -u;
    g.s = -1.0 / u;
    g.c = -t * g.s;
  }
  return g;
}

// numext::hypot for finite arguments (positive_real_hypot).
double eigen_hypot(double a, double b) {
  const double x = std::abs(a), y = std::abs(b);
  const double p = std::max(x, y);
  if (p == 0.0) return 0.0;
  const double qp = std::min(y, x) / p;
  return p * std::sqrt(1.0 + qp * qp);
}

// tridiagonal_qr_step (Francis implicit QR step, Wilkinson shift), Q = Q * G per rotation.
void qr_step(double* diag, double* subdiag, int start, int end, double* q) {
  const double td = (diag[end - 1] - diag[end]) * 0.5;
  const double e = subdiag[end - 1];
  double mu = diag[end];
  if (td == 0.0) {
    mu -= std::abs(e);
  } else if (e != 0.0) {
    const double e2 = e * e;
    const double h = eigen_hypot(td, e);
    if (e2 == 0.0)
      mu -= e / ((td + (td > 0.0 ? h : -h)) / e);
    else
      mu -= e2 / (td + (td > 0.0 ? h : -h));
  }
  double x = diag[start] - mu;
  double z = subdiag[start];
  for (int k = start; k < end && z != 0.0; ++k) {
    const Givens rot = make_givens(x, z);
    const double sdk = rot.s * diag[k] + rot.c * subdiag[k];
    const double dkp1 = rot.s * subdiag[k] + rot.c * diag[k + 1];
    diag[k] = rot.c * (rot.c * diag[k] - rot.s * subdiag[k]) - rot.s * (rot.c * subdiag[k] - rot.s * diag[k + 1]);
    diag[k + 1] = rot.s * sdk + rot.c * dkp1;
    subdiag[k] = rot.c * sdk - rot.s * dkp1;
    if (k > start) subdiag[k - 1] = rot.c * subdiag[k - 1] - rot.s * z;
    x = subdiag[k];
    if (k < end - 1) {
      z = -rot.s * subdiag[k + 1];
      subdiag[k + 1] = rot.c * subdiag[k + 1];
    }
    // applyOnTheRight(k, k + 1, rot): apply_rotation_in_the_plane with rot.transpose().
    const double c = rot.c, s = -rot.s;
    if (c == 1.0 && s == 0.0) continue;
    double* xs = q + 3 * k;
    double* ys = q + 3 * (k + 1);
    for (int i = 0; i < 3; ++i) {
      const double xi = xs[i], yi = ys[i];
      xs[i] = c * xi + s * yi;
      ys[i] = -s * xi + c * yi;
    }
  }
}

}  // namespace

Vec3 smallest_eigenvector(const Eigen::Matrix3d& a) {
  // Non-finite input: Eigen's own handling (its max and comparisons with NaN).
  if (!a.allFinite()) {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(a);
    return solver.eigenvectors().col(0);
  }
  // Map the lower triangle to [-1, 1].
  double m[3][3] = {{a(0, 0), 0.0, 0.0}, {a(1, 0), a(1, 1), 0.0}, {a(2, 0), a(2, 1), a(2, 2)}};
  double scale = 0.0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j <= i; ++j) scale = std::max(scale, std::abs(m[i][j]));
  }
  if (scale == 0.0) scale = 1.0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j <= i; ++j) m[i][j] /= scale;
  }
  // Tridiagonalization (the 3x3 specialisation), Q into q.
  double diag[3], subdiag[2];
  double q[9];
  diag[0] = m[0][0];
  const double v1norm2 = m[2][0] * m[2][0];
  if (v1norm2 <= std::numeric_limits<double>::min()) {
    diag[1] = m[1][1];
    diag[2] = m[2][2];
    subdiag[0] = m[1][0];
    subdiag[1] = m[2][1];
    const double identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    std::copy(identity, identity + 9, q);
  } else {
    const double beta = std::sqrt(m[1][0] * m[1][0] + v1norm2);
    const double inv_beta = 1.0 / beta;
    const double m01 = m[1][0] * inv_beta;
    const double m02 = m[2][0] * inv_beta;
    const double qq = 2.0 * m01 * m[2][1] + m02 * (m[2][2] - m[1][1]);
    diag[1] = m[1][1] + m02 * qq;
    diag[2] = m[2][2] - m02 * qq;
    subdiag[0] = beta;
    subdiag[1] = m[2][1] - m01 * qq;
    // mat << 1, 0, 0,  0, m01, m02,  0, m02, -m01 (column-major).
    const double tri[9] = {1, 0, 0, 0, m01, m02, 0, m02, -m01};
    std::copy(tri, tri + 9, q);
  }
  // computeFromTridiagonal_impl with the default 30 iterations per row.
  const double consider_as_zero = std::numeric_limits<double>::min();
  const double precision_inv = 1.0 / std::numeric_limits<double>::epsilon();
  int end = 2, start = 0, iter = 0;
  constexpr int kMaxIterations = 30 * 3;
  while (end > 0) {
    for (int i = start; i < end; ++i) {
      if (std::abs(subdiag[i]) < consider_as_zero) {
        subdiag[i] = 0.0;
      } else {
        const double scaled = precision_inv * subdiag[i];
        if (scaled * scaled <= (std::abs(diag[i]) + std::abs(diag[i + 1]))) subdiag[i] = 0.0;
      }
    }
    while (end > 0 && subdiag[end - 1] == 0.0) end--;
    if (end <= 0) break;
    iter++;
    if (iter > kMaxIterations) break;
    start = end - 1;
    while (start > 0 && subdiag[start - 1] != 0.0) start--;
    qr_step(diag, subdiag, start, end, q);
  }
  if (iter <= kMaxIterations) {
    // The sort: only its first pass decides column 0 (the first smallest eigenvalue).
    int k = 0;
    for (int i = 1; i < 3; ++i) {
      if (diag[i] < diag[k]) k = i;
    }
    if (k > 0) std::swap_ranges(q, q + 3, q + 3 * k);
  }
  return Vec3(q[0], q[1], q[2]);
}

}  // namespace ff
