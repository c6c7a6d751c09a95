// Remesher's polish (core/remesher_polish.cpp): local splits at the best attempt's problems
// when the rounds and mend_best() leave it invalid (issue 3, seed 2), one attempt per step(),
// and the split it is made of, split_cluster_at (core/cluster/cluster_edits.h).
#include <gtest/gtest.h>

#include <vector>

#include "cluster_checks.h"
#include "core/cluster/cluster_edits.h"
#include "core/quality/report.h"
#include "panel_checks.h"

namespace ff {
namespace {

// Steps `r` until it has made `attempts` polish steps (steps of the panel stage that run no
// panel round: every panel round counts itself in panel_rounds_done()) or is done. Returns
// the polish steps made.
int step_into_polish(Remesher& r, int attempts) {
  int polish = 0;
  while (!r.done() && polish < attempts) {
    const bool panels = r.progress().stage == Stage::Panels;
    const int rounds = r.panel_rounds_done();
    r.step();
    if (panels && r.panel_rounds_done() == rounds) ++polish;
  }
  return polish;
}

// cow.off at 56 panels, seed 3: its rounds end invalid, so the polish runs: 9 steps, then
// valid, with no retry. (Seed 1 was this example, with two clusters that were not disks,
// until the relaxation stopped once settled, plane_relax.h: its rounds now end valid.)
RemeshParams cow56() {
  RemeshParams p;
  p.panels = 56;
  p.seed = 3;
  return p;
}

// `r` two polish steps in, with more to come (still in the panel stage).
::testing::AssertionResult two_steps_into_polish(Remesher& r) {
  const int made = step_into_polish(r, 2);
  if (made != 2) return ::testing::AssertionFailure() << made << " polish steps, not 2";
  if (r.progress().stage != Stage::Panels) return ::testing::AssertionFailure() << "the polish ended after 2 steps";
  return ::testing::AssertionSuccess();
}

// Valid, or the invalid panels reported: the progress, the panel mesh and the quality check
// agree on how many there are.
void expect_valid_or_reported(const Remesher& r, int panels, double max_hausdorff) {
  ASSERT_TRUE(r.done());
  EXPECT_TRUE(test::keeps_invariants(r.topology(), r.clustering(), panels));
  const PanelMesh& pm = r.panels();
  EXPECT_EQ(pm.num_panels() + static_cast<int>(pm.unbuilt_clusters.size()), panels);
  EXPECT_EQ(r.progress().invalid_panels, pm.num_invalid());
  if (pm.num_invalid() == 0) {
    EXPECT_TRUE(test::valid_panels(r, panels, max_hausdorff));
  } else {
    EXPECT_GT(measure_quality(r.mesh(), r.topology(), pm).invalid_panels, 0);
  }
}

// The halves grow from the two faces given, inside the cluster: the cluster keeps its id and
// face a, the new one gets face b, both contiguous, together exactly the old cluster.
TEST(PolishSplitAt, HalvesGrowFromTheGivenFaces) {
  RemeshParams p;
  p.panels = 20;
  p.make_panels = false;
  Remesher r(test::load_clean("bunny.off"), p);
  r.run();
  const Clustering& before = r.clustering();
  const int cluster = 5;
  std::vector<int> faces;
  for (size_t f = 0; f < before.labels.size(); ++f) {
    if (before.labels[f] == cluster) faces.push_back(static_cast<int>(f));
  }
  ASSERT_GE(faces.size(), 4u);
  const int a = before.seeds[static_cast<size_t>(cluster)];
  const int b = faces[faces.size() / 2] != a ? faces[faces.size() / 2] : faces.front();
  Clustering c = before;
  ASSERT_EQ(split_cluster_at(r.metric(), r.topology(), c, cluster, a, b), 20);
  EXPECT_EQ(c.labels[static_cast<size_t>(a)], cluster);
  EXPECT_EQ(c.labels[static_cast<size_t>(b)], 20);
  EXPECT_EQ(c.seeds[static_cast<size_t>(cluster)], a);
  EXPECT_EQ(c.seeds[20], b);
  EXPECT_TRUE(clusters_are_contiguous(r.topology(), c.labels, 21));
  for (size_t f = 0; f < c.labels.size(); ++f) {
    const bool was = before.labels[f] == cluster, is = c.labels[f] == cluster || c.labels[f] == 20;
    EXPECT_EQ(was, is) << f;
  }
  // Not two distinct faces of the cluster: nothing changes.
  Clustering same = before;
  EXPECT_EQ(split_cluster_at(r.metric(), r.topology(), same, cluster, a, a), -1);
  int other = 0;
  while (before.labels[static_cast<size_t>(other)] == cluster) ++other;
  EXPECT_EQ(split_cluster_at(r.metric(), r.topology(), same, cluster, a, other), -1);
  EXPECT_EQ(split_cluster_at(r.metric(), r.topology(), same, cluster, a, -1), -1);
  EXPECT_EQ(same.labels, before.labels);
  EXPECT_EQ(same.num_clusters(), 20);
}

// Each test below checks that its rounds did end invalid, so the polish ran: the draws are
// chaotic and re-chosen when the rounds change.
::testing::AssertionResult polish_ran(Remesher& r) {
  if (step_into_polish(r, 1) != 1) return ::testing::AssertionFailure() << "the rounds ended valid: no polish";
  r.run();
  return ::testing::AssertionSuccess();
}

// cow.off at 100 panels, seed 11: the rounds end invalid and mend() leaves it so; the polish
// ends valid with the 100 panels asked for, with no retry. (Seeds 2, 7 and 9 were this
// example until the panel checks took the quality report's tolerance, the relaxation stopped
// once settled, and clusters too small to cut moved elsewhere: their rounds now go other ways.)
TEST(PolishBest, CowAt100PanelsSeed11EndsValid) {
  const auto r = test::remesher("cow.off", 100, 11);
  ASSERT_TRUE(polish_ran(*r));
  EXPECT_EQ(r->retries_done(), 0);
  EXPECT_TRUE(test::valid_panels(*r, 100, 0.12));
}

// cow.off at 78 panels, seed 6: the rounds end with one invalid panel that neither mend()
// nor the second pass's splits near it mend; the third pass cuts its cluster in two along its
// length and a round chained from there ends valid, with no retry. (Until the early mend
// stopped at 3 invalid panels this was face.obj at 574 panels, seed 2, a plane 94 degrees
// from its faces; it now ends valid in the rounds.) The bound is the cow's
// (test_panel_rounds.cpp).
TEST(PolishBest, CowAt78PanelsSeed6EndsValidInTheThirdPass) {
  const auto r = test::remesher("cow.off", 78, 6);
  ASSERT_TRUE(polish_ran(*r));
  EXPECT_EQ(r->retries_done(), 0);
  EXPECT_TRUE(test::valid_panels(*r, 78, 0.15));
}

// cow.off at 56 panels, seed 3: after the polish every cluster is a disk and gets its panel,
// at most one is invalid. (The draws before it, cow.off at 61 panels, seed 2 and at 56 panels,
// seed 1, had clusters that were not disks in their best round, which the polish cut.)
TEST(PolishBest, CowAt56PanelsEveryClusterGetsItsPanel) {
  RemeshParams p = cow56();
  p.retries = 0;
  Remesher r(test::load_clean("cow.off"), p);
  ASSERT_TRUE(polish_ran(r));
  const PanelMesh& pm = r.panels();
  EXPECT_EQ(pm.num_panels(), 56);
  EXPECT_LE(pm.num_invalid(), 1);
  for (int c = 0; c < pm.num_panels(); ++c) EXPECT_FALSE(pm.issues[static_cast<size_t>(c)].not_disk) << c;
}

// The polish is resumable: each step() mends one attempt, so the worker answers a cancel
// within one panel round's time. On cow.off at 56 panels, seed 3, it runs 9 steps (the
// bounds below leave room: the draws are chaotic);
// through them the progress stays the panel stage's (its round count, at most `of`) and its
// invalid count (the best's) never goes up; the result is the one
// CowAt56PanelsEveryClusterGetsItsPanel checks.
TEST(PolishBest, OneAttemptPerStep) {
  Remesher r(test::load_clean("cow.off"), cow56());
  int polish = 0, rounds = -1, last_invalid = -1;
  while (!r.done()) {
    const bool panels = r.progress().stage == Stage::Panels;
    const int before = r.panel_rounds_done();
    const Progress progress = r.step();
    if (!panels || r.panel_rounds_done() != before) continue;
    ++polish;
    if (rounds < 0) rounds = before;
    EXPECT_EQ(r.panel_rounds_done(), rounds);    // no more rounds once it polishes
    if (progress.stage != Stage::Panels) break;  // the last polish step ends the phase
    EXPECT_EQ(progress.iteration, rounds);
    EXPECT_LE(progress.iteration, progress.of);
    EXPECT_GT(progress.invalid_panels, 0);
    if (last_invalid >= 0) {
      EXPECT_LE(progress.invalid_panels, last_invalid);
    }
    last_invalid = progress.invalid_panels;
  }
  RecordProperty("polish_steps", polish);
  EXPECT_GE(polish, 3);  // more than one pass
  EXPECT_LE(polish, 18);
  r.run();
  EXPECT_EQ(r.panels().num_panels(), 56);
  EXPECT_LE(r.panels().num_invalid(), 1);
}

// A new panel count in the middle of the polish: the warm start takes the clustering of the
// moment (n clusters between steps) and the run finishes, valid or with its invalid panels
// reported; the count is the new one.
TEST(PolishBest, NewPanelCountMidPolishFinishes) {
  RemeshParams p = cow56();
  Remesher r(test::load_clean("cow.off"), p);
  ASSERT_TRUE(two_steps_into_polish(r));
  p.panels = 70;
  r.set_params(p);
  EXPECT_EQ(r.progress().stage, Stage::Lloyd);
  r.run();
  expect_valid_or_reported(r, 70, 0.15);  // the cow's bound at 61 panels: its legs' tips (0.149 here)
}

// A new seed in the middle of the polish starts over: nothing of the polish is left, the
// result is exactly that of a fresh solve with the new seed.
TEST(PolishBest, NewSeedMidPolishEqualsAFreshSolve) {
  const TriMesh mesh = test::load_clean("cow.off");
  RemeshParams p = cow56();
  Remesher r(mesh, p);
  ASSERT_TRUE(two_steps_into_polish(r));
  p.seed = 2;
  r.set_params(p);
  r.run();
  Remesher fresh(mesh, p);
  fresh.run();
  EXPECT_EQ(r.clustering().labels, fresh.clustering().labels);
  EXPECT_EQ(r.panels().panels, fresh.panels().panels);
  EXPECT_EQ(r.panels().vertices, fresh.panels().vertices);
  EXPECT_EQ(r.progress().invalid_panels, fresh.progress().invalid_panels);
}

// An edit asked for in the middle of the polish: set_edits finishes the solve first (its
// retry from a new seeding too), then splits the panel; the design ends valid or reported
// with one panel more. The bound is the cow's below 61 panels (the sweep's cow at 46 panels:
// 0.14-0.17): its legs' tips far from the panels (0.150 here).
TEST(PolishBest, EditMidPolishFinishesTheSolveFirst) {
  RemeshParams p = cow56();
  Remesher r(test::load_clean("cow.off"), p);
  ASSERT_TRUE(two_steps_into_polish(r));
  r.set_edits({PanelEdit{PanelEdit::Op::Split, 0, -1}});
  expect_valid_or_reported(r, 57, 0.17);
}

}  // namespace
}  // namespace ff
