#pragma once
// Teleportation (Cohen-Steiner et al. 2004; paper 2.3 "shuffle the planes"): move a cluster
// from where it is cheap to lose to where it is needed, by merging the adjacent pair whose
// union costs least and splitting the worst cluster at its worst face. The new cluster is
// sticky for a few iterations so it does not drift straight back. The same two moves
// change the cluster count when a designer asks for more or fewer panels (warm start).
#include <vector>

#include "core/cluster/clustering.h"

namespace ff {

struct TeleportOptions {
  int max_moves = 1;          // at most this many merge+split moves in one call
  int sticky_iterations = 3;  // how long new clusters keep their seed
};

// Each move happens only when the merge costs less than half the worst cluster's energy
// (the gain a split is expected to bring). Keeps n, refloods and refits when anything moved.
// Returns the number of moves.
int teleport(const Metric& metric, const MeshTopology& topology, Clustering& clustering,
             const TeleportOptions& options = {});

// Adds `count` clusters by splitting the worst ones (sticky), then refloods.
void add_clusters(const Metric& metric, const MeshTopology& topology, Clustering& clustering, int count,
                  int sticky_iterations = 3);

// Removes `count` clusters by merging the cheapest adjacent pairs, renumbers labels to stay
// in [0, n - count), then refloods.
void remove_clusters(const Metric& metric, const MeshTopology& topology, Clustering& clustering, int count);

}  // namespace ff
