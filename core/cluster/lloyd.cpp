#include "core/cluster/lloyd.h"

#include "core/cluster/flood.h"
#include "core/cluster/refine.h"

namespace ff {

Clustering initial_clustering(const Metric& metric, const MeshTopology& topology, const std::vector<int>& seeds) {
  const FaceData& faces = metric.faces();
  Clustering c;
  c.seeds = seeds;
  c.sticky.assign(seeds.size(), 0);
  c.proxies.reserve(seeds.size());
  for (int f : seeds) {
    Proxy p;
    p.center = faces[f].centroid;
    const Vec3& n = faces[f].normal;
    p.normal = n.squaredNorm() > 0.0 ? n : Vec3::UnitZ();
    p.density = faces[f].density;
    c.proxies.push_back(p);
  }
  reflood(metric, topology, c);
  return c;
}

LloydResult reflood(const Metric& metric, const MeshTopology& topology, Clustering& clustering) {
  const std::vector<int> before = clustering.labels;
  flood(metric, topology, clustering);
  LloydResult result;
  for (size_t f = 0; f < clustering.labels.size(); ++f) {
    if (f >= before.size() || before[f] != clustering.labels[f]) ++result.changed_faces;
  }
  const std::vector<ClusterMoments> moments = fit_proxies(metric, clustering);
  result.energy = clustering_energy(metric, moments, clustering.proxies);
  clustering.energy = result.energy.total();
  return result;
}

LloydResult lloyd_iteration(const Metric& metric, const MeshTopology& topology, Clustering& clustering) {
  choose_seeds(metric, clustering);
  const std::vector<int> before = clustering.labels;
  const double energy_before = clustering.energy;  // under the current proxies
  const double flooded = flood(metric, topology, clustering);
  // Flooding is greedy and can, rarely, land on a worse partition; then improve the previous
  // one by boundary moves instead, so the energy never rises (fitting then only lowers it).
  if (flooded > energy_before * (1.0 + 1e-12)) {
    clustering.labels = before;
    refine_boundaries(metric, topology, clustering);
  }
  LloydResult result;
  for (size_t f = 0; f < before.size(); ++f) result.changed_faces += before[f] != clustering.labels[f];
  const std::vector<ClusterMoments> moments = fit_proxies(metric, clustering);
  result.energy = clustering_energy(metric, moments, clustering.proxies);
  clustering.energy = result.energy.total();
  for (int& s : clustering.sticky) {
    if (s > 0) --s;
  }
  return result;
}

}  // namespace ff
