// The report's list of invalid panels (core/quality/report_json.h) and the phrase the CLI
// prints on stderr when it exits 3: every panel phase flag, the quality check's own finds and
// the unbuilt clusters are named, each counted once per panel.
#include <gtest/gtest.h>

#include "core/quality/report_json.h"

namespace ff {
namespace {

// Four triangles, each its own panel, issues set per test.
PanelMesh four_panels() {
  PanelMesh pm;
  pm.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)};
  pm.panels = {{0, 1, 2}, {1, 3, 2}, {0, 1, 3}, {0, 3, 2}};
  pm.panel_cluster = {10, 11, 12, 13};
  pm.issues.resize(4);
  return pm;
}

TEST(ReportJson, NothingInvalidGivesNoPhrase) {
  const PanelMesh pm = four_panels();
  const QualityReport q;
  EXPECT_TRUE(list_invalid_panels(pm, q).empty());
  EXPECT_EQ(invalid_panels_phrase(pm, q), "");
}

TEST(ReportJson, CountsEachProblemOverPanelsInAFixedOrder) {
  PanelMesh pm = four_panels();
  pm.issues[0].spike_vertices = 2;
  pm.issues[0].not_star = true;
  pm.issues[2].not_star = true;
  pm.unbuilt_clusters = {7};
  QualityReport q;
  q.invalid_panel_ids = {3};  // the independent check only: a panel phase bug, named so
  const std::vector<InvalidPanel> list = list_invalid_panels(pm, q);
  ASSERT_EQ(list.size(), 4u);
  EXPECT_EQ(list[0].panel, 0);
  EXPECT_EQ(list[0].cluster, 10);
  EXPECT_EQ(list[0].problems, (std::vector<std::string>{"not_star", "spike"}));
  EXPECT_EQ(list[0].spike_vertices, 2);
  EXPECT_EQ(list[0].vertices, 3);
  EXPECT_EQ(list[1].panel, 2);
  EXPECT_EQ(list[2].panel, 3);
  EXPECT_EQ(list[2].problems, (std::vector<std::string>{"quality_check"}));
  EXPECT_EQ(list[3].panel, -1);
  EXPECT_EQ(list[3].cluster, 7);
  EXPECT_EQ(list[3].problems, (std::vector<std::string>{"unbuilt"}));
  EXPECT_EQ(invalid_panels_phrase(pm, q), "4 panels invalid (not_star 2, spike 1, quality_check 1, unbuilt 1)");
  // Off its plane with nothing else wrong (QualityReport::solver_error_panel_ids): named so.
  q.invalid_panel_ids = {1, 3};
  q.solver_error_panel_ids = {1};
  EXPECT_EQ(list_invalid_panels(pm, q)[1].problems, (std::vector<std::string>{"off_plane"}));
  EXPECT_EQ(invalid_panels_phrase(pm, q),
            "5 panels invalid (not_star 2, spike 1, off_plane 1, quality_check 1, unbuilt 1)");

  PanelMesh one = four_panels();
  one.issues[1].flipped = true;
  EXPECT_EQ(invalid_panels_phrase(one, QualityReport{}), "1 panel invalid (flipped 1)");
}

// Every name panel_problems can give reaches the phrase (none is dropped for want of a place
// in its order).
TEST(ReportJson, EveryProblemNameIsInThePhrase) {
  PanelMesh pm = four_panels();
  PanelIssues& all = pm.issues[1];
  all.not_simple = all.flipped = all.not_star = all.too_few_vertices = all.not_disk = all.acute_corner = true;
  all.spike_vertices = 1;
  const std::string phrase = invalid_panels_phrase(pm, QualityReport{});
  const std::vector<std::string> names = panel_problems(all);
  EXPECT_EQ(names.size(), 7u);
  for (const std::string& name : names) EXPECT_NE(phrase.find(name + " 1"), std::string::npos) << name;
  EXPECT_EQ(phrase.rfind("1 panel invalid (", 0), 0u) << phrase;
}

// Planarity above 1e-9 is explained where the coordinates' rounding allows no better
// (planarity_floor), or named at its panel; under it there is nothing to say.
TEST(ReportJson, PlanarityPhrase) {
  QualityReport q;
  q.max_planarity = 4e-16;
  q.planarity_floor = 2e-16;
  EXPECT_EQ(planarity_phrase(q), "");
  q.max_planarity = 1.52e-6;  // a model 1e9 from the origin
  q.planarity_floor = 9.07e-6;
  EXPECT_EQ(planarity_phrase(q),
            "the panels as written are flat to 1.52e-06 of their size, not 1e-09: the coordinates are so far from "
            "the origin that their last digit is already 9.07e-06 of a panel's size; moved near the origin, the "
            "model gives flat panels");
  q.max_planarity = 1.19e-9;  // a triangle 1e8 away: the panels were solved about the middle
  q.planarity_floor = 1.8e-16;
  q.planarity_floor_solve = 2.52e-9;
  EXPECT_EQ(planarity_phrase(q),
            "the panels as written are flat to 1.19e-09 of their size, not 1e-09: a part of the mesh lies so far from "
            "the rest that, about the middle of the whole, the coordinates' last digit is already 2.52e-09 of a "
            "panel's size; without the far-off part, the model gives flat panels");
  q.planarity_floor_solve = 0.0;
  q.max_planarity = 9.27e-8;  // a spike vertex whose planes do not meet
  q.planarity_floor = 8e-16;
  q.max_planarity_panel = 7;
  q.invalid_panel_ids = {2, 7};
  EXPECT_EQ(planarity_phrase(q),
            "the panels as written are flat to 9.27e-08 of their size, not 1e-09; the least flat is panel 7, an "
            "invalid one (a vertex where its planes do not meet)");
  q.invalid_panel_ids = {2};
  EXPECT_EQ(planarity_phrase(q), "the panels as written are flat to 9.27e-08 of their size, not 1e-09; the least "
                                 "flat is panel 7");
  // Off its plane with every other check passed: no spike explains it, the solver erred.
  q.invalid_panel_ids = {2, 7};
  q.solver_error_panel_ids = {7};
  EXPECT_EQ(planarity_phrase(q),
            "the panels as written are flat to 9.27e-08 of their size, not 1e-09; the least flat is panel 7, an "
            "invalid one, off its plane though it passes every other check (an error of the solver: please report "
            "it)");
}

TEST(ReportJson, TopologyChangedIsItsOwnStatusAndNotExitZero) {
  const PanelMesh pm = four_panels();
  QualityReport q;
  q.topology_preserved = true;
  EXPECT_TRUE(result_valid(pm, q));
  EXPECT_STREQ(panels_status(pm, q), "valid");
  EXPECT_EQ(topology_phrase(q), "");
  q.topology_preserved = false;
  q.oriented_manifold = true;
  q.euler_in = 1, q.euler_out = 2, q.boundary_loops_in = 1, q.boundary_loops_out = 0;
  EXPECT_TRUE(all_panels_valid(pm, q));
  EXPECT_FALSE(result_valid(pm, q));
  EXPECT_STREQ(panels_status(pm, q), "topology changed");
  EXPECT_EQ(topology_phrase(q),
            "the panels do not keep the surface's topology (Euler characteristic 1 -> 2, boundary loops 1 -> 0)");
  q.oriented_manifold = false;
  EXPECT_EQ(topology_phrase(q), "the panels do not keep the surface's topology (they are not an oriented 2-manifold)");
  q.invalid_panel_ids = {1};
  q.invalid_panels = 1;
  EXPECT_STREQ(panels_status(pm, q), "some panels invalid");  // invalid panels come first
}

}  // namespace
}  // namespace ff
