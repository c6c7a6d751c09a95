// Flooding, Lloyd iterations, boundary refinement and teleports.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <utility>
#include <vector>

#include "cluster_checks.h"
#include "core/cluster/flood.h"
#include "core/cluster/lloyd.h"
#include "core/cluster/refine.h"
#include "core/cluster/seeding.h"
#include "core/cluster/teleport.h"
#include "core/shapes/shapes.h"
#include "core/util/random.h"
#include "synthetic_meshes.h"
#include "test_meshes.h"

namespace ff {
namespace {

TEST(Flood, ClustersAreContiguousAndCoverEveryFace) {
  const TriMesh mesh = make_roof(40, 30);
  const MeshTopology topo = build_topology(mesh);
  const FaceData fd = make_face_data(mesh);
  const Metric metric(fd, MetricWeights{}, 25);
  Clustering c = initial_clustering(metric, topo, place_seeds(fd, topo, 25, SeedingMethod::Random, 9));
  EXPECT_TRUE(test::keeps_invariants(topo, c, 25));
}

// The flood as the paper states it, with an ordered set for a queue: every face joins the
// cluster of the cheapest offer made to it so far, popped in (cost, face) order.
std::vector<int> reference_flood(const Metric& metric, const MeshTopology& topo, const Clustering& c) {
  const size_t faces = c.labels.size();
  std::vector<int> label(faces, -1), best_cluster(faces, -1);
  std::vector<double> best(faces, std::numeric_limits<double>::infinity());
  std::set<std::pair<double, int>> queue;
  const auto offer = [&](int f, int i) {
    for (int g : topo.face_neighbors[static_cast<size_t>(f)]) {
      if (g < 0 || label[static_cast<size_t>(g)] >= 0 || best_cluster[static_cast<size_t>(g)] == i) continue;
      const double cost = metric.cost(g, metric.terms(c.proxies[static_cast<size_t>(i)]));
      if (cost < best[static_cast<size_t>(g)]) {
        best[static_cast<size_t>(g)] = cost;
        best_cluster[static_cast<size_t>(g)] = i;
        queue.insert({cost, g});
      }
    }
  };
  for (int i = 0; i < c.num_clusters(); ++i) label[static_cast<size_t>(c.seeds[static_cast<size_t>(i)])] = i;
  for (size_t f = 0; f < faces; ++f) {
    if (label[f] >= 0) offer(static_cast<int>(f), label[f]);
  }
  while (!queue.empty()) {
    const auto [cost, f] = *queue.begin();
    queue.erase(queue.begin());
    if (label[static_cast<size_t>(f)] >= 0 || cost != best[static_cast<size_t>(f)]) continue;
    label[static_cast<size_t>(f)] = best_cluster[static_cast<size_t>(f)];
    offer(f, label[static_cast<size_t>(f)]);
  }
  return label;
}

TEST(Flood, MatchesTheReferenceFloodFaceForFace) {
  // Real proxies (after a few iterations) on a real mesh, so the queue holds long fronts.
  const TriMesh mesh = test::load_clean("bunny.off");
  const MeshTopology topo = build_topology(mesh);
  const FaceData fd = make_face_data(mesh);
  const Metric metric(fd, MetricWeights{}, 150);
  Clustering c = initial_clustering(metric, topo, place_seeds(fd, topo, 150, SeedingMethod::FarthestPoint, 5));
  for (int it = 0; it < 3; ++it) lloyd_iteration(metric, topo, c);
  choose_seeds(metric, c);
  std::fill(c.sticky.begin(), c.sticky.end(), 0);
  const std::vector<int> expected = reference_flood(metric, topo, c);
  flood(metric, topo, c);
  EXPECT_EQ(c.labels, expected);
}

EnergyTerms single_term_run(const TriMesh& mesh, MetricWeights w, std::vector<double>& energies) {
  const MeshTopology topo = build_topology(mesh);
  const FaceData fd = make_face_data(mesh);
  const Metric metric(fd, w, 40);
  Clustering c = initial_clustering(metric, topo, place_seeds(fd, topo, 40, SeedingMethod::Random, 11));
  EnergyTerms e;
  for (int it = 0; it < 25; ++it) {
    const LloydResult r = lloyd_iteration(metric, topo, c);
    energies.push_back(r.energy.total());
    e = r.energy;
  }
  return e;
}

class LloydEnergy : public ::testing::TestWithParam<std::string> {};

// For one L2 or L2,1 term (the ask) and for all three together: each fit is exact
// and a flood that would raise the energy is replaced by boundary refinement.
TEST_P(LloydEnergy, NeverIncreases) {
  for (const char* term : {"l2", "l21", "all"}) {
    MetricWeights w;
    w.euclidean = std::string(term) == "all" ? 1.0 : 0.0;
    w.l2 = std::string(term) != "l21" ? 1.0 : 0.0;
    w.l21 = std::string(term) != "l2" ? 1.0 : 0.0;
    const std::string name = GetParam();
    const TriMesh mesh = name == "roof" ? make_roof(50, 35) : test::load_clean(name);
    std::vector<double> energies;
    single_term_run(mesh, w, energies);
    for (size_t i = 1; i < energies.size(); ++i) {
      EXPECT_LE(energies[i], energies[i - 1] * (1.0 + 1e-12) + 1e-15)
          << name << " " << term << " iteration " << i << ": " << energies[i - 1] << " -> " << energies[i];
    }
    EXPECT_LT(energies.back(), energies.front());
  }
}

INSTANTIATE_TEST_SUITE_P(Meshes, LloydEnergy,
                         ::testing::Values("roof", "bunny.off", "inspired_mesh.obj", "fandisk.off"),
                         [](const auto& info) { return test::test_name(info.param); });

TEST(Teleport, KeepsClusterCountContiguityAndLowersEnergy) {
  // All seeds crowded into one corner: tiny clusters there are cheap to merge and one
  // huge cluster is the worst, so teleports must happen and pay off.
  const TriMesh mesh = make_roof(60, 40);
  const MeshTopology topo = build_topology(mesh);
  const FaceData fd = make_face_data(mesh);
  const Metric metric(fd, MetricWeights{}, 30);
  std::vector<int> crowded;
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 5; ++i) crowded.push_back(2 * (j * 60 + i));
  Clustering c = initial_clustering(metric, topo, crowded);
  const double before = c.energy;
  TeleportOptions options;
  options.max_moves = 3;
  const int moves = teleport(metric, topo, c, options);
  EXPECT_EQ(moves, 3);
  EXPECT_TRUE(test::keeps_invariants(topo, c, 30));
  int sticky = 0;
  for (int s : c.sticky) sticky += s > 0;
  EXPECT_EQ(sticky, moves);
  lloyd_iteration(metric, topo, c);
  EXPECT_LT(c.energy, before);
  EXPECT_TRUE(test::keeps_invariants(topo, c, 30));
}

TEST(Teleport, AddAndRemoveClustersKeepInvariants) {
  const TriMesh mesh = make_roof(40, 30);
  const MeshTopology topo = build_topology(mesh);
  const FaceData fd = make_face_data(mesh);
  const Metric metric(fd, MetricWeights{}, 20);
  Clustering c = initial_clustering(metric, topo, place_seeds(fd, topo, 20, SeedingMethod::FarthestPoint, 2));
  add_clusters(metric, topo, c, 13);
  EXPECT_TRUE(test::keeps_invariants(topo, c, 33));
  remove_clusters(metric, topo, c, 25);
  EXPECT_TRUE(test::keeps_invariants(topo, c, 8));
  // Down to one cluster per face and back up to one.
  add_clusters(metric, topo, c, mesh.num_faces() - 8);
  EXPECT_TRUE(test::keeps_invariants(topo, c, mesh.num_faces()));
  remove_clusters(metric, topo, c, mesh.num_faces() - 1);
  EXPECT_TRUE(test::keeps_invariants(topo, c, 1));
}

TEST(Refine, BoundaryMovesLowerTheEnergyAndKeepClustersWhole) {
  // A clustering under proxies it was not flooded with: plenty of border faces to move.
  const TriMesh mesh = make_roof(60, 40);
  const MeshTopology topo = build_topology(mesh);
  const FaceData fd = make_face_data(mesh);
  const Metric metric(fd, MetricWeights{}, 40);
  Clustering c = initial_clustering(metric, topo, place_seeds(fd, topo, 40, SeedingMethod::Random, 4));
  for (Proxy& p : c.proxies) p.center += Vec3(0.05, -0.03, 0.0);  // shifted proxies
  const auto energy_under_proxies = [&] {
    return clustering_energy(metric, cluster_moments(fd, c.labels, 40), c.proxies).total();
  };
  const std::vector<int> seeds = c.seeds;
  const double before = energy_under_proxies();
  const int moves = refine_boundaries(metric, topo, c);
  EXPECT_GT(moves, 0);
  EXPECT_LT(energy_under_proxies(), before);
  EXPECT_EQ(c.seeds, seeds);
  EXPECT_TRUE(test::keeps_invariants(topo, c, 40));
  // A fixed point: nothing left to move under the same proxies.
  EXPECT_EQ(refine_boundaries(metric, topo, c, 1000), 0);
}

TEST(Clustering, InvariantsHoldOnHardInputs) {
  // Two separate parts, zero-area faces, and as many clusters as faces.
  TriMesh mesh = make_plane(6, 4);
  test::append_shifted(mesh, make_plane(3, 3, 0.5, 0.5), Vec3(3, 0, 0));
  mesh.positions[1] = 0.5 * (mesh.positions[0] + mesh.positions[2]);  // flattens the faces at vertex 1
  const MeshTopology topo = build_topology(mesh);
  const FaceData fd = make_face_data(mesh);
  for (int n : {2, 7, mesh.num_faces()}) {
    for (SeedingMethod method : {SeedingMethod::Random, SeedingMethod::FarthestPoint}) {
      const Metric metric(fd, MetricWeights{}, n);
      Clustering c = initial_clustering(metric, topo, place_seeds(fd, topo, n, method, 3));
      for (int it = 0; it < 6; ++it) {
        if (it % 2 == 1) teleport(metric, topo, c, TeleportOptions{3, 2});
        lloyd_iteration(metric, topo, c);
        ASSERT_TRUE(test::keeps_invariants(topo, c, n)) << "n=" << n << " iteration " << it;
      }
    }
  }
}

TEST(Clustering, AdjacentPairsAreTheSortedDistinctPairsAcrossEdges) {
  const TriMesh mesh = test::load_clean("bunny.off");
  const MeshTopology topo = build_topology(mesh);
  const FaceData fd = make_face_data(mesh);
  SplitMix64 rng(5);
  for (int n : {1, 2, 37, 200, 3000}) {
    const Metric metric(fd, MetricWeights{}, n);
    Clustering c = initial_clustering(metric, topo, place_seeds(fd, topo, n, SeedingMethod::FarthestPoint, 4));
    for (int variant = 0; variant < 3; ++variant) {
      std::vector<int> labels = c.labels;
      if (variant == 1) {  // some faces unassigned
        for (int& l : labels) l = rng.below(5) == 0 ? -1 : l;
      } else if (variant == 2) {  // scattered labels: many distinct pairs, few repeats
        for (int& l : labels) l = static_cast<int>(rng.below(static_cast<std::uint64_t>(n)));
      }
      std::vector<std::pair<int, int>> expected;
      for (const auto& ef : topo.edge_faces) {
        if (ef[1] < 0) continue;
        const int a = labels[static_cast<size_t>(ef[0])], b = labels[static_cast<size_t>(ef[1])];
        if (a != b && a >= 0 && b >= 0) expected.emplace_back(std::min(a, b), std::max(a, b));
      }
      std::sort(expected.begin(), expected.end());
      expected.erase(std::unique(expected.begin(), expected.end()), expected.end());
      EXPECT_EQ(adjacent_cluster_pairs(topo, labels), expected) << "n=" << n << " variant " << variant;
      if (n > 1) {
        EXPECT_FALSE(expected.empty());
      }
    }
  }
  EXPECT_TRUE(adjacent_cluster_pairs(topo, std::vector<int>(static_cast<size_t>(mesh.num_faces()), -1)).empty());
}

}  // namespace
}  // namespace ff
