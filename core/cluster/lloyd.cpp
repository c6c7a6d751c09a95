#include "core/cluster/lloyd.h"

#include "core/cluster/flood.h"
#include "core/cluster/refine.h"

namespace ff {

namespace {

// refit(), through the cache when there is one (the same bits either way).
EnergyTerms refit_with(const Metric& metric, Clustering& clustering, ClusterMomentsCache* moments) {
  return moments ? moments->refit(metric, clustering) : refit(metric, clustering);
}

int count_changes(const std::vector<int>& before, const std::vector<int>& after) {
  int changed = 0;
  for (size_t f = 0; f < after.size(); ++f) changed += f >= before.size() || before[f] != after[f];
  return changed;
}

}  // namespace

Clustering initial_clustering(const Metric& metric, const MeshTopology& topology, const std::vector<int>& seeds) {
  Clustering c;
  c.seeds = seeds;
  c.sticky.assign(seeds.size(), 0);
  c.proxies.reserve(seeds.size());
  for (int f : seeds) c.proxies.push_back(single_face_proxy(metric.faces(), f, Vec3::UnitZ()));
  reflood(metric, topology, c);
  return c;
}

LloydResult reflood(const Metric& metric, const MeshTopology& topology, Clustering& clustering,
                    ClusterMomentsCache* moments) {
  const std::vector<int> before = clustering.labels;
  flood(metric, topology, clustering);
  LloydResult result;
  result.changed_faces = count_changes(before, clustering.labels);
  result.energy = refit_with(metric, clustering, moments);
  return result;
}

LloydResult lloyd_iteration(const Metric& metric, const MeshTopology& topology, Clustering& clustering,
                            ClusterMomentsCache* moments) {
  if (moments) {
    moments->choose_seeds(metric, clustering);
  } else {
    choose_seeds(metric, clustering);
  }
  const std::vector<int> before = clustering.labels;
  const double energy_before = clustering.energy;  // under the current proxies (refit() keeps it)
  const double flooded = flood(metric, topology, clustering);
  // Flooding is greedy and can land on a worse partition; then improve the previous one by
  // boundary moves instead, so the energy never rises (fitting then only lowers it, density
  // aside: see Metric::fit). Near convergence with few faces per cluster this happens often
  // and late iterations become pure boundary refinement, which is what a fixed point needs.
  if (flooded > energy_before * (1.0 + 1e-12)) {
    clustering.labels = before;
    refine_boundaries(metric, topology, clustering);
  }
  LloydResult result;
  result.changed_faces = count_changes(before, clustering.labels);
  result.energy = refit_with(metric, clustering, moments);
  for (int& s : clustering.sticky) {
    if (s > 0) --s;
  }
  return result;
}

}  // namespace ff
