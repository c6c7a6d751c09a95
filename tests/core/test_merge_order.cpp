// MergeOrder must hand out exactly the order of fitting every adjacent pair and sorting the
// costs (all_merges_sorted), for every prefix, while fitting only what the prefix needs; and
// Metric::energy_lower_bound must stay below the fitted energy. On real meshes and clusters
// left mid-Lloyd (proxies off their optimum), under every metric the designer can weight:
// euclidean, L2, L2,1 alone and together, a painted density, anisotropy.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/cluster/lloyd.h"
#include "core/cluster/merge_order.h"
#include "core/cluster/seeding.h"
#include "core/density/density_field.h"
#include "test_meshes.h"

namespace ff {
namespace {

struct MetricSetup {
  std::string name;
  MetricWeights weights;
  bool painted = false;
  bool stretched = false;
};

TEST(MergeOrder, EveryPrefixIsTheSortedOrderAndFewArePrefitted) {
  const TriMesh mesh = test::load_clean("bunny.off");
  const MeshTopology topology = build_topology(mesh);
  std::vector<double> paint(mesh.positions.size());
  for (size_t v = 0; v < paint.size(); ++v) paint[v] = 1.0 + 4.0 * (mesh.positions[v].y() > 0.1);
  Anisotropy stretch;
  stretch.direction = AnisotropyDirection::Constant;
  stretch.vector = Vec3(1, 2, 0);
  stretch.stretch = 3.0;
  const std::vector<MetricSetup> setups = {
      {"default", MetricWeights{}},
      {"euclidean only", MetricWeights{1, 0, 0, 1, 1}},
      {"L2 only", MetricWeights{0, 1, 0, 1, 1}},
      {"L2,1 only", MetricWeights{0, 0, 1, 1, 1}},
      {"painted density", MetricWeights{1, 1, 1, 2, 1}, true},
      {"anisotropy", MetricWeights{}, false, true},
  };
  for (const MetricSetup& setup : setups) {
    SCOPED_TRACE(setup.name);
    const FaceData faces = make_shaped_face_data(mesh, topology, setup.painted ? paint : std::vector<double>{}, "",
                                                 setup.stretched ? stretch : Anisotropy{});
    const Metric metric(faces, setup.weights, 150);
    Clustering c = initial_clustering(metric, topology, place_seeds(faces, topology, 150, SeedingMethod::Random, 4));
    for (int lloyd = 0; lloyd <= 4; lloyd += 4) {
      for (int i = 0; i < lloyd; ++i) lloyd_iteration(metric, topology, c);
      const std::vector<ClusterMoments> moments = cluster_moments(faces, c.labels, c.num_clusters());
      std::vector<double> energy;
      for (int i = 0; i < c.num_clusters(); ++i)
        energy.push_back(metric.energy(moments[static_cast<size_t>(i)], c.proxies[static_cast<size_t>(i)]).total());
      const std::vector<std::pair<int, int>> pairs = adjacent_cluster_pairs(topology, c.labels);
      const std::vector<MergeCandidate> sorted = all_merges_sorted(metric, pairs, moments, energy, c.proxies);
      ASSERT_EQ(sorted.size(), pairs.size());
      // Each pair's bound below its fitted cost (as the union's energy, rounding included).
      for (const auto& [a, b] : pairs) {
        ClusterMoments merged = moments[static_cast<size_t>(a)];
        merged.add(moments[static_cast<size_t>(b)]);
        const double fitted = metric.energy(merged, metric.fit(merged, c.proxies[static_cast<size_t>(a)])).total();
        EXPECT_LE(metric.energy_lower_bound(merged), fitted) << a << " " << b;
      }
      // The first few, as a teleport reads them, fit a small share of the pairs.
      MergeOrder order(metric, pairs, moments, energy, c.proxies);
      for (size_t i = 0; i < 5; ++i) {
        const MergeCandidate* m = order.at(i);
        ASSERT_NE(m, nullptr);
        EXPECT_EQ(m->cost, sorted[i].cost);
        EXPECT_EQ(m->a, sorted[i].a);
        EXPECT_EQ(m->b, sorted[i].b);
      }
      std::printf("%s after %d Lloyd iterations: %zu of %zu pairs fitted for the first 5\n", setup.name.c_str(), lloyd,
                  order.fitted(), pairs.size());
      // (Not with L2 alone, whose bound is 0, nor with anisotropy, whose euclidean bound is.)
      if (!setup.stretched && setup.weights.euclidean + setup.weights.l21 > 0.0) {
        EXPECT_LT(order.fitted(), pairs.size() / 10);
      }
      // Then every one, in the same order as the sort, and nothing past the last.
      for (size_t i = 5; i < sorted.size(); ++i) {
        const MergeCandidate* m = order.at(i);
        ASSERT_NE(m, nullptr);
        ASSERT_TRUE(m->cost == sorted[i].cost && m->a == sorted[i].a && m->b == sorted[i].b) << "merge " << i;
      }
      EXPECT_EQ(order.at(sorted.size()), nullptr);
      EXPECT_EQ(order.fitted(), pairs.size());
    }
  }
}

// Ties in cost come out by (a, b), as the sort orders them, also where bounds tie with costs.
TEST(MergeOrder, EqualCostsComeOutByPair) {
  // Six clusters of the same two faces (the order reads only moments): every pair of them
  // costs exactly the same.
  TriMesh mesh;
  for (int k = 0; k < 6; ++k) {
    const int base = static_cast<int>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {Vec3(0, 0, 0), Vec3(1, 0, 0.1), Vec3(1, 1, 0), Vec3(0, 1, 0.2)});
    mesh.triangles.push_back({base, base + 1, base + 2});
    mesh.triangles.push_back({base, base + 2, base + 3});
  }
  const FaceData faces = make_face_data(mesh);
  const Metric metric(faces, MetricWeights{}, 6);
  std::vector<ClusterMoments> moments(6);
  std::vector<Proxy> proxies(6);
  std::vector<double> energy(6);
  for (size_t k = 0; k < 6; ++k) {
    moments[k].add_face(faces, static_cast<int>(2 * k));
    moments[k].add_face(faces, static_cast<int>(2 * k + 1));
    proxies[k] = metric.fit(moments[k], Proxy{});
    energy[k] = metric.energy(moments[k], proxies[k]).total();
  }
  const std::vector<std::pair<int, int>> pairs = {{3, 4}, {0, 5}, {2, 3}, {1, 2}, {4, 5}, {1, 3}, {0, 2}, {2, 4}};
  const std::vector<MergeCandidate> sorted = all_merges_sorted(metric, pairs, moments, energy, proxies);
  ASSERT_EQ(sorted.front().cost, sorted.back().cost);  // all tied
  MergeOrder order(metric, pairs, moments, energy, proxies);
  for (size_t i = 0; i < sorted.size(); ++i) {
    const MergeCandidate* m = order.at(i);
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(m->cost, sorted[i].cost);
    EXPECT_EQ(std::make_pair(m->a, m->b), std::make_pair(sorted[i].a, sorted[i].b)) << i;
  }
  EXPECT_EQ(std::make_pair(sorted[0].a, sorted[0].b), std::make_pair(0, 2));
  EXPECT_EQ(std::make_pair(sorted[1].a, sorted[1].b), std::make_pair(0, 5));
}

}  // namespace
}  // namespace ff
