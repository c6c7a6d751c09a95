#pragma once
// Cluster moments kept between calls, for the panel phase: each round changes the faces of a
// few clusters (the settled ones keep theirs), yet refit() and every panel attempt summed the
// moments of all faces again. The cache compares the labels with the last ones it saw and sums
// again only the clusters that gained or lost a face, each over its faces in face order like
// cluster_moments(), so the moments are the same bits as a full sum.
#include <vector>

#include "core/cluster/clustering.h"
#include "core/cluster/metric.h"

namespace ff {

class ClusterMomentsCache {
 public:
  // The moments of `labels` (cluster_moments(faces, labels, num_clusters), bit for bit).
  // faces must be the FaceData of earlier calls: clear() when it changes.
  const std::vector<ClusterMoments>& update(const FaceData& faces, const std::vector<int>& labels, int num_clusters);
  // refit(metric, clustering) with update()'s moments, the same bits: Metric::fit is a
  // function of a cluster's moments (or keeps the proxy when it has no area), so a cluster
  // whose faces did not change and whose proxy is still the one the last refit() gave it
  // keeps that proxy without fitting again. The metric must be the one of earlier calls.
  EnergyTerms refit(const Metric& metric, Clustering& clustering);
  // choose_seeds(metric, clustering), the same bits: a cluster's new seed is a function of
  // its faces, proxy, stickiness and old seed, so a cluster whose faces, proxy and seed are
  // what they were after the last call here (and was not sticky then) keeps its seed without
  // a pass over its faces. The metric must be the one of earlier calls.
  void choose_seeds(const Metric& metric, Clustering& clustering);
  // Forget everything: the next update() sums all faces, the next choose_seeds() visits all.
  void clear();

 private:
  std::vector<int> labels_;  // as of the last update()
  std::vector<ClusterMoments> moments_;
  std::vector<char> dirty_;      // update()'s working memory
  std::vector<Proxy> fitted_;    // per cluster: the proxy the last refit() gave it
  std::vector<char> fitted_ok_;  // per cluster: fitted_ holds the fit of its current moments
  // choose_seeds(): the labels, and per cluster the proxy and the seed, as of its last call;
  // seeded_ marks the clusters it chose a seed for then (not sticky).
  std::vector<int> seed_labels_;
  std::vector<Proxy> seed_proxies_;
  std::vector<int> seed_results_;
  std::vector<char> seeded_, seed_work_;
};

}  // namespace ff
