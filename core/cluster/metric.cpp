#include "core/cluster/metric.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/util/error.h"

namespace ff {

void ClusterMoments::add_face(const FaceData& faces, int face) {
  const size_t f = static_cast<size_t>(face);
  const double a = faces[f].area;
  const Vec3& c = faces[f].centroid;
  const std::array<double, 6>& s = faces[f].spread;
  area += a;
  first += a * c;
  centroid_sq += a * c.squaredNorm();
  // integral p p^T = a (c c^T + spread). Symmetric: each off-diagonal term is computed once
  // and added to both of its entries, with the bits a full 3x3 product gives each of them
  // (c_i c_j = c_j c_i exactly); a third of the arithmetic of the flood's refits.
  const double xx = a * (c.x() * c.x() + s[0]), yy = a * (c.y() * c.y() + s[1]), zz = a * (c.z() * c.z() + s[2]);
  const double xy = a * (c.x() * c.y() + s[3]), xz = a * (c.x() * c.z() + s[4]), yz = a * (c.y() * c.z() + s[5]);
  second(0, 0) += xx;
  second(1, 1) += yy;
  second(2, 2) += zz;
  second(0, 1) += xy;
  second(1, 0) += xy;
  second(0, 2) += xz;
  second(2, 0) += xz;
  second(1, 2) += yz;
  second(2, 1) += yz;
  normal_sum += a * faces[f].normal;
  density_area += a * faces[f].density;
  if (!faces.stretch.empty()) {
    const Vec3& e = faces.stretch[f];
    const double ec = e.dot(c);
    stretch_second += a * e * e.transpose();
    stretch_first += (a * ec) * e;
    stretch_sq += a * ec * ec;
  }
}

void ClusterMoments::add(const ClusterMoments& o) {
  area += o.area;
  first += o.first;
  centroid_sq += o.centroid_sq;
  second += o.second;
  normal_sum += o.normal_sum;
  density_area += o.density_area;
  stretch_second += o.stretch_second;
  stretch_first += o.stretch_first;
  stretch_sq += o.stretch_sq;
}

void ClusterMoments::add(const ClusterMoments& o, double weight) {
  area += weight * o.area;
  first += weight * o.first;
  centroid_sq += weight * o.centroid_sq;
  second += weight * o.second;
  normal_sum += weight * o.normal_sum;
  density_area += weight * o.density_area;
  stretch_second += weight * o.stretch_second;
  stretch_first += weight * o.stretch_first;
  stretch_sq += weight * o.stretch_sq;
}

EnergyTerms EnergyTerms::scaled(double factor) const {
  return EnergyTerms{euclidean * factor, l2 * factor, l21 * factor, density * factor};
}

EnergyTerms& EnergyTerms::operator+=(const EnergyTerms& o) {
  euclidean += o.euclidean;
  l2 += o.l2;
  l21 += o.l21;
  density += o.density;
  return *this;
}

Metric::Metric(const FaceData& faces, const MetricWeights& weights, int num_clusters)
    : faces_(&faces), weights_(weights), diameter_(0.0) {
  // Only ratios of weights matter; the caps keep every cost finite.
  const auto bad = [](double w, double cap) { return !(w >= 0.0 && w <= cap); };
  if (bad(weights.euclidean, kMaxWeight) || bad(weights.l2, kMaxWeight) || bad(weights.l21, kMaxWeight) ||
      bad(weights.boundary, kMaxWeight)) {
    throw InputError("metric weights must be between 0 and 1e6");
  }
  if (bad(weights.density, kMaxDensityWeight)) throw InputError("the density weight must be between 0 and 8");
  if (weights.euclidean + weights.l2 + weights.l21 <= 0.0) {
    throw InputError("at least one of the euclidean, l2 and l21 weights must be > 0");
  }
  if (num_clusters < 1) throw InputError("the number of panels must be at least 1");
  diameter_ = std::sqrt(faces.total_area / num_clusters);
  if (!(diameter_ > 0.0)) throw InputError("the surface has zero area");
  if (!faces.stretch.empty()) {
    if (faces.stretch.size() != faces.records.size()) throw InputError("anisotropy: one direction per face expected");
    stretch_ = faces.stretch.data();
  }
}

double Metric::density_scale(double density) const {
  // pow(1, y) is exactly 1 (C99 F.9.4.4): the uniform case skips the call, same bits.
  return weights_.density == 0.0 || density == 1.0 ? 1.0 : std::pow(density, weights_.density);
}

Metric::Terms Metric::terms(const Proxy& proxy) const {
  const double inv_d2 = 1.0 / (diameter_ * diameter_);
  return Terms{proxy.center, proxy.normal, weights_.euclidean * density_scale(proxy.density) * inv_d2,
               weights_.l2 * inv_d2, weights_.l21};
}

std::vector<Metric::Terms> Metric::terms(const std::vector<Proxy>& proxies) const {
  std::vector<Terms> out;
  out.reserve(proxies.size());
  for (const Proxy& p : proxies) out.push_back(terms(p));
  return out;
}

Vec3 minimize_quadratic_on_sphere(const Eigen::Matrix3d& A, const Vec3& b) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(A);
  const Vec3 lambda = eig.eigenvalues();  // ascending
  const Eigen::Matrix3d Q = eig.eigenvectors();
  const Vec3 beta = Q.transpose() * b;
  const double bnorm = b.norm();
  const double scale = std::max({std::abs(lambda[0]), std::abs(lambda[2]), bnorm, 1e-300});
  if (bnorm <= 1e-14 * scale) return Q.col(0);  // pure eigenproblem

