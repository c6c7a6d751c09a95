// Needle corners at split nodes (widen_needle_corners.cpp): at a node group of four or more
// clusters with a corner below the threshold, the group's other pairings are tried and the one
// whose smallest nearby corner is widest kept, never one that makes a panel invalid. The
// corners are measured here by the quality report (its own 2D outlines), not by the code
// under test.
#include <gtest/gtest.h>

#include <vector>

#include "bunny_attempt.h"
#include "core/quality/report.h"
#include "core/remesher.h"
#include "test_meshes.h"

namespace ff {
namespace {

QualityReport report_of(const test::BunnyAttempt& b, const PanelLayout& layout) {
  return measure_quality(b.mesh, b.topology, layout.to_panel_mesh(b.faces));
}

// Corners below `deg` over all panels (the report's acute corners at that minimum).
int corners_below(const test::BunnyAttempt& b, const PanelLayout& layout, double deg) {
  QualityOptions options;
  options.min_corner_angle_deg = deg;
  return measure_quality(b.mesh, b.topology, layout.to_panel_mesh(b.faces), options).acute_corners;
}

TEST(WidenNeedleCorners, WidensWithoutInvalidatingOrNarrowingAnything) {
  test::BunnyAttempt b;
  PanelLayout layout = b.attempt->layout();
  const QualityReport before = report_of(b, layout);
  ASSERT_LT(before.min_corner_angle_deg, 1.0) << "the attempt should have a needle to work on";
  const int invalid = layout.num_invalid();
  const int needles = corners_below(b, layout, 1.0);

  const int changed = layout.widen_needle_corners(5.0);
  EXPECT_GT(changed, 0);
  EXPECT_LE(layout.num_invalid(), invalid);
  // Each change raises the smallest corner near its group, and no corner elsewhere moves:
  // the smallest corner overall can only rise.
  const QualityReport after = report_of(b, layout);
  EXPECT_GE(after.min_corner_angle_deg, before.min_corner_angle_deg);
  EXPECT_LT(corners_below(b, layout, 1.0), needles);
  // The pairings it kept are the layout's own: a rebuild from the planes gives the same panels.
  PanelLayout fresh = layout;
  std::vector<Plane> moved = layout.planes().planes;
  for (Plane& p : moved) p.offset += 1e-3;
  fresh.set_planes(moved);
  fresh.set_planes(layout.planes().planes);
  test::expect_same_panels(layout, fresh);
}

TEST(WidenNeedleCorners, NothingBelowAZeroThreshold) {
  test::BunnyAttempt b;
  PanelLayout layout = b.attempt->layout();
  EXPECT_EQ(layout.widen_needle_corners(0.0), 0);
  test::expect_same_panels(b.attempt->layout(), layout);
}

// The page's default example (the hyperboloid at 300 panels, seed 1) ended with a quad whose
// corner at a split node was 0.45 degrees; another pairing of that node gives 2.2.
TEST(WidenNeedleCorners, TheDefaultExampleHasNoNeedle) {
  const TriMesh mesh = test::load_clean("hyperboloid_s4.off");
  RemeshParams p;
  p.panels = 300;
  p.seed = 1;
  Remesher r(mesh, p);
  r.run();
  const QualityReport q = measure_quality(r.mesh(), r.topology(), r.panels());
  EXPECT_EQ(q.invalid_panels, 0);
  EXPECT_GT(q.min_corner_angle_deg, 1.0);
}

}  // namespace
}  // namespace ff
