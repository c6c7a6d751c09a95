// split_near and relocate_clusters (teleport.h; paper 2.3 "split a plane near the problem area and merge two
// planes elsewhere"): n stays, the new seed is the requested face, the merge is the cheapest adjacent pair outside
// `protect` and the split clusters, bad requests are skipped and unservable ones dropped, new clusters are sticky;
// relocations go to the worst face of a different worst cluster, never one in `keep`.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "cluster_checks.h"
#include "core/cluster/lloyd.h"
#include "core/cluster/seeding.h"
#include "core/cluster/teleport.h"
#include "core/shapes/shapes.h"

namespace ff {
namespace {

constexpr int kN = 12;
constexpr int kSticky = 5;  // not the default 3, so a default cannot pass for it
using Requests = std::vector<std::pair<int, int>>;

// A double-curved roof, so cluster energies and merge costs all differ. Never copied: the metric points at fd.
struct Roof {
  TriMesh mesh = make_roof(20, 14);
  MeshTopology topo = build_topology(mesh);
  FaceData fd = make_face_data(mesh);
  Metric metric{fd, MetricWeights{}, kN};
  Clustering c = initial_clustering(metric, topo, place_seeds(fd, topo, kN, SeedingMethod::FarthestPoint, 7));

  int inner_face(int i) const {  // the first face of cluster i that is not its seed
    for (int f = 0; f < fd.num_faces(); ++f) {
      if (c.labels[static_cast<size_t>(f)] == i && f != c.seeds[static_cast<size_t>(i)]) return f;
    }
    return -1;
  }
  double energy(const Clustering& x, int i) const {
    const size_t k = static_cast<size_t>(i);
    return metric.energy(cluster_moments(fd, x.labels, kN)[k], x.proxies[k]).total();
  }
  // Clusters a and b of x merged: the refitted proxy and the energy it adds (as teleport.cpp computes it).
  std::pair<Proxy, double> merge(const Clustering& x, int a, int b) const {
    const std::vector<ClusterMoments> m = cluster_moments(fd, x.labels, kN);
    ClusterMoments ab = m[static_cast<size_t>(a)];
    ab.add(m[static_cast<size_t>(b)]);
    const Proxy p = metric.fit(ab, x.proxies[static_cast<size_t>(a)]);
    return {p, metric.energy(ab, p).total() - energy(x, a) - energy(x, b)};
  }
  // Clusters by decreasing energy, and the face of cluster w farthest from its proxy (not its seed).
  std::vector<int> by_energy(const Clustering& x) const {
    std::vector<int> order(kN);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int i, int j) { return energy(x, i) > energy(x, j); });
    return order;
  }
  int worst_face(const Clustering& x, int w) const {
    const Metric::Terms t = metric.terms(x.proxies[static_cast<size_t>(w)]);
    int best = -1;
    for (int f = 0; f < fd.num_faces(); ++f) {
      if (x.labels[static_cast<size_t>(f)] != w || f == x.seeds[static_cast<size_t>(w)]) continue;
      if (best < 0 || metric.cost(f, t) > metric.cost(best, t)) best = f;
    }
    return best;
  }
};

bool same(const Proxy& p, const Proxy& q) {
  return p.center == q.center && p.normal == q.normal && p.density == q.density;
}

std::vector<int> changed_proxies(const Clustering& before, const Clustering& after) {
  std::vector<int> out;
  for (size_t i = 0; i < before.proxies.size(); ++i) {
    if (!same(before.proxies[i], after.proxies[i])) out.push_back(static_cast<int>(i));
  }
  return out;
}

int seeded_at(const Clustering& c, int face) {  // the cluster seeded at face, or -1
  const auto it = std::find(c.seeds.begin(), c.seeds.end(), face);
  return it == c.seeds.end() ? -1 : static_cast<int>(it - c.seeds.begin());
}

