// The end's mend tried on a round with few invalid panels (PanelAttempt::mend_to_valid,
// Remesher::panel_round): kept only when every panel ends valid, else the layout goes back
// exactly as it was, so the rounds go on as if it had not been tried.
#include <gtest/gtest.h>

#include <vector>

#include "bunny_attempt.h"
#include "core/panels/panel_attempt.h"
#include "core/remesher.h"
#include "panel_checks.h"
#include "remesh_checks.h"

namespace ff {
namespace {

// A first attempt with many invalid panels (no fixes after its relaxation): the mend leaves
// some invalid, so it is undone, every panel bit for bit.
TEST(MendToValid, AMendThatFailsLeavesEveryPanelAsItWas) {
  test::BunnyAttempt b;
  const PanelLayout before = b.attempt->layout();
  ASSERT_GT(before.num_invalid(), 10);
  EXPECT_FALSE(b.attempt->mend_to_valid(b.faces, {}, PanelAttemptOptions{}));
  EXPECT_EQ(b.attempt->num_invalid(), before.num_invalid());
  test::expect_same_panels(before, b.attempt->layout());
  for (size_t m = 0; m < before.planes().planes.size(); ++m) {
    EXPECT_EQ(before.planes().planes[m].normal, b.attempt->layout().planes().planes[m].normal) << "master " << m;
    EXPECT_EQ(before.planes().planes[m].offset, b.attempt->layout().planes().planes[m].offset) << "master " << m;
  }
}

// The bunny at 200 panels, seed 4: 54, 8 and 2 invalid panels in its first three rounds, and
// then 1, 0 (valid at round 5) without the mend; the mend makes round 3 valid.
// The result is judged as at the end (orientation included) and passes the quality check.
TEST(MendEarly, BunnyEndsValidAtItsThirdRound) {
  RemeshParams p;
  p.panels = 200;
  p.seed = 4;
  Remesher r(test::load_clean("bunny.off"), p);
  r.run();
  EXPECT_EQ(r.panel_rounds_done(), 3);
  // Hausdorff 0.0190 of the bounding box (the same when valid at round 5).
  EXPECT_TRUE(test::valid_panels(r, 200, 0.02));
}

}  // namespace
}  // namespace ff
