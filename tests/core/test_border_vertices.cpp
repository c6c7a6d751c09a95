// Extra border vertices: Douglas-Peucker between fixed ends and on closed borders. Every
// dropped point must lie within the tolerance of the kept polyline, straight borders need no
// extra vertex, and the minimum counts hold.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/panels/border_vertices.h"
#include "core/util/angles.h"

namespace ff {
namespace {

double segment_distance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + t * ab - p).norm();
}

// Indices strictly increasing and in range.
void expect_sorted_indices(const std::vector<int>& kept, size_t n) {
  for (size_t k = 0; k < kept.size(); ++k) {
    EXPECT_GE(kept[k], 0);
    EXPECT_LT(kept[k], static_cast<int>(n));
    if (k > 0) {
      EXPECT_LT(kept[k - 1], kept[k]);
    }
  }
}

// Each dropped point within tolerance of the kept segment spanning it.
void expect_within_tolerance(const Vec3& from, const std::vector<Vec3>& points, const Vec3& to,
                             const std::vector<int>& kept, double tolerance) {
  std::vector<Vec3> polyline{from};
  std::vector<int> index{-1};
  for (int k : kept) polyline.push_back(points[static_cast<size_t>(k)]), index.push_back(k);
  polyline.push_back(to);
  index.push_back(static_cast<int>(points.size()));
  for (size_t s = 0; s + 1 < polyline.size(); ++s) {
    for (int i = index[s] + 1; i < index[s + 1]; ++i) {
      EXPECT_LE(segment_distance(points[static_cast<size_t>(i)], polyline[s], polyline[s + 1]), tolerance)
          << "point " << i;
    }
  }
}

TEST(BorderVertices, StraightBorderKeepsNothing) {
  std::vector<Vec3> points;
  for (int i = 1; i < 10; ++i) points.emplace_back(0.1 * i, 0.2 * i, 1e-4 * ((i % 2) ? 1 : -1));
  const Vec3 from(0, 0, 0), to(1, 2, 0);
  EXPECT_TRUE(thin_border(from, points, to, 1e-3, 0).empty());
  // min_keep = 1 keeps exactly one, even here.
  const std::vector<int> one = thin_border(from, points, to, 1e-3, 1);
  ASSERT_EQ(one.size(), 1u);
  expect_sorted_indices(one, points.size());
  expect_within_tolerance(from, points, to, one, 1e-3);
  // No points, nothing to keep whatever min_keep says.
  EXPECT_TRUE(thin_border(from, {}, to, 1e-3, 1).empty());
}

TEST(BorderVertices, BentBorderKeepsItsApex) {
  const Vec3 from(0, 0, 0), to(2, 0, 0);
  const std::vector<Vec3> points = {Vec3(0.5, 0.25, 0), Vec3(1.0, 0.5, 0), Vec3(1.5, 0.25, 0)};
  EXPECT_EQ(thin_border(from, points, to, 0.1, 0), std::vector<int>{1});
  EXPECT_EQ(thin_border(from, points, to, 0.1, 1), std::vector<int>{1});
  // Within the tolerance the bend is dropped.
  EXPECT_TRUE(thin_border(from, points, to, 0.6, 0).empty());
  // A bend out of the plane counts the same (3D distances).
  const std::vector<Vec3> lifted = {Vec3(0.5, 0, 0.25), Vec3(1.0, 0, 0.5), Vec3(1.5, 0, 0.25)};
  EXPECT_EQ(thin_border(from, lifted, to, 0.1, 0), std::vector<int>{1});
}

// The end node lands short of the last border point (the vertex rule puts it near its mesh
// corner, not on it): the border would run out to that point and straight back, a needle.
// The point goes, at either end; a sharp design corner (30 degrees) stays.
TEST(BorderVertices, NoNeedleWhereAnEndLandsShortOfTheBorder) {
  const std::vector<Vec3> points = {Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(3, 0, 0)};
  const Vec3 from(0, 0.001, 0), short_end(2.9, 0.001, 0);
  // Douglas-Peucker alone keeps point 2 (0.1 from the end, above the tolerance).
  EXPECT_EQ(thin_border(from, points, short_end, 0.05, 0), std::vector<int>{});
  EXPECT_EQ(thin_border(from, points, short_end, 0.05, 1).size(), 1u);  // min_keep still holds
  // Mirrored: the start lands past the first point.
  const std::vector<Vec3> reversed = {Vec3(3, 0, 0), Vec3(2, 0, 0), Vec3(1, 0, 0)};
  EXPECT_EQ(thin_border(short_end, reversed, from, 0.05, 0), std::vector<int>{});
  // A real corner of 30 degrees at the last point is the design's: kept.
  const Vec3 corner_end = Vec3(3, 0, 0) + 0.5 * Vec3(-std::cos(kPi / 6), std::sin(kPi / 6), 0);
  EXPECT_EQ(thin_border(from, points, corner_end, 0.05, 0), std::vector<int>{2});
}

