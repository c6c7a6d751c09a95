// Cut sheets packing: random convex and concave outlines (no overlaps with the spacing,
// inside the margins, deterministic), nesting into concave notches, and the errors.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/fabricate/cut_sheets.h"
#include "core/util/error.h"
#include "cut_sheet_checks.h"

namespace ff {
namespace {

using namespace cut_sheet_test;

TEST(CutSheets, RandomOutlinesPackWithoutOverlapInsideTheMargins) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const std::vector<PanelOutline> outlines = random_outlines(80, seed);
    const SheetOptions options;
    const SheetLayout layout = pack_outlines(outlines, options);
    expect_valid_layout(outlines, layout, options);
    // Every sheet but the last holds parts; a skyline of bounding boxes keeps a fair share.
    RecordProperty("material_use_" + std::to_string(seed), std::to_string(layout.material_use));
    std::printf("seed %d: %d sheets, material use %.3f\n", static_cast<int>(seed), layout.sheets, layout.material_use);
    EXPECT_GT(layout.material_use, 0.2) << "seed " << seed << ": " << layout.sheets << " sheets";
  }
}

TEST(CutSheets, ZeroSpacingAndMarginStillNeverOverlap) {
  const std::vector<PanelOutline> outlines = random_outlines(60, 4);
  SheetOptions options;
  options.margin = 0;
  options.spacing = 0;
  const SheetLayout layout = pack_outlines(outlines, options);
  expect_valid_layout(outlines, layout, options);
}

TEST(CutSheets, PackingIsDeterministic) {
  const std::vector<PanelOutline> outlines = random_outlines(50, 7);
  const SheetLayout a = pack_outlines(outlines, SheetOptions{});
  const SheetLayout b = pack_outlines(outlines, SheetOptions{});
  ASSERT_EQ(a.sheets, b.sheets);
  for (std::size_t i = 0; i < a.placed.size(); ++i) {
    EXPECT_EQ(a.placed[i].sheet, b.placed[i].sheet);
    EXPECT_EQ(a.placed[i].angle_rad, b.placed[i].angle_rad);
    EXPECT_EQ(a.placed[i].offset, b.placed[i].offset);
  }
  EXPECT_EQ(cut_sheets_svg(outlines, a, SheetOptions{}), cut_sheets_svg(outlines, b, SheetOptions{}));
  EXPECT_EQ(cut_sheets_dxf(outlines, a, SheetOptions{}), cut_sheets_dxf(outlines, b, SheetOptions{}));
}

TEST(CutSheets, ExactFitAndZeroSpacing) {
  // Eight 100 x 100 squares fill a 200 x 400 sheet without margin or spacing.
  std::vector<PanelOutline> squares(8);
  for (int i = 0; i < 8; ++i) {
    squares[i].label = "S" + std::to_string(i + 1);
    squares[i].outer = {Vec2(0, 0), Vec2(100, 0), Vec2(100, 100), Vec2(0, 100)};
  }
  SheetOptions options;
  options.width = 200;
  options.height = 400;
  options.margin = 0;
  options.spacing = 0;
  const SheetLayout layout = pack_outlines(squares, options);
  EXPECT_EQ(layout.sheets, 1);
  EXPECT_NEAR(layout.material_use, 1.0, 1e-12);
  expect_valid_layout(squares, layout, options);
}

TEST(CutSheets, SmallPartNestsInAConcaveNotch) {
  // The L's bounding box fills the sheet; the square only fits inside the L's notch.
  std::vector<PanelOutline> parts(2);
  parts[0].label = "L";
  parts[0].outer = {Vec2(0, 0), Vec2(290, 0), Vec2(290, 100), Vec2(100, 100), Vec2(100, 290), Vec2(0, 290)};
  parts[1].label = "S";
  parts[1].outer = {Vec2(0, 0), Vec2(100, 0), Vec2(100, 100), Vec2(0, 100)};
  SheetOptions options;
  options.width = 300;
  options.height = 300;
  options.margin = 0;
  const SheetLayout layout = pack_outlines(parts, options);
  EXPECT_EQ(layout.sheets, 1);
  expect_valid_layout(parts, layout, options);
}

TEST(CutSheets, LongPartTurnsToFit) {
  // Its minimum-area rectangle is tilted; only lying along the sheet does it fit.
  PanelOutline o;
  o.label = "LONG";
  const Eigen::Rotation2Dd r(0.3);
  for (const Vec2& q : {Vec2(0, 0), Vec2(1000, 0), Vec2(1000, 100), Vec2(0, 100)}) o.outer.push_back(r * q);
  SheetOptions options;
  options.width = 1100;
  options.height = 300;
  const SheetLayout layout = pack_outlines({o}, options);
  expect_valid_layout({o}, layout, options);
}

TEST(CutSheets, ClearErrors) {
  std::vector<PanelOutline> outlines = random_outlines(3, 1);
  PanelOutline big;
  big.label = "P99";
  big.outer = {Vec2(0, 0), Vec2(3000, 0), Vec2(3000, 1500), Vec2(0, 1500)};
  outlines.push_back(big);
  try {
    pack_outlines(outlines, SheetOptions{});
    FAIL() << "an oversized part must be refused";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("P99"), std::string::npos) << what;
    EXPECT_NE(what.find("3000 x 1500"), std::string::npos) << what;
    EXPECT_NE(what.find("2440 x 1220"), std::string::npos) << what;
  }
  SheetOptions bad;
  bad.width = 0;
  EXPECT_THROW(pack_outlines({}, bad), InputError);
  bad = SheetOptions{};
  bad.height = std::nan("");
  EXPECT_THROW(pack_outlines({}, bad), InputError);
  bad = SheetOptions{};
  bad.margin = 700;
  EXPECT_THROW(pack_outlines({}, bad), InputError);
  bad = SheetOptions{};
  bad.spacing = -1;
  EXPECT_THROW(pack_outlines({}, bad), InputError);
  std::vector<PanelOutline> nan_point = random_outlines(1, 1);
  nan_point[0].outer[1].x() = std::nan("");
  EXPECT_THROW(pack_outlines(nan_point, SheetOptions{}), InputError);
}

TEST(CutSheets, NoOutlinesNoSheets) {
  const SheetLayout layout = pack_outlines({}, SheetOptions{});
  EXPECT_EQ(layout.sheets, 0);
  EXPECT_EQ(layout.material_use, 0.0);
  EXPECT_NE(cut_sheets_svg({}, layout, SheetOptions{}).find("</svg>"), std::string::npos);
  EXPECT_NE(cut_sheets_dxf({}, layout, SheetOptions{}).find("EOF"), std::string::npos);
}

TEST(CutSheets, OverlapCheckerSeesOverlapsAndGaps) {
  const Poly a{Vec2(0, 0), Vec2(10, 0), Vec2(10, 10), Vec2(0, 10)};
  Poly b = a, inside{Vec2(2, 2), Vec2(3, 2), Vec2(3, 3)};
  for (Vec2& q : b) q.x() += 13;
  EXPECT_NEAR(polygon_distance(a, b), 3.0, 1e-12);
  for (Vec2& q : b) q.x() -= 5;
  EXPECT_EQ(polygon_distance(a, b), 0.0);
  EXPECT_EQ(polygon_distance(a, inside), 0.0);
  EXPECT_TRUE(overlaps(a, b));
  EXPECT_TRUE(overlaps(a, inside));
  for (Vec2& q : b) q.x() += 5;  // touching along x = 10
  EXPECT_FALSE(overlaps(a, b));
}

}  // namespace
}  // namespace ff
