// The Remesher: stepping, parameters, warm starts, determinism, and every shared mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "cluster_checks.h"
#include "core/remesher.h"
#include "core/shapes/hard_cases.h"
#include "core/shapes/shapes.h"
#include "input_error_message.h"
#include "subdivision_shapes.h"
#include "synthetic_meshes.h"
#include "test_meshes.h"

namespace ff {
namespace {

TEST(Remesher, DeterministicForASeedAndDifferentAcrossSeeds) {
  const TriMesh mesh = make_roof(50, 30);
  RemeshParams p;
  p.make_panels = false;  // the Lloyd phase alone; the panel phase: test_panel_phase.cpp
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
  p.make_panels = false;  // the Lloyd phase alone; the panel phase: test_panel_phase.cpp
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
    EXPECT_NEAR(pr.energy, r.energy().total(), 1e-9 * pr.energy);  // progress reports the real energy
  }
  EXPECT_LE(steps, 5);
  EXPECT_EQ(pr.iteration, r.lloyd_iterations_done());
  EXPECT_EQ(r.step().stage, Stage::Done);  // stepping when done is harmless
}

TEST(Remesher, RejectsImpossibleParameters) {
  const TriMesh mesh = make_plane(3, 3);  // 18 faces
  RemeshParams p;
  p.make_panels = false;  // the Lloyd phase alone; the panel phase: test_panel_phase.cpp
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
  EXPECT_TRUE(test::keeps_invariants(r.topology(), r.clustering(), 18));
}

TEST(Remesher, WarmStartChangesThePanelCount) {
  RemeshParams p;
  p.make_panels = false;  // the Lloyd phase alone; the panel phase: test_panel_phase.cpp
  p.panels = 30;
  Remesher r(make_roof(50, 30), p);
  r.run();
  p.panels = 45;
  r.set_params(p);
  EXPECT_TRUE(test::keeps_invariants(r.topology(), r.clustering(), 45));
  r.run();
  EXPECT_TRUE(test::keeps_invariants(r.topology(), r.clustering(), 45));
  p.panels = 12;
  p.weights.l2 = 3.0;
  r.set_params(p);
  r.run();
  EXPECT_TRUE(test::keeps_invariants(r.topology(), r.clustering(), 12));
}

TEST(Remesher, DenseRegionsGetSmallerClusters) {
  // A 2:1 plate, density 4 on the left half: left clusters should be about 4x smaller.
  const TriMesh mesh = make_plane(120, 60, 2.0, 1.0);
  std::vector<double> density(static_cast<size_t>(mesh.num_vertices()));
  for (size_t v = 0; v < density.size(); ++v) density[v] = mesh.positions[v].x() < 1.0 ? 4.0 : 1.0;
  RemeshParams p;
  p.make_panels = false;  // the Lloyd phase alone; the panel phase: test_panel_phase.cpp
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
    const bool is_left = fd.to_world(cm.first / cm.area).x() < 1.0;
    (is_left ? left_area : right_area) += cm.area;
    (is_left ? left : right) += 1;
  }
  const double ratio = (left_area / left) / (right_area / right);
  RecordProperty("area_ratio", std::to_string(ratio));
  // 1/4 is the ideal; the panel-count issue asks for below 1/2; we get about 0.31.
  EXPECT_LT(ratio, 0.4) << left << " left clusters, " << right << " right";
}

TEST(Remesher, WeightAndDensityChangesRefitUnderTheNewMetric) {
  const TriMesh mesh = make_roof(50, 30);
  RemeshParams p;
  p.make_panels = false;  // the Lloyd phase alone; the panel phase: test_panel_phase.cpp
  p.panels = 30;
  Remesher r(mesh, p);
  r.run();
  for (double factor : {10.0, 0.1}) {
    p.weights.euclidean *= factor;
    p.weights.l2 *= factor;
    p.weights.l21 *= factor;
    r.set_params(p);
    // The energy the monotone check starts from is the energy under the new metric.
    EXPECT_NEAR(r.progress().energy, r.energy().total(), 1e-9 * r.energy().total());
    r.run();
    EXPECT_TRUE(test::keeps_invariants(r.topology(), r.clustering(), 30));
  }
  p.density.assign(static_cast<size_t>(mesh.num_vertices()), 1.0);
  for (size_t v = 0; v < p.density.size(); v += 2) p.density[v] = 3.0;
  r.set_params(p);
  EXPECT_NEAR(r.progress().energy, r.energy().total(), 1e-9 * r.energy().total());
  r.run();
  EXPECT_TRUE(test::keeps_invariants(r.topology(), r.clustering(), 30));
}

