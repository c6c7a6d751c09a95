// The closest-point tree behind the Hausdorff distance: exact against brute force.
#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "core/quality/closest_point.h"
#include "core/shapes/shapes.h"
#include "core/util/error.h"
#include "core/util/random.h"

namespace ff {
namespace {

TEST(ClosestPoint, TreeMatchesBruteForce) {
  SplitMix64 rng(11);
  const auto r = [&] { return Vec3(rng.uniform(), rng.uniform(), rng.uniform()); };
  TriMesh soup;
  for (int t = 0; t < 700; ++t) {
    const Vec3 c = r();
    const int base = soup.num_vertices();
    soup.positions.push_back(c);
    soup.positions.push_back(c + 0.1 * (r() - Vec3::Constant(0.5)));
    // Some slivers and points: degenerate triangles must work too.
    soup.positions.push_back(t % 10 == 0   ? c
                             : t % 10 == 1 ? Vec3(c + 0.03 * Vec3::UnitX())
                                           : Vec3(c + 0.1 * (r() - Vec3::Constant(0.5))));
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  const TriangleTree tree(soup);
  EXPECT_EQ(tree.num_triangles(), 700);
  for (int i = 0; i < 2000; ++i) {
    const Vec3 q = 2.0 * r() - Vec3::Constant(0.5);
    double best = std::numeric_limits<double>::infinity();
    for (int t = 0; t < soup.num_faces(); ++t) {
      const Triangle& tri = soup.triangles[static_cast<size_t>(t)];
      const Vec3 x = closest_point_on_triangle(q, soup.positions[static_cast<size_t>(tri[0])],
                                               soup.positions[static_cast<size_t>(tri[1])],
                                               soup.positions[static_cast<size_t>(tri[2])]);
      best = std::min(best, (x - q).norm());
    }
    const ClosestPoint c = tree.closest_point(q, i % 2 == 0 ? -1 : i % 700);
    EXPECT_DOUBLE_EQ(c.distance, best);
    EXPECT_NEAR((c.point - q).norm(), c.distance, 1e-15);
    const Triangle& tri = soup.triangles[static_cast<size_t>(c.triangle)];
    EXPECT_TRUE(c.point.isApprox(closest_point_on_triangle(q, soup.positions[static_cast<size_t>(tri[0])],
                                                           soup.positions[static_cast<size_t>(tri[1])],
                                                           soup.positions[static_cast<size_t>(tri[2])]),
                                 1e-15));
  }
  // good_enough: any triangle within it ends the search; beyond it the answer is exact. With
  // a hint too, the search starts in the subtree around the hint (the Hausdorff queries), and
  // the contract is the same: hints near and far, bounds loose and tight.
  int exact_beyond = 0, within = 0;
  for (int i = 0; i < 600; ++i) {
    const Vec3 q = 2.0 * r() - Vec3::Constant(0.5);
    const ClosestPoint exact = tree.closest_point(q);
    const double enough = i % 3 == 0 ? 0.1 : i % 3 == 1 ? 0.02 : 0.3;
    const int hint = i % 4 == 0 ? -1 : i % 4 == 1 ? exact.triangle : (i * 37) % 700;
    const ClosestPoint quick = tree.closest_point(q, hint, enough);
    if (exact.distance > enough) {
      EXPECT_EQ(quick.distance, exact.distance);
      ++exact_beyond;
    } else {
      EXPECT_LE(quick.distance, enough);
      ++within;
    }
  }
  EXPECT_GT(exact_beyond, 50);
  EXPECT_GT(within, 50);
  EXPECT_TRUE(std::isinf(TriangleTree(TriMesh{}).closest_point(Vec3::Zero()).distance));
  EXPECT_THROW(TriangleTree({Vec3::Zero()}, {Triangle{0, 0, 1}}), InputError);
}

// The tree splits on float centroids, taken in the box's own frame: in world units a model
// at 1e39 overflowed a float (inf, then NaN bins: a crash) and one at 1e-44 vanished in it.
TEST(ClosestPoint, TreeWorksAtAnyScale) {
  for (const double scale : {1e39, 1e-44, 1e30, 1e-30}) {
    const TriMesh unit = make_roof(12, 10);
    TriMesh m = unit;
    for (Vec3& p : m.positions) p *= scale;
    const TriangleTree tree(m), reference(unit);
    for (int i = 0; i < 50; ++i) {
      const Vec3 q(20 + 25 * std::cos(i), 12 + 15 * std::sin(0.7 * i), 4 + 6 * std::cos(1.3 * i));
      const ClosestPoint c = tree.closest_point(q * scale), r = reference.closest_point(q);
      EXPECT_NEAR(c.distance / scale, r.distance, 1e-9) << scale;
    }
  }
}

// Centroids a few float subnormals apart: the bins' scale overflowed a float (NaN bins).
TEST(ClosestPoint, TreeSplitsCentroidsSubnormalsApart) {
  TriMesh m;
  m.positions = {Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(0, 1, 0)};
  m.triangles = {{0, 1, 2}};
  for (int i = 0; i < 200; ++i) {
    const int base = m.num_vertices();
    m.positions.push_back(Vec3(i * 1e-40, 0, 0));
    m.positions.push_back(Vec3((i + 1) * 1e-40, 0, 0));
    m.positions.push_back(Vec3(i * 1e-40, 1e-40, 0));
    m.triangles.push_back({base, base + 1, base + 2});
  }
  const TriangleTree tree(m);
  EXPECT_NEAR(tree.closest_point(Vec3(0.5, 0, 1)).distance, 1.0, 1e-12);
}

TEST(ClosestPoint, OnTriangleIsTheMinimum) {
  SplitMix64 rng(5);
  const auto r = [&] { return Vec3(2 * rng.uniform() - 1, 2 * rng.uniform() - 1, 2 * rng.uniform() - 1); };
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 a = r(), b = r(), c = r(), q = 2 * r();
    const double d = (closest_point_on_triangle(q, a, b, c) - q).norm();
    const int k = 60;
    for (int i = 0; i <= k; ++i) {
      for (int j = 0; i + j <= k; ++j) {
        const Vec3 x = a + (b - a) * (static_cast<double>(i) / k) + (c - a) * (static_cast<double>(j) / k);
        ASSERT_LE(d, (x - q).norm() + 1e-12);
      }
    }
  }
  // Vertex, edge and face regions of a right triangle.
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_TRUE(closest_point_on_triangle(Vec3(-1, -1, 1), a, b, c).isApprox(a));
  EXPECT_TRUE(closest_point_on_triangle(Vec3(0.5, -1, 0), a, b, c).isApprox(Vec3(0.5, 0, 0)));
  EXPECT_TRUE(closest_point_on_triangle(Vec3(1, 1, 0), a, b, c).isApprox(Vec3(0.5, 0.5, 0)));
  EXPECT_TRUE(closest_point_on_triangle(Vec3(0.2, 0.3, 4), a, b, c).isApprox(Vec3(0.2, 0.3, 0)));
  EXPECT_TRUE(closest_point_on_triangle(Vec3(3, 1, 0), a, a, b).isApprox(b));  // degenerate
}

}  // namespace
}  // namespace ff
