#pragma once
// Clustering: the state the Lloyd engine iterates on: a label per face, a proxy, a seed
// face and a stickiness countdown per cluster. Invariants after every public operation:
// labels in [0, n), every cluster non-empty and edge-connected, seeds[i] has label i.
#include <vector>

#include "core/cluster/metric.h"
#include "core/mesh/topology.h"

namespace ff {

struct Clustering {
  std::vector<int> labels;     // per face
  std::vector<Proxy> proxies;  // per cluster
  std::vector<int> seeds;      // per cluster: its seed face
  std::vector<int> sticky;     // per cluster: iterations left during which its seed stays put
  double energy = 0.0;         // energy of labels under proxies (local frame), set by refit()

  int num_clusters() const { return static_cast<int>(proxies.size()); }
};

// The proxy of a cluster grown from one face: its centroid, its normal (or `fallback_normal`
// for a zero-area face) and its density.
Proxy single_face_proxy(const FaceData& faces, int face, const Vec3& fallback_normal);

std::vector<ClusterMoments> cluster_moments(const FaceData& faces, const std::vector<int>& labels, int num_clusters);

// Per cluster, its number of faces.
std::vector<int> cluster_sizes(const Clustering& clustering);

// Refits every proxy to its cluster (Metric::fit), sets clustering.energy and returns the
// energy by term. Call it whenever labels or the metric changed.
EnergyTerms refit(const Metric& metric, Clustering& clustering);
// The same with the moments of clustering.labels already at hand (ClusterMomentsCache).
EnergyTerms refit(const Metric& metric, Clustering& clustering, const std::vector<ClusterMoments>& moments);

EnergyTerms clustering_energy(const Metric& metric, const std::vector<ClusterMoments>& moments,
                              const std::vector<Proxy>& proxies);

// Per cluster, the face of least cost to its own proxy (paper: "choose new seed"); sticky
// clusters keep theirs.
void choose_seeds(const Metric& metric, Clustering& clustering);

// The clusters adjacent to each other across an edge, as sorted unique pairs (a < b).
std::vector<std::pair<int, int>> adjacent_cluster_pairs(const MeshTopology& topology, const std::vector<int>& labels);

// True when every cluster is non-empty and edge-connected (for tests and debug checks).
bool clusters_are_contiguous(const MeshTopology& topology, const std::vector<int>& labels, int num_clusters);

}  // namespace ff
