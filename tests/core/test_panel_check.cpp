// Panel checks in the panel's own plane: convex and concave star-shaped panels pass; a
// clockwise panel is flipped, a bow-tie not simple, a comb not star-shaped, a far vertex a
// spike, and fewer than three vertices too few. On a tilted plane far from the origin too.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/panels/panel_check.h"
#include "core/panels/polygon2d.h"
#include "core/util/random.h"

namespace ff {
namespace {

// 2D outlines (counter-clockwise unless said otherwise), placed on a plane below.
using Outline = std::vector<std::array<double, 2>>;

const Outline kSquare = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
const Outline kLShape = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
const Outline kBowTie = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};
// Three teeth on a base: the inner sides of neighbouring teeth face away from each other.
const Outline kComb = {{0, 0}, {5, 0}, {5, 3}, {4, 3}, {4, 1}, {3, 1}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};

struct Placed {
  Plane plane;
  std::vector<Vec3> points;
};

// The outline in a plane: z = 0 by default, or tilted and far from the origin, with (u, v)
// chosen right-handed about the normal so that counter-clockwise stays counter-clockwise.
Placed place(const Outline& outline, bool tilted) {
  const Vec3 normal = tilted ? Vec3(1, -2, 2).normalized() : Vec3::UnitZ();
  const Vec3 origin = tilted ? Vec3(1e4, -3e3, 250.0) : Vec3::Zero();
  const Vec3 u = tilted ? normal.cross(Vec3::UnitX()).normalized() : Vec3::UnitX();
  const Vec3 v = normal.cross(u);
  Placed p{Plane::through(origin, normal), {}};
  for (const auto& [x, y] : outline) p.points.push_back(origin + x * u + y * v);
  return p;
}

PanelIssues check(const Outline& outline, bool tilted, double spike = 10.0) {
  const Placed p = place(outline, tilted);
  return check_panel(p.points, p.points, p.plane, spike, 1e-9);
}

Outline reversed(Outline o) {
  std::reverse(o.begin(), o.end());
  return o;
}

TEST(PanelCheck, ConvexPanelIsValid) {
  for (bool tilted : {false, true}) {
    SCOPED_TRACE(tilted ? "tilted plane" : "z = 0");
    const PanelIssues issues = check(kSquare, tilted);
    EXPECT_TRUE(issues.valid());
    EXPECT_FALSE(issues.flipped);
    EXPECT_EQ(issues.spike_vertices, 0);
  }
}

TEST(PanelCheck, ConcaveStarShapedPanelIsValid) {
  for (bool tilted : {false, true}) {
    SCOPED_TRACE(tilted ? "tilted plane" : "z = 0");
    const PanelIssues issues = check(kLShape, tilted);
    EXPECT_TRUE(issues.valid());
    EXPECT_FALSE(issues.not_star);
    EXPECT_FALSE(issues.not_simple);
  }
}

TEST(PanelCheck, CollinearBorderVerticesAreFine) {
  // Extra border vertices on a straight stretch: 180 degree corners, still a valid panel.
  for (bool tilted : {false, true}) {
    SCOPED_TRACE(tilted ? "tilted plane" : "z = 0");
    EXPECT_TRUE(check({{0, 0}, {0.5, 0}, {1, 0}, {1, 1}, {0, 1}}, tilted).valid());
    EXPECT_TRUE(check({{0, 0}, {0.3, 0}, {0.6, 0}, {1, 0}, {1, 0.5}, {1, 1}, {0, 1}}, tilted).valid());
  }
}

TEST(PanelCheck, ClockwisePanelIsFlipped) {
  for (bool tilted : {false, true}) {
    SCOPED_TRACE(tilted ? "tilted plane" : "z = 0");
    for (const Outline& o : {kSquare, kLShape}) {
      const PanelIssues issues = check(reversed(o), tilted);
      EXPECT_TRUE(issues.flipped);
      EXPECT_FALSE(issues.not_simple);
      EXPECT_FALSE(issues.valid());
    }
  }
}

TEST(PanelCheck, BowTieIsNotSimple) {
  for (bool tilted : {false, true}) {
    SCOPED_TRACE(tilted ? "tilted plane" : "z = 0");
    const PanelIssues issues = check(kBowTie, tilted);
    EXPECT_TRUE(issues.not_simple);
    EXPECT_FALSE(issues.valid());
  }
}

TEST(PanelCheck, CombIsNotStarShaped) {
  for (bool tilted : {false, true}) {
    SCOPED_TRACE(tilted ? "tilted plane" : "z = 0");
    const PanelIssues issues = check(kComb, tilted);
    EXPECT_TRUE(issues.not_star);
    EXPECT_FALSE(issues.not_simple);
    EXPECT_FALSE(issues.valid());
  }
}

TEST(PanelCheck, FarVertexIsASpike) {
  for (bool tilted : {false, true}) {
    SCOPED_TRACE(tilted ? "tilted plane" : "z = 0");
    const Placed p = place(kSquare, tilted);
    std::vector<Vec3> references = p.points;
    references[2] += Vec3(0.3, 0.4, 0.0);  // 0.5 from its vertex
    EXPECT_EQ(check_panel(p.points, references, p.plane, 0.49, 1e-9).spike_vertices, 1);
    EXPECT_FALSE(check_panel(p.points, references, p.plane, 0.49, 1e-9).valid());
    EXPECT_EQ(check_panel(p.points, references, p.plane, 0.51, 1e-9).spike_vertices, 0);
    references[0] -= Vec3(0.0, 0.0, 2.0);  // off the plane counts too: 3D distance
    EXPECT_EQ(check_panel(p.points, references, p.plane, 0.51, 1e-9).spike_vertices, 1);
    EXPECT_EQ(check_panel(p.points, references, p.plane, 0.49, 1e-9).spike_vertices, 2);
  }
}

TEST(PanelCheck, FewerThanThreeVertices) {
  for (bool tilted : {false, true}) {
    SCOPED_TRACE(tilted ? "tilted plane" : "z = 0");
    for (size_t n : {0u, 1u, 2u}) {
      const Placed p = place(Outline(kSquare.begin(), kSquare.begin() + static_cast<long>(n)), tilted);
      const PanelIssues issues = check_panel(p.points, p.points, p.plane, 1.0, 1e-9);
      EXPECT_TRUE(issues.too_few_vertices) << n;
      EXPECT_FALSE(issues.valid()) << n;
    }
  }
}

TEST(PanelCheck, DegenerateSliverIsNotValid) {
  for (bool tilted : {false, true}) {
    SCOPED_TRACE(tilted ? "tilted plane" : "z = 0");
    // A triangle of (near) zero area: no kernel, so not a valid panel.
    const PanelIssues issues = check({{0, 0}, {1, 0}, {2, 1e-12}}, tilted);
    EXPECT_FALSE(issues.valid());
  }
}

// check_panel decides star-shape and flips by a shortcut where the vertex average lies well
// inside every edge line: the same decisions as the kernel clipping it skips, on random
// polygons of every kind (convex, star-shaped, not star-shaped, clockwise, slivers, and
// sizes from far above the tolerance down to it, where the shortcut must step aside).
TEST(PanelCheck, ShortcutDecidesAsTheKernel) {
  SplitMix64 rng(23);
  const double tol = 1e-9;
  int shortcut = 0, clipped = 0;
  for (int t = 0; t < 20000; ++t) {
    const int k = 3 + static_cast<int>(rng.uniform() * 9);
    const double size = std::pow(10.0, -8.5 + 9.0 * rng.uniform());  // 3e-9 .. 3
    const double wobble = rng.uniform() < 0.5 ? 0.3 : 1.2;           // convex-ish or wild
    Outline outline;
    for (int i = 0; i < k; ++i) {
      const double angle = 2.0 * 3.14159265358979 * (i + wobble * (rng.uniform() - 0.5)) / k;
      const double radius = size * (1.0 + wobble * (rng.uniform() - 0.5));
      outline.push_back({radius * std::cos(angle), radius * std::sin(angle) * (t % 7 == 0 ? 1e-7 : 1.0)});
    }
    if (t % 5 == 0) outline = reversed(outline);
    const Placed p = place(outline, t % 2 == 1);
    const PanelIssues issues = check_panel(p.points, p.points, p.plane, 10.0, tol);
    // The decisions by the kernel, as check_panel made them before the shortcut.
    const PlaneFrame frame = make_plane_frame(p.plane.offset * p.plane.normal, p.plane.normal);
    std::vector<Vec2> polygon;
    for (const Vec3& q : p.points) polygon.push_back(frame.to_2d(q));
    const double area = signed_area(polygon);
    const std::vector<Vec2> kernel = area > 0.0 ? polygon_kernel(polygon, tol) : std::vector<Vec2>{};
    const Vec2 reference = kernel.empty() ? polygon_centroid(polygon) : polygon_centroid(kernel);
    ASSERT_EQ(issues.not_star, kernel.empty()) << "polygon " << t;
    ASSERT_EQ(issues.flipped, area <= 0.0 || has_flipped_edge(polygon, reference)) << "polygon " << t;
    (area > 0.0 && clearly_in_kernel(polygon, vertex_average(polygon), tol) ? shortcut : clipped) += 1;
  }
  // Both paths were taken often.
  EXPECT_GT(shortcut, 2000);
  EXPECT_GT(clipped, 2000);
}

}  // namespace
}  // namespace ff
