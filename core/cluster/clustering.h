#pragma once
// Clustering: the state the Lloyd engine iterates on: a label per face, a proxy, a seed
// face and a stickiness countdown per cluster. Invariants after every public operation:
// labels in [0, n), every cluster non-empty and edge-connected, seeds[i] has label i.
#include <vector>

#include "core/cluster/metric.h"
#include "core/mesh/topology.h"

namespace ff {

struct Clustering {
  std::vector<int> labels;    // per face
  std::vector<Proxy> proxies; // per cluster
  std::vector<int> seeds;     // per cluster: its seed face
  std::vector<int> sticky;    // per cluster: iterations left during which its seed stays put
  double energy = 0.0;        // total metric energy of labels under proxies, kept by every refit

  int num_clusters() const { return static_cast<int>(proxies.size()); }
};

std::vector<ClusterMoments> cluster_moments(const FaceData& faces, const std::vector<int>& labels,
                                            int num_clusters);

// Refits every proxy to its cluster (Metric::fit); returns the moments it used.
std::vector<ClusterMoments> fit_proxies(const Metric& metric, Clustering& clustering);

EnergyTerms clustering_energy(const Metric& metric, const std::vector<ClusterMoments>& moments,
                              const std::vector<Proxy>& proxies);

// Per cluster, the face of least cost to its own proxy (paper: "choose new seed"); sticky
// clusters keep theirs.
void choose_seeds(const Metric& metric, Clustering& clustering);

// The clusters adjacent to each other across an edge, as sorted unique pairs (a < b).
std::vector<std::pair<int, int>> adjacent_cluster_pairs(const MeshTopology& topology,
                                                        const std::vector<int>& labels);

// True when every cluster is non-empty and edge-connected (for tests and debug checks).
bool clusters_are_contiguous(const MeshTopology& topology, const std::vector<int>& labels, int num_clusters);

}  // namespace ff
