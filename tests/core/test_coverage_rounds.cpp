// Coverage (issue 3): a panel covering under a tenth of its faces' area on its plane has
// collapsed (PanelIssues::collapsed): a sliver over its neighbours' faces that the paper's
// checks pass. A valid attempt with one gets coverage rounds (its collapsed clusters move
// elsewhere), and the final plane fit and needle widening make none. Judged by the quality
// report's own coverage (measure_quality), not by the panel phase's flags alone.
#include <gtest/gtest.h>

#include <string>

#include "core/panels/panel_check.h"
#include "panel_checks.h"

namespace ff {
namespace {

QualityReport quality_of(const Remesher& r) { return measure_quality(r.mesh(), r.topology(), r.panels()); }

int flagged_collapsed(const PanelMesh& pm) {
  int count = 0;
  for (const PanelIssues& issues : pm.issues) count += issues.collapsed ? 1 : 0;
  return count;
}

// epcot.off at 26 panels, seed 1: the rounds' first valid attempt has a sliver panel covering
// 0.03% of its faces; a coverage round moves its cluster elsewhere. (This was seed 2 at 34
// panels until the relaxation stopped once settled, plane_relax.h: the draws are chaotic.)
TEST(CoverageRounds, ASliverPanelsClusterMovesElsewhere) {
  const auto r = test::remeshed("epcot.off", 26, 1);
  EXPECT_TRUE(test::valid_panels(*r, 26, 0.08));
  const QualityReport q = quality_of(*r);
  EXPECT_EQ(q.collapsed_panels, 0);
  EXPECT_GE(q.min_panel_coverage, kMinCoveredShare);
  EXPECT_GT(q.min_corner_angle_deg, 30.0);
}

// bunny.off at 200 panels, seed 1: the rounds end without one, but the final plane fit used
// to make one (6.8% covered); it now refuses a plane that collapses a panel.
TEST(CoverageRounds, TheFinalFitMakesNoSliver) {
  const auto r = test::remeshed("bunny.off", 200, 1);
  EXPECT_TRUE(test::valid_panels(*r, 200, 0.08));
  EXPECT_EQ(quality_of(*r).collapsed_panels, 0);
}

// fandisk.off at 300 panels, seed 7: the rounds' first valid attempt (round 16) has a panel
// their planes collapse, and the final fit widens it (the report's least coverage is 0.154).
// Judged as the end judges it, it needs no coverage round: the run ends there, not after the
// 8 coverage rounds it used to spend finding nothing better (24 rounds, the same panels).
TEST(CoverageRounds, APanelTheFitWidensNeedsNoCoverageRound) {
  const auto r = test::remeshed("fandisk.off", 300, 7);
  EXPECT_TRUE(test::valid_panels(*r, 300, 0.02));
  EXPECT_LE(r->panel_rounds_done(), 16);
  const QualityReport q = quality_of(*r);
  EXPECT_EQ(q.collapsed_panels, 0);
  EXPECT_EQ(flagged_collapsed(r->panels()), 0);
}

// What the coverage rounds do not reach stays valid and is reported: cow.off at 61 panels,
// seed 11 keeps one (1.2% covered), left by the mends of its long run (80 rounds). The panel
// phase's flags and the report agree, and a collapsed panel passes the paper's checks (it is
// not invalid). The bound is the cow's at 61 panels (test_panel_rounds.cpp).
TEST(CoverageRounds, WhatRemainsIsValidAndReported) {
  const auto r = test::remeshed("cow.off", 61, 11);
  EXPECT_TRUE(test::valid_panels(*r, 61, 0.15));
  const QualityReport q = quality_of(*r);
  EXPECT_EQ(q.collapsed_panels, 1);
  EXPECT_EQ(flagged_collapsed(r->panels()), q.collapsed_panels);
  EXPECT_LT(q.min_panel_coverage, kMinCoveredShare);
  ASSERT_GE(q.min_panel_coverage_panel, 0);
  EXPECT_TRUE(r->panels().issues[static_cast<size_t>(q.min_panel_coverage_panel)].collapsed);
}

// The coverage rounds keep to k2: epcot.off at 25 panels, seed 3 ends its rounds at the
// twelfth without a collapsed panel, but its first valid attempt has one; given 4 rounds, the
// fourth (a coverage round that found nothing better) is the budget's last and the run ends
// with the valid fallback, its collapsed panel reported.
TEST(CoverageRounds, KeepToThePanelRoundBudget) {
  auto r = test::remesher("epcot.off", 25, 3);
  RemeshParams p = r->params();
  p.panel_rounds = 4;
  p.retries = 0;
  Remesher limited(r->mesh(), p);
  limited.run();
  EXPECT_TRUE(test::valid_panels(limited, 25, 0.08));
  EXPECT_LE(limited.panel_rounds_done(), 4);
  EXPECT_EQ(quality_of(limited).collapsed_panels, 1);
}

// Runs of the sweep (bench/sweep_validity.sh's counts) that ended with a collapsed panel, one
// per mesh, and end valid without one now (each checked against the build before).
struct Case {
  std::string file;
  int panels;
  int seed;
};
class CoverageSweep : public ::testing::TestWithParam<Case> {};
TEST_P(CoverageSweep, EndsValidWithoutACollapsedPanel) {
  const Case& c = GetParam();
  const auto r = test::remeshed(c.file, c.panels, static_cast<std::uint64_t>(c.seed));
  EXPECT_TRUE(test::valid_panels(*r, c.panels, 0.08));
  const QualityReport q = quality_of(*r);
  EXPECT_EQ(q.collapsed_panels, 0);
  EXPECT_EQ(flagged_collapsed(r->panels()), 0);
}
INSTANTIATE_TEST_SUITE_P(Sweep, CoverageSweep,
                         ::testing::Values(Case{"3holes.off", 130, 1}, Case{"fandisk.off", 206, 2},
                                           Case{"epcot.off", 27, 6}, Case{"bunny.off", 99, 6},
                                           Case{"camelhead.off", 252, 4}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string name = info.param.file.substr(0, info.param.file.find('.'));
                           return name + "_" + std::to_string(info.param.panels) + "_" +
                                  std::to_string(info.param.seed);
                         });

}  // namespace
}  // namespace ff
