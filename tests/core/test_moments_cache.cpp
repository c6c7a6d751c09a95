// ClusterMomentsCache: after any sequence of label changes its moments are cluster_moments()
// bit for bit, and its refit() gives refit()'s proxies and energy bit for bit.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

#include "core/cluster/clustering.h"
#include "core/cluster/face_data.h"
#include "core/cluster/flood.h"
#include "core/cluster/lloyd.h"
#include "core/cluster/moments_cache.h"
#include "core/cluster/seeding.h"
#include "core/cluster/teleport.h"
#include "core/mesh/topology.h"
#include "core/shapes/hard_cases.h"
#include "core/shapes/shapes.h"
#include "core/util/random.h"

namespace ff {
namespace {

template <typename T>
bool same_bits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

bool same_moments(const ClusterMoments& a, const ClusterMoments& b) {
  return same_bits(a.area, b.area) && same_bits(a.first, b.first) && same_bits(a.centroid_sq, b.centroid_sq) &&
         same_bits(a.second, b.second) && same_bits(a.normal_sum, b.normal_sum) &&
         same_bits(a.density_area, b.density_area);
}

bool same_proxy(const Proxy& a, const Proxy& b) {
  return same_bits(a.center, b.center) && same_bits(a.normal, b.normal) && same_bits(a.density, b.density);
}

// A mesh with its topology, face data and a 30-cluster metric: what every test here starts from.
struct Prepared {
  TriMesh mesh;
  MeshTopology topology;
  FaceData faces;
  Metric metric;

  explicit Prepared(TriMesh m)
      : mesh(std::move(m)),
        topology(build_topology(mesh)),
        faces(make_face_data(mesh, {})),
        metric(faces, MetricWeights{}, 30) {}

