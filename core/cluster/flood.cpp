#include "core/cluster/flood.h"

#include <algorithm>
#include <array>
#include <limits>

#include "core/cluster/quad_heap.h"

namespace ff {

double flood(const Metric& metric, const MeshTopology& topology, Clustering& clustering) {
  return flood(metric, topology, clustering, nullptr);
}

double flood(const Metric& metric, const MeshTopology& topology, Clustering& clustering, const ExtraCost* extra,
             bool with_energy) {
  const int faces = metric.faces().num_faces();
  const int n = clustering.num_clusters();

  const std::vector<Metric::Terms> terms = metric.terms(clustering.proxies);

  // Per face, together so one cache miss brings all of it: its label, and its cheapest
  // pending offer. A face is pushed only when an offer beats the pending one, and when
  // popped first it joins that offer's cluster (later, costlier entries are stale).
  struct FaceState {
    double best = std::numeric_limits<double>::infinity();
    int best_cluster = -1;
    int label = -1;
  };
  std::vector<FaceState> state(static_cast<size_t>(faces));
  QuadHeap<KeyedItem, KeyedBefore> queue;
  queue.reserve(static_cast<size_t>(faces) / 8 + 64);

  const FaceData& records = metric.faces();
  const bool reads_spread = metric.weights().l2 != 0.0;
  // Below about 1 MB the face data sits in the core's own cache and prefetching only costs
  // (bunny.off, 0.9 MB: level); above it pays (fandisk.off, 1.8 MB: the whole solve 3.5% faster).
  const bool prefetch = static_cast<size_t>(faces) * sizeof(FaceRecord) > (size_t{1} << 20);
  const auto push_neighbours = [&](int face, int cluster) {
    const std::array<int, 3>& neighbours = topology.face_neighbors[static_cast<size_t>(face)];
    for (int g : neighbours) {
      if (g < 0) continue;
      FaceState& s = state[static_cast<size_t>(g)];
      if (s.label >= 0 || s.best_cluster == cluster) continue;
      double c = metric.cost(g, terms[static_cast<size_t>(cluster)]);
      if (extra) c += (*extra)(g, cluster);
      // Costs are finite for validated input; should one not be, the face must still be
      // reached (an unassigned face would break every caller), just last.
      if (!(c <= std::numeric_limits<double>::max())) c = std::numeric_limits<double>::max();
      if (c < s.best) {
        s.best = c;
        s.best_cluster = cluster;
        queue.push(KeyedItem{order_key(c), g});
      }
    }
  };

  if (extra) {
    for (int f = 0; f < faces; ++f) state[static_cast<size_t>(f)].label = extra->fixed_label(f);
  }
  for (int i = 0; i < n; ++i) state[static_cast<size_t>(clustering.seeds[static_cast<size_t>(i)])].label = i;
  // Sticky clusters hold their seed's neighbours (unless another seed sits there).
  for (int i = 0; i < n; ++i) {
    if (clustering.sticky[static_cast<size_t>(i)] <= 0) continue;
    for (int g : topology.face_neighbors[static_cast<size_t>(clustering.seeds[static_cast<size_t>(i)])]) {
      if (g >= 0 && state[static_cast<size_t>(g)].label < 0) state[static_cast<size_t>(g)].label = i;
    }
  }
  double energy = 0.0;
  for (int f = 0; f < faces; ++f) {
    const int label = state[static_cast<size_t>(f)].label;
    if (label < 0) continue;
    if (with_energy) energy += metric.cost(f, terms[static_cast<size_t>(label)]) + (extra ? (*extra)(f, label) : 0.0);
    push_neighbours(f, label);
  }
  while (!queue.empty()) {
    const KeyedItem popped = queue.pop();
    const double cost = key_value(popped.key);
    const int face = popped.id;
    if (prefetch && !queue.empty()) {
      // A flood waits on memory, not arithmetic: consecutive pops jump between all fronts.
      // Fetch in two stages: the neighbour lists of the likely pops after next (the root's
      // children), and everything the next pop reads (its list is cached by now).
      for (size_t k = 1; k < std::min<size_t>(queue.size(), 5); ++k)
        __builtin_prefetch(&topology.face_neighbors[static_cast<size_t>(queue.at(k).id)]);
      const int next = queue.top().id;
      __builtin_prefetch(&state[static_cast<size_t>(next)]);
      for (int g : topology.face_neighbors[static_cast<size_t>(next)]) {
        if (g < 0) continue;
        __builtin_prefetch(&state[static_cast<size_t>(g)]);
        const char* record = reinterpret_cast<const char*>(&records[static_cast<size_t>(g)]);
        __builtin_prefetch(record);
        if (reads_spread) __builtin_prefetch(record + 64);
      }
    }
    FaceState& s = state[static_cast<size_t>(face)];
    if (s.label >= 0 || cost != s.best) continue;  // assigned already, or superseded
    s.label = s.best_cluster;
    energy += cost;
    push_neighbours(face, s.label);
  }
  std::vector<int>& labels = clustering.labels;
  labels.resize(static_cast<size_t>(faces));
  for (size_t f = 0; f < state.size(); ++f) labels[f] = state[f].label;
  return with_energy ? energy : 0.0;
}

}  // namespace ff
