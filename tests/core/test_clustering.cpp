// The Lloyd engine: seeding, flooding, iterations, teleports and the Remesher driving them,
// on generated surfaces and on every shared real mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/cluster/flood.h"
#include "core/cluster/lloyd.h"
#include "core/cluster/seeding.h"
#include "core/cluster/teleport.h"
#include "core/mesh/clean.h"
#include "core/mesh/mesh_io.h"
#include "core/remesher.h"
#include "core/shapes/shapes.h"
#include "test_meshes.h"

namespace ff {
namespace {

TriMesh load_clean(const std::string& file) { return clean_mesh(read_mesh_file(test::shared_mesh(file)).mesh).mesh; }

TEST(Seeding, DistinctDeterministicAndPerComponent) {
  // Two separate plates: every part gets at least one seed, in proportion to its area.
  TriMesh a = make_plane(20, 20, 1.0, 1.0), b = make_plane(10, 10, 0.5, 0.5);
  const int offset = a.num_vertices();
  for (const Vec3& p : b.positions) a.positions.push_back(p + Vec3(5, 0, 0));
  for (const Triangle& t : b.triangles) a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  const MeshTopology topo = build_topology(a);
  const FaceData fd = make_face_data(a);
  ASSERT_EQ(topo.num_components, 2);
  for (SeedingMethod method : {SeedingMethod::Random, SeedingMethod::FarthestPoint}) {
    const std::vector<int> s1 = place_seeds(fd, topo, 10, method, 42);
    const std::vector<int> s2 = place_seeds(fd, topo, 10, method, 42);
    EXPECT_EQ(s1, s2);
    EXPECT_EQ(std::set<int>(s1.begin(), s1.end()).size(), 10u);
    int in_small = 0;
    for (int f : s1) in_small += topo.face_component[static_cast<size_t>(f)] == 1;
    EXPECT_EQ(in_small, 2);  // area share 0.2 of 10
    EXPECT_NE(place_seeds(fd, topo, 10, method, 43), s1);
  }
  EXPECT_THROW(place_seeds(fd, topo, 1, SeedingMethod::Random, 1), std::runtime_error);
  EXPECT_THROW(place_seeds(fd, topo, a.num_faces() + 1, SeedingMethod::Random, 1), std::runtime_error);
  // Every face can be a seed.
  const std::vector<int> all = place_seeds(fd, topo, a.num_faces(), SeedingMethod::Random, 5);
  EXPECT_EQ(std::set<int>(all.begin(), all.end()).size(), static_cast<size_t>(a.num_faces()));
}

double min_seed_distance(const FaceData& fd, const std::vector<int>& seeds) {
  double best = 1e300;
  for (size_t i = 0; i < seeds.size(); ++i)
    for (size_t j = i + 1; j < seeds.size(); ++j)
      best = std::min(best, (fd[seeds[i]].centroid - fd[seeds[j]].centroid).norm());
  return best;
}

TEST(Seeding, FarthestPointSpreadsBetterThanRandom) {
  const TriMesh mesh = make_roof(60, 40);
  const MeshTopology topo = build_topology(mesh);
  const FaceData fd = make_face_data(mesh);
  const double spread_far = min_seed_distance(fd, place_seeds(fd, topo, 50, SeedingMethod::FarthestPoint, 1));
  const double spread_rnd = min_seed_distance(fd, place_seeds(fd, topo, 50, SeedingMethod::Random, 1));
  EXPECT_GT(spread_far, 2.0 * spread_rnd);
  // Far seeds sit about one cluster diameter apart.
  EXPECT_GT(spread_far, 0.5 * std::sqrt(fd.total_area / 50));
}

TEST(Flood, ClustersAreContiguousAndCoverEveryFace) {
  const TriMesh mesh = make_roof(40, 30);
  const MeshTopology topo = build_topology(mesh);
  const FaceData fd = make_face_data(mesh);
  const Metric metric(fd, MetricWeights{}, 25);
  Clustering c = initial_clustering(metric, topo, place_seeds(fd, topo, 25, SeedingMethod::Random, 9));
  EXPECT_TRUE(clusters_are_contiguous(topo, c.labels, 25));
  for (int i = 0; i < 25; ++i) EXPECT_EQ(c.labels[static_cast<size_t>(c.seeds[static_cast<size_t>(i)])], i);
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

TEST_P(LloydEnergy, NonIncreasingForASingleTerm) {
  for (const char* term : {"l2", "l21"}) {
    MetricWeights w;
    w.euclidean = 0.0;
    w.l2 = std::string(term) == "l2" ? 1.0 : 0.0;
    w.l21 = std::string(term) == "l21" ? 1.0 : 0.0;
    const std::string name = GetParam();
    const TriMesh mesh = name == "roof" ? make_roof(50, 35) : load_clean(name);
    std::vector<double> energies;
    single_term_run(mesh, w, energies);
    for (size_t i = 1; i < energies.size(); ++i) {
      EXPECT_LE(energies[i], energies[i - 1] * (1.0 + 1e-12) + 1e-15)
          << name << " " << term << " iteration " << i << ": " << energies[i - 1] << " -> " << energies[i];
    }
    EXPECT_LT(energies.back(), energies.front());
  }
}

INSTANTIATE_TEST_SUITE_P(Meshes, LloydEnergy, ::testing::Values("roof", "bunny.off", "inspired_mesh.obj", "fandisk.off"),
                         [](const auto& info) {
                           std::string s = info.param;
                           std::replace_if(s.begin(), s.end(), [](char ch) { return !std::isalnum(static_cast<unsigned char>(ch)); }, '_');
                           return s;
                         });

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
  EXPECT_EQ(c.num_clusters(), 30);
  EXPECT_TRUE(clusters_are_contiguous(topo, c.labels, 30));
  int sticky = 0;
  for (int s : c.sticky) sticky += s > 0;
  EXPECT_EQ(sticky, moves);
  lloyd_iteration(metric, topo, c);
  EXPECT_LT(c.energy, before);
  // Clusters keep every face and their seeds.
  for (int i = 0; i < 30; ++i) EXPECT_EQ(c.labels[static_cast<size_t>(c.seeds[static_cast<size_t>(i)])], i);
}

TEST(Teleport, AddAndRemoveClustersKeepInvariants) {
  const TriMesh mesh = make_roof(40, 30);
  const MeshTopology topo = build_topology(mesh);
  const FaceData fd = make_face_data(mesh);
  const Metric metric(fd, MetricWeights{}, 20);
  Clustering c = initial_clustering(metric, topo, place_seeds(fd, topo, 20, SeedingMethod::FarthestPoint, 2));
  add_clusters(metric, topo, c, 13);
  EXPECT_EQ(c.num_clusters(), 33);
  EXPECT_TRUE(clusters_are_contiguous(topo, c.labels, 33));
  remove_clusters(metric, topo, c, 25);
  EXPECT_EQ(c.num_clusters(), 8);
  EXPECT_TRUE(clusters_are_contiguous(topo, c.labels, 8));
}

TEST(Remesher, DeterministicForASeedAndDifferentAcrossSeeds) {
  const TriMesh mesh = make_roof(50, 30);
  RemeshParams p;
  p.panels = 40;
  p.seed = 77;
  Remesher a(mesh, p), b(mesh, p);
  a.run();
  b.run();
  EXPECT_EQ(a.clustering().labels, b.clustering().labels);
  p.seed = 78;
  Remesher c(mesh, p);
  c.run();
  EXPECT_NE(a.clustering().labels, c.clustering().labels);
}

TEST(Remesher, StepsReportProgressAndStopAtTheLimit) {
  RemeshParams p;
  p.panels = 20;
  p.lloyd_iterations = 5;
  Remesher r(make_roof(30, 20), p);
  Progress pr = r.step();
  EXPECT_EQ(pr.stage, Stage::Lloyd);
  EXPECT_EQ(pr.of, 5);
  int steps = 0;
  while (!r.done()) {
    pr = r.step();
    ++steps;
    EXPECT_GT(pr.energy, 0.0);
  }
  EXPECT_LE(steps, 5);
  EXPECT_EQ(pr.iteration, r.lloyd_iterations_done());
  EXPECT_EQ(r.step().stage, Stage::Done);  // stepping when done is harmless
}

TEST(Remesher, RejectsImpossibleParameters) {
  const TriMesh mesh = make_plane(3, 3);  // 18 faces
  RemeshParams p;
  p.panels = 19;
  EXPECT_THROW(Remesher(mesh, p), std::runtime_error);
  p.panels = 0;
  EXPECT_THROW(Remesher(mesh, p), std::runtime_error);
  p.panels = 5;
  p.lloyd_iterations = -1;
  EXPECT_THROW(Remesher(mesh, p), std::runtime_error);
  p.lloyd_iterations = 3;
  p.density = {1.0, 2.0};
  EXPECT_THROW(Remesher(mesh, p), std::runtime_error);
  p.density.clear();
  p.panels = 18;  // one face per panel is allowed
  Remesher r(mesh, p);
  r.run();
  EXPECT_EQ(r.clustering().num_clusters(), 18);
  EXPECT_TRUE(clusters_are_contiguous(r.topology(), r.clustering().labels, 18));
}

TEST(Remesher, WarmStartChangesThePanelCount) {
  RemeshParams p;
  p.panels = 30;
  Remesher r(make_roof(50, 30), p);
  r.run();
  p.panels = 45;
  r.set_params(p);
  EXPECT_EQ(r.clustering().num_clusters(), 45);
  r.run();
  EXPECT_TRUE(clusters_are_contiguous(r.topology(), r.clustering().labels, 45));
  p.panels = 12;
  p.weights.l2 = 3.0;
  r.set_params(p);
  r.run();
  EXPECT_EQ(r.clustering().num_clusters(), 12);
  EXPECT_TRUE(clusters_are_contiguous(r.topology(), r.clustering().labels, 12));
}

TEST(Remesher, DenseRegionsGetSmallerClusters) {
  // A 2:1 plate, density 4 on the left half: left clusters should be about 4x smaller.
  const TriMesh mesh = make_plane(120, 60, 2.0, 1.0);
  std::vector<double> density(static_cast<size_t>(mesh.num_vertices()));
  for (size_t v = 0; v < density.size(); ++v) density[v] = mesh.positions[v].x() < 1.0 ? 4.0 : 1.0;
  RemeshParams p;
  p.panels = 60;
  p.density = density;
  p.lloyd_iterations = 40;
  Remesher r(mesh, p);
  r.run();
  const FaceData fd = make_face_data(mesh);
  const std::vector<ClusterMoments> m = cluster_moments(fd, r.clustering().labels, 60);
  double left_area = 0, right_area = 0;
  int left = 0, right = 0;
  for (const ClusterMoments& cm : m) {
    const bool is_left = cm.first.x() / cm.area + fd.origin.x() < 1.0;
    (is_left ? left_area : right_area) += cm.area;
    (is_left ? left : right) += 1;
  }
  const double ratio = (left_area / left) / (right_area / right);
  EXPECT_LT(ratio, 0.5) << left << " left clusters, " << right << " right";
}

class SharedMeshClustering : public ::testing::TestWithParam<test::SharedMesh> {};

TEST_P(SharedMeshClustering, ContiguousWithTheRequestedCountAndDeterministic) {
  const TriMesh mesh = load_clean(GetParam().file);
  for (int n : {12, 150}) {
    RemeshParams p;
    p.panels = n;
    p.seed = 5;
    Remesher r(mesh, p);
    r.run();
    EXPECT_EQ(r.clustering().num_clusters(), n) << GetParam().file;
    EXPECT_TRUE(clusters_are_contiguous(r.topology(), r.clustering().labels, n)) << GetParam().file << " n=" << n;
    if (n == 12) {
      Remesher again(mesh, p);
      again.run();
      EXPECT_EQ(again.clustering().labels, r.clustering().labels) << GetParam().file;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(All, SharedMeshClustering, ::testing::ValuesIn(test::shared_meshes()),
                         [](const auto& info) {
                           std::string s = info.param.file;
                           std::replace_if(s.begin(), s.end(), [](char ch) { return !std::isalnum(static_cast<unsigned char>(ch)); }, '_');
                           return s;
                         });

}  // namespace
}  // namespace ff
