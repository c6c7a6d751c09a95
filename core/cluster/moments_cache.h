#pragma once
// Cluster moments kept between calls, for the panel phase: each round changes the faces of a
// few clusters (the settled ones keep theirs), yet refit() and every panel attempt summed the
// moments of all faces again. The cache compares the labels with the last ones it saw and sums
// again only the clusters that gained or lost a face, each over its faces in face order like
// cluster_moments(), so the moments are the same bits as a full sum.
#include <vector>

#include "core/cluster/metric.h"

namespace ff {

class ClusterMomentsCache {
 public:
  // The moments of `labels` (cluster_moments(faces, labels, num_clusters), bit for bit).
  // faces must be the FaceData of earlier calls: clear() when it changes.
  const std::vector<ClusterMoments>& update(const FaceData& faces, const std::vector<int>& labels, int num_clusters);
  // Forget everything: the next update() sums all faces.
  void clear();

 private:
  std::vector<int> labels_;  // as of the last update()
  std::vector<ClusterMoments> moments_;
  std::vector<char> dirty_;  // update()'s working memory
};

}  // namespace ff
