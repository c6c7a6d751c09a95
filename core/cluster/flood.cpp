#include "core/cluster/flood.h"

#include <limits>
#include <queue>

namespace ff {

namespace {

struct Entry {
  double cost;
  int face;
  int cluster;
  // Min-heap by cost; ties broken by face then cluster so the result never depends on
  // anything but the input.
  bool operator<(const Entry& o) const {
    if (cost != o.cost) return cost > o.cost;
    if (face != o.face) return face > o.face;
    return cluster > o.cluster;
  }
};

}  // namespace

double flood(const Metric& metric, const MeshTopology& topology, Clustering& clustering) {
  const int faces = metric.faces().num_faces();
  const int n = clustering.num_clusters();
  std::vector<int>& labels = clustering.labels;
  labels.assign(static_cast<size_t>(faces), -1);

  std::vector<Metric::Terms> terms;
  terms.reserve(static_cast<size_t>(n));
  for (const Proxy& p : clustering.proxies) terms.push_back(metric.terms(p));

  std::vector<double> best(static_cast<size_t>(faces), std::numeric_limits<double>::infinity());
  std::vector<Entry> storage;
  storage.reserve(static_cast<size_t>(faces) / 4 + 16);
  std::priority_queue<Entry> queue(std::less<Entry>(), std::move(storage));

  const auto push_neighbours = [&](int face, int cluster) {
    for (int g : topology.face_neighbors[static_cast<size_t>(face)]) {
      if (g < 0 || labels[static_cast<size_t>(g)] >= 0) continue;
      const double c = metric.cost(g, terms[static_cast<size_t>(cluster)]);
      if (c < best[static_cast<size_t>(g)]) {
        best[static_cast<size_t>(g)] = c;
        queue.push(Entry{c, g, cluster});
      }
    }
  };

  for (int i = 0; i < n; ++i) labels[static_cast<size_t>(clustering.seeds[static_cast<size_t>(i)])] = i;
  // Sticky clusters hold their seed's neighbours (unless another seed sits there).
  for (int i = 0; i < n; ++i) {
    if (clustering.sticky[static_cast<size_t>(i)] <= 0) continue;
    for (int g : topology.face_neighbors[static_cast<size_t>(clustering.seeds[static_cast<size_t>(i)])]) {
      if (g >= 0 && labels[static_cast<size_t>(g)] < 0) labels[static_cast<size_t>(g)] = i;
    }
  }
  double energy = 0.0;
  for (int f = 0; f < faces; ++f) {
    const int label = labels[static_cast<size_t>(f)];
    if (label < 0) continue;
    energy += metric.cost(f, terms[static_cast<size_t>(label)]);
    push_neighbours(f, label);
  }
  while (!queue.empty()) {
    const Entry e = queue.top();
    queue.pop();
    if (labels[static_cast<size_t>(e.face)] >= 0) continue;
    labels[static_cast<size_t>(e.face)] = e.cluster;
    energy += e.cost;
    push_neighbours(e.face, e.cluster);
  }
  return energy;
}

}  // namespace ff
