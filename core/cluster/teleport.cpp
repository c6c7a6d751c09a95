#include "core/cluster/teleport.h"

#include <algorithm>
#include <numeric>

#include "core/cluster/lloyd.h"
#include "core/cluster/merge_order.h"

namespace ff {

namespace {

// Everything the moves need, computed in one pass over the faces.
struct ClusterStats {
  std::vector<ClusterMoments> moments;
  std::vector<double> energy;
  std::vector<int> worst_face;  // the face farthest from the proxy (never the seed), or -1
};

ClusterStats cluster_stats(const Metric& metric, const Clustering& c, ClusterMomentsCache* cache = nullptr) {
  ClusterStats s;
  const int n = c.num_clusters();
  s.moments = cache ? cache->update(metric.faces(), c.labels, n) : cluster_moments(metric.faces(), c.labels, n);
  s.energy.resize(static_cast<size_t>(n));
  for (size_t i = 0; i < s.moments.size(); ++i) s.energy[i] = metric.energy(s.moments[i], c.proxies[i]).total();
  const std::vector<Metric::Terms> terms = metric.terms(c.proxies);
  s.worst_face.assign(static_cast<size_t>(n), -1);
  std::vector<double> worst_cost(static_cast<size_t>(n), -1.0);
  for (int f = 0; f < metric.faces().num_faces(); ++f) {
    const int i = c.labels[static_cast<size_t>(f)];
    if (i < 0 || f == c.seeds[static_cast<size_t>(i)]) continue;
    const double cost = metric.cost(f, terms[static_cast<size_t>(i)]);
    if (cost > worst_cost[static_cast<size_t>(i)]) {
      worst_cost[static_cast<size_t>(i)] = cost;
      s.worst_face[static_cast<size_t>(i)] = f;
    }
  }
  return s;
}

// The candidate merges of the clusters' adjacent pairs, cheapest first (merge_order.h).
MergeOrder merge_order(const Metric& metric, const MeshTopology& topology, const Clustering& c,
                       const ClusterStats& s) {
  return MergeOrder(metric, adjacent_cluster_pairs(topology, c.labels), s.moments, s.energy, c.proxies);
}

// Clusters per connected part against the part's floor (cluster_floors): a merge must not
// leave a part fewer clusters than it needs to become valid panels (a small closed part below
// four), unless the split it pays for lands in the same part. On one part every move is
// allowed, as before.
class PartCounts {
 public:
  PartCounts(const MeshTopology& topology, const Clustering& c, int target)
      : topology_(topology), floors_(cluster_floors(topology, target)), counts_(floors_.size(), 0) {
    for (int i = 0; i < c.num_clusters(); ++i) {
      const int p = part_of(c, i);
      if (p >= 0) ++counts_[static_cast<size_t>(p)];
    }
  }
  int part_of(const Clustering& c, int cluster) const {
    const int seed = c.seeds[static_cast<size_t>(cluster)];
    return seed >= 0 ? topology_.face_component[static_cast<size_t>(seed)] : -1;
  }
  // Whether cluster a (of a merged pair) may go from its part when the split is in `to` (-1:
  // nowhere, a plain merge).
  bool may_merge(const Clustering& c, int a, int to) const {
    const int p = part_of(c, a);
    return p < 0 || p == to || counts_[static_cast<size_t>(p)] > floors_[static_cast<size_t>(p)];
  }
  void merged(const Clustering& c, int a, int to) {
    const int p = part_of(c, a);
    if (p >= 0) --counts_[static_cast<size_t>(p)];
    if (to >= 0) ++counts_[static_cast<size_t>(to)];
  }

 private:
  const MeshTopology& topology_;
  std::vector<int> floors_;
  std::vector<int> counts_;
};

// The first merge from `from` on that is free and whose part can give a cluster to part `to`
// (null when there is none); on one part simply the first free one.
template <typename FreePair>
const MergeCandidate* first_mergeable(MergeOrder& merges, size_t from, const FreePair& free_pair,
                                      const PartCounts& parts, const Clustering& c, int to) {
  for (const MergeCandidate* m = merges.at(from); m; m = merges.at(++from)) {
    if (free_pair(*m) && parts.may_merge(c, m->a, to)) return m;
  }
  return nullptr;
}

// Clusters by decreasing energy (ties by id).
std::vector<int> worst_first(const std::vector<double>& energy) {
  std::vector<int> order(energy.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int x, int y) { return energy[static_cast<size_t>(x)] > energy[static_cast<size_t>(y)]; });
  return order;
}

// Folds cluster b's moments into a and refits a. Labels are left alone: the reflood that
// follows every move rebuilds them from the seeds.
void merge_into(const Metric& metric, Clustering& c, ClusterStats& s, int a, int b) {
  s.moments[static_cast<size_t>(a)].add(s.moments[static_cast<size_t>(b)]);
  c.proxies[static_cast<size_t>(a)] = metric.fit(s.moments[static_cast<size_t>(a)], c.proxies[static_cast<size_t>(a)]);
}

// Seeds cluster slot `id` at the worst face of cluster w with a one-face proxy.
bool split_into(const Metric& metric, Clustering& c, const ClusterStats& s, int w, int id, int sticky_iterations) {
  const int face = s.worst_face[static_cast<size_t>(w)];
  if (face < 0) return false;  // a one-face cluster cannot be split
  c.proxies[static_cast<size_t>(id)] =
      single_face_proxy(metric.faces(), face, c.proxies[static_cast<size_t>(w)].normal);
  c.seeds[static_cast<size_t>(id)] = face;
  c.sticky[static_cast<size_t>(id)] = sticky_iterations;
  return true;
}

}  // namespace

