#pragma once
// Boundary refinement: move faces on cluster borders to a neighbouring cluster whose proxy
// fits them better, one face at a time, never emptying or disconnecting a cluster and never
// moving a seed. Every move lowers the energy under fixed proxies, so Lloyd can fall back on
// it when a flood would raise the energy: the iteration stays monotone.
#include "core/cluster/clustering.h"

namespace ff {

// Visits border faces (and the neighbours of faces that moved) until nothing moves or
// max_passes visits per initial border face are spent. Returns the number of moves.
int refine_boundaries(const Metric& metric, const MeshTopology& topology, Clustering& clustering, int max_passes = 8);

}  // namespace ff
