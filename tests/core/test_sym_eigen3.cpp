// smallest_eigenvector must be Eigen's SelfAdjointEigenSolver column 0 bit for bit (the panel
// rounds are chaotic: a last-bit change moves every result), and an eigenvector of the
// smallest eigenvalue: checked on random symmetric matrices of many scales and on the
// degenerate ones (zero, multiples of the identity, repeated eigenvalues, already diagonal or
// tridiagonal, rank one, flat scatters like a plane's).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstring>
#include <vector>

#include "core/panels/sym_eigen3.h"
#include "core/util/random.h"

namespace ff {

namespace {

bool same_bits(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), sizeof(double) * 3) == 0; }

Vec3 eigen_reference(const Eigen::Matrix3d& a) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(a);
  return solver.eigenvectors().col(0);
}

double uniform(SplitMix64& rng, double lo, double hi) {
  return lo + (hi - lo) * static_cast<double>(rng.next() >> 11) * (1.0 / 9007199254740992.0);
}

Eigen::Matrix3d symmetric(const Eigen::Matrix3d& m) { return 0.5 * (m + m.transpose()); }

std::vector<Eigen::Matrix3d> special_matrices() {
  std::vector<Eigen::Matrix3d> out;
  out.push_back(Eigen::Matrix3d::Zero());
  out.push_back(Eigen::Matrix3d::Identity());
  out.push_back(-2.5 * Eigen::Matrix3d::Identity());
  out.push_back(Eigen::Vector3d(3, 1, 2).asDiagonal());
  out.push_back(Eigen::Vector3d(1, 1, 2).asDiagonal());
  out.push_back(Eigen::Vector3d(2, 1, 1).asDiagonal());
  out.push_back(Eigen::Vector3d(0, -1, 0).asDiagonal());
  Eigen::Matrix3d tri;
  tri << 2, 1, 0, 1, 2, 1, 0, 1, 2;
  out.push_back(tri);
  tri << 1, 1e-300, 0, 1e-300, 1, 1e-310, 0, 1e-310, 1;
  out.push_back(tri);
  const Vec3 v(0.3, -0.4, 0.5);
  out.push_back(v * v.transpose());
  out.push_back(1e-200 * v * v.transpose());
  out.push_back(1e200 * v * v.transpose());
  // A flat scatter: points on a plane (one eigenvalue 0), and two equal ones.
  Eigen::Matrix3d flat = Eigen::Matrix3d::Zero();
  for (int i = 0; i < 7; ++i) {
    const Vec3 p(std::cos(i), std::sin(i), 0.0);
    flat += p * p.transpose();
  }
  out.push_back(flat);
  Eigen::Matrix3d rot = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  out.push_back(rot * flat * rot.transpose());
  out.push_back(rot * Eigen::Vector3d(1, 1, 1e-12).asDiagonal() * rot.transpose());
  out.push_back(rot * Eigen::Vector3d(5, 5, 5).asDiagonal() * rot.transpose());
  return out;
}

}  // namespace

TEST(SymEigen3, MatchesEigenBitForBitOnSpecialMatrices) {
  for (const Eigen::Matrix3d& a : special_matrices()) {
    EXPECT_TRUE(same_bits(smallest_eigenvector(a), eigen_reference(a))) << a;
  }
}

TEST(SymEigen3, MatchesEigenBitForBitOnRandomMatrices) {
  SplitMix64 rng(7);
  int exact = 0;
  const int n = 20000;
  for (int t = 0; t < n; ++t) {
    Eigen::Matrix3d m;
    for (int i = 0; i < 9; ++i) m(i) = uniform(rng, -1.0, 1.0);
    const double scale = std::pow(10.0, uniform(rng, -12.0, 12.0));
    Eigen::Matrix3d a = scale * symmetric(m);
    if (t % 4 == 1) a = scale * m * m.transpose();  // positive semidefinite, like a scatter
    if (t % 4 == 2) a(2, 0) = a(0, 2) = 0.0;        // already tridiagonal
    if (t % 4 == 3) {                               // nearly flat: a scatter of near-planar points
      const Vec3 n0 = Vec3(m(0), m(1), m(2)).normalized();
      a = scale * (Eigen::Matrix3d::Identity() - (1.0 - 1e-9) * n0 * n0.transpose());
    }
    exact += same_bits(smallest_eigenvector(a), eigen_reference(a));
  }
  EXPECT_EQ(exact, n);
}

TEST(SymEigen3, IsAnEigenvectorOfTheSmallestEigenvalue) {
  const Eigen::Matrix3d rot = Eigen::AngleAxisd(1.1, Vec3(-1, 2, 0.5).normalized()).toRotationMatrix();
  const Eigen::Matrix3d a = rot * Eigen::Vector3d(4.0, 0.25, 9.0).asDiagonal() * rot.transpose();
  const Vec3 v = smallest_eigenvector(a);
  EXPECT_NEAR(v.norm(), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(v.dot(rot.col(1))), 1.0, 1e-12);  // the axis of eigenvalue 0.25
  EXPECT_LT((a * v - 0.25 * v).norm(), 1e-12);
}

TEST(SymEigen3, NonFiniteInputGivesEigensAnswer) {
  Eigen::Matrix3d a = Eigen::Matrix3d::Identity();
  a(1, 0) = a(0, 1) = std::nan("");
  const Vec3 ours = smallest_eigenvector(a);
  const Vec3 theirs = eigen_reference(a);
  EXPECT_TRUE(same_bits(ours, theirs) || (!ours.allFinite() && !theirs.allFinite()));
}

}  // namespace ff
