#pragma once
// Candidate merges of adjacent clusters, cheapest first (the teleports' and the panel
// rounds' merges, teleport.h), fitted only as far as they are read. The cost of merging a
// and b is the union's energy at its fitted proxy less the energies of a and b; a move reads
// the first few free pairs, yet sorting every cost fitted every adjacent pair. Here each pair
// enters with a lower bound of its cost (Metric::energy_lower_bound, no fit), and a pair is
// fitted when its bound comes first: the order that comes out is exactly that of sorting the
// fitted costs by (cost, a, b), for every prefix read.
#include <cstddef>
#include <utility>
#include <vector>

#include "core/cluster/clustering.h"
#include "core/cluster/metric.h"

namespace ff {

struct MergeCandidate {
  double cost;  // energy of the union minus the energies of the two parts
  int a, b;     // a < b
  bool operator<(const MergeCandidate& o) const {
    if (cost != o.cost) return cost < o.cost;
    return a != o.a ? a < o.a : b < o.b;
  }
};

class MergeOrder {
 public:
  // pairs: adjacent cluster pairs (a < b); moments and energy: per cluster, energy at its
  // current proxy; proxies: the fits' fallbacks (a's proxy, as for a fit of zero area). All
  // are copied: the costs are those of the clusters as they are now.
  MergeOrder(const Metric& metric, const std::vector<std::pair<int, int>>& pairs,
             const std::vector<ClusterMoments>& moments, const std::vector<double>& energy,
             const std::vector<Proxy>& proxies);

  // The i-th cheapest merge, or null past the last. Reading i fits what ranking it needs.
  const MergeCandidate* at(size_t i);
  // How many pairs have been fitted so far (for tests and measurements).
  size_t fitted() const { return fitted_; }

 private:
  struct Pending {
    double key;  // the cost, or a lower bound of it
    bool exact;
    int a, b;
  };
  // Heap order, first out: the smallest key; at equal keys a bound before a cost (its cost
  // may tie and come first by (a, b)); costs at equal keys by (a, b).
  static bool later(const Pending& x, const Pending& y);

  const Metric& metric_;
  // Copies: the moves change the clusters' moments and proxies as they go, while every cost
  // must be the one of the clusters as they were (as when all were fitted up front).
  std::vector<ClusterMoments> moments_;
  std::vector<double> energy_;
  std::vector<Proxy> proxies_;
  std::vector<Pending> heap_;
  std::vector<MergeCandidate> sorted_;
  size_t fitted_ = 0;
};

// Every adjacent pair fitted and sorted: the reference MergeOrder must reproduce.
std::vector<MergeCandidate> all_merges_sorted(const Metric& metric, const std::vector<std::pair<int, int>>& pairs,
                                              const std::vector<ClusterMoments>& moments,
                                              const std::vector<double>& energy, const std::vector<Proxy>& proxies);

}  // namespace ff
