#include "core/panels/sym_eigen3_newton.h"

#include <algorithm>
#include <cmath>

#include "core/panels/sym_eigen3.h"

namespace ff {

namespace {

// Below this share of P (see below) for (l2 - l1)(l3 - l1), the smallest eigenvalue is
// treated as near-double: the eigenvector of a near-double eigenvalue is ill-conditioned,
// and the cross product loses precision as (gap)^-2 where QR loses it as (gap)^-1.
constexpr double kGapShare = 1e-3;
// Newton converges in ~5-8 steps from the bound below; near a double root only linearly.
constexpr int kMaxNewton = 64;

// Written out (the same operations Eigen's cross product does).
Vec3 cross(const Vec3& a, const Vec3& b) {
  return Vec3(a.y() * b.z() - a.z() * b.y(), a.z() * b.x() - a.x() * b.z(), a.x() * b.y() - a.y() * b.x());
}

}  // namespace

Vec3 smallest_eigenvector_newton(const Eigen::Matrix3d& a) {
  if (!a.allFinite()) return smallest_eigenvector(a);
  // The lower triangle, scaled to [-1, 1] (no overflow in the cubic's terms).
  double scale = 0.0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j <= i; ++j) scale = std::max(scale, std::abs(a(i, j)));
  }
  if (scale == 0.0) return smallest_eigenvector(a);
  const double inv = 1.0 / scale;
  const double a00 = a(0, 0) * inv, a11 = a(1, 1) * inv, a22 = a(2, 2) * inv;
  const double a10 = a(1, 0) * inv, a20 = a(2, 0) * inv, a21 = a(2, 1) * inv;
  // B = A - qI has trace 0: det(mu I - B) = mu^3 - P mu - D, its roots in [-2s, 2s] with
  // s = sqrt(P / 3); the shift keeps the cubic's terms of the size of the spread.
  const double q = (a00 + a11 + a22) / 3.0;
  const double b00 = a00 - q, b11 = a11 - q, b22 = a22 - q;
  const double p = 0.5 * (b00 * b00 + b11 * b11 + b22 * b22) + a10 * a10 + a20 * a20 + a21 * a21;
  if (!(p > 0.0)) return smallest_eigenvector(a);
  const double d = b00 * (b11 * b22 - a21 * a21) - a10 * (a10 * b22 - a21 * a20) + a20 * (a10 * a21 - b11 * a20);
  // f is increasing and concave left of its smallest root (f' >= 0 there, f'' = 6 mu < 0):
  // Newton from the bound -2s climbs to the root without overshooting; it stops when
  // rounding no longer lets it climb.
  double mu = -2.0 * std::sqrt(p / 3.0);
  int steps = 0;
  for (; steps < kMaxNewton; ++steps) {
    const double f = (mu * mu - p) * mu - d;
    const double fp = 3.0 * mu * mu - p;
    if (!(fp > 0.0)) break;
    const double next = mu - f / fp;
    if (!(next > mu)) break;
    mu = next;
  }
  // f'(mu1) = (mu1 - mu2)(mu1 - mu3): both gaps.
  const double gaps = 3.0 * mu * mu - p;
  if (steps == kMaxNewton || !(gaps > kGapShare * p)) return smallest_eigenvector(a);
  // Rows of M = B - mu I (rank 2): the eigenvector is orthogonal to all of them.
  const Vec3 r0(b00 - mu, a10, a20), r1(a10, b11 - mu, a21), r2(a20, a21, b22 - mu);
  const Vec3 c01 = cross(r0, r1), c02 = cross(r0, r2), c12 = cross(r1, r2);
  const double n01 = c01.squaredNorm(), n02 = c02.squaredNorm(), n12 = c12.squaredNorm();
  // The longest is the best conditioned (the first on ties: deterministic).
  const Vec3& best = n01 >= n02 ? (n01 >= n12 ? c01 : c12) : (n02 >= n12 ? c02 : c12);
  const double norm2 = std::max(n01, std::max(n02, n12));
  if (!(norm2 > 0.0) || !std::isfinite(norm2)) return smallest_eigenvector(a);
  return best / std::sqrt(norm2);
}

}  // namespace ff
