// Glass mode's convex split (glass_split.h): L-shape, comb and star outlines come apart into
// convex pieces on their own vertices, whose areas add up to the outline's, avoiding corners
// below the minimum angle when a cut allows; a panel mesh split in place keeps its vertices,
// planes and topology, and its pieces are labelled after their panel.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <set>

#include "core/fabricate/parts_list.h"
#include "core/panels/glass_split.h"
#include "core/panels/panel_check.h"
#include "core/quality/report.h"

namespace ff {
namespace {

std::vector<Vec2> outline(const std::vector<std::array<double, 2>>& xy) {
  std::vector<Vec2> out;
  for (const auto& [x, y] : xy) out.emplace_back(x, y);
  return out;
}

const std::vector<Vec2> kLShape = outline({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
const std::vector<Vec2> kComb =
    outline({{0, 0}, {5, 0}, {5, 3}, {4, 3}, {4, 1}, {3, 1}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}});

// A five-pointed star: five reflex corners.
std::vector<Vec2> star() {
  std::vector<Vec2> out;
  for (int i = 0; i < 10; ++i) {
    const double a = M_PI / 2 + i * M_PI / 5, r = i % 2 == 0 ? 2.0 : 1.0;
    out.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return out;
}

struct Split {
  std::vector<std::vector<Vec2>> pieces;
  double area = 0.0, smallest_angle = 360.0;
  bool convex = true;
};

Split split(const std::vector<Vec2>& polygon, double min_deg) {
  Split s;
  std::set<int> used;
  for (const std::vector<int>& piece : convex_pieces(polygon, min_deg)) {
    std::vector<Vec2> points;
    for (int i : piece) points.push_back(polygon[static_cast<size_t>(i)]), used.insert(i);
    s.area += signed_area(points);
    s.convex = s.convex && reflex_corners(points).empty() && signed_area(points) > 0.0;
    s.smallest_angle = std::min(s.smallest_angle, min_interior_angle_deg(points));
    s.pieces.push_back(points);
  }
  EXPECT_EQ(used.size(), polygon.size());  // every vertex in some piece, no new ones
  return s;
}

TEST(GlassSplit, ConvexPolygonStaysWhole) {
  const std::vector<Vec2> square = outline({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  EXPECT_EQ(convex_pieces(square, 15.0).size(), 1u);
}

TEST(GlassSplit, LShapeTwoConvexPieces) {
  const Split s = split(kLShape, 15.0);
  EXPECT_EQ(s.pieces.size(), 2u);
  EXPECT_TRUE(s.convex);
  EXPECT_NEAR(s.area, signed_area(kLShape), 1e-12);
  EXPECT_GE(s.smallest_angle, 15.0);
}

TEST(GlassSplit, CombConvexPiecesAboveTheMinimum) {
  const Split s = split(kComb, 20.0);
  EXPECT_TRUE(s.convex);
  EXPECT_LE(s.pieces.size(), 5u);  // four reflex corners: at most one more piece each
  EXPECT_NEAR(s.area, signed_area(kComb), 1e-12);
  EXPECT_GE(s.smallest_angle, 20.0);
}

TEST(GlassSplit, StarConvexPieces) {
  const std::vector<Vec2> polygon = star();
  const Split s = split(polygon, 15.0);
  EXPECT_TRUE(s.convex);
  EXPECT_NEAR(s.area, signed_area(polygon), 1e-12);
  // The star's own tips are 36 degrees; the cuts keep every new corner above 15 too.
  EXPECT_GE(s.smallest_angle, 15.0);
}

TEST(GlassSplit, PrefersCutsAboveTheMinimum) {
  // A shallow notch: cutting to the near corner of the base would make a thin corner; the
  // split takes a cut that keeps every corner at or above 25 degrees.
  const std::vector<Vec2> notch = outline({{0, 0}, {4, 0}, {4, 2}, {2, 1.6}, {0, 2}});
  const Split s = split(notch, 25.0);
  EXPECT_TRUE(s.convex);
  EXPECT_GE(s.smallest_angle, 25.0);
}

// An L-shaped panel of a tilted plane in a two-panel mesh (the L and a square beside it).
PanelMesh l_and_square() {
  const Vec3 n = Vec3(1, -2, 2).normalized();
  const Vec3 u = n.cross(Vec3::UnitX()).normalized(), v = n.cross(u);
  const Vec3 origin(100, -30, 25);
  PanelMesh pm;
  const std::vector<std::array<double, 2>> xy = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}, {3, 0}, {3, 1}};
  for (const auto& [x, y] : xy) pm.vertices.push_back(origin + x * u + y * v), pm.vertex_corner.push_back(-1);
  pm.panels = {{0, 1, 2, 3, 4, 5}, {1, 6, 7, 2}};
  pm.plane_normals = {n, n};
  pm.plane_offsets = {n.dot(origin), n.dot(origin)};
  pm.panel_cluster = {0, 1};
  pm.issues.resize(2);
  return pm;
}

TEST(GlassSplit, PanelMeshSplitKeepsVerticesPlanesAndTopology) {
  PanelMesh pm = l_and_square();
  const PanelMesh before = pm;
  EXPECT_EQ(split_concave_panels(pm, TriMesh{}, 15.0), 1);
  ASSERT_EQ(pm.num_panels(), 3);
  EXPECT_EQ(pm.vertices, before.vertices);
  EXPECT_EQ(pm.panel_source, (std::vector<int>{0, 0, 1}));
  EXPECT_EQ(pm.panel_cluster, (std::vector<int>{0, 0, 1}));
  for (int p = 0; p < 3; ++p) {
    EXPECT_TRUE(pm.issues[static_cast<size_t>(p)].valid());
    EXPECT_EQ(pm.plane_normals[static_cast<size_t>(p)], before.plane_normals[0]);
    for (int v : pm.panels[static_cast<size_t>(p)])
      EXPECT_NEAR(pm.plane_normals[0].dot(pm.vertices[static_cast<size_t>(v)]), pm.plane_offsets[0], 1e-12);
  }
  // V - E + F: 8 - 10 + 3 (one diagonal, one face more) = 8 - 9 + 2 before.
  std::set<std::pair<int, int>> edges;
  for (const auto& poly : pm.panels)
    for (size_t i = 0; i < poly.size(); ++i) edges.insert(std::minmax(poly[i], poly[(i + 1) % poly.size()]));
  EXPECT_EQ(8 - static_cast<int>(edges.size()) + pm.num_panels(), 1);
  const std::vector<PanelPart> parts = panel_parts(pm);
  EXPECT_EQ(parts[0].label, "P1a");
  EXPECT_EQ(parts[1].label, "P1b");
  EXPECT_EQ(parts[2].label, "P2");
}

TEST(GlassSplit, AcuteCornerFlaggedOnThePiece) {
  // A sliver of 10 degrees: acute under a 15-degree minimum, fine under 5.
  const double t = std::tan(10.0 * M_PI / 180.0);
  const std::vector<Vec2> sliver = outline({{0, 0}, {1, 0}, {1, t}});
  EXPECT_EQ(acute_corners(sliver, 15.0), (std::vector<int>{0}));
  EXPECT_TRUE(acute_corners(sliver, 5.0).empty());
  EXPECT_EQ(reflex_corners(kLShape), (std::vector<int>{3}));
}

}  // namespace
}  // namespace ff