int teleport(const Metric& metric, const MeshTopology& topology, Clustering& c, const TeleportOptions& options,
             ClusterMomentsCache* moments) {
  ClusterStats s = cluster_stats(metric, c, moments);
  MergeOrder merges = merge_order(metric, topology, c, s);
  const std::vector<int> worst = worst_first(s.energy);
  std::vector<char> used(static_cast<size_t>(c.num_clusters()), 0);
  for (int i = 0; i < c.num_clusters(); ++i) used[static_cast<size_t>(i)] = c.sticky[static_cast<size_t>(i)] > 0;
  PartCounts parts(topology, c, c.num_clusters());

  int moves = 0;
  size_t next_merge = 0, next_worst = 0;
  while (moves < options.max_moves) {
    while (next_worst < worst.size() &&
           (used[static_cast<size_t>(worst[next_worst])] || s.worst_face[static_cast<size_t>(worst[next_worst])] < 0)) {
      ++next_worst;
    }
    if (next_worst == worst.size()) break;
    const int w = worst[next_worst];
    const auto free_pair = [&](const MergeCandidate& m) {
      return !used[static_cast<size_t>(m.a)] && !used[static_cast<size_t>(m.b)] && m.a != w && m.b != w;
    };
    while (merges.at(next_merge) && !free_pair(*merges.at(next_merge))) ++next_merge;
    // The cheapest free pair whose part can give a cluster to w's.
    const int to = parts.part_of(c, w);
    const MergeCandidate* found = first_mergeable(merges, next_merge, free_pair, parts, c, to);
    if (!found) break;
    const MergeCandidate m = *found;  // a copy: reading further may grow the order's storage
    if (!(m.cost < 0.5 * s.energy[static_cast<size_t>(w)])) break;
    used[static_cast<size_t>(w)] = used[static_cast<size_t>(m.a)] = used[static_cast<size_t>(m.b)] = 1;
    parts.merged(c, m.a, to);
    merge_into(metric, c, s, m.a, m.b);
    split_into(metric, c, s, w, m.b, options.sticky_iterations);  // slot b now seeds the new cluster
    ++moves;
  }
  if (moves > 0) reflood(metric, topology, c, moments);
  return moves;
}

int split_near(const Metric& metric, const MeshTopology& topology, Clustering& c,
               const std::vector<std::pair<int, int>>& requests, const std::vector<char>& protect,
               int sticky_iterations, bool reflood_after) {
  ClusterStats s = cluster_stats(metric, c);
  MergeOrder merges = merge_order(metric, topology, c, s);
  std::vector<char> used(protect.begin(), protect.end());
  used.resize(static_cast<size_t>(c.num_clusters()), 0);
  std::vector<char> split(static_cast<size_t>(c.num_clusters()), 0);
  for (const auto& [w, face] : requests) {
    if (w >= 0 && w < c.num_clusters()) used[static_cast<size_t>(w)] = 1;
  }
  PartCounts parts(topology, c, c.num_clusters());
  size_t next_merge = 0;
  int splits = 0;
  for (const auto& [w, face] : requests) {
    if (w < 0 || w >= c.num_clusters() || face < 0 || face >= static_cast<int>(c.labels.size())) continue;
    if (c.labels[static_cast<size_t>(face)] != w || c.seeds[static_cast<size_t>(w)] == face) continue;
    if (split[static_cast<size_t>(w)]) continue;
    split[static_cast<size_t>(w)] = 1;
    const auto free_pair = [&](const MergeCandidate& m) {
      return !used[static_cast<size_t>(m.a)] && !used[static_cast<size_t>(m.b)];
    };
    while (merges.at(next_merge) && !free_pair(*merges.at(next_merge))) ++next_merge;
    if (!merges.at(next_merge)) break;  // nothing left to merge: n stays as asked
    // The cheapest free pair whose part can give a cluster to w's.
    const int to = parts.part_of(c, w);
    const MergeCandidate* found = first_mergeable(merges, next_merge, free_pair, parts, c, to);
    if (!found) continue;  // no part can spare one for this request
    const MergeCandidate m = *found;
    used[static_cast<size_t>(m.a)] = used[static_cast<size_t>(m.b)] = 1;
    parts.merged(c, m.a, to);
    merge_into(metric, c, s, m.a, m.b);
    const int id = m.b;
    c.proxies[static_cast<size_t>(id)] =
        single_face_proxy(metric.faces(), face, c.proxies[static_cast<size_t>(w)].normal);
    c.seeds[static_cast<size_t>(id)] = face;
    c.sticky[static_cast<size_t>(id)] = sticky_iterations;
    c.sticky[static_cast<size_t>(w)] = std::max(c.sticky[static_cast<size_t>(w)], sticky_iterations);
    ++splits;
  }
  if (splits > 0 && reflood_after) reflood(metric, topology, c);
  return splits;
}