TEST(Remesher, AFailedParameterChangeLeavesEverythingAsItWas) {
  RemeshParams p;
  p.make_panels = false;  // the Lloyd phase alone; the panel phase: test_panel_phase.cpp
  p.panels = 30;
  Remesher r(make_roof(50, 30), p);
  r.run();
  const std::vector<int> labels = r.clustering().labels;
  const double energy = r.energy().total();
  RemeshParams bad = p;
  bad.panels = 31;
  bad.weights.euclidean = -1.0;
  EXPECT_THROW(r.set_params(bad), std::runtime_error);
  bad = p;
  bad.panels = 31;
  bad.density = {1.0, 2.0, 3.0};
  EXPECT_THROW(r.set_params(bad), std::runtime_error);
  bad = p;
  bad.panels = 100000;
  EXPECT_THROW(r.set_params(bad), std::runtime_error);
  EXPECT_EQ(r.params().panels, 30);
  EXPECT_EQ(r.clustering().labels, labels);
  EXPECT_EQ(r.energy().total(), energy);
  p.panels = 35;  // and the next good change works from there
  r.set_params(p);
  r.run();
  EXPECT_TRUE(test::keeps_invariants(r.topology(), r.clustering(), 35));
}

TEST(Remesher, ARestartClearsTheOldClustering) {
  RemeshParams p;
  p.make_panels = false;  // the Lloyd phase alone; the panel phase: test_panel_phase.cpp
  p.panels = 20;
  Remesher r(make_roof(40, 30), p);
  r.run();
  p.seed = 99;
  p.panels = 25;
  r.set_params(p);
  EXPECT_EQ(r.progress().stage, Stage::Seeding);
  EXPECT_EQ(r.clustering().num_clusters(), 0);
  EXPECT_EQ(r.teleports_done(), 0);
  r.run();
  EXPECT_TRUE(test::keeps_invariants(r.topology(), r.clustering(), 25));
}

TEST(Remesher, UnitsDoNotMatter) {
  // The same shape in kilometres, in nanometres and at absurd scales clusters identically
  // (no overflow or underflow in the moments); energies scale with area.
  const TriMesh base = test::load_clean("bunny.off");
  RemeshParams p;
  p.make_panels = false;  // the Lloyd phase alone; the panel phase: test_panel_phase.cpp
  p.panels = 40;
  Remesher reference(base, p);
  reference.run();
  for (double scale : {1e-90, 1e-9, 1e3, 1e90}) {
    TriMesh mesh = base;
    for (Vec3& v : mesh.positions) v = v * scale + Vec3(3.0, -2.0, 1.0) * scale;
    Remesher r(mesh, p);
    r.run();
    EXPECT_EQ(r.clustering().labels, reference.clustering().labels) << "scale " << scale;
    EXPECT_NEAR(r.energy().total() / (scale * scale), reference.energy().total(), 1e-6 * reference.energy().total());
  }
}

class SharedMeshClustering : public ::testing::TestWithParam<test::SharedMesh> {};

