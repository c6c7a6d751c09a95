#pragma once
// Lloyd iterations (paper 4, lloyd_iter): choose new seeds, flood, refit the proxies.
#include <vector>

#include "core/cluster/clustering.h"
#include "core/cluster/moments_cache.h"

namespace ff {

struct LloydResult {
  int changed_faces = 0;  // faces whose label changed; 0 means a fixed point
  EnergyTerms energy;     // after refitting
};

// Clusters grown from the given seed faces with single-face proxies, then refitted.
Clustering initial_clustering(const Metric& metric, const MeshTopology& topology, const std::vector<int>& seeds);

// One iteration; counts down stickiness. `moments` (optional, kept by the caller across
// iterations on the same FaceData): refit through it, so only the clusters whose faces changed
// are summed and fitted again; the result is the same bits as without it.
LloydResult lloyd_iteration(const Metric& metric, const MeshTopology& topology, Clustering& clustering,
                            ClusterMomentsCache* moments = nullptr);

// Floods from the current seeds and refits: used after seeds or proxies were changed by hand.
// `moments` as for lloyd_iteration.
LloydResult reflood(const Metric& metric, const MeshTopology& topology, Clustering& clustering,
                    ClusterMomentsCache* moments = nullptr);

}  // namespace ff
