// Metric terms against their definitions: closed forms vs numeric integration, moments vs
// per-face sums, the sphere-constrained proxy fit vs brute force.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <vector>

#include "core/cluster/clustering.h"
#include "core/cluster/metric.h"
#include "core/shapes/shapes.h"
#include "core/util/random.h"

namespace ff {
namespace {

TriMesh one_triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  TriMesh m;
  m.positions = {a, b, c};
  m.triangles = {{0, 1, 2}};
  return m;
}

// Midpoint rule on a fine barycentric subdivision of the triangle.
template <class F>
double integrate(const Vec3& a, const Vec3& b, const Vec3& c, F f, int k = 200) {
  const double area = 0.5 * (b - a).cross(c - a).norm();
  double sum = 0.0;
  for (int i = 0; i < k; ++i) {
    for (int j = 0; i + j < k; ++j) {
      // Upward sub-triangle centroid.
      const double u = (i + 1.0 / 3.0) / k, v = (j + 1.0 / 3.0) / k;
      sum += f(a + u * (b - a) + v * (c - a));
      if (i + j + 1 < k) {  // downward sub-triangle centroid
        const double u2 = (i + 2.0 / 3.0) / k, v2 = (j + 2.0 / 3.0) / k;
        sum += f(a + u2 * (b - a) + v2 * (c - a));
      }
    }
  }
  return sum * area / (static_cast<double>(k) * k);
}

TEST(Metric, L2ClosedFormMatchesNumericIntegration) {
  SplitMix64 rng(7);
  for (int trial = 0; trial < 5; ++trial) {
    const auto r = [&] { return Vec3(rng.uniform() * 2 - 1, rng.uniform() * 2 - 1, rng.uniform() * 2 - 1); };
    const Vec3 a = r(), b = r(), c = r();
    const TriMesh mesh = one_triangle(a, b, c);
    const FaceData fd = make_face_data(mesh);
    MetricWeights w;
    w.euclidean = 0.0;
    w.l21 = 0.0;
    w.l2 = 1.0;
    const Metric metric(fd, w, 1);
    Proxy p;
    p.center = r() * 0.5;
    p.normal = r().normalized();
    // The metric works in FaceData's local frame; integrate in world coordinates, where D
    // and the cost (an area) carry the frame's scale.
    const double d_world = metric.diameter() * fd.scale;
    const Vec3 x_world = fd.to_world(p.center);
    const double numeric =
        integrate(a, b, c, [&](const Vec3& q) { return std::pow(p.normal.dot(q - x_world), 2); }) / (d_world * d_world);
    const double cost_world = metric.cost(0, metric.terms(p)) * fd.area_to_world();
    EXPECT_NEAR(cost_world, numeric, 1e-4 * std::max(1e-3, numeric));
  }
}

TEST(Metric, SecondMomentMatchesNumericIntegration) {
  const Vec3 a(0.3, -1, 2), b(1.5, 0.2, 1.1), c(-0.7, 0.9, 0.4);
  const TriMesh mesh = one_triangle(a, b, c);
  const FaceData fd = make_face_data(mesh);
  ClusterMoments m;
  m.add_face(fd, 0);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      // Local coordinates l = (q - origin) / scale, local area = world area / scale^2.
      const double numeric = integrate(a, b, c,
                                       [&](const Vec3& q) {
                                         const Vec3 l = (q - fd.origin) / fd.scale;
                                         return l[i] * l[j];
                                       }) /
                             fd.area_to_world();
      EXPECT_NEAR(m.second(i, j), numeric, 1e-4 * std::max(1.0, std::abs(numeric)));
    }
  }
  // Exactly symmetric, also after more faces (add_face fills both halves from one term).
  m.add_face(fd, 0);
  EXPECT_TRUE(m.second == m.second.transpose());
}

