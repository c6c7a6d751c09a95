#pragma once
// Lloyd iterations (paper 4, lloyd_iter): choose new seeds, flood, refit the proxies.
#include <vector>

#include "core/cluster/clustering.h"

namespace ff {

struct LloydResult {
  int changed_faces = 0;  // faces whose label changed; 0 means a fixed point
  EnergyTerms energy;     // after refitting
};

// Clusters grown from the given seed faces with single-face proxies, then refitted.
Clustering initial_clustering(const Metric& metric, const MeshTopology& topology, const std::vector<int>& seeds);

// One iteration; counts down stickiness.
LloydResult lloyd_iteration(const Metric& metric, const MeshTopology& topology, Clustering& clustering);

// Floods from the current seeds and refits: used after seeds or proxies were changed by hand.
LloydResult reflood(const Metric& metric, const MeshTopology& topology, Clustering& clustering);

}  // namespace ff
