// Seeding: distinct, deterministic, per connected part, and well spread.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/cluster/seeding.h"
#include "core/shapes/shapes.h"
#include "synthetic_meshes.h"

namespace ff {
namespace {

TEST(Seeding, DistinctDeterministicAndPerComponent) {
  // Two separate plates: every part gets at least one seed, in proportion to its area.
  TriMesh a = make_plane(20, 20, 1.0, 1.0);
  test::append_shifted(a, make_plane(10, 10, 0.5, 0.5), Vec3(5, 0, 0));
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

TEST(Seeding, FarthestSeedsCrowdWhereDensityIsHigh) {
  // Density 1 on the left half (the uniform value, which skips pow) and 4 on the right:
  // with the density weight, seed distances on the right are stretched 2x, so the right
  // half gets about 4x the seeds. Uniform density 1 must give exactly the seeds of none.
  const TriMesh mesh = make_plane(40, 40, 2.0, 2.0);
  const MeshTopology topo = build_topology(mesh);
  const FaceData plain = make_face_data(mesh);
  std::vector<double> density(static_cast<size_t>(mesh.num_faces()));
  for (size_t f = 0; f < density.size(); ++f) density[f] = plain[f].centroid.x() < 0.0 ? 1.0 : 4.0;
  const FaceData fd = make_face_data(mesh, density);
  const std::vector<int> seeds = place_seeds(fd, topo, 60, SeedingMethod::FarthestPoint, 3, 1.0);
  int right = 0;
  for (int f : seeds) right += fd[static_cast<size_t>(f)].centroid.x() >= 0.0;
  EXPECT_GE(right, 40);  // 48 of 60 for a 4:1 split; equal halves would be 30
  EXPECT_LE(right, 56);
  const FaceData ones = make_face_data(mesh, std::vector<double>(density.size(), 1.0));
  EXPECT_EQ(place_seeds(ones, topo, 60, SeedingMethod::FarthestPoint, 3, 1.0),
            place_seeds(plain, topo, 60, SeedingMethod::FarthestPoint, 3, 0.0));
}

TEST(Seeding, ManySeparatePartsAreApportionedInLinearTime) {
  // 20000 separate two-triangle plates (a facade of loose panels): one seed each, plus the
  // rest by area. This used to take seconds (a sort per seed).
  TriMesh mesh;
  for (int k = 0; k < 20000; ++k) {
    const int base = mesh.num_vertices();
    const double x = 2.0 * (k % 200), y = 2.0 * (k / 200), size = k % 2 == 0 ? 1.0 : 0.5;
    mesh.positions.push_back(Vec3(x, y, 0));
    mesh.positions.push_back(Vec3(x + size, y, 0));
    mesh.positions.push_back(Vec3(x + size, y + size, 0));
    mesh.positions.push_back(Vec3(x, y + size, 0));
    mesh.triangles.push_back({base, base + 1, base + 2});
    mesh.triangles.push_back({base, base + 2, base + 3});
  }
  const MeshTopology topo = build_topology(mesh);
  const FaceData fd = make_face_data(mesh);
  const std::vector<int> counts = seeds_per_component(fd, topo, 30000);
  ASSERT_EQ(counts.size(), 20000u);
  int total = 0, big_two = 0, small_two = 0;
  for (size_t c = 0; c < counts.size(); ++c) {
    total += counts[c];
    ASSERT_GE(counts[c], 1);
    ASSERT_LE(counts[c], 2);
    (c % 2 == 0 ? big_two : small_two) += counts[c] == 2;
  }
  EXPECT_EQ(total, 30000);
  EXPECT_GT(big_two, small_two);  // the larger plates get the extra seeds first
}

}  // namespace
}  // namespace ff