TEST(Metric, EnergyFromMomentsEqualsSumOfFaceCosts) {
  const TriMesh mesh = make_roof(12, 9);
  const FaceData fd = make_face_data(mesh);
  MetricWeights w;
  w.euclidean = 0.7;
  w.l2 = 1.3;
  w.l21 = 0.4;
  const Metric metric(fd, w, 6);
  ClusterMoments m;
  for (int f = 0; f < 40; ++f) m.add_face(fd, f);
  Proxy p = metric.fit(m, Proxy{});
  p.center += Vec3(0.1, -0.2, 0.05);  // any proxy, not only the fitted one
  double sum = 0.0;
  for (int f = 0; f < 40; ++f) sum += metric.cost(f, metric.terms(p));
  EXPECT_NEAR(metric.energy(m, p).total(), sum, 1e-9 * sum);
}

// add(other, w) counts `other` w times: every field, the anisotropy moments too; with
// w = 1 it is add(other) to the bit.
TEST(Metric, WeightedAddCountsEveryMomentThatManyTimes) {
  const TriMesh mesh = make_roof(6, 5);
  FaceData fd = make_face_data(mesh);
  fd.stretch.assign(static_cast<size_t>(fd.num_faces()), Vec3(0.3, -0.2, 0.1));
  ClusterMoments part;
  for (int f = 0; f < 20; ++f) part.add_face(fd, f);
  ClusterMoments twice, weighted, once, unit;
  twice.add(part);
  twice.add(part);
  weighted.add(part, 2.0);
  once.add(part);
  unit.add(part, 1.0);
  const auto fields = [](const ClusterMoments& m) {
    std::vector<double> v = {m.area, m.centroid_sq, m.density_area, m.stretch_sq};
    for (int i = 0; i < 3; ++i) v.insert(v.end(), {m.first[i], m.normal_sum[i], m.stretch_first[i]});
    for (int i = 0; i < 9; ++i) v.insert(v.end(), {m.second(i), m.stretch_second(i)});
    return v;
  };
  const std::vector<double> a = fields(twice), b = fields(weighted);
  for (size_t k = 0; k < a.size(); ++k) {
    EXPECT_NEAR(a[k], b[k], 1e-12 * (1.0 + std::abs(a[k]))) << "field " << k;
  }
  EXPECT_GT(part.stretch_sq, 0.0);  // the anisotropy moments are really there
  EXPECT_EQ(fields(once), fields(unit));
}

TEST(Metric, DensityScalesTheEuclideanTerm) {
  const TriMesh mesh = make_plane(4, 4);
  std::vector<double> density(static_cast<size_t>(mesh.num_faces()), 1.0);
  for (size_t f = 0; f < density.size() / 2; ++f) density[f] = 4.0;
  const FaceData fd = make_face_data(mesh, density);
  double mean = 0.0;
  for (int f = 0; f < fd.num_faces(); ++f) mean += fd[f].area * fd[f].density;
  EXPECT_NEAR(mean / fd.total_area, 1.0, 1e-12);  // normalised
  EXPECT_NEAR(fd.records.front().density / fd.records.back().density, 4.0, 1e-12);
  MetricWeights w;
  w.l2 = w.l21 = 0.0;
  const Metric metric(fd, w, 2);
  Proxy dense, sparse;
  dense.density = fd.records.front().density;
  sparse.density = fd.records.back().density;
  EXPECT_NEAR(metric.cost(5, metric.terms(dense)) / metric.cost(5, metric.terms(sparse)), 4.0, 1e-12);
}

TEST(Metric, RejectsBadDensityAndWeights) {
  const TriMesh mesh = make_plane(2, 2);
  EXPECT_THROW(make_face_data(mesh, {1.0, 2.0}), std::runtime_error);
  std::vector<double> bad(static_cast<size_t>(mesh.num_vertices()), 1.0);
  bad[3] = 0.0;
  EXPECT_THROW(make_face_data(mesh, bad), std::runtime_error);
  bad[3] = std::nan("");
  EXPECT_THROW(make_face_data(mesh, bad), std::runtime_error);
  const FaceData fd = make_face_data(mesh);
  MetricWeights w;
  w.l2 = -1.0;
  EXPECT_THROW(Metric(fd, w, 2), std::runtime_error);
  w = MetricWeights{};
  w.euclidean = w.l2 = w.l21 = 0.0;
  EXPECT_THROW(Metric(fd, w, 2), std::runtime_error);
  w = MetricWeights{};
  w.euclidean = 1e308;  // would make costs overflow
  EXPECT_THROW(Metric(fd, w, 2), std::runtime_error);
  w = MetricWeights{};
  w.density = 100.0;
  EXPECT_THROW(Metric(fd, w, 2), std::runtime_error);
  w = MetricWeights{};
  w.l21 = std::nan("");
  EXPECT_THROW(Metric(fd, w, 2), std::runtime_error);
}

