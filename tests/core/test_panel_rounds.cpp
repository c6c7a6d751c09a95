// The panel-round budget (issue 3, cow.off): at most k2 rounds, at most a few splits each, and
// an early end when the fewest invalid panels stops going down. The cow at the sweep's
// counts (bench/sweep_validity.sh) ended invalid at all five with 30 rounds; these four end
// valid with the defaults now.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cluster_checks.h"
#include "core/shapes/shapes.h"
#include "panel_checks.h"

namespace ff {
namespace {

// A torus cannot be 5 planar panels (a polyhedral torus needs 7 faces): every round is
// invalid, however long it runs.
TriMesh torus() {
  constexpr double kPi = 3.14159265358979323846;
  return make_grid_surface(
      40, 16,
      [&](double u, double v) {
        const double a = 2.0 * kPi * u, b = 2.0 * kPi * v;
        return Vec3((3.0 + std::cos(b)) * std::cos(a), (3.0 + std::cos(b)) * std::sin(a), std::sin(b));
      },
      true, true);
}

class CowPanelRounds : public ::testing::TestWithParam<test::ValidRemesh> {};
TEST_P(CowPanelRounds, ValidWithTheDefaults) { EXPECT_TRUE(test::remeshes_valid(GetParam())); }

// 2-5 s of Release each (30 to 100 rounds). The Hausdorff bound is the shared meshes' 0.08
// where the result has it; at 61 and 100 the valid result leaves a thin part (a tip) farther
// from its panels (0.14 and 0.11 of the diagonal, measured input to panels).
const auto cow = [] { return test::load_clean("cow.off"); };
INSTANTIATE_TEST_SUITE_P(SweepCounts, CowPanelRounds,
                         ::testing::Values(test::ValidRemesh{"At61", cow, 61, 0, 0.15},
                                           test::ValidRemesh{"At78", cow, 78},
                                           test::ValidRemesh{"At100", cow, 100, 0, 0.12},
                                           test::ValidRemesh{"At122", cow, 122}),
                         test::valid_remesh_name);

// A hopeless input stops once 50 rounds bring no fewer invalid panels, long before a large k2.
TEST(PanelRoundBudget, HopelessInputEndsBeforeALargeBudget) {
  RemeshParams p;
  p.panels = 5;
  p.panel_rounds = 1000;
  Remesher r(torus(), p);
  r.run();
  EXPECT_TRUE(r.done());
  EXPECT_GT(r.panels().num_invalid(), 0);
  EXPECT_GE(r.panel_rounds_done(), 51);  // at least the patience after the first round
  EXPECT_LT(r.panel_rounds_done(), 300);
}

// k2 stays the hard bound the CLI documents (--iterations K1,K2: at most K2 panel rounds).
TEST(PanelRoundBudget, NeverMoreRoundsThanAsked) {
  RemeshParams p;
  p.panels = 5;
  p.panel_rounds = 7;
  Remesher r(torus(), p);
  r.run();
  EXPECT_EQ(r.panel_rounds_done(), 7);
  EXPECT_GT(r.panels().num_invalid(), 0);
}

}  // namespace
}  // namespace ff
