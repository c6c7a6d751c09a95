#pragma once
// Teleportation (Cohen-Steiner et al. 2004; paper 2.3 "shuffle the planes"): move a cluster
// from where it is cheap to lose to where it is needed, by merging the adjacent pair whose
// union costs least and splitting the worst cluster at its worst face. The new cluster is
// sticky for a few iterations so it does not drift straight back. The same two moves
// change the cluster count when a designer asks for more or fewer panels (warm start).
// On a mesh of several parts, no merge takes a part below its floor (cluster_floors,
// topology.h: four clusters on a closed part) unless the split it pays for is in that part.
#include <vector>

#include "core/cluster/clustering.h"
#include "core/cluster/moments_cache.h"

namespace ff {

struct TeleportOptions {
  int max_moves = 1;          // at most this many merge+split moves in one call
  int sticky_iterations = 3;  // how long new clusters keep their seed
};

// Each move happens only when the merge costs less than half the worst cluster's energy
// (the gain a split is expected to bring). Keeps n, refloods and refits when anything moved.
// Returns the number of moves. `moments` (optional, as for lloyd_iteration): the cluster
// moments and the refit come from it; the result is the same bits as without it.
int teleport(const Metric& metric, const MeshTopology& topology, Clustering& clustering,
             const TeleportOptions& options = {}, ClusterMomentsCache* moments = nullptr);

// Adds `count` clusters by splitting the worst ones (sticky), then refloods.
void add_clusters(const Metric& metric, const MeshTopology& topology, Clustering& clustering, int count,
                  int sticky_iterations = 3);

// Seeds a new cluster at each (cluster, face) request (the face must belong to that cluster
// and not be its seed; others are skipped, as are later requests for a cluster already split
// here): near a problem, "split a plane near the problem area and merge two planes elsewhere"
// (paper 2.3). For each split the cheapest adjacent pair of clusters not in `protect` and not
// named by any request is merged, so n stays; when no such pair is left, the remaining
// requests are dropped. The new clusters and the split ones are sticky. Refloods when
// `reflood_after` (else the caller floods next, e.g. with an extra cost). Returns the splits
// made.
int split_near(const Metric& metric, const MeshTopology& topology, Clustering& clustering,
               const std::vector<std::pair<int, int>>& requests, const std::vector<char>& protect,
               int sticky_iterations = 3, bool reflood_after = true);

// Moves each given cluster to the worst face of the worst cluster (by energy; a different
// one per move): its old faces go to its neighbours at the next flood. For clusters that
// cannot be panels where they are (enclosed by one neighbour). The moved clusters and the
// ones that gave up a face are sticky; no reflood (the caller floods next). Returns the moves
// made (list each cluster once: a repeated one moves again).
// Clusters marked in `keep` (e.g. settled ones) are never the worst cluster that receives one.
// On a mesh of several parts, a cluster whose part is at its floor moves within its part.
int relocate_clusters(const Metric& metric, const MeshTopology& topology, Clustering& clustering,
                      const std::vector<int>& clusters, const std::vector<char>& keep = {}, int sticky_iterations = 3);

// Removes `count` clusters by merging the cheapest adjacent pairs, renumbers labels to stay
// in [0, n - count), then refloods.
void remove_clusters(const Metric& metric, const MeshTopology& topology, Clustering& clustering, int count);

}  // namespace ff