double sphere_objective(const Eigen::Matrix3d& A, const Vec3& b, const Vec3& n) {
  return n.dot(A * n) - 2.0 * b.dot(n);
}

// Brute force: dense sampling of the sphere, then local refinement.
double brute_force_min(const Eigen::Matrix3d& A, const Vec3& b) {
  double best = 1e300;
  Vec3 best_n = Vec3::UnitZ();
  const int k = 300;
  for (int i = 0; i <= k; ++i) {
    const double theta = M_PI * i / k;
    for (int j = 0; j < 2 * k; ++j) {
      const double phi = M_PI * j / k;
      const Vec3 n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      const double v = sphere_objective(A, b, n);
      if (v < best) best = v, best_n = n;
    }
  }
  for (double step = 1e-2; step > 1e-9; step *= 0.5) {
    for (int axis = 0; axis < 3; ++axis) {
      for (int sgn = -1; sgn <= 1; sgn += 2) {
        Vec3 n = best_n;
        n[axis] += sgn * step;
        n.normalize();
        const double v = sphere_objective(A, b, n);
        if (v < best) best = v, best_n = n;
      }
    }
  }
  return best;
}

TEST(Metric, SphereConstrainedFitIsTheGlobalMinimum) {
  SplitMix64 rng(3);
  for (int trial = 0; trial < 12; ++trial) {
    Eigen::Matrix3d R;
    for (int i = 0; i < 9; ++i) R(i / 3, i % 3) = rng.uniform() * 2 - 1;
    Eigen::Matrix3d A = R.transpose() * R;  // PSD like a covariance
    Vec3 b(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
    b *= (trial % 3 == 0) ? 0.01 : (trial % 3 == 1 ? 1.0 : 20.0);
    const Vec3 n = minimize_quadratic_on_sphere(A, b);
    EXPECT_NEAR(n.norm(), 1.0, 1e-12);
    EXPECT_LE(sphere_objective(A, b, n), brute_force_min(A, b) + 1e-9) << "trial " << trial;
  }
}

// The minimiser by the stationarity conditions alone, to full precision: (A - mu I) n = b
// with |n| = 1 and mu below A's smallest eigenvalue (the global minimum's multiplier), mu
// found by bisection down to adjacent doubles. A slow reference for the fast solver (which
// stopped its own bisection at 1e-15 relative before it used Newton's method).
Vec3 sphere_min_by_bisection(const Eigen::Matrix3d& A, const Vec3& b) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(A);
  const Vec3 lambda = eig.eigenvalues();
  const Vec3 beta = eig.eigenvectors().transpose() * b;
  const auto norm_sq = [&](double mu) {
    double sum = 0.0;
    for (int k = 0; k < 3; ++k) sum += beta[k] * beta[k] / ((lambda[k] - mu) * (lambda[k] - mu));
    return sum;
  };
  double lo = lambda[0] - b.norm(), hi = lambda[0];
  for (;;) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (norm_sq(mid) > 1.0 ? hi : lo) = mid;
  }
  Vec3 y;
  for (int k = 0; k < 3; ++k) y[k] = beta[k] / (lambda[k] - lo);
  return eig.eigenvectors() * y.normalized();
}

