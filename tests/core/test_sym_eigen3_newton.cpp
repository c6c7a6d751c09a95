// smallest_eigenvector_newton must give a unit eigenvector of the smallest eigenvalue: the
// same axis as Eigen's solver to rounding on random symmetric matrices of many scales and on
// plane-fit scatters (one eigenvalue near 0, the relaxation's weights up to 1e11), and a
// vector of the eigenspace on the degenerate ones (double smallest eigenvalue, zero,
// multiples of the identity) where it hands over to smallest_eigenvector.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "core/panels/sym_eigen3.h"
#include "core/panels/sym_eigen3_newton.h"
#include "core/util/random.h"

namespace ff {

namespace {

double uniform(SplitMix64& rng, double lo, double hi) { return lo + (hi - lo) * rng.uniform(); }

Eigen::Matrix3d random_rotation(SplitMix64& rng) {
  const Vec3 axis(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
  return Eigen::AngleAxisd(uniform(rng, 0.0, 3.0), axis.normalized()).toRotationMatrix();
}

// |v| = 1 and A v = l1 v up to `tol` of the matrix's scale, l1 Eigen's smallest eigenvalue.
void expect_smallest_eigenvector(const Eigen::Matrix3d& a, const Vec3& v, double tol) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(a);
  const double l1 = solver.eigenvalues()(0);
  const double scale = std::max(1e-300, a.cwiseAbs().maxCoeff());
  EXPECT_NEAR(v.norm(), 1.0, 1e-14) << a;
  EXPECT_LE((a * v - l1 * v).norm() / scale, tol) << a;
}

// A symmetric matrix of scale 10^[lo, hi] with eigenvalues l1 < l2 < l3 at least 1% of the
// spread apart (the axes are well defined), along the columns of `axes`.
struct Separated {
  Eigen::Matrix3d a;
  Eigen::Matrix3d axes;
  double scale;
};

Separated well_separated(SplitMix64& rng, double lo, double hi) {
  const double scale = std::pow(10.0, uniform(rng, lo, hi));
  const double l1 = uniform(rng, -1.0, 1.0);
  const double l2 = l1 + uniform(rng, 0.05, 1.0);
  const double l3 = l2 + uniform(rng, 0.05, 1.0);
  const Eigen::Matrix3d r = random_rotation(rng);
  return {scale * (r * Vec3(l1, l2, l3).asDiagonal() * r.transpose()), r, scale};
}

}  // namespace

TEST(SymEigen3Newton, MatchesEigenOnWellSeparatedEigenvalues) {
  SplitMix64 rng(7);
  for (int t = 0; t < 2000; ++t) {
    const auto [a, r, scale] = well_separated(rng, -30.0, 30.0);
    const Vec3 v = smallest_eigenvector_newton(a);
    EXPECT_NEAR(std::abs(v.dot(r.col(0))), 1.0, 1e-12) << a;
    expect_smallest_eigenvector(a, v, 1e-12);
    EXPECT_NEAR(std::abs(v.dot(smallest_eigenvector(a))), 1.0, 1e-12) << a;
  }
}

TEST(SymEigen3Newton, PlaneFitScattersGiveTheirNormal) {
  // Points near a plane plus nodes on it weighted up to 1e11 (plane_relax.cpp's W): the
  // smallest eigenvalue is ~0 against the others, the normal must come out to ~1e-12.
  SplitMix64 rng(11);
  for (int t = 0; t < 500; ++t) {
    const Eigen::Matrix3d r = random_rotation(rng);
    const Vec3 normal = r.col(2);
    Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
    const double aspect = uniform(rng, 0.1, 1.0);
    for (int i = 0; i < 6; ++i) {
      const double weight = i < 3 ? 1.0 : std::pow(10.0, uniform(rng, 0.0, 11.0));
      const Vec3 p = uniform(rng, -1, 1) * r.col(0) + aspect * uniform(rng, -1, 1) * r.col(1);
      s += weight * p * p.transpose();
    }
    const Vec3 v = smallest_eigenvector_newton(s);
    EXPECT_NEAR(std::abs(v.dot(normal)), 1.0, 1e-12) << s;
  }
}

TEST(SymEigen3Newton, DegenerateMatricesGiveAVectorOfTheEigenspace) {
  const Eigen::Matrix3d rot = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Matrix3d cases[] = {
      Eigen::Matrix3d::Identity(),
      -2.5 * Eigen::Matrix3d::Identity(),
      Eigen::Vector3d(1, 1, 2).asDiagonal(),
      rot * Eigen::Vector3d(1, 1, 2).asDiagonal() * rot.transpose(),
      rot * Eigen::Vector3d(1, 1 + 1e-9, 2).asDiagonal() * rot.transpose(),
      rot * Eigen::Vector3d(0, 0, 1).asDiagonal() * rot.transpose(),
      rot * Eigen::Vector3d(1, 1, 1e-12).asDiagonal() * rot.transpose(),
      Eigen::Vector3d(3, 1, 2).asDiagonal(),
  };
  for (const Eigen::Matrix3d& a : cases) expect_smallest_eigenvector(a, smallest_eigenvector_newton(a), 1e-9);
  // All zero: any unit vector.
  EXPECT_NEAR(smallest_eigenvector_newton(Eigen::Matrix3d::Zero()).norm(), 1.0, 1e-15);
}

TEST(SymEigen3Newton, ReadsOnlyTheLowerTriangle) {
  Eigen::Matrix3d a;
  a << 4, 1, 0.5, 1, 3, 0.2, 0.5, 0.2, 1;
  Eigen::Matrix3d b = a;
  b(0, 1) = 100.0, b(0, 2) = -7.0, b(1, 2) = 3.0;  // upper triangle ignored
  const Vec3 va = smallest_eigenvector_newton(a), vb = smallest_eigenvector_newton(b);
  EXPECT_EQ(0, std::memcmp(va.data(), vb.data(), sizeof(double) * 3));
}

// Two at once gives what two calls give, bit for bit, whichever of the two stops first or
// falls back (degenerate, zero, non-finite).
TEST(SymEigen3Newton, TwoAtOnceAsTwoCalls) {
  SplitMix64 rng(5);
  std::vector<Eigen::Matrix3d> cases = {Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Identity(),
                                        Eigen::Vector3d(1, 1, 2).asDiagonal()};
  Eigen::Matrix3d nan = Eigen::Matrix3d::Identity();
  nan(1, 0) = std::nan("");
  cases.push_back(nan);
  for (int t = 0; t < 200; ++t) {
    const Eigen::Matrix3d r = random_rotation(rng);
    const Vec3 l(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
    cases.push_back(std::pow(10.0, uniform(rng, -5.0, 5.0)) * (r * l.asDiagonal() * r.transpose()));
  }
  const auto same = [](const Vec3& x, const Vec3& y) {
    return std::memcmp(x.data(), y.data(), sizeof(double) * 3) == 0 || (!x.allFinite() && !y.allFinite());
  };
  for (size_t i = 0; i < cases.size(); ++i) {
    const Eigen::Matrix3d& a = cases[i];
    const Eigen::Matrix3d& b = cases[(i * 7 + 3) % cases.size()];
    Vec3 va, vb;
    smallest_eigenvectors_newton(a, b, va, vb);
    EXPECT_TRUE(same(va, smallest_eigenvector_newton(a))) << a;
    EXPECT_TRUE(same(vb, smallest_eigenvector_newton(b))) << b;
  }
}

// A guess (the relaxation passes each plane's last normal) only moves the start: good, poor,
// wrong (another eigenvector), zero or not finite, the result is the smallest eigenvector
// to the same accuracy, and two at once still give what two calls give.
TEST(SymEigen3Newton, AGuessOnlyMovesTheStart) {
  SplitMix64 rng(13);
  for (int t = 0; t < 1000; ++t) {
    const auto [a, r, scale] = well_separated(rng, -20.0, 20.0);
    const Vec3 noise(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
    const Vec3 guesses[] = {r.col(0),
                            r.col(0) + 1e-6 * noise,
                            r.col(0) + 1e-2 * noise,
                            -(r.col(0) + 0.5 * noise),
                            r.col(1),
                            r.col(2),
                            noise,
                            Vec3::Zero(),
                            Vec3(std::nan(""), 0.0, 1.0),
                            Vec3(std::numeric_limits<double>::infinity(), 0.0, 0.0)};
    for (const Vec3& g : guesses) {
      const Vec3 v = smallest_eigenvector_newton(a, &g);
      EXPECT_NEAR(std::abs(v.dot(r.col(0))), 1.0, 1e-12) << a << "\nguess " << g.transpose();
      expect_smallest_eigenvector(a, v, 1e-12);
    }
    const Eigen::Matrix3d b = a + scale * Eigen::Matrix3d::Identity();
    Vec3 va, vb;
    smallest_eigenvectors_newton(a, b, va, vb, &guesses[1], &guesses[4]);
    const Vec3 ca = smallest_eigenvector_newton(a, &guesses[1]), cb = smallest_eigenvector_newton(b, &guesses[4]);
    EXPECT_EQ(0, std::memcmp(va.data(), ca.data(), sizeof(double) * 3));
    EXPECT_EQ(0, std::memcmp(vb.data(), cb.data(), sizeof(double) * 3));
  }
  // Plane-fit scatters (smallest eigenvalue ~0, weights up to 1e11) with their normal nearly
  // known, as in the relaxation's later iterations.
  for (int t = 0; t < 500; ++t) {
    const Eigen::Matrix3d r = random_rotation(rng);
    Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
    for (int i = 0; i < 6; ++i) {
      const double weight = i < 3 ? 1.0 : std::pow(10.0, uniform(rng, 0.0, 11.0));
      const Vec3 p = uniform(rng, -1, 1) * r.col(0) + uniform(rng, -1, 1) * r.col(1);
      s += weight * p * p.transpose();
    }
    const Vec3 guess = r.col(2) + 1e-4 * r.col(0);
    EXPECT_NEAR(std::abs(smallest_eigenvector_newton(s, &guess).dot(r.col(2))), 1.0, 1e-12) << s;
  }
}

TEST(SymEigen3Newton, NonFiniteInputGoesToTheExactSolver) {
  Eigen::Matrix3d a = Eigen::Matrix3d::Identity();
  a(1, 0) = a(0, 1) = std::nan("");
  const Vec3 ours = smallest_eigenvector_newton(a);
  const Vec3 exact = smallest_eigenvector(a);
  EXPECT_TRUE(std::memcmp(ours.data(), exact.data(), sizeof(double) * 3) == 0 ||
              (!ours.allFinite() && !exact.allFinite()));
}

}  // namespace ff
