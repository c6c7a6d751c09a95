#pragma once
// The designer's clustering metric (paper 3.2, DESIGN.md 3): the cost of putting a face in a
// cluster, the per-cluster moments that make energies and proxy fits O(1), and the proxy
// fit that minimises the weighted energy exactly.
//
// For face f (area a, centroid c, normal n, density rho_f) and cluster i (proxy centre x,
// unit normal N, density rho_i = area mean of its faces' densities), with D the expected
// cluster diameter sqrt(total area / n):
//   euclidean  a |c - x|^2 / D^2, scaled by rho_i^w_density (the density term: panel area
//              ~ 1/density, because a denser cluster pays more for the same reach); with
//              anisotropy a (c-x)^T M_f (c-x) / D^2, M_f = I - e_f e_f^T (FaceData::stretch)
//   L2         integral over f of (N.(p - x))^2 / D^2   (exact, per triangle)
//   L2,1       a |n - N|^2                               (unit-less, as in the paper)
// All terms are areas, so the user weights compare like with like.
#include <Eigen/Core>
#include <vector>

#include "core/cluster/face_data.h"

namespace ff {

struct MetricWeights {
  double euclidean = 1.0;
  double l2 = 1.0;
  double l21 = 1.0;
  double density = 1.0;   // exponent of the density scaling of the euclidean term
  double boundary = 1.0;  // panel phase only
};

// A cluster's proxy plane (local frame of FaceData) and its density.
struct Proxy {
  Vec3 center = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
  double density = 1.0;
};

// Additive sufficient statistics of a set of faces.
struct ClusterMoments {
  double area = 0.0;
  Vec3 first = Vec3::Zero();                         // sum a c  (= integral of p dA)
  double centroid_sq = 0.0;                          // sum a |c|^2
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();  // integral of p p^T dA
  Vec3 normal_sum = Vec3::Zero();                    // sum a n
  double density_area = 0.0;                         // sum a rho_f
  // Anisotropy only (zero without): sum a e e^T, sum a e (e.c), sum a (e.c)^2, so the
  // euclidean energy sum a (c-x)^T (I - e e^T) (c-x) stays O(1) per cluster.
  Eigen::Matrix3d stretch_second = Eigen::Matrix3d::Zero();
  Vec3 stretch_first = Vec3::Zero();
  double stretch_sq = 0.0;

  void add_face(const FaceData& faces, int f);
  void add(const ClusterMoments& other);
  // Adds `weight` times other's moments: a set counted `weight` times (e.g. a border's line
  // moments scaled to weigh like the faces).
  void add(const ClusterMoments& other, double weight);
};

// Energy of a cluster (or a whole clustering) split by term; `density` is the part the
// density scaling adds to the euclidean term, so total() = sum of the four.
struct EnergyTerms {
  double euclidean = 0.0;
  double l2 = 0.0;
  double l21 = 0.0;
  double density = 0.0;

  double total() const { return euclidean + l2 + l21 + density; }
  EnergyTerms scaled(double factor) const;
  EnergyTerms& operator+=(const EnergyTerms& o);
};

class Metric {
 public:
  // num_clusters sets D = sqrt(total area / num_clusters).
  Metric(const FaceData& faces, const MetricWeights& weights, int num_clusters);

  const FaceData& faces() const { return *faces_; }
  const MetricWeights& weights() const { return weights_; }
  double diameter() const { return diameter_; }

  // Per-cluster factors for cost(): precompute once per proxy, then evaluate many faces.
  struct Terms {
    Vec3 center;
    Vec3 normal;
    double euclid_scale;  // w_e rho_i^w_d / D^2
    double l2_scale;      // w_2 / D^2
    double l21_scale;     // w_21
  };
  Terms terms(const Proxy& proxy) const;
  std::vector<Terms> terms(const std::vector<Proxy>& proxies) const;

  double cost(int face, const Terms& t) const {
    const FaceRecord& r = (*faces_)[static_cast<size_t>(face)];
    const Vec3& N = t.normal;
    const double l21 = (r.normal - N).squaredNorm();
    const Vec3 d = r.centroid - t.center;
    double reach = d.squaredNorm();
    if (stretch_ != nullptr) {
      const double along_e = stretch_[face].dot(d);
      reach -= along_e * along_e;
    }
    // A zero-weight term adds exactly +0.0 (its factors are finite and >= 0): skipping it
    // changes no bit of the result and spares the record's second cache line.
    double l2 = 0.0;
    if (t.l2_scale != 0.0) {
      const std::array<double, 6>& s = r.spread;
      const double along = N.dot(d);
      const double spread = s[0] * N.x() * N.x() + s[1] * N.y() * N.y() + s[2] * N.z() * N.z() +
                            2.0 * (s[3] * N.x() * N.y() + s[4] * N.x() * N.z() + s[5] * N.y() * N.z());
      l2 = t.l2_scale * (along * along + spread);
    }
    return r.area * (t.euclid_scale * reach + l2 + t.l21_scale * l21);
  }

  // The proxy minimising this cluster's weighted energy: centre at the area centroid (optimal
  // for both the euclidean and the L2 term), normal minimising w_2 L2 + w_21 L2,1 jointly on
  // the unit sphere (exact; reduces to the L2 eigenvector or the L2,1 mean normal when one
  // weight is 0), oriented with the cluster's mean normal. The cluster's density becomes its
  // area-mean density: a size target rather than a minimiser, so with a density field a
  // refit may raise the energy slightly (without one, fits only lower it). `fallback` is
  // returned for a cluster of zero area. With anisotropy the best centre is no longer the
  // centroid: centre and normal are then refined by block coordinate descent (each block
  // solved exactly, so the energy only goes down), a few rounds.
  Proxy fit(const ClusterMoments& m, const Proxy& fallback) const;

  EnergyTerms energy(const ClusterMoments& m, const Proxy& proxy) const;

  // A number no proxy's energy(m, proxy).total() falls below, as computed (rounding
  // included): each term's own minimum (L2,1 at the mean normal's direction, the euclidean
  // term at the centroid, L2 at 0), which their joint minimum cannot beat, less a margin for
  // rounding. Cheap (no fit): candidate merges are ranked by it before any is fitted.
  double energy_lower_bound(const ClusterMoments& m) const;

  static constexpr double kMaxWeight = 1e6;
  static constexpr double kMaxDensityWeight = 8.0;

 private:
  double density_scale(double density) const;
  Vec3 fit_normal(const ClusterMoments& m, const Eigen::Matrix3d& scatter) const;
  void refine_anisotropic(const ClusterMoments& m, Proxy& p) const;

  const FaceData* faces_;
  const Vec3* stretch_ = nullptr;  // faces_->stretch, or null when isotropic
  MetricWeights weights_;
  double diameter_;
};

// Minimises N^T A N - 2 b.N over unit vectors N (A symmetric 3x3): the trust-region
// subproblem on the sphere, solved through A's eigen-decomposition and the secular equation,
// including the "hard case". Exposed for tests.
Vec3 minimize_quadratic_on_sphere(const Eigen::Matrix3d& A, const Vec3& b);

}  // namespace ff
