// Every part keeps enough clusters to become valid panels (cluster_floors, topology.h): four on
// a closed part, one on an open part. A small closed part next to a large one used to get its
// clusters by area alone (one or two), and the teleports, the panel phase's split-and-merge and
// its relocations took its cheap clusters away; three clusters on a closed part cannot all be
// planar panels.
#include <gtest/gtest.h>

#include <set>

#include "core/cluster/lloyd.h"
#include "core/cluster/seeding.h"
#include "core/cluster/teleport.h"
#include "core/remesher.h"
#include "core/shapes/shapes.h"
#include "subdivision_shapes.h"
#include "synthetic_meshes.h"
#include "test_meshes.h"

namespace ff {
namespace {

// A 10 x 10 open plate (part 0) and a small closed icosahedron of radius 0.1 (part 1): by area
// the icosahedron's share of 20 clusters is 0.01.
TriMesh plate_and_pebble() {
  TriMesh mesh = make_plane(12, 12, 10.0, 10.0);
  TriMesh pebble = test::icosahedron();
  for (Vec3& p : pebble.positions) p *= 0.1 / p.norm();
  test::append_shifted(mesh, pebble, Vec3(20, 0, 0));
  return mesh;
}

std::vector<int> clusters_per_part(const MeshTopology& topo, const Clustering& c) {
  std::vector<int> count(static_cast<size_t>(topo.num_components), 0);
  for (int seed : c.seeds) ++count[static_cast<size_t>(topo.face_component[static_cast<size_t>(seed)])];
  return count;
}

TEST(PartFloors, FewestPanelsPerPart) {
  const MeshTopology topo = build_topology(plate_and_pebble());
  ASSERT_EQ(topo.num_components, 2);
  EXPECT_EQ(fewest_panels(topo), (std::vector<int>{1, 4}));
  EXPECT_EQ(cluster_floors(topo, 5), (std::vector<int>{1, 4}));
  EXPECT_EQ(cluster_floors(topo, 4), (std::vector<int>{1, 1}));  // too few for both: one each
}

// The counting bound per shape (fewest_panels, topology.h), and the shapes of real meshes.
TEST(PartFloors, FewestPanelsByShape) {
  const auto fewest = [](bool closed, int euler) {
    PartShape shape;
    shape.closed = closed;
    shape.euler = euler;
    return fewest_panels(shape);
  };
  EXPECT_EQ(fewest(true, 2), 4);      // a sphere: the tetrahedron
  EXPECT_EQ(fewest(true, 0), 5);      // a torus (no torus of planar faces below 7 is known)
  EXPECT_EQ(fewest(true, -4), 7);     // three handles
  EXPECT_EQ(fewest(false, 1), 1);     // a disc
  EXPECT_EQ(fewest(false, 0), 3);     // an annulus: a band of three
  EXPECT_EQ(fewest(false, -8), 6);    // three handles and four holes
  EXPECT_EQ(fewest(true, -200), 23);  // 101 handles: grows as the square root

  const auto shape_of = [](const std::string& file) { return part_shapes(build_topology(test::load_clean(file))); };
  const std::vector<PartShape> holes = shape_of("3holes.off");
  ASSERT_EQ(holes.size(), 1u);
  EXPECT_TRUE(holes[0].closed);
  EXPECT_EQ(holes[0].handles(), 3);
  const std::vector<PartShape> hyperboloid = shape_of("hyperboloid_s4.off");
  ASSERT_EQ(hyperboloid.size(), 1u);
  EXPECT_FALSE(hyperboloid[0].closed);
  EXPECT_EQ(hyperboloid[0].boundary_loops, 2);
  EXPECT_EQ(hyperboloid[0].handles(), 0);
  EXPECT_EQ(fewest_panels(build_topology(test::load_clean("hyperboloid_s4.off"))), (std::vector<int>{3}));
  // The shapes of the parts add up to the whole mesh's Euler characteristic, on every shared mesh.
  for (const test::SharedMesh& m : test::shared_meshes()) {
    const TriMesh mesh = test::load_clean(m.file);
    const MeshTopology topo = build_topology(mesh);
    int euler = 0;
    for (const PartShape& shape : part_shapes(topo)) {
      euler += shape.euler;
      EXPECT_EQ((2 - shape.boundary_loops - shape.euler) % 2, 0) << m.file;
      EXPECT_GE(shape.handles(), 0) << m.file;
    }
    EXPECT_EQ(euler, euler_characteristic(mesh, topo)) << m.file;
  }
}

TEST(PartFloors, SeedingGivesASmallClosedPartFour) {
  const TriMesh mesh = plate_and_pebble();
  const MeshTopology topo = build_topology(mesh);
  const FaceData fd = make_face_data(mesh);
  EXPECT_EQ(seeds_per_component(fd, topo, 20), (std::vector<int>{16, 4}));
  EXPECT_EQ(seeds_per_component(fd, topo, 5), (std::vector<int>{1, 4}));
  EXPECT_EQ(seeds_per_component(fd, topo, 3), (std::vector<int>{2, 1}));  // below the floors: by area, one each
  for (SeedingMethod method : {SeedingMethod::Random, SeedingMethod::FarthestPoint}) {
    const std::vector<int> seeds = place_seeds(fd, topo, 20, method, 3);
    EXPECT_EQ(std::set<int>(seeds.begin(), seeds.end()).size(), 20u);
    int on_pebble = 0;
    for (int f : seeds) on_pebble += topo.face_component[static_cast<size_t>(f)] == 1;
    EXPECT_EQ(on_pebble, 4);
  }
}

// The pebble's clusters are the cheapest to merge (its energies are tiny) and the worst
// cluster is on the plate: without the floors every move took one from the pebble.
struct PlateAndPebble {
  TriMesh mesh = plate_and_pebble();
  MeshTopology topo = build_topology(mesh);
  FaceData fd = make_face_data(mesh);
  Metric metric{fd, MetricWeights{}, 20};
  Clustering c = initial_clustering(metric, topo, place_seeds(fd, topo, 20, SeedingMethod::FarthestPoint, 3));
};

TEST(PartFloors, TeleportKeepsTheFloor) {
  PlateAndPebble s;
  ASSERT_EQ(clusters_per_part(s.topo, s.c), (std::vector<int>{16, 4}));
  TeleportOptions options;
  options.max_moves = 4;
  int moves = 0;
  for (int round = 0; round < 5; ++round) {
    moves += teleport(s.metric, s.topo, s.c, options);
    EXPECT_EQ(clusters_per_part(s.topo, s.c)[1], 4) << "round " << round;
    for (int& sticky : s.c.sticky) sticky = 0;  // let every cluster move again
  }
  EXPECT_GT(moves, 0);  // the plate's clusters still move among themselves
  EXPECT_EQ(s.c.num_clusters(), 20);
}

TEST(PartFloors, SplitNearTakesNoMergeFromAPartAtItsFloor) {
  PlateAndPebble s;
  // Split requests on the plate: each needs a merge; the pebble's pairs are cheaper, but its
  // part is at its floor, so the merges come from the plate.
  std::vector<std::pair<int, int>> requests;
  for (int i = 0; i < s.c.num_clusters() && requests.size() < 3; ++i) {
    if (s.topo.face_component[static_cast<size_t>(s.c.seeds[static_cast<size_t>(i)])] != 0) continue;
    for (int f = 0; f < s.fd.num_faces(); ++f) {
      if (s.c.labels[static_cast<size_t>(f)] == i && f != s.c.seeds[static_cast<size_t>(i)]) {
        requests.emplace_back(i, f);
        break;
      }
    }
  }
  ASSERT_EQ(requests.size(), 3u);
  EXPECT_EQ(split_near(s.metric, s.topo, s.c, requests, {}), 3);
  EXPECT_EQ(clusters_per_part(s.topo, s.c), (std::vector<int>{16, 4}));
}

TEST(PartFloors, RelocationStaysInAPartAtItsFloor) {
  PlateAndPebble s;
  // A pebble cluster to move (as an enclosed one would): the worst clusters are on the plate,
  // but the pebble cannot spare it, so it goes to the pebble's worst; a plate cluster still
  // goes to the plate's worst.
  int pebble = -1, plate = -1;
  for (int i = 0; i < s.c.num_clusters(); ++i) {
    const int part = s.topo.face_component[static_cast<size_t>(s.c.seeds[static_cast<size_t>(i)])];
    (part == 1 ? pebble : plate) = i;
  }
  EXPECT_EQ(relocate_clusters(s.metric, s.topo, s.c, {pebble, plate}), 2);
  EXPECT_EQ(clusters_per_part(s.topo, s.c), (std::vector<int>{16, 4}));
  EXPECT_EQ(s.topo.face_component[static_cast<size_t>(s.c.seeds[static_cast<size_t>(pebble)])], 1);
}

TEST(PartFloors, FewerPanelsKeepTheFloor) {
  PlateAndPebble s;
  remove_clusters(s.metric, s.topo, s.c, 14);
  EXPECT_EQ(s.c.num_clusters(), 6);
  EXPECT_EQ(clusters_per_part(s.topo, s.c), (std::vector<int>{2, 4}));
}

// End to end on a real mesh: the bunny and a copy at an eighth of its size (area share 1.4%).
// At 100 panels the copy's share is 1.4 panels; it now starts with 4 and every part ends valid.
// (Before, the panel rounds split their way up to 6 on it, valid after 52 rounds; now 5.)
TEST(PartFloors, BunnyAndSmallBunnyAreValid) {
  TriMesh mesh = test::load_clean("bunny.off");
  Vec3 lo = mesh.positions[0], hi = lo;
  for (const Vec3& p : mesh.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  TriMesh small = mesh;
  for (Vec3& p : small.positions) p = lo + 0.12 * (p - lo);
  test::append_shifted(mesh, small, Vec3(2.0 * (hi - lo).norm(), 0, 0));
  RemeshParams p;
  p.panels = 100;
  Remesher r(mesh, p);
  r.run();
  const PanelMesh& panels = r.panels();
  EXPECT_EQ(panels.num_invalid(), 0);
  EXPECT_EQ(panels.num_panels(), 100);
  const MeshTopology topo = build_topology(mesh);
  ASSERT_EQ(topo.num_components, 2);
  ASSERT_EQ(panels.face_panel.size(), mesh.triangles.size());
  std::vector<std::set<int>> per_part(2);
  for (size_t f = 0; f < mesh.triangles.size(); ++f)
    per_part[static_cast<size_t>(topo.face_component[f])].insert(panels.face_panel[f]);
  EXPECT_GE(per_part[1].size(), 4u);
  EXPECT_EQ(per_part[0].size() + per_part[1].size(), 100u);
  EXPECT_LE(r.panel_rounds_done(), 10);
}

}  // namespace
}  // namespace ff
