// Glass mode on the shared meshes (issue 5): with --glass and a 10-degree minimum, every
// panel is convex, every corner at least 10 degrees, planar to 1e-9, and the topology kept.
// The counts are ones checked to pass: the acute-corner condition makes the panel phase's
// job harder, and some counts still end with a thin corner or a flipped panel (the glass
// sweep in bench/README.md); hyperboloid_s4 (long thin triangles, strongly curved) does not
// reach the minimum at the counts tried. The default (glass off, no minimum) is untouched:
// test_panel_phase.cpp pins it.
#include <gtest/gtest.h>

#include "cluster_checks.h"
#include "core/panels/panel_check.h"
#include "core/panels/polygon2d.h"
#include "core/quality/report.h"
#include "core/remesher.h"
#include "panel_checks.h"

namespace ff {
namespace {

struct GlassCase {
  std::string file;
  int panels;
};

void PrintTo(const GlassCase& c, std::ostream* os) { *os << c.file << " at " << c.panels; }

class GlassPanels : public ::testing::TestWithParam<GlassCase> {};

TEST_P(GlassPanels, ConvexAboveTheMinimumPlanarTopologyKept) {
  const GlassCase& c = GetParam();
  RemeshParams p;
  p.panels = c.panels;
  p.glass = true;
  p.min_corner_angle_deg = 10.0;
  Remesher r(test::load_clean(c.file), p);
  r.run();
  const PanelMesh& pm = r.panels();
  QualityOptions options;
  options.glass = true;
  options.min_corner_angle_deg = 10.0;
  const QualityReport q = measure_quality(r.mesh(), r.topology(), pm, options);
  EXPECT_EQ(pm.num_invalid(), 0);
  EXPECT_EQ(q.invalid_panels, 0);
  EXPECT_EQ(q.concave_panels, 0);
  EXPECT_EQ(q.acute_corners, 0);
  EXPECT_GE(q.min_corner_angle_deg, 10.0);
  EXPECT_LE(q.max_planarity, 1e-9);
  EXPECT_TRUE(q.topology_preserved) << "euler " << q.euler_in << " -> " << q.euler_out;
  // Pieces come from panels: at least as many as asked for, each naming its panel.
  EXPECT_GE(pm.num_panels(), c.panels);
  ASSERT_EQ(pm.panel_source.size(), pm.panels.size());
  for (size_t i = 1; i < pm.panel_source.size(); ++i) EXPECT_LE(pm.panel_source[i - 1], pm.panel_source[i]);
  EXPECT_EQ(pm.panel_source.back(), c.panels - 1);
  // The same check again, by hand: every corner of every panel, in the panel's plane.
  for (int i = 0; i < pm.num_panels(); ++i) {
    const PlaneFrame frame =
        make_plane_frame(pm.plane_offsets[static_cast<size_t>(i)] * pm.plane_normals[static_cast<size_t>(i)],
                         pm.plane_normals[static_cast<size_t>(i)]);
    std::vector<Vec2> outline;
    for (int v : pm.panels[static_cast<size_t>(i)]) outline.push_back(frame.to_2d(pm.vertices[static_cast<size_t>(v)]));
    EXPECT_TRUE(reflex_corners(outline).empty()) << "panel " << i;
    EXPECT_TRUE(acute_corners(outline, 10.0).empty()) << "panel " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(Shared, GlassPanels,
                         ::testing::Values(GlassCase{"inspired_mesh.obj", 35}, GlassCase{"inspired_mesh.obj", 60},
                                           GlassCase{"YasIsland.off", 40}, GlassCase{"epcot.off", 20},
                                           GlassCase{"epcot.off", 38}, GlassCase{"fandisk.off", 80},
                                           GlassCase{"YasIsland.off", 45}, GlassCase{"bumpy.off", 30},
                                           GlassCase{"bunny.off", 77}),
                         [](const auto& info) {
                           return test::test_name(info.param.file) + "_" + std::to_string(info.param.panels);
                         });

// Glass off with a minimum angle only: no pieces, and the corners left below it are reported
// as acute_corner problems, never silently dropped.
TEST(GlassMode, MinimumAngleAloneKeepsPanelsWhole) {
  RemeshParams p;
  p.panels = 20;
  p.min_corner_angle_deg = 10.0;
  Remesher r(test::load_clean("epcot.off"), p);
  r.run();
  EXPECT_EQ(r.panels().num_panels(), 20);
  EXPECT_TRUE(r.panels().panel_source.empty());
  QualityOptions options;
  options.min_corner_angle_deg = 10.0;
  const QualityReport q = measure_quality(r.mesh(), r.topology(), r.panels(), options);
  int flagged = 0;
  for (const PanelIssues& i : r.panels().issues) flagged += i.acute_corner ? 1 : 0;
  EXPECT_EQ(q.acute_corners > 0, flagged > 0);
  EXPECT_GE(q.min_corner_angle_deg, 10.0);
}

// The quality check judges a glass piece's orientation as the panel it was cut from, on all
// of that panel's faces: the faces under one piece alone can face away from it. cow.off at
// 78 panels, seed 4, glass without a minimum: a piece has faces whose normals sum against its
// own (checked below, so the case still shows it); the report called such a piece misoriented
// although the panel phase had judged the whole panel, an invalid "quality_check" panel (4 of
// 128 glass runs at seeds 1-2 of bench/sweep_validity.sh's cases, all cow.off). (This was
// 122 panels, seed 1 until the relaxation stopped once settled, plane_relax.h.)
TEST(GlassMode, PiecesAreJudgedAsThePanelTheyWereCutFrom) {
  RemeshParams p;
  p.panels = 78;
  p.seed = 4;
  p.glass = true;
  Remesher r(test::load_clean("cow.off"), p);
  r.run();
  const PanelMesh& pm = r.panels();
  ASSERT_EQ(pm.panel_source.size(), pm.panels.size());
  std::vector<Vec3> under(pm.panels.size(), Vec3::Zero());  // per piece: its own faces' normals
  for (int f = 0; f < r.mesh().num_faces(); ++f) {
    const int piece = pm.face_panel[static_cast<size_t>(f)];
    if (piece >= 0) under[static_cast<size_t>(piece)] += face_normal(r.mesh(), f) * face_area(r.mesh(), f);
  }
  int facing_away = 0;
  for (size_t i = 0; i < pm.panels.size(); ++i) {
    std::vector<Vec3> outline;
    for (int v : pm.panels[i]) outline.push_back(pm.vertices[static_cast<size_t>(v)]);
    facing_away += under[i].squaredNorm() > 0.0 && newell_normal(outline).dot(under[i]) <= 0.0;
  }
  EXPECT_GT(facing_away, 0) << "no piece whose own faces face away: the case no longer tests this";
  QualityOptions options;
  options.glass = true;
  const QualityReport q = measure_quality(r.mesh(), r.topology(), pm, options);
  EXPECT_EQ(q.misoriented_panels, 0);
  EXPECT_EQ(q.invalid_panels, 0);
  EXPECT_EQ(pm.num_invalid(), 0);
}

TEST(GlassMode, MinimumAngleOutOfRangeIsRefused) {
  RemeshParams p;
  p.panels = 20;
  p.min_corner_angle_deg = 61.0;
  EXPECT_ANY_THROW(Remesher(test::load_clean("epcot.off"), p));
}

}  // namespace
}  // namespace ff