TEST(BorderVertices, DroppedPointsStayWithinTolerance) {
  // A wiggly border: a sine of two periods with many points, at several tolerances.
  const Vec3 from(0, 0, 0), to(4, 0, 0);
  std::vector<Vec3> points;
  const int n = 199;
  for (int i = 1; i <= n; ++i) {
    const double x = 4.0 * i / (n + 1);
    points.emplace_back(x, 0.3 * std::sin(kPi * x) + 0.01 * std::sin(37.0 * x), 0.05 * std::cos(3.0 * x));
  }
  size_t previous = 0;
  for (double tolerance : {0.2, 0.05, 0.01, 0.002}) {
    const std::vector<int> kept = thin_border(from, points, to, tolerance, 0);
    expect_sorted_indices(kept, points.size());
    expect_within_tolerance(from, points, to, kept, tolerance);
    EXPECT_LT(kept.size(), points.size()) << tolerance;  // it does thin
    previous = kept.size();
  }
  EXPECT_GE(previous, 4u);  // at 0.002: the two humps and two troughs at least
}

TEST(BorderVertices, OneFixedVertexAtBothEnds) {
  // A panel with a single node on its border: the chain starts and ends at that node.
  const Vec3 node(1, 0, 0);
  std::vector<Vec3> points;
  for (int i = 1; i < 40; ++i) points.emplace_back(std::cos(2 * kPi * i / 40), std::sin(2 * kPi * i / 40), 0.0);
  for (double tolerance : {0.01, 0.1}) {
    const std::vector<int> kept = thin_border(node, points, node, tolerance, 1);
    expect_sorted_indices(kept, points.size());
    EXPECT_GE(kept.size(), 2u) << tolerance;  // a polygon, not a spike to the far side and back
    expect_within_tolerance(node, points, node, kept, tolerance);
  }
}

// Closed: each dropped point within tolerance of the kept segment spanning it (cyclically).
void expect_closed_within_tolerance(const std::vector<Vec3>& points, const std::vector<int>& kept, double tolerance) {
  ASSERT_FALSE(kept.empty());
  const size_t n = points.size();
  for (size_t s = 0; s < kept.size(); ++s) {
    const int a = kept[s], b = kept[(s + 1) % kept.size()];
    const int span = ((b - a) % static_cast<int>(n) + static_cast<int>(n)) % static_cast<int>(n);
    for (int t = 1; t < (span == 0 ? static_cast<int>(n) : span); ++t) {
      const size_t i = static_cast<size_t>((a + t) % static_cast<int>(n));
      EXPECT_LE(segment_distance(points[i], points[static_cast<size_t>(a)], points[static_cast<size_t>(b)]), tolerance)
          << "point " << i;
    }
  }
}

TEST(BorderVertices, ClosedCircleKeepsAPolygonWithinTolerance) {
  const int n = 64;
  std::vector<Vec3> circle;
  for (int i = 0; i < n; ++i) circle.emplace_back(std::cos(2 * kPi * i / n), std::sin(2 * kPi * i / n), 0.0);
  for (double tolerance : {0.01, 0.05, 0.2, 0.5, 10.0}) {
    const std::vector<int> kept = thin_closed_border(circle, tolerance);
    expect_sorted_indices(kept, circle.size());
    EXPECT_GE(kept.size(), 3u) << tolerance;
    EXPECT_LT(kept.size(), circle.size()) << tolerance;
    if (tolerance < 1.0) expect_closed_within_tolerance(circle, kept, tolerance);
    // The kept points span a real polygon, not a sliver.
    Vec3 normal = Vec3::Zero();
    for (size_t k = 0; k < kept.size(); ++k) {
      normal += circle[static_cast<size_t>(kept[k])].cross(circle[static_cast<size_t>(kept[(k + 1) % kept.size()])]);
    }
    EXPECT_GT(0.5 * normal.z(), 0.5) << tolerance;  // area of a triangle in the unit circle >= 1
  }
  // A polygon inscribed in the circle with dropped arcs of at most the tolerance: a regular
  // polygon of m sides leaves 1 - cos(pi / m), so about pi / sqrt(2 tol) sides are needed.
  EXPECT_GE(thin_closed_border(circle, 0.01).size(), 20u);
}

TEST(BorderVertices, ClosedBorderWithFewPointsKeepsThemAll) {
  const std::vector<Vec3> triangle = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  EXPECT_EQ(thin_closed_border(triangle, 100.0), (std::vector<int>{0, 1, 2}));
  // A flat sliver of many collinear-ish points still gives 3.
  std::vector<Vec3> sliver;
  for (int i = 0; i < 10; ++i) sliver.emplace_back(i, 1e-6 * (i % 3), 0.0);
  for (int i = 8; i > 0; --i) sliver.emplace_back(i, -1e-6, 0.0);
  EXPECT_EQ(thin_closed_border(sliver, 0.1).size(), 3u);
}

}  // namespace
}  // namespace ff
