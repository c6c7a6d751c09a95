#include "core/cluster/flood.h"

#include <algorithm>
#include <array>
#include <limits>

namespace ff {

namespace {

struct Entry {
  double cost;
  int face;
};

// Ties broken by face so the result never depends on anything but the input.
inline bool before(const Entry& a, const Entry& b) { return a.cost < b.cost || (a.cost == b.cost && a.face < b.face); }

// A 4-ary min-heap: half the levels of a binary heap and children on one cache line, which
// is what a flood of a million faces spends its time on.
class QuadHeap {
 public:
  bool empty() const { return items_.empty(); }
  size_t size() const { return items_.size(); }
  const Entry& at(size_t i) const { return items_[i]; }
  const Entry& top() const { return items_.front(); }
  void reserve(size_t n) { items_.reserve(n); }
  void push(Entry e) {
    size_t i = items_.size();
    items_.push_back(e);
    while (i > 0) {
      const size_t parent = (i - 1) / 4;
      if (!before(e, items_[parent])) break;
      items_[i] = items_[parent];
      i = parent;
    }
    items_[i] = e;
  }
  // Bottom-up: the hole walks down along the smaller children to a leaf (3 comparisons a
  // level, as a pairwise tournament), then the last entry, which belongs near the bottom,
  // sifts up from there; a top-down sift would also compare it with every child pair.
  // (cost, face) is a strict total order over the entries (a face is pushed again only at
  // a lower cost), so any exact heap pops the same sequence.
  Entry pop() {
    const Entry top = items_.front();
    const Entry last = items_.back();
    items_.pop_back();
    const size_t n = items_.size();
    if (n == 0) return top;
    size_t i = 0;
    for (;;) {
      const size_t first = 4 * i + 1;
      size_t best;
      if (first + 4 <= n) {
        const size_t a = before(items_[first + 1], items_[first]) ? first + 1 : first;
        const size_t b = before(items_[first + 3], items_[first + 2]) ? first + 3 : first + 2;
        best = before(items_[b], items_[a]) ? b : a;
      } else if (first < n) {
        best = first;
        for (size_t k = first + 1; k < n; ++k) {
          if (before(items_[k], items_[best])) best = k;
        }
      } else {
        break;
      }
      items_[i] = items_[best];
      i = best;
    }
    while (i > 0) {
      const size_t parent = (i - 1) / 4;
      if (!before(last, items_[parent])) break;
      items_[i] = items_[parent];
      i = parent;
    }
    items_[i] = last;
    return top;
  }

 private:
  std::vector<Entry> items_;
};

}  // namespace

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
  QuadHeap queue;
  queue.reserve(static_cast<size_t>(faces) / 8 + 64);

  const FaceData& records = metric.faces();
  const bool reads_spread = metric.weights().l2 != 0.0;
  // Below a few MB the face data sits in the core's own cache and prefetching only costs.
  const bool prefetch = static_cast<size_t>(faces) * sizeof(FaceRecord) > (size_t{4} << 20);
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
        queue.push(Entry{c, g});
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
    const Entry e = queue.pop();
    if (prefetch && !queue.empty()) {
      // A flood waits on memory, not arithmetic: consecutive pops jump between all fronts.
      // Fetch in two stages: the neighbour lists of the likely pops after next (the root's
      // children), and everything the next pop reads (its list is cached by now).
      for (size_t k = 1; k < std::min<size_t>(queue.size(), 5); ++k)
        __builtin_prefetch(&topology.face_neighbors[static_cast<size_t>(queue.at(k).face)]);
      const int next = queue.top().face;
      __builtin_prefetch(&state[static_cast<size_t>(next)]);
      for (int g : topology.face_neighbors[static_cast<size_t>(next)]) {
        if (g < 0) continue;
        __builtin_prefetch(&state[static_cast<size_t>(g)]);
        const char* record = reinterpret_cast<const char*>(&records[static_cast<size_t>(g)]);
        __builtin_prefetch(record);
        if (reads_spread) __builtin_prefetch(record + 64);
      }
    }
    FaceState& s = state[static_cast<size_t>(e.face)];
    if (s.label >= 0 || e.cost != s.best) continue;  // assigned already, or superseded
    s.label = s.best_cluster;
    energy += e.cost;
    push_neighbours(e.face, s.label);
  }
  std::vector<int>& labels = clustering.labels;
  labels.resize(static_cast<size_t>(faces));
  for (size_t f = 0; f < state.size(); ++f) labels[f] = state[f].label;
  return with_energy ? energy : 0.0;
}

}  // namespace ff