TEST(SplitNear, SeedsTheFaceAndMergesTheCheapestAdjacentPair) {
  Roof r;
  const Clustering before = r.c;
  const int w = 0, face = r.inner_face(w);
  ASSERT_EQ(split_near(r.metric, r.topo, r.c, {{w, face}}, {}, kSticky, /*reflood_after=*/false), 1);
  EXPECT_EQ(r.c.labels, before.labels);  // no reflood asked
  // Slot b seeds the new cluster; a keeps its seed under the proxy of a and b together.
  const int b = seeded_at(r.c, face);
  const std::vector<int> changed = changed_proxies(before, r.c);
  ASSERT_EQ(changed.size(), 2u);
  ASSERT_TRUE(b == changed[0] || b == changed[1]);
  const int a = changed[0] == b ? changed[1] : changed[0];
  EXPECT_TRUE(a != w && b != w);
  EXPECT_EQ(r.c.sticky[static_cast<size_t>(b)], kSticky);
  const Requests pairs = adjacent_cluster_pairs(r.topo, before.labels);
  EXPECT_NE(std::find(pairs.begin(), pairs.end(), std::make_pair(std::min(a, b), std::max(a, b))), pairs.end());
  EXPECT_TRUE(same(r.c.proxies[static_cast<size_t>(a)], r.merge(before, a, b).first));
  for (const auto& [p, q] : pairs) {
    if (p == w || q == w) continue;
    EXPECT_LE(r.merge(before, a, b).second, r.merge(before, p, q).second) << p << "-" << q;
  }
  reflood(r.metric, r.topo, r.c);
  EXPECT_EQ(r.c.labels[static_cast<size_t>(face)], b);
  EXPECT_TRUE(test::keeps_invariants(r.topo, r.c, kN));
}

TEST(SplitNear, MergesOnlyATouchingPairOutsideProtectAndTheSplitCluster) {
  const Roof r;
  const int w = 0, face = r.inner_face(w);
  const Requests touching = adjacent_cluster_pairs(r.topo, r.c.labels);
  for (int p = 1; p < kN; ++p) {
    for (int q = p + 1; q < kN; ++q) {
      // Only p, q and w unprotected: w is being split, so p-q is the one pair left, if it touches.
      std::vector<char> protect(kN, 1);
      protect[static_cast<size_t>(p)] = protect[static_cast<size_t>(q)] = protect[static_cast<size_t>(w)] = 0;
      const bool touch = std::count(touching.begin(), touching.end(), std::make_pair(p, q)) > 0;
      Clustering c = r.c;
      EXPECT_EQ(split_near(r.metric, r.topo, c, {{w, face}}, protect, kSticky, false), touch ? 1 : 0) << p << "-" << q;
      EXPECT_EQ(changed_proxies(r.c, c), (touch ? std::vector<int>{p, q} : std::vector<int>{})) << p << "-" << q;
    }
  }
}

TEST(SplitNear, DropsRequestsOnceNoPairIsLeft) {
  Roof r;
  const int f1 = r.inner_face(0), f2 = r.inner_face(1);
  // One mergeable pair, away from the two split clusters: only the first request is served.
  std::vector<char> protect(kN, 1);
  for (const auto& [p, q] : adjacent_cluster_pairs(r.topo, r.c.labels)) {
    if (p < 2 || q < 2) continue;
    protect[static_cast<size_t>(p)] = protect[static_cast<size_t>(q)] = 0;
    break;
  }
  EXPECT_EQ(split_near(r.metric, r.topo, r.c, {{0, f1}, {1, f2}}, protect, kSticky), 1);
  EXPECT_GE(seeded_at(r.c, f1), 0);
  EXPECT_EQ(seeded_at(r.c, f2), -1);
  EXPECT_TRUE(test::keeps_invariants(r.topo, r.c, kN));
}

