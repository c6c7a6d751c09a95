// 2D polygon geometry used to check panels in their planes: simplicity, kernels, flipped
// edges, ear clipping, corner angles and the plane frame.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/panels/polygon2d.h"
#include "core/util/angles.h"
#include "core/util/error.h"
#include "core/util/random.h"

namespace ff {
namespace {

using Poly = std::vector<Vec2>;

Poly square() { return {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)}; }
Poly l_shape() { return {Vec2(0, 0), Vec2(2, 0), Vec2(2, 1), Vec2(1, 1), Vec2(1, 2), Vec2(0, 2)}; }
// A "C" open to the right: its two inner edges face each other, so no point sees both.
Poly c_shape() {
  return {Vec2(0, 0), Vec2(3, 0), Vec2(3, 1), Vec2(1, 1), Vec2(1, 2), Vec2(3, 2), Vec2(3, 3), Vec2(0, 3)};
}
// Three teeth on a base.
Poly comb() {
  return {Vec2(0, 0), Vec2(5, 0), Vec2(5, 3), Vec2(4, 3), Vec2(4, 1), Vec2(3, 1),
          Vec2(3, 3), Vec2(2, 3), Vec2(2, 1), Vec2(1, 1), Vec2(1, 3), Vec2(0, 3)};
}
// Five-pointed star, outer radius 2, inner radius 0.8: its kernel is the inner pentagon.
Poly star(int points = 5, double outer = 2.0, double inner = 0.8) {
  Poly p;
  for (int i = 0; i < 2 * points; ++i) {
    const double a = kPi / 2 + kPi * i / points;
    const double r = i % 2 == 0 ? outer : inner;
    p.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return p;
}
// An arrow pointing right: concave tail notch, star-shaped (kernel near (2, 1)).
Poly arrow() {
  return {Vec2(0, 0.2), Vec2(1, 0.5), Vec2(2, 0.5), Vec2(2, 0),  Vec2(3, 1),
          Vec2(2, 2),   Vec2(2, 1.5), Vec2(1, 1.5), Vec2(0, 1.8)};
}
// A square spiral corridor of width 1 (simple, not star-shaped).
Poly spiral() {
  return {Vec2(0, 0), Vec2(5, 0), Vec2(5, 5), Vec2(1, 5), Vec2(1, 2), Vec2(3, 2),
          Vec2(3, 3), Vec2(2, 3), Vec2(2, 4), Vec2(4, 4), Vec2(4, 1), Vec2(0, 1)};
}
// Random star-shaped polygon around the origin (radii in [0.5, 1.5]).
Poly random_star_shaped(int k, std::uint64_t seed) {
  SplitMix64 rng(seed);
  Poly p;
  for (int i = 0; i < k; ++i) {
    const double a = 2 * kPi * i / k, r = 0.5 + rng.uniform();
    p.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return p;
}
Poly reversed(Poly p) {
  std::reverse(p.begin(), p.end());
  return p;
}

// Checks k - 2 triangles, all oriented like the polygon, areas summing to its area.
void expect_valid_triangulation(const Poly& p) {
  const auto tris = triangulate_polygon(p);
  ASSERT_EQ(tris.size(), p.size() - 2);
  const double area = signed_area(p);
  double sum = 0.0, abs_sum = 0.0;
  for (const auto& t : tris) {
    for (int i : t) ASSERT_TRUE(i >= 0 && i < static_cast<int>(p.size()));
    const double a =
        0.5 * orient2d(p[static_cast<size_t>(t[0])], p[static_cast<size_t>(t[1])], p[static_cast<size_t>(t[2])]);
    EXPECT_GE(a * (area > 0 ? 1 : -1), -1e-12 * std::abs(area));
    sum += a;
    abs_sum += std::abs(a);
  }
  EXPECT_NEAR(sum, area, 1e-9 * std::abs(area));
  // No overlap: absolute areas add up to the same.
  EXPECT_NEAR(abs_sum, std::abs(area), 1e-9 * std::abs(area));
}

// Every kernel point sees every edge from its left (within eps).
void expect_sees_all_edges(const Poly& p, const Vec2& k, double eps = 1e-12) {
  for (size_t i = 0; i < p.size(); ++i) EXPECT_GE(orient2d(k, p[i], p[(i + 1) % p.size()]), -eps);
}

TEST(Polygon2d, SignedAreaAndOrientation) {
  EXPECT_DOUBLE_EQ(signed_area(square()), 1.0);
  EXPECT_DOUBLE_EQ(signed_area(reversed(square())), -1.0);
  EXPECT_DOUBLE_EQ(signed_area(l_shape()), 3.0);
  EXPECT_DOUBLE_EQ(signed_area({Vec2(0, 0), Vec2(1, 0)}), 0.0);
  // Far from the origin: relative evaluation keeps the digits.
  Poly far = square();
  for (Vec2& q : far) q += Vec2(1e7, -3e7);
  EXPECT_NEAR(signed_area(far), 1.0, 1e-8);
  EXPECT_TRUE(polygon_centroid(l_shape()).isApprox(Vec2(5.0 / 6.0, 5.0 / 6.0), 1e-12));
}

TEST(Polygon2d, ConvexSquare) {
  const Poly p = square();
  EXPECT_TRUE(is_simple(p, 1e-9));
  const Poly kernel = polygon_kernel(p, 0.0);
  EXPECT_NEAR(signed_area(kernel), 1.0, 1e-12);
  EXPECT_TRUE(is_star_shaped(p, 1e-9));
  const Vec2 k = kernel_point(p, 1e-9);
  EXPECT_TRUE(k.isApprox(Vec2(0.5, 0.5), 1e-9));
  EXPECT_EQ(flipped_edges(p, k).size(), 0u);
  EXPECT_NEAR(min_interior_angle_deg(p), 90.0, 1e-12);
  expect_valid_triangulation(p);
  // The kernel is eroded by tol.
  EXPECT_NEAR(signed_area(polygon_kernel(p, 0.1)), 0.64, 1e-12);
  EXPECT_TRUE(polygon_kernel(p, 0.5).empty());
}

TEST(Polygon2d, LShapeKernelIsTheCornerSquare) {
  const Poly p = l_shape();
  EXPECT_TRUE(is_simple(p, 1e-9));
  const Poly kernel = polygon_kernel(p, 0.0);
  ASSERT_FALSE(kernel.empty());
  EXPECT_NEAR(signed_area(kernel), 1.0, 1e-12);
  for (const Vec2& q : kernel) {
    EXPECT_GE(q.minCoeff(), -1e-12);
    EXPECT_LE(q.maxCoeff(), 1.0 + 1e-12);
  }
  const Vec2 k = kernel_point(p, 1e-9);
  EXPECT_TRUE(k.isApprox(Vec2(0.5, 0.5), 1e-9));
  expect_sees_all_edges(p, k);
  EXPECT_EQ(flipped_edges(p, k).size(), 0u);
  // Seen from the lower arm, the reflex corner's upward edge runs clockwise.
  EXPECT_EQ(flipped_edges(p, Vec2(1.5, 0.5)).size(), 1u);
  EXPECT_TRUE(has_flipped_edge(p, Vec2(1.5, 0.5)));
  EXPECT_TRUE(flipped_edges(p, k).empty());
  EXPECT_FALSE(has_flipped_edge(p, k));
  EXPECT_NEAR(min_interior_angle_deg(p), 90.0, 1e-12);
  expect_valid_triangulation(p);
}

TEST(Polygon2d, StarAndArrowAreStarShaped) {
  for (const Poly& p : {star(), star(7, 3.0, 1.0), arrow()}) {
    EXPECT_TRUE(is_simple(p, 1e-9));
    const Poly kernel = polygon_kernel(p, 1e-9);
    ASSERT_FALSE(kernel.empty());
    EXPECT_GT(signed_area(kernel), 0.0);
    EXPECT_LT(signed_area(kernel), signed_area(p));
    for (const Vec2& q : kernel) expect_sees_all_edges(p, q, 1e-9);
    const Vec2 k = kernel_point(p, 1e-9);
    EXPECT_TRUE(point_in_polygon(p, k));
    EXPECT_EQ(flipped_edges(p, k).size(), 0u);
    expect_valid_triangulation(p);
  }
  // A regular pentagram (each edge line through two inner vertices): its kernel is the
  // inner pentagon, area (5/2) r^2 sin(72 deg).
  const double r = 2.0 * std::cos(2 * kPi / 5) / std::cos(kPi / 5);
  EXPECT_NEAR(signed_area(polygon_kernel(star(5, 2.0, r), 0.0)), 2.5 * r * r * std::sin(2 * kPi / 5), 1e-9);
  // The star's points; the arrow's barbs: 45 degrees.
  EXPECT_NEAR(min_interior_angle_deg(star()),
              std::atan(0.8 * std::sin(kPi / 5) / (2 - 0.8 * std::cos(kPi / 5))) * 2 * 180 / kPi, 1e-9);
  EXPECT_NEAR(min_interior_angle_deg(arrow()), 45.0, 1e-9);
}

TEST(Polygon2d, NonStarShapesHaveEmptyKernels) {
  for (const Poly& p : {c_shape(), comb(), spiral()}) {
    EXPECT_TRUE(is_simple(p, 1e-9));
    EXPECT_GT(signed_area(p), 0.0);
    EXPECT_TRUE(polygon_kernel(p, 0.0).empty());
    EXPECT_FALSE(is_star_shaped(p, 1e-9));
    // No point sees every edge: from the vertex average (the fallback) some edge is flipped.
    const Vec2 k = kernel_point(p, 1e-9);
    Vec2 average = Vec2::Zero();
    for (const Vec2& q : p) average += q;
    EXPECT_TRUE(k.isApprox(average / static_cast<double>(p.size())));
    EXPECT_GT(flipped_edges(p, k).size(), 0u);
    expect_valid_triangulation(p);
    EXPECT_NEAR(min_interior_angle_deg(p), 90.0, 1e-12);
  }
}

TEST(Polygon2d, KernelOfZeroAreaIsEmpty) {
  // A deeper tail notch: the lines of the tail edges and of the barbs' inner edges leave
  // only the point (2, 1).
  const Poly p = {Vec2(0, 0), Vec2(1, 0.5), Vec2(2, 0.5), Vec2(2, 0), Vec2(3, 1),
                  Vec2(2, 2), Vec2(2, 1.5), Vec2(1, 1.5), Vec2(0, 2)};
  EXPECT_TRUE(is_simple(p, 1e-9));
  EXPECT_LT(std::abs(signed_area(polygon_kernel(p, 0.0))), 1e-12);
  EXPECT_TRUE(polygon_kernel(p, 1e-12).empty());
  EXPECT_FALSE(is_star_shaped(p, 1e-12));
}

TEST(Polygon2d, BowtieIsNotSimple) {
  const Poly bowtie = {Vec2(0, 0), Vec2(1, 1), Vec2(1, 0), Vec2(0, 1)};
  EXPECT_FALSE(is_simple(bowtie, 0.0));
  EXPECT_FALSE(is_simple(bowtie, 1e-9));
  EXPECT_FALSE(is_star_shaped(bowtie, 1e-9));
  // Fallback: a fan from vertex 0, still k - 2 triangles.
  const auto tris = triangulate_polygon(bowtie);
  ASSERT_EQ(tris.size(), 2u);
  EXPECT_EQ(tris[0], (std::array<int, 3>{0, 1, 2}));
  EXPECT_EQ(tris[1], (std::array<int, 3>{0, 2, 3}));
}

TEST(Polygon2d, DegenerateAndTouchingPolygonsAreNotSimple) {
  EXPECT_FALSE(is_simple({Vec2(0, 0), Vec2(1, 0)}, 0.0));
  // Zero-length edge.
  EXPECT_FALSE(is_simple({Vec2(0, 0), Vec2(1, 0), Vec2(1, 0), Vec2(0, 1)}, 0.0));
  // A repeated vertex (two loops touching).
  EXPECT_FALSE(is_simple({Vec2(0, 0), Vec2(2, 0), Vec2(1, 1), Vec2(2, 2), Vec2(0, 2), Vec2(1, 1)}, 0.0));
  // An edge folding back onto its predecessor.
  EXPECT_FALSE(is_simple({Vec2(0, 0), Vec2(2, 0), Vec2(1, 0), Vec2(1, 1)}, 0.0));
  // A collinear triangle.
  EXPECT_FALSE(is_simple({Vec2(0, 0), Vec2(1, 0), Vec2(2, 0)}, 0.0));
  // A vertex 1e-3 from a non-adjacent edge: simple or not depending on the tolerance.
  const Poly near = {Vec2(0, 0), Vec2(4, 0), Vec2(4, 2), Vec2(2, 1e-3), Vec2(0, 2)};
  EXPECT_TRUE(is_simple(near, 1e-6));
  EXPECT_FALSE(is_simple(near, 1e-2));
  // Crossing far from any vertex (a figure eight with a long crossing).
  EXPECT_FALSE(is_simple({Vec2(0, 0), Vec2(10, 1), Vec2(10, 0), Vec2(0, 1)}, 0.0));
}

TEST(Polygon2d, CollinearVertices) {
  const Poly p = {Vec2(0, 0), Vec2(0.5, 0), Vec2(1, 0), Vec2(1, 0.5), Vec2(1, 1), Vec2(0.5, 1), Vec2(0, 1)};
  EXPECT_TRUE(is_simple(p, 1e-9));
  EXPECT_NEAR(signed_area(polygon_kernel(p, 0.0)), 1.0, 1e-12);
  EXPECT_EQ(flipped_edges(p, kernel_point(p, 1e-9)).size(), 0u);
  EXPECT_NEAR(min_interior_angle_deg(p), 90.0, 1e-12);
  expect_valid_triangulation(p);
  // Many collinear points on every side of an L.
  Poly dense;
  const Poly l = l_shape();
  for (size_t i = 0; i < l.size(); ++i) {
    for (int s = 0; s < 10; ++s) dense.push_back(l[i] + (l[(i + 1) % l.size()] - l[i]) * (s / 10.0));
  }
  EXPECT_TRUE(is_simple(dense, 1e-9));
  EXPECT_NEAR(signed_area(polygon_kernel(dense, 0.0)), 1.0, 1e-12);
  expect_valid_triangulation(dense);
}

TEST(Polygon2d, ClockwiseInput) {
  const Poly cw = reversed(l_shape());
  EXPECT_TRUE(is_simple(cw, 1e-9));
  EXPECT_LT(signed_area(cw), 0.0);
  // The kernel wants CCW: a clockwise polygon has none, and from its vertex average
  // (documented fallback) most edges run clockwise.
  EXPECT_TRUE(polygon_kernel(cw, 0.0).empty());
  EXPECT_EQ(flipped_edges(reversed(square()), Vec2(0.5, 0.5)).size(), 4u);
  // Angles are interior angles whatever the orientation; triangles keep the orientation.
  EXPECT_NEAR(min_interior_angle_deg(cw), 90.0, 1e-12);
  expect_valid_triangulation(cw);
  expect_valid_triangulation(reversed(spiral()));
}

TEST(Polygon2d, ReflexAnglesAbove180) {
  // The arrow's notch corners: reflex.
  const Poly p = {Vec2(0, 0), Vec2(2, 0), Vec2(2, 2), Vec2(1, 1), Vec2(0, 2)};
  EXPECT_NEAR(min_interior_angle_deg(p), 45.0, 1e-12);
  const Poly tri = {Vec2(0, 0), Vec2(std::sqrt(3.0), 0), Vec2(0, 1)};  // 30-60-90
  EXPECT_NEAR(min_interior_angle_deg(tri), 30.0, 1e-12);
  EXPECT_NEAR(min_interior_angle_deg(reversed(tri)), 30.0, 1e-12);
  EXPECT_EQ(min_interior_angle_deg({Vec2(0, 0), Vec2(1, 0)}), 0.0);
}

TEST(Polygon2d, PointInPolygonAndDistance) {
  const Poly p = l_shape();
  EXPECT_TRUE(point_in_polygon(p, Vec2(0.5, 1.5)));
  EXPECT_TRUE(point_in_polygon(p, Vec2(1.5, 0.5)));
  EXPECT_FALSE(point_in_polygon(p, Vec2(1.5, 1.5)));
  EXPECT_FALSE(point_in_polygon(p, Vec2(-0.1, 0.5)));
  EXPECT_TRUE(point_in_polygon(reversed(p), Vec2(0.5, 1.5)));
  EXPECT_NEAR(distance_to_boundary(p, Vec2(0.5, 0.4)), 0.4, 1e-15);
  EXPECT_NEAR(distance_to_boundary(p, Vec2(1.5, 1.5)), 0.5, 1e-15);
  EXPECT_NEAR(distance_to_boundary(p, Vec2(3, 3)), std::sqrt(5.0), 1e-15);
  EXPECT_NEAR(distance_point_segment(Vec2(0, 1), Vec2(1, 0), Vec2(1, 0)), std::sqrt(2.0), 1e-15);
}

TEST(Polygon2d, RandomStarShapedPolygonsUpTo2000Vertices) {
  for (int k : {5, 12, 64, 300, 2000}) {
    const Poly p = random_star_shaped(k, 100 + static_cast<std::uint64_t>(k));
    EXPECT_TRUE(is_simple(p, 1e-12)) << k;
    const Vec2 origin = Vec2::Zero();
    EXPECT_EQ(flipped_edges(p, origin).size(), 0u);
    ASSERT_TRUE(is_star_shaped(p, 1e-12)) << k;
    const Vec2 kp = kernel_point(p, 1e-12);
    EXPECT_EQ(flipped_edges(p, kp).size(), 0u);
    expect_valid_triangulation(p);
  }
}

// is_simple's definition checked pair by pair, with no pruning: no edge of length <= tol, no
// two non-adjacent edges within tol, no two adjacent edges folding back within tol.
double reference_segment_distance(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double o1 = orient2d(a, b, c), o2 = orient2d(a, b, d), o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) return 0.0;
  return std::min(std::min(distance_point_segment(a, c, d), distance_point_segment(b, c, d)),
                  std::min(distance_point_segment(c, a, b), distance_point_segment(d, a, b)));
}
bool reference_is_simple(const Poly& p, double tol) {
  const size_t k = p.size();
  if (k < 3) return false;
  for (size_t i = 0; i < k; ++i) {
    if ((p[(i + 1) % k] - p[i]).norm() <= tol) return false;
  }
  for (size_t i = 0; i < k; ++i) {
    for (size_t j = i + 1; j < k; ++j) {
      const Vec2 &a = p[i], &b = p[(i + 1) % k], &c = p[j], &d = p[(j + 1) % k];
      if (j == i + 1) {  // a -> b=c -> d
        if (distance_point_segment(a, c, d) <= tol || distance_point_segment(d, a, b) <= tol) return false;
      } else if ((j + 1) % k == i) {  // c -> d=a -> b
        if (distance_point_segment(c, a, b) <= tol || distance_point_segment(b, c, d) <= tol) return false;
      } else if (reference_segment_distance(a, b, c, d) <= tol) {
        return false;
      }
    }
  }
  return true;
}

TEST(Polygon2d, IsSimpleMatchesThePairwiseDefinition) {
  // Star-shaped polygons with a few vertices thrown elsewhere, on a coarse grid so that
  // touching, collinear and repeated vertices come up; up to 12 vertices and more.
  SplitMix64 rng(7);
  int simple[2] = {0, 0}, not_simple[2] = {0, 0};
  for (int trial = 0; trial < 20000; ++trial) {
    const int k = 3 + static_cast<int>(rng.below(18));
    Poly p = random_star_shaped(k, 1000 + static_cast<std::uint64_t>(trial));
    const int moves = static_cast<int>(rng.below(3));
    for (int m = 0; m < moves; ++m) {
      p[rng.below(p.size())] = Vec2(3.0 * rng.uniform() - 1.5, 3.0 * rng.uniform() - 1.5);
    }
    if (trial % 2 == 0) {
      for (Vec2& q : p) q = (q * 8.0).array().round().matrix() / 8.0;
    }
    for (double tol : {0.0, 1e-3, 0.05}) {
      const bool expected = reference_is_simple(p, tol);
      ASSERT_EQ(is_simple(p, tol), expected) << "trial " << trial << " k " << k << " tol " << tol;
      (expected ? simple : not_simple)[k > 12] += 1;
    }
  }
  for (int large = 0; large < 2; ++large) {  // both answers, small polygons and larger
    EXPECT_GT(simple[large], 2000) << large;
    EXPECT_GT(not_simple[large], 2000) << large;
  }
}

TEST(Polygon2d, PlaneFrameRoundTrip) {
  SplitMix64 rng(3);
  const auto r = [&] { return 2 * rng.uniform() - 1; };
  for (int trial = 0; trial < 50; ++trial) {
    Vec3 n(r(), r(), r());
    if (trial == 0) n = Vec3(0, 0, -1);
    if (trial == 1) n = Vec3(1, 0, 0);
    n.normalize();
    const Vec3 origin(10 * r(), 10 * r(), 10 * r());
    const PlaneFrame f = make_plane_frame(origin, n);
    EXPECT_NEAR(f.u.norm(), 1.0, 1e-14);
    EXPECT_NEAR(f.v.norm(), 1.0, 1e-14);
    EXPECT_NEAR(f.u.dot(f.v), 0.0, 1e-14);
    EXPECT_TRUE(f.u.cross(f.v).isApprox(n, 1e-14));
    const Vec2 q(r(), r());
    EXPECT_TRUE(f.to_2d(f.to_3d(q)).isApprox(q, 1e-12));
    const Vec3 p = origin + 3 * f.u - 2 * f.v;
    EXPECT_TRUE(f.to_3d(f.to_2d(p)).isApprox(p, 1e-12));
    // Off-plane points project orthogonally.
    EXPECT_TRUE(f.to_2d(p + 5 * n).isApprox(f.to_2d(p), 1e-12));
    // A triangle counter-clockwise around n (right-hand rule) is CCW in 2D.
    const Vec3 a = origin, b = origin + n.unitOrthogonal(), c = origin + n.cross(n.unitOrthogonal());
    ASSERT_GT((b - a).cross(c - a).dot(n), 0.0);
    EXPECT_GT(signed_area({f.to_2d(a), f.to_2d(b), f.to_2d(c)}), 0.0);
  }
  // The normal is normalised here; zero is garbage.
  EXPECT_TRUE(make_plane_frame(Vec3::Zero(), Vec3(0, 0, 5)).normal.isApprox(Vec3::UnitZ()));
  EXPECT_THROW(make_plane_frame(Vec3::Zero(), Vec3::Zero()), InputError);
}

TEST(Polygon2d, NewellNormal) {
  const std::vector<Vec3> quad = {Vec3(0, 0, 5), Vec3(2, 0, 5), Vec3(2, 3, 5), Vec3(0, 3, 5)};
  EXPECT_TRUE(newell_normal(quad).isApprox(Vec3(0, 0, 12)));
  EXPECT_EQ(newell_normal({}), Vec3::Zero());
}

}  // namespace
}  // namespace ff