  // Stationary points: (lambda_k - mu) y_k = beta_k with |y| = 1 and mu <= lambda_0, where
  // norm_sq(mu) = sum_k beta_k^2 / (lambda_k - mu)^2 = 1.
  // Hard case: b has (almost) no component in the lowest eigenspace (every k with
  // lambda_k ~ lambda_0), and the other components alone do not reach the sphere at
  // mu = lambda_0: the minimiser is their part plus whatever length is left along e_0.
  const double tiny = 1e-12 * bnorm;
  const double gap = 1e-14 * scale;
  double low_sq = 0.0, rest = 0.0;
  Vec3 y = Vec3::Zero();
  for (int k = 0; k < 3; ++k) {
    const double d = lambda[k] - lambda[0];
    if (d <= gap) {
      low_sq += beta[k] * beta[k];
    } else {
      y[k] = beta[k] / d;
      rest += y[k] * y[k];
    }
  }
  if (low_sq <= tiny * tiny && rest <= 1.0) {
    y[0] = std::sqrt(1.0 - rest);
    return Q * y;
  }
  // norm_sq is increasing on (-inf, lambda_0) and <= 1 at lambda_0 - |b|: find where it is 1.
  // Newton on 1 - 1/sqrt(norm_sq), nearly linear in mu (exactly so with one term; Moré and
  // Sorensen's secular function), inside a bracket [lo, hi] that each evaluation narrows; a
  // step that leaves the bracket bisects it instead. About 5 steps where plain bisection took
  // about 50, each waiting on its divisions (the clustering fits every cluster's normal on
  // every Lloyd iteration and every candidate merge).
  double lo = lambda[0] - bnorm, hi = lambda[0];
  double mu = lo;
  for (int it = 0; it < 200; ++it) {
    double sq = 0.0, slope = 0.0;  // norm_sq(mu) and its derivative
    for (int k = 0; k < 3; ++k) {
      const double inv = 1.0 / (lambda[k] - mu);
      const double term = beta[k] * beta[k] * inv * inv;
      sq += term;
      slope += 2.0 * term * inv;
    }
    (sq > 1.0 ? hi : lo) = mu;
    if (sq == 1.0) break;
    const double root = std::sqrt(sq);
    // g(mu) = 1 - 1/root, g'(mu) = slope / (2 sq root).
    double next = mu - (1.0 - 1.0 / root) * (2.0 * sq * root) / slope;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) break;  // the bracket is down to neighbouring doubles
    const bool settled = std::abs(next - mu) <= 2.2e-16 * std::max(std::abs(mu), std::abs(lambda[0]));
    mu = next;
    if (settled) break;
  }
  for (int k = 0; k < 3; ++k) {
    const double d = lambda[k] - mu;
    y[k] = d > 0.0 ? beta[k] / d : (beta[k] >= 0 ? 1.0 : -1.0);
  }
  return Q * y.normalized();
}

Proxy Metric::fit(const ClusterMoments& m, const Proxy& fallback) const {
  if (!(m.area > 0.0)) return fallback;
  Proxy p;
  p.center = m.first / m.area;
  p.density = m.density_area / m.area;
  Eigen::Matrix3d cov = m.second - m.area * p.center * p.center.transpose();
  cov = 0.5 * (cov + cov.transpose());
  p.normal = fit_normal(m, cov);
  if (stretch_ != nullptr && weights_.euclidean > 0.0) refine_anisotropic(m, p);
  return p;
}