  Clustering farthest_point_clusters(std::uint64_t seed) const {
    return initial_clustering(metric, topology, place_seeds(faces, topology, 30, SeedingMethod::FarthestPoint, seed));
  }
};

TEST(MomentsCache, MatchesFullSumsAndRefitBitForBit) {
  const Prepared saddle(make_saddle(3000));
  const auto& [mesh, topology, faces, metric] = saddle;
  Clustering plain = saddle.farthest_point_clusters(1);
  Clustering cached = plain;
  ClusterMomentsCache cache;
  SplitMix64 rng(3);
  int reused_rounds = 0;
  for (int round = 0; round < 12; ++round) {
    // Move a few faces between clusters (or none), as a panel round would.
    const int moves = round % 3 == 0 ? 0 : 1 + static_cast<int>(rng.uniform() * 20.0);
    for (int k = 0; k < moves; ++k) {
      const size_t f = static_cast<size_t>(rng.uniform() * static_cast<double>(plain.labels.size()));
      const int to = static_cast<int>(rng.uniform() * plain.num_clusters());
      plain.labels[f] = cached.labels[f] = to;
    }
    if (round == 6) {  // a proxy changed without its faces changing (a split's new proxy)
      plain.proxies[2].center += Vec3(0.1, 0.0, 0.0);
      cached.proxies[2] = plain.proxies[2];
    }
    const std::vector<ClusterMoments> full = cluster_moments(faces, plain.labels, plain.num_clusters());
    const std::vector<ClusterMoments>& kept = cache.update(faces, cached.labels, cached.num_clusters());
    ASSERT_EQ(full.size(), kept.size());
    for (size_t c = 0; c < full.size(); ++c) ASSERT_TRUE(same_moments(full[c], kept[c])) << "round " << round;
    const EnergyTerms a = refit(metric, plain);
    const EnergyTerms b = cache.refit(metric, cached);
    EXPECT_TRUE(same_bits(a.total(), b.total())) << "round " << round;
    EXPECT_TRUE(same_bits(plain.energy, cached.energy));
    for (int c = 0; c < plain.num_clusters(); ++c)
      ASSERT_TRUE(same_proxy(plain.proxies[static_cast<size_t>(c)], cached.proxies[static_cast<size_t>(c)]))
          << "round " << round << " cluster " << c;
    reused_rounds += moves == 0 ? 1 : 0;
  }
  EXPECT_GT(reused_rounds, 0);
  // Fewer clusters (a merge renumbers): still the full sums.
  for (int& l : plain.labels) l = l == 29 ? 0 : l;
  plain.proxies.pop_back(), plain.seeds.pop_back(), plain.sticky.pop_back();
  const std::vector<ClusterMoments> full = cluster_moments(faces, plain.labels, 29);
  const std::vector<ClusterMoments>& kept = cache.update(faces, plain.labels, 29);
  ASSERT_EQ(kept.size(), 29u);
  for (size_t c = 0; c < full.size(); ++c) EXPECT_TRUE(same_moments(full[c], kept[c]));
}

// choose_seeds through the cache equals choose_seeds after any change a caller makes between
// calls: faces moving, a proxy refitted, a cluster turning sticky and back, a seed set by hand
// (a teleport's split), and no change at all (where the cache must keep every seed).
TEST(MomentsCache, ChooseSeedsMatchesAFullPass) {
  const Prepared saddle(make_saddle(3000));
  const auto& [mesh, topology, faces, metric] = saddle;
  Clustering plain = saddle.farthest_point_clusters(4);
  Clustering cached = plain;
  ClusterMomentsCache cache;
  SplitMix64 rng(5);
  int seeds_moved = 0;
  for (int round = 0; round < 16; ++round) {
    const std::vector<int> seeds_before = plain.seeds;
    choose_seeds(metric, plain);
    cache.choose_seeds(metric, cached);
    ASSERT_EQ(plain.seeds, cached.seeds) << "round " << round;
    for (size_t i = 0; i < plain.seeds.size(); ++i) seeds_moved += plain.seeds[i] != seeds_before[i];
    const int kind = round % 4;
    if (kind == 1) {  // a few faces move, and their clusters are refitted
      for (int k = 0; k < 10; ++k) {
        const size_t f = static_cast<size_t>(rng.uniform() * static_cast<double>(plain.labels.size()));
        plain.labels[f] = cached.labels[f] = static_cast<int>(rng.uniform() * plain.num_clusters());
      }
      refit(metric, plain);
      cached.proxies = plain.proxies;
    } else if (kind == 2) {  // one proxy moves, one cluster turns sticky, another stops being sticky
      plain.proxies[3].center += Vec3(0.05, 0.0, 0.0);
      plain.sticky[static_cast<size_t>(round % 7)] = 1;
      plain.sticky[static_cast<size_t>((round + 3) % 7)] = 0;
      cached.proxies = plain.proxies;
      cached.sticky = plain.sticky;
    } else if (kind == 3) {  // a seed set by hand to another face of its cluster
      for (size_t f = 0; f < plain.labels.size(); ++f) {
        if (plain.labels[f] == 5 && static_cast<int>(f) != plain.seeds[5]) {
          plain.seeds[5] = cached.seeds[5] = static_cast<int>(f);
          break;
        }
      }
    }
  }
  EXPECT_GT(seeds_moved, 0);
}

// The Lloyd phase through the cache (lloyd_iteration, teleport and its reflood) walks the
// same path as without it, bit for bit, teleports and all; the clusters an iteration leaves
// alone (there must be some) are where the cache spares work.
TEST(MomentsCache, LloydAndTeleportThroughTheCacheAreBitIdentical) {
  // All seeds crowded into one corner of a roof, so the teleports have work to do.
  const Prepared roof(make_roof(60, 40));
  const auto& [mesh, topology, faces, metric] = roof;
  std::vector<int> crowded;
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 5; ++i) crowded.push_back(2 * (j * 60 + i));
  Clustering plain = initial_clustering(metric, topology, crowded);
  Clustering cached = plain;
  ClusterMomentsCache cache;
  int teleported = 0, kept_clusters = 0;
  for (int it = 1; it <= 40; ++it) {
    const std::vector<int> before = plain.labels;
    if (it % 4 == 0 && it <= 12) {  // teleports early, then Lloyd settles
      const int a = teleport(metric, topology, plain, TeleportOptions{2, 3});
      const int b = teleport(metric, topology, cached, TeleportOptions{2, 3}, &cache);
      ASSERT_EQ(a, b) << "iteration " << it;
      teleported += a;
    } else {
      const LloydResult a = lloyd_iteration(metric, topology, plain);
      const LloydResult b = lloyd_iteration(metric, topology, cached, &cache);
      ASSERT_EQ(a.changed_faces, b.changed_faces) << "iteration " << it;
      EXPECT_TRUE(same_bits(a.energy.total(), b.energy.total())) << "iteration " << it;
    }
    ASSERT_EQ(plain.labels, cached.labels) << "iteration " << it;
    ASSERT_EQ(plain.seeds, cached.seeds) << "iteration " << it;
    EXPECT_TRUE(same_bits(plain.energy, cached.energy)) << "iteration " << it;
    std::vector<char> changed(static_cast<size_t>(plain.num_clusters()), 0);
    for (size_t f = 0; f < before.size(); ++f) {
      if (before[f] != plain.labels[f])
        changed[static_cast<size_t>(before[f])] = changed[static_cast<size_t>(plain.labels[f])] = 1;
    }
    for (char k : changed) kept_clusters += k == 0;
    for (int c = 0; c < plain.num_clusters(); ++c)
      ASSERT_TRUE(same_proxy(plain.proxies[static_cast<size_t>(c)], cached.proxies[static_cast<size_t>(c)]))
          << "iteration " << it << " cluster " << c;
  }
  EXPECT_GT(teleported, 0);
  EXPECT_GT(kept_clusters, 0);
}

}  // namespace
}  // namespace ff
