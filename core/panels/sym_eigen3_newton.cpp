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
// Newton converges in ~5-8 steps from the bound below (fewer from a good guess); near a
// double root only linearly.
constexpr int kMaxNewton = 64;

// Written out (the same operations Eigen's cross product does).
Vec3 cross(const Vec3& a, const Vec3& b) {
  return Vec3(a.y() * b.z() - a.z() * b.y(), a.z() * b.x() - a.x() * b.z(), a.x() * b.y() - a.y() * b.x());
}

}  // namespace

namespace {

// One solve, in three parts so that two can run their Newton loops side by side.
struct CubicSolve {
  const Eigen::Matrix3d* a = nullptr;
  bool fallback = false;  // hand over to smallest_eigenvector
  double b00 = 0.0, b11 = 0.0, b22 = 0.0, a10 = 0.0, a20 = 0.0, a21 = 0.0, p = 0.0, d = 0.0, mu = 0.0;
  int steps = 0;

  explicit CubicSolve(const Eigen::Matrix3d& m, const Vec3* guess = nullptr) : a(&m) {
    if (!m.allFinite()) {
      fallback = true;
      return;
    }
    // The lower triangle, scaled to [-1, 1] (no overflow in the cubic's terms).
    double scale = 0.0;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j <= i; ++j) scale = std::max(scale, std::abs(m(i, j)));
    }
    if (scale == 0.0) {
      fallback = true;
      return;
    }
    const double inv = 1.0 / scale;
    const double a00 = m(0, 0) * inv, a11 = m(1, 1) * inv, a22 = m(2, 2) * inv;
    a10 = m(1, 0) * inv, a20 = m(2, 0) * inv, a21 = m(2, 1) * inv;
    // B = A - qI has trace 0: det(mu I - B) = mu^3 - P mu - D, its roots in [-2s, 2s] with
    // s = sqrt(P / 3); the shift keeps the cubic's terms of the size of the spread.
    const double q = (a00 + a11 + a22) / 3.0;
    b00 = a00 - q, b11 = a11 - q, b22 = a22 - q;
    p = 0.5 * (b00 * b00 + b11 * b11 + b22 * b22) + a10 * a10 + a20 * a20 + a21 * a21;
    if (!(p > 0.0)) {
      fallback = true;
      return;
    }
    d = b00 * (b11 * b22 - a21 * a21) - a10 * (a10 * b22 - a21 * a20) + a20 * (a10 * a21 - b11 * a20);
    // f is increasing and concave left of its smallest root (f' >= 0 there, f'' = 6 mu < 0):
    // Newton from the bound -2s climbs to the root without overshooting; it stops when
    // rounding no longer lets it climb.
    mu = -2.0 * std::sqrt(p / 3.0);
    if (guess) start_near(*guess);
  }

  // A start closer than the bound: the Rayleigh quotient r of a guess (B's, in the scaled and
  // shifted frame) is at or above the smallest root. Where f(r) > 0 and r < 0 with f'(r) > 0,
  // r lies between the smallest root and f's first critical point, where f is increasing and
  // concave: one Newton step from r lands at or left of the root (the tangent lies above f),
  // off by about the square of r's error, and the climb goes on from there as from the bound.
  // A poor guess fails these tests or lands below the bound, and the bound stays.
  void start_near(const Vec3& g) {
    const double x = g.x(), y = g.y(), z = g.z();
    const double r = (b00 * x * x + b11 * y * y + b22 * z * z + 2.0 * (a10 * x * y + a20 * x * z + a21 * y * z)) /
                     (x * x + y * y + z * z);
    if (!(r < 0.0) || !(3.0 * r * r - p > 0.0)) return;
    const double f = (r * r - p) * r - d;
    if (!(f > 0.0)) return;
    const double next = r - f / (3.0 * r * r - p);
    if (next > mu) mu = next;
  }

  // One Newton step; false once it stops.
  bool step() {
    const double f = (mu * mu - p) * mu - d;
    const double fp = 3.0 * mu * mu - p;
    if (!(fp > 0.0)) return false;
    const double next = mu - f / fp;
    if (!(next > mu)) return false;
    mu = next;
    return ++steps < kMaxNewton;
  }

  Vec3 vector() const {
    if (fallback) return smallest_eigenvector(*a);
    // f'(mu1) = (mu1 - mu2)(mu1 - mu3): both gaps.
    const double gaps = 3.0 * mu * mu - p;
    if (steps == kMaxNewton || !(gaps > kGapShare * p)) return smallest_eigenvector(*a);
    // Rows of M = B - mu I (rank 2): the eigenvector is orthogonal to all of them.
    const Vec3 r0(b00 - mu, a10, a20), r1(a10, b11 - mu, a21), r2(a20, a21, b22 - mu);
    const Vec3 c01 = cross(r0, r1), c02 = cross(r0, r2), c12 = cross(r1, r2);
    const double n01 = c01.squaredNorm(), n02 = c02.squaredNorm(), n12 = c12.squaredNorm();
    // The longest is the best conditioned (the first on ties: deterministic).
    const Vec3& best = n01 >= n02 ? (n01 >= n12 ? c01 : c12) : (n02 >= n12 ? c02 : c12);
    const double norm2 = std::max(n01, std::max(n02, n12));
    if (!(norm2 > 0.0) || !std::isfinite(norm2)) return smallest_eigenvector(*a);
    return best / std::sqrt(norm2);
  }
};

}  // namespace

Vec3 smallest_eigenvector_newton(const Eigen::Matrix3d& a, const Vec3* guess) {
  CubicSolve solve(a, guess);
  if (!solve.fallback) {
    while (solve.step()) {
    }
  }
  return solve.vector();
}

void smallest_eigenvectors_newton(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b, Vec3& va, Vec3& vb,
                                  const Vec3* guess_a, const Vec3* guess_b) {
  CubicSolve x(a, guess_a), y(b, guess_b);
  bool xs = !x.fallback, ys = !y.fallback;
  // Each step waits on its division: two independent chains fill each other's wait.
  while (xs && ys) xs = x.step(), ys = y.step();
  while (xs) xs = x.step();
  while (ys) ys = y.step();
  va = x.vector();
  vb = y.vector();
}

}  // namespace ff
