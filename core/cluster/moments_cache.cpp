#include "core/cluster/moments_cache.h"

#include <cstring>
#include <limits>

namespace ff {

const std::vector<ClusterMoments>& ClusterMomentsCache::update(const FaceData& faces, const std::vector<int>& labels,
                                                               int num_clusters) {
  const size_t n = static_cast<size_t>(num_clusters);
  if (labels_.size() != labels.size() || labels.size() != static_cast<size_t>(faces.num_faces())) {
    moments_ = cluster_moments(faces, labels, num_clusters);
    labels_ = labels;
    fitted_ok_.assign(n, 0);
    return moments_;
  }
  // A cluster is summed again when a face joined or left it, or when it is new.
  dirty_.assign(n, 0);
  for (size_t c = moments_.size(); c < n; ++c) dirty_[c] = 1;
  bool any = moments_.size() < n;
  for (size_t f = 0; f < labels.size(); ++f) {
    const int now = labels[f], before = labels_[f];
    if (now == before) continue;
    if (now >= 0 && static_cast<size_t>(now) < n) dirty_[static_cast<size_t>(now)] = 1;
    if (before >= 0 && static_cast<size_t>(before) < n) dirty_[static_cast<size_t>(before)] = 1;
    any = true;
  }
  moments_.resize(n);
  fitted_ok_.resize(n, 0);
  if (!any) return moments_;
  for (size_t c = 0; c < n; ++c) {
    if (dirty_[c]) moments_[c] = ClusterMoments{}, fitted_ok_[c] = 0;
  }
  for (size_t f = 0; f < labels.size(); ++f) {
    const int label = labels[f];
    if (label >= 0 && static_cast<size_t>(label) < n && dirty_[static_cast<size_t>(label)])
      moments_[static_cast<size_t>(label)].add_face(faces, static_cast<int>(f));
  }
  labels_ = labels;
  return moments_;
}

namespace {

bool same_bits(const Proxy& a, const Proxy& b) {
  return std::memcmp(a.center.data(), b.center.data(), sizeof(double) * 3) == 0 &&
         std::memcmp(a.normal.data(), b.normal.data(), sizeof(double) * 3) == 0 &&
         std::memcmp(&a.density, &b.density, sizeof(double)) == 0;
}

}  // namespace

EnergyTerms ClusterMomentsCache::refit(const Metric& metric, Clustering& clustering) {
  const std::vector<ClusterMoments>& moments = update(metric.faces(), clustering.labels, clustering.num_clusters());
  const size_t n = moments.size();
  fitted_.resize(n);
  for (size_t i = 0; i < n; ++i) {
    Proxy& proxy = clustering.proxies[i];
    if (!fitted_ok_[i] || !same_bits(proxy, fitted_[i])) proxy = metric.fit(moments[i], proxy);
    fitted_[i] = proxy;
    fitted_ok_[i] = 1;
  }
  const EnergyTerms energy = clustering_energy(metric, moments, clustering.proxies);
  clustering.energy = energy.total();
  return energy;
}

void ClusterMomentsCache::choose_seeds(const Metric& metric, Clustering& c) {
  const size_t n = static_cast<size_t>(c.num_clusters());
  const size_t faces = c.labels.size();
  if (seed_labels_.size() != faces) seeded_.assign(n, 0);
  seeded_.resize(n, 0);
  seed_proxies_.resize(n);
  seed_results_.resize(n, -1);
  // seed_work_: 1 = a face joined or left since the last call, then 2 = choose a seed now.
  seed_work_.assign(n, 0);
  if (seed_labels_.size() == faces) {
    for (size_t f = 0; f < faces; ++f) {
      const int now = c.labels[f], before = seed_labels_[f];
      if (now == before) continue;
      if (now >= 0 && static_cast<size_t>(now) < n) seed_work_[static_cast<size_t>(now)] = 1;
      if (before >= 0 && static_cast<size_t>(before) < n) seed_work_[static_cast<size_t>(before)] = 1;
    }
  }
  bool any = false;
  for (size_t i = 0; i < n; ++i) {
    const bool sticky = c.sticky[i] > 0;
    const bool kept =
        seeded_[i] && !seed_work_[i] && same_bits(c.proxies[i], seed_proxies_[i]) && c.seeds[i] == seed_results_[i];
    seed_work_[i] = !sticky && !kept ? 2 : 0;
    any = any || seed_work_[i] == 2;
  }
  if (any) {
    // choose_seeds() restricted to the clusters marked 2: the same costs in the same face order.
    const std::vector<Metric::Terms> terms = metric.terms(c.proxies);
    std::vector<double> best(n, std::numeric_limits<double>::infinity());
    for (size_t f = 0; f < faces; ++f) {
      const int i = c.labels[f];
      if (i < 0 || seed_work_[static_cast<size_t>(i)] != 2) continue;
      const double area = metric.faces()[f].area;
      if (!(area > 0.0)) continue;
      const double cost = metric.cost(static_cast<int>(f), terms[static_cast<size_t>(i)]) / area;
      if (cost < best[static_cast<size_t>(i)]) {
        best[static_cast<size_t>(i)] = cost;
        c.seeds[static_cast<size_t>(i)] = static_cast<int>(f);
      }
    }
  }
  seed_labels_ = c.labels;
  for (size_t i = 0; i < n; ++i) {
    seeded_[i] = c.sticky[i] <= 0;
    seed_proxies_[i] = c.proxies[i];
    seed_results_[i] = c.seeds[i];
  }
}

void ClusterMomentsCache::clear() {
  seed_labels_.clear();
  seeded_.clear();
  labels_.clear();
  moments_.clear();
  fitted_.clear();
  fitted_ok_.clear();
}

}  // namespace ff
