#pragma once
// Flooding (Cohen-Steiner et al. 2004, paper 3.1): grow all clusters at once from their
// seeds; a priority queue holds (cost, face, cluster) for faces next to a cluster and a face
// joins the cluster of its cheapest entry, when that entry is popped first. Clusters grow
// across edges only, so each stays contiguous. O(m log m); an entry is pushed only when it
// beats the face's best pending cost, so the queue stays near the size of the fronts.
#include <vector>

#include "core/cluster/clustering.h"
#include "core/cluster/metric.h"
#include "core/mesh/topology.h"

namespace ff {

// Reassigns clustering.labels from clustering.seeds and proxies. Sticky clusters also keep
// the faces around their seed (its edge neighbours), so a fresh cluster cannot be swallowed.
// Faces unreachable from any seed (a component without a seed) keep label -1; callers place
// at least one seed per component. Returns the energy of the new labels under the proxies it
// flooded with (the sum of the costs of every assignment), which Lloyd compares with the
// energy before to keep the iteration monotone.
double flood(const Metric& metric, const MeshTopology& topology, Clustering& clustering);

// A cost added to the metric's for a face in a cluster: the panel phase's boundary term
// (paper 3.2, fifth metric). Must be finite and >= 0.
class ExtraCost {
 public:
  virtual ~ExtraCost() = default;
  virtual double operator()(int face, int cluster) const = 0;
  // A face whose cluster is settled (>= 0) keeps it: the flood assigns it up front and never
  // queues it, so only the unsettled part of the surface costs time.
  virtual int fixed_label(int /*face*/) const { return -1; }
};

// flood() with `extra` added to every cost (nullptr: none). with_energy false: the labels
// only, returns 0 (the energy of the faces assigned up front costs a metric and an extra
// cost each: most of the surface in the panel phase's later rounds).
double flood(const Metric& metric, const MeshTopology& topology, Clustering& clustering, const ExtraCost* extra,
             bool with_energy = true);

}  // namespace ff