int relocate_clusters(const Metric& metric, const MeshTopology& topology, Clustering& c,
                      const std::vector<int>& clusters, const std::vector<char>& keep, int sticky_iterations) {
  if (clusters.empty()) return 0;
  const ClusterStats s = cluster_stats(metric, c);
  std::vector<char> moving(static_cast<size_t>(c.num_clusters()), 0);
  for (int e : clusters) {
    if (e >= 0 && e < c.num_clusters()) moving[static_cast<size_t>(e)] = 1;
  }
  const std::vector<int> worst = worst_first(s.energy);
  const auto kept = [&](int w) { return static_cast<size_t>(w) < keep.size() && keep[static_cast<size_t>(w)]; };
  // Which clusters can receive one (fixed for the call), and which have.
  std::vector<char> open(worst.size(), 0);
  for (size_t k = 0; k < worst.size(); ++k) {
    const int w = worst[k];
    open[k] = !moving[static_cast<size_t>(w)] && s.worst_face[static_cast<size_t>(w)] >= 0 && !kept(w);
  }
  PartCounts parts(topology, c, c.num_clusters());
  int moves = 0;
  for (int e : clusters) {
    if (e < 0 || e >= c.num_clusters()) continue;
    // The worst open cluster; in e's own part when that part cannot spare e (on one part:
    // simply the next worst).
    size_t k = 0;
    while (k < worst.size() && !(open[k] && parts.may_merge(c, e, parts.part_of(c, worst[k])))) ++k;
    if (k == worst.size()) continue;
    const int w = worst[k];
    open[k] = 0;
    parts.merged(c, e, parts.part_of(c, w));
    split_into(metric, c, s, w, e, sticky_iterations);
    c.sticky[static_cast<size_t>(w)] = std::max(c.sticky[static_cast<size_t>(w)], sticky_iterations);
    ++moves;
  }
  return moves;
}

void add_clusters(const Metric& metric, const MeshTopology& topology, Clustering& c, int count, int sticky_iterations) {
  while (count > 0) {
    const ClusterStats s = cluster_stats(metric, c);
    int added = 0;
    for (int w : worst_first(s.energy)) {
      if (added == count) break;
      const int id = c.num_clusters();
      c.proxies.emplace_back();
      c.seeds.push_back(-1);
      c.sticky.push_back(0);
      if (split_into(metric, c, s, w, id, sticky_iterations)) {
        ++added;
      } else {
        c.proxies.pop_back();
        c.seeds.pop_back();
        c.sticky.pop_back();
      }
    }
    reflood(metric, topology, c);
    if (added == 0) break;  // only one-face clusters left
    count -= added;
  }
}

void remove_clusters(const Metric& metric, const MeshTopology& topology, Clustering& c, int count) {
  while (count > 0) {
    ClusterStats s = cluster_stats(metric, c);
    MergeOrder merges = merge_order(metric, topology, c, s);
    const int n = c.num_clusters();
    std::vector<char> used(static_cast<size_t>(n), 0), gone(static_cast<size_t>(n), 0);
    PartCounts parts(topology, c, n - count);
    int merged = 0;
    // Cheapest disjoint pairs first, at most half of what is left per pass; none that takes
    // its part below its floor.
    for (size_t i = 0; merged < count && merges.at(i); ++i) {
      const MergeCandidate m = *merges.at(i);
      if (used[static_cast<size_t>(m.a)] || used[static_cast<size_t>(m.b)]) continue;
      if (!parts.may_merge(c, m.a, -1)) continue;
      parts.merged(c, m.a, -1);
      used[static_cast<size_t>(m.a)] = used[static_cast<size_t>(m.b)] = 1;
      merge_into(metric, c, s, m.a, m.b);
      gone[static_cast<size_t>(m.b)] = 1;
      ++merged;
    }
    if (merged == 0) break;  // every part is at its floor (or every cluster a part of its own)
    // Compact ids: survivors keep their order; the reflood relabels every face.
    Clustering kept;
    for (int i = 0; i < n; ++i) {
      if (gone[static_cast<size_t>(i)]) continue;
      kept.proxies.push_back(c.proxies[static_cast<size_t>(i)]);
      kept.seeds.push_back(c.seeds[static_cast<size_t>(i)]);
      kept.sticky.push_back(c.sticky[static_cast<size_t>(i)]);
    }
    c = std::move(kept);
    reflood(metric, topology, c);
    count -= merged;
  }
}

}  // namespace ff