TEST_P(SharedMeshClustering, ContiguousWithTheRequestedCountAndDeterministic) {
  const TriMesh mesh = test::load_clean(GetParam().file);
  for (int n : {12, 150}) {
    RemeshParams p;
    p.make_panels = false;  // the Lloyd phase alone; the panel phase: test_panel_phase.cpp
    p.panels = n;
    p.seed = 5;
    Remesher r(mesh, p);
    r.run();
    EXPECT_TRUE(test::keeps_invariants(r.topology(), r.clustering(), n)) << GetParam().file << " n=" << n;
    if (n == 12) {
      Remesher again(mesh, p);
      again.run();
      EXPECT_EQ(again.clustering().labels, r.clustering().labels) << GetParam().file;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(All, SharedMeshClustering, ::testing::ValuesIn(test::shared_meshes()),
                         [](const auto& info) { return test::test_name(info.param.file); });

}  // namespace
}  // namespace ff

namespace ff {
namespace {

// A closed part cannot be fewer than four planar panels (each panel meets at least three
// others), a torus fewer than five (fewest_panels, topology.h): asking for fewer is refused at
// once with the reason, and the Remesher keeps its last design; an open part can be one panel.
// The Lloyd phase alone has no such limit.
TEST(Remesher, TooFewPanelsForAClosedSurfaceAreRefused) {
  const TriMesh closed = make_torus(800);
  RemeshParams p;
  p.panels = 4;
  EXPECT_EQ(test::input_error_message([&] { Remesher r(closed, p); }),
            "a closed surface with 1 handle needs at least 5 planar panels (each meets at least three others, each "
            "neighbour along one side); asked for 4");
  p.panels = 3;
  EXPECT_EQ(test::input_error_message([&] { Remesher r(test::icosahedron(), p); }),
            "a closed surface needs at least 4 planar panels (each meets at least three others); asked for 3");
  p.make_panels = false;
  EXPECT_EQ(test::input_error_message([&] { Remesher r(closed, p); }), "");
  p.make_panels = true;
  p.panels = 8;
  p.lloyd_iterations = 2;
  Remesher r(closed, p);
  r.run();
  const int panels = r.panels().num_panels();
  RemeshParams fewer = p;
  fewer.panels = 2;
  EXPECT_NE(test::input_error_message([&] { r.set_params(fewer); }), "");
  EXPECT_EQ(r.params().panels, 8);
  EXPECT_EQ(r.panels().num_panels(), panels);

  RemeshParams one;
  one.panels = 1;
  one.lloyd_iterations = 2;
  Remesher flat(make_plane(6, 6), one);  // open: one panel is a valid answer
  flat.run();
  EXPECT_EQ(flat.panels().num_panels(), 1);
  EXPECT_EQ(flat.panels().num_invalid(), 0);
}

// With several parts the count is the sum: four per closed part without handles, one per
// disc, more per handle and hole, grouped by kind in the message.
TEST(Remesher, TooFewPanelsCountEveryPart) {
  TriMesh mesh = test::icosahedron();
  test::append_shifted(mesh, make_plane(4, 4), Vec3(100, 0, 0));
  RemeshParams p;
  p.panels = 4;
  EXPECT_EQ(test::input_error_message([&] { Remesher r(mesh, p); }),
            "the mesh has 1 closed part (at least 4 panels each) and 1 open part (at least 1 each): it needs at least "
            "5 panels; asked for 4");
  p.panels = 5;
  EXPECT_EQ(test::input_error_message([&] { Remesher r(mesh, p); }), "");
  test::append_shifted(mesh, make_torus(800), Vec3(-100, 0, 0));
  test::append_shifted(mesh, make_torus(800), Vec3(-200, 0, 0));
  p.panels = 12;
  EXPECT_EQ(test::input_error_message([&] { Remesher r(mesh, p); }),
            "the mesh has 1 closed part (at least 4 panels each), 2 closed parts with 1 handle (at least 5 each) and 1 "
            "open part (at least 1 each): it needs at least 15 panels; asked for 12");
}

// An open part that is no disc cannot be one panel: the hyperboloid (an annulus) needs three,
// and at three every panel is valid; at two it spent nine solves (16 s) on two unbuilt panels.
TEST(Remesher, AnAnnulusNeedsThreePanels) {
  const TriMesh hyperboloid = test::load_clean("hyperboloid_s4.off");
  RemeshParams p;
  p.panels = 2;
  EXPECT_EQ(test::input_error_message([&] { Remesher r(hyperboloid, p); }),
            "an open surface with 2 boundary loops needs at least 3 planar panels (each a disc, each neighbour along "
            "one side); asked for 2");
  p.panels = 3;
  p.seed = 1;
  Remesher r(hyperboloid, p);
  r.run();
  EXPECT_EQ(r.panels().num_panels(), 3);
  EXPECT_EQ(r.panels().num_invalid(), 0);
}

}  // namespace
}  // namespace ff