TEST(SplitNear, SkipsRequestsOutsideTheClusterOrAtItsSeed) {
  Roof r;
  const Clustering before = r.c;
  const int other = r.inner_face(1), faces = r.fd.num_faces();
  Requests requests = {{0, other}, {0, r.c.seeds[0]}, {-1, other}, {kN, other}, {0, -1}, {0, faces}};
  EXPECT_EQ(split_near(r.metric, r.topo, r.c, requests, {}, kSticky), 0);
  EXPECT_EQ(r.c.seeds, before.seeds);
  EXPECT_EQ(r.c.sticky, before.sticky);
  EXPECT_EQ(r.c.labels, before.labels);
  // A good request after them is still served.
  requests.emplace_back(0, r.inner_face(0));
  EXPECT_EQ(split_near(r.metric, r.topo, r.c, requests, {}, kSticky), 1);
}

TEST(SplitNear, RefloodsToValidStickyClustersDeterministically) {
  Roof r;
  const Clustering before = r.c;
  const Requests requests = {{2, r.inner_face(2)}, {5, r.inner_face(5)}, {9, r.inner_face(9)}};
  ASSERT_EQ(split_near(r.metric, r.topo, r.c, requests, {}, kSticky), 3);
  EXPECT_TRUE(test::keeps_invariants(r.topo, r.c, kN));
  for (const auto& [w, face] : requests) {
    const int id = seeded_at(r.c, face);
    ASSERT_GE(id, 0) << w;
    EXPECT_EQ(r.c.labels[static_cast<size_t>(face)], id);
    EXPECT_EQ(r.c.sticky[static_cast<size_t>(id)], kSticky);
  }
  Clustering again = before;
  split_near(r.metric, r.topo, again, requests, {}, kSticky);
  EXPECT_EQ(again.labels, r.c.labels);
  EXPECT_EQ(again.seeds, r.c.seeds);
}

TEST(RelocateClusters, MovesEachToTheWorstFaceOfADifferentWorstCluster) {
  Roof r;
  const Clustering before = r.c;
  const std::vector<int> order = r.by_energy(before);
  const int m1 = order[kN - 1], m2 = order[kN - 2];  // the two cheapest clusters move; bad ids are skipped
  EXPECT_EQ(relocate_clusters(r.metric, r.topo, r.c, {-1, m1, kN, m2}, {}, kSticky), 2);
  EXPECT_EQ(r.c.seeds[static_cast<size_t>(m1)], r.worst_face(before, order[0]));
  EXPECT_EQ(r.c.seeds[static_cast<size_t>(m2)], r.worst_face(before, order[1]));
  EXPECT_EQ(r.c.sticky[static_cast<size_t>(m1)], kSticky);
  EXPECT_EQ(r.c.sticky[static_cast<size_t>(m2)], kSticky);
  EXPECT_EQ(r.c.labels, before.labels);  // the caller floods
  reflood(r.metric, r.topo, r.c);
  EXPECT_TRUE(test::keeps_invariants(r.topo, r.c, kN));
}

TEST(RelocateClusters, KeptClustersNeverReceiveOne) {
  Roof r;
  const Clustering before = r.c;
  const std::vector<int> order = r.by_energy(before);
  const int m = order[kN - 1];
  std::vector<char> keep(kN, 0);
  keep[static_cast<size_t>(order[0])] = keep[static_cast<size_t>(order[1])] = 1;
  EXPECT_EQ(relocate_clusters(r.metric, r.topo, r.c, {m}, keep, kSticky), 1);
  EXPECT_EQ(r.c.seeds[static_cast<size_t>(m)], r.worst_face(before, order[2]));
  // Every other cluster kept: nowhere to go.
  Clustering c = before;
  EXPECT_EQ(relocate_clusters(r.metric, r.topo, c, {m}, std::vector<char>(kN, 1), kSticky), 0);
  EXPECT_EQ(c.seeds, before.seeds);
}

}  // namespace
}  // namespace ff
