// The layout's shortcuts that keep panels instead of building them again (panel_fixes.cpp):
// try_planes puts a refused plane's panels back from saved copies, stops a trial once it is
// refused, and skips planes whose surroundings did not change since they were refused;
// switch_pairings puts the panels of a kept pairing back and keeps the last trial's panels
// when that is the pairing chosen. Each must leave every panel exactly (bit for bit) as a
// fresh build from the final planes and pairings gives.
#include <gtest/gtest.h>

#include <vector>

#include "bunny_attempt.h"
#include "core/panels/plane_fit.h"
#include "remesh_checks.h"

namespace ff {
namespace {

TEST(LayoutReuse, TryPlanesLeavesPanelsAsAFreshBuild) {
  test::BunnyAttempt b;
  const PanelLayout& start = b.attempt->layout();
  // The final fit's candidates (as Remesher::optimize_planes), and the same halfway.
  const std::vector<Plane> fitted =
      surface_fit_planes(b.faces, b.clustering.labels, start.planes(), start.node_constraints());
  PanelLayout layout = start;
  const int invalid = layout.num_invalid();
  const int kept = layout.try_planes(fitted, 2);
  EXPECT_GT(kept, 0);
  // Some refused (else nothing was undone): not every plane is the fitted one.
  int refused = 0;
  for (size_t m = 0; m < fitted.size(); ++m) {
    const Plane& p = layout.planes().planes[m];
    refused += p.normal == fitted[m].normal && p.offset == fitted[m].offset ? 0 : 1;
  }
  EXPECT_GT(refused, 0);
  EXPECT_LE(layout.num_invalid(), invalid);  // a plane is kept only where it adds none
  test::expect_as_built_fresh(layout);
  layout.try_planes(planes_toward(layout.planes().planes, fitted, 0.5));
  test::expect_as_built_fresh(layout);
}

TEST(LayoutReuse, TryPlanesTwoPassesAsTwoCalls) {
  test::BunnyAttempt b;
  const PanelLayout& start = b.attempt->layout();
  const std::vector<Plane> fitted =
      surface_fit_planes(b.faces, b.clustering.labels, start.planes(), start.node_constraints());
  PanelLayout twice = start, calls = start;
  twice.try_planes(fitted, 2);
  if (calls.try_planes(fitted) > 0) calls.try_planes(fitted);
  for (size_t m = 0; m < fitted.size(); ++m) {
    EXPECT_EQ(twice.planes().planes[m].normal, calls.planes().planes[m].normal) << "master " << m;
    EXPECT_EQ(twice.planes().planes[m].offset, calls.planes().planes[m].offset) << "master " << m;
  }
}

TEST(LayoutReuse, SwitchPairingsLeavesPanelsAsAFreshBuild) {
  test::BunnyAttempt b;
  PanelLayout layout = b.attempt->layout();
  ASSERT_GT(layout.num_invalid(), 0);
  const int invalid = layout.num_invalid();
  layout.switch_pairings();
  EXPECT_LE(layout.num_invalid(), invalid);
  test::expect_as_built_fresh(layout);
}

}  // namespace
}  // namespace ff