TEST(Metric, SphereFitMatchesTheStationarityConditions) {
  // Covariances of every shape and scale (flat, thin, round), mean normals from tiny to
  // dominant, and b nearly orthogonal to the lowest eigenvector (close to the hard case).
  SplitMix64 rng(17);
  for (int trial = 0; trial < 3000; ++trial) {
    const Eigen::Matrix3d R = Eigen::AngleAxisd(6.0 * rng.uniform(), Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5,
                                                                          rng.uniform() - 0.5).normalized())
                                  .toRotationMatrix();
    const double scale = std::pow(10.0, 8.0 * rng.uniform() - 4.0);
    const Vec3 l(std::pow(10.0, -6.0 * rng.uniform()), rng.uniform(), 1.0);
    const Eigen::Matrix3d A = scale * (R * l.asDiagonal() * R.transpose());
    Vec3 b = Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
    if (trial % 4 == 0) b -= b.dot(R.col(0)) * R.col(0) * (1.0 - 1e-6);  // almost the hard case
    b *= scale * std::pow(10.0, 6.0 * rng.uniform() - 3.0);
    const Vec3 n = minimize_quadratic_on_sphere(A, b);
    const Vec3 ref = sphere_min_by_bisection(A, b);
    EXPECT_NEAR(n.norm(), 1.0, 1e-14);
    // Near the hard case the minimiser is ill-conditioned (it moves by ~1e-7 where the
    // objective moves by rounding): compare the objective there, the vector elsewhere.
    if (trial % 4 != 0) {
      EXPECT_LE((n - ref).norm(), 1e-12) << "trial " << trial;
    }
    EXPECT_LE(sphere_objective(A, b, n), sphere_objective(A, b, ref) + 1e-15 * (scale + b.norm())) << "trial " << trial;
  }
}

TEST(Metric, SphereFitHardCaseAndPureCases) {
  // Hard case: b orthogonal to the lowest eigenvector, small enough not to reach the sphere.
  Eigen::Matrix3d A = Eigen::Vector3d(1.0, 3.0, 5.0).asDiagonal();
  Vec3 b(0.0, 0.5, 0.0);
  Vec3 n = minimize_quadratic_on_sphere(A, b);
  EXPECT_NEAR(sphere_objective(A, b, n), brute_force_min(A, b), 1e-9);
  // Hard case with a repeated lowest eigenvalue: the minimiser mixes e0/e1 with b's direction.
  const Eigen::Matrix3d flat = Eigen::Vector3d(0.0, 0.0, 1.0).asDiagonal();
  const Vec3 up(0.0, 0.0, 0.5);
  n = minimize_quadratic_on_sphere(flat, up);
  EXPECT_NEAR(sphere_objective(flat, up, n), -0.25, 1e-12);
  EXPECT_NEAR(sphere_objective(flat, up, n), brute_force_min(flat, up), 1e-9);
  // b = 0: the smallest eigenvector.
  n = minimize_quadratic_on_sphere(A, Vec3::Zero());
  EXPECT_NEAR(std::abs(n.x()), 1.0, 1e-12);
  // A = 0: b's direction (the L2,1 mean normal).
  n = minimize_quadratic_on_sphere(Eigen::Matrix3d::Zero(), Vec3(1, 2, 2));
  EXPECT_NEAR((n - Vec3(1, 2, 2) / 3.0).norm(), 0.0, 1e-9);
}

TEST(Metric, FitGivesL2EigenvectorOrL21MeanNormal) {
  const TriMesh mesh = make_roof(10, 10);
  const FaceData fd = make_face_data(mesh);
  ClusterMoments m;
  for (int f = 0; f < fd.num_faces(); f += 3) m.add_face(fd, f);
  MetricWeights l2only;
  l2only.euclidean = 0.0;
  l2only.l21 = 0.0;
  const Proxy p2 = Metric(fd, l2only, 4).fit(m, Proxy{});
  const Vec3 c = m.first / m.area;
  const Eigen::Matrix3d cov = m.second - m.area * c * c.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  EXPECT_NEAR(std::abs(p2.normal.dot(eig.eigenvectors().col(0))), 1.0, 1e-9);
  EXPECT_GT(p2.normal.dot(m.normal_sum), 0.0);
  MetricWeights l21only;
  l21only.euclidean = 0.0;
  l21only.l2 = 0.0;
  const Proxy p21 = Metric(fd, l21only, 4).fit(m, Proxy{});
  EXPECT_NEAR((p21.normal - m.normal_sum.normalized()).norm(), 0.0, 1e-9);
  EXPECT_NEAR((p21.center - c).norm(), 0.0, 1e-12);
}

}  // namespace
}  // namespace ff