Vec3 Metric::fit_normal(const ClusterMoments& m, const Eigen::Matrix3d& cov) const {
  const double inv_d2 = 1.0 / (diameter_ * diameter_);
  const Vec3 mean_normal = m.normal_sum;
  Vec3 normal;
  if (weights_.l2 > 0.0 || weights_.l21 > 0.0) {
    normal = minimize_quadratic_on_sphere(weights_.l2 * inv_d2 * cov, weights_.l21 * mean_normal);
  } else {
    // Euclidean only: the normal plays no part in the cost; keep the plane meaningful.
    normal =
        mean_normal.norm() > 0.0 ? Vec3(mean_normal.normalized()) : minimize_quadratic_on_sphere(cov, Vec3::Zero());
  }
  if (normal.dot(mean_normal) < 0.0) normal = -normal;
  return normal;
}

void Metric::refine_anisotropic(const ClusterMoments& m, Proxy& p) const {
  // Euclidean: x^T A x - 2 b.x + const with A = sum a M_f, b = sum a M_f c. L2 about x:
  // N^T cov N + area (N.(centroid - x))^2. For a fixed normal both are quadratic in x (one
  // 3x3 solve); for a fixed centre the normal is the usual sphere-constrained fit.
  const double inv_d2 = 1.0 / (diameter_ * diameter_);
  const double we = weights_.euclidean * density_scale(p.density) * inv_d2;
  const double w2 = weights_.l2 * inv_d2;
  const Eigen::Matrix3d A = m.area * Eigen::Matrix3d::Identity() - m.stretch_second;
  const Vec3 b = m.first - m.stretch_first;
  const Vec3 centroid = m.first / m.area;
  for (int round = 0; round < 3; ++round) {
    const Vec3& N = p.normal;
    const Eigen::Matrix3d lhs = we * A + (w2 * m.area) * N * N.transpose();
    const Vec3 rhs = we * b + (w2 * m.area * N.dot(centroid)) * N;
    const Vec3 x = lhs.ldlt().solve(rhs);
    if (!x.allFinite()) return;
    p.center = x;
    Eigen::Matrix3d about = m.second - m.first * x.transpose() - x * m.first.transpose() + m.area * x * x.transpose();
    about = 0.5 * (about + about.transpose());
    p.normal = fit_normal(m, about);
  }
}

EnergyTerms Metric::energy(const ClusterMoments& m, const Proxy& proxy) const {
  EnergyTerms e;
  if (!(m.area > 0.0)) return e;
  const double inv_d2 = 1.0 / (diameter_ * diameter_);
  const Vec3& x = proxy.center;
  const Vec3& N = proxy.normal;
  double euclid = std::max(0.0, m.centroid_sq - 2.0 * x.dot(m.first) + m.area * x.squaredNorm());
  if (stretch_ != nullptr) {
    euclid = std::max(0.0, m.centroid_sq - 2.0 * x.dot(m.first) + m.area * x.squaredNorm() - m.stretch_sq +
                               2.0 * x.dot(m.stretch_first) - x.dot(m.stretch_second * x));
  }
  const Eigen::Matrix3d about_x =
      m.second - m.first * x.transpose() - x * m.first.transpose() + m.area * x * x.transpose();
  const double l2 = std::max(0.0, N.dot(about_x * N));
  const double l21 = std::max(0.0, 2.0 * m.area - 2.0 * N.dot(m.normal_sum));
  e.euclidean = weights_.euclidean * euclid * inv_d2;
  e.density = weights_.euclidean * (density_scale(proxy.density) - 1.0) * euclid * inv_d2;
  e.l2 = weights_.l2 * l2 * inv_d2;
  e.l21 = weights_.l21 * l21;
  return e;
}

double Metric::energy_lower_bound(const ClusterMoments& m) const {
  if (!(m.area > 0.0)) return 0.0;  // energy() is 0 then
  const double inv_d2 = 1.0 / (diameter_ * diameter_);
  // |N.S| <= |S| for a unit N: l21 = 2A - 2 N.S >= 2A - 2|S|.
  const double l21 = weights_.l21 * std::max(0.0, 2.0 * m.area - 2.0 * m.normal_sum.norm());
  // The euclidean and density terms add up to w_e rho^w_d |p - x|^2 / D^2 integrated, least
  // at the centroid; with anisotropy the least is elsewhere, so only 0 is certain.
  const double we = weights_.euclidean * density_scale(m.density_area / m.area) * inv_d2;
  const double euclid = stretch_ == nullptr ? we * std::max(0.0, m.centroid_sq - m.first.squaredNorm() / m.area) : 0.0;
  // energy() subtracts large, nearly equal sums (centroid_sq against 2 x.first); its rounding
  // is a few ulps of them. 1e-9 of their size covers it many times over.
  const double margin = 1e-9 * (weights_.l21 * 2.0 * m.area + we * m.centroid_sq);
  const double bound = l21 + euclid - margin;
  return std::isnan(bound) ? -std::numeric_limits<double>::infinity() : bound;
}

}  // namespace ff
