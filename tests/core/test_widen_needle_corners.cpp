// Needle corners at split nodes (widen_needle_corners.cpp): at a node group of four or more
// clusters with a corner below the threshold, the group's other pairings are tried and the one
// whose smallest nearby corner is widest kept, never one that makes a panel invalid. The
// corners are measured here by the quality report (its own 2D outlines), not by the code
// under test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
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
  test::expect_as_built_fresh(layout);
}

// Fixed clusters (locked panels and their neighbours) keep their planes: no group on one of
// their masters is made one vertex. With none fixed, the widening moves planes on this attempt.
TEST(WidenNeedleCorners, FixedClustersKeepTheirPlanes) {
  test::BunnyAttempt b;
  const std::vector<Plane> before = b.attempt->layout().planes().planes;
  const auto moved = [&](const PanelLayout& layout) {
    int count = 0;
    for (size_t m = 0; m < before.size(); ++m) {
      const Plane& p = layout.planes().planes[m];
      count += p.normal == before[m].normal && p.offset == before[m].offset ? 0 : 1;
    }
    return count;
  };
  PanelLayout free = b.attempt->layout();
  free.widen_needle_corners(30.0);
  EXPECT_GT(moved(free), 0) << "some group should be made one vertex";
  PanelLayout fixed = b.attempt->layout();
  fixed.widen_needle_corners(30.0, std::vector<char>(static_cast<size_t>(fixed.num_clusters()), 1));
  EXPECT_EQ(moved(fixed), 0);
  EXPECT_LE(fixed.num_invalid(), b.attempt->layout().num_invalid());
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

// Where no pairing of a group is needle-free, the group becomes one vertex: its planes
// translated through their least-squares point (single-point nodes, paper 2.2). On these runs
// the smallest corner was a needle at such a group.
struct SingleCase {
  const char* file;
  int panels;
  std::uint64_t seed;
  double needle_before;  // the smallest corner without the widening (degrees), for the record
};

class WidenBySinglePoint : public ::testing::TestWithParam<SingleCase> {};

TEST_P(WidenBySinglePoint, TheNeedleBecomesAVertexOfFourOrMorePanels) {
  const SingleCase& c = GetParam();
  const TriMesh mesh = test::load_clean(c.file);
  RemeshParams p;
  p.panels = c.panels;
  p.seed = c.seed;
  Remesher r(mesh, p);
  r.run();
  const QualityReport q = measure_quality(r.mesh(), r.topology(), r.panels());
  EXPECT_EQ(q.invalid_panels, 0);
  EXPECT_TRUE(q.topology_preserved);
  EXPECT_LE(q.max_planarity, 1e-9);  // the translated planes still hold their panels exactly
  EXPECT_GT(q.min_corner_angle_deg, 2.0) << "was " << c.needle_before;
  int beyond_three = 0;
  for (const auto& [valence, count] : q.interior_valence) beyond_three += valence > 3 ? count : 0;
  EXPECT_GT(beyond_three, 0);
}

INSTANTIATE_TEST_SUITE_P(Sweep, WidenBySinglePoint,
                         ::testing::Values(SingleCase{"bunny.off", 154, 6, 0.83},
                                           SingleCase{"3holes.off", 60, 1, 0.014}),
                         [](const auto& info) {
                           std::string name = std::string(info.param.file) + "_" + std::to_string(info.param.panels);
                           std::replace(name.begin(), name.end(), '.', '_');
                           return name;
                         });

}  // namespace
}  // namespace ff
