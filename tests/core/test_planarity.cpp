// Polygon planarity, and the planarity of panels moved back to their mesh corners (what the
// page shows as "before the planes are intersected").
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>

#include "core/quality/planarity.h"
#include "core/shapes/hard_cases.h"

namespace ff {
namespace {

TEST(Planarity, FlatAndBentQuads) {
  EXPECT_EQ(polygon_planarity({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}), 0.0);
  EXPECT_LT(polygon_planarity({Vec3(0, 0, 5), Vec3(2, 0, 5), Vec3(2, 2, 5), Vec3(0, 2, 5)}), 1e-15);
  // Opposite corners lifted by h: every vertex h/2 from the mean plane z = h/2, diameter 2 sqrt 2.
  const double h = 0.4;
  const double p = polygon_planarity({Vec3(0, 0, 0), Vec3(2, 0, h), Vec3(2, 2, 0), Vec3(0, 2, h)});
  EXPECT_NEAR(p, (h / 2) / (2 * std::sqrt(2.0)), 1e-12);
}

TEST(Planarity, CornerPolygonsOfASaddleBend) {
  // One "panel" through the saddle's edge midpoints (x, y) = (10, 0), (0, 10), (-10, 0), (0, -10):
  // heights +3, -3, +3, -3, far from coplanar; and its flattened version.
  const TriMesh saddle = make_saddle(200);
  PanelMesh pm;
  const Vec3 targets[4] = {Vec3(10, 0, 0), Vec3(0, 10, 0), Vec3(-10, 0, 0), Vec3(0, -10, 0)};
  int corners[4] = {0, 0, 0, 0};
  for (int k = 0; k < 4; ++k) {
    for (int v = 0; v < saddle.num_vertices(); ++v) {
      const auto planar = [&](int i) {
        return (saddle.positions[static_cast<size_t>(i)] - targets[k]).head<2>().norm();
      };
      if (planar(v) < planar(corners[k])) corners[k] = v;
    }
  }
  for (const int c : corners) {
    Vec3 flat = saddle.positions[static_cast<size_t>(c)];
    flat.z() = 0.0;
    pm.vertices.push_back(flat);
    pm.vertex_corner.push_back(c);
  }
  pm.panels = {{0, 1, 2, 3}};
  const std::vector<double> before = corner_polygon_planarity(saddle, pm);
  ASSERT_EQ(before.size(), 1u);
  EXPECT_GT(before[0], 0.05);  // the saddle's corners are far from coplanar
  std::vector<Vec3> after;
  for (const Vec3& q : pm.vertices) after.push_back(q);
  EXPECT_LT(polygon_planarity(after), 1e-15);
  pm.vertex_corner.clear();
  EXPECT_TRUE(corner_polygon_planarity(saddle, pm).empty());
}

// What the doubles allow: the spacing at the largest coordinate over the diameter. A unit
// square at the origin can be flat to 1e-16; moved 1e9 away, to no better than about 1.6e-7.
TEST(Planarity, RoundingFloorGrowsWithTheDistanceFromTheOrigin) {
  const std::vector<Vec3> square = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  EXPECT_NEAR(planarity_rounding_floor(square), DBL_EPSILON / std::sqrt(2.0), 1e-20);
  std::vector<Vec3> far = square;
  for (Vec3& p : far) p.x() += 1e9;
  EXPECT_NEAR(planarity_rounding_floor(far), DBL_EPSILON * (1e9 + 1) / std::sqrt(2.0), 1e-12);
  EXPECT_GT(planarity_rounding_floor(far), 1e-9);
  // About another point (the middle of a mesh with a part 1e9 away): the same as far away.
  EXPECT_NEAR(planarity_rounding_floor(square, Vec3(5e8, 0, 0)), DBL_EPSILON * 5e8 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(planarity_rounding_floor(far, Vec3(1e9, 0, 0)), DBL_EPSILON / std::sqrt(2.0), 1e-20);
  EXPECT_EQ(planarity_rounding_floor({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}), 0.0);
  EXPECT_EQ(planarity_rounding_floor({Vec3(2, 2, 2), Vec3(2, 2, 2), Vec3(2, 2, 2), Vec3(2, 2, 2)}), 0.0);
}

}  // namespace
}  // namespace ff
