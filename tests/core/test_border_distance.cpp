// border_distance (core/density/border_distance.h): the distance to the border that density
// expressions read as `border`. Exact on a flat grid, 0 on every boundary loop (an opening's
// too), infinite on a closed surface, and a distance: on a roof with an opening, the straight
// distance to the nearest boundary edge to rounding, and never changing by more than an
// edge's length across one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/density/border_distance.h"
#include "core/density/density_field.h"
#include "core/shapes/hard_cases.h"
#include "core/shapes/shapes.h"

namespace ff {
namespace {

TEST(BorderDistance, OnAGridItIsTheDistanceToTheNearestSide) {
  const TriMesh mesh = make_plane(30, 20, 1.5, 1.0);
  const std::vector<double> d = border_distance(mesh, build_topology(mesh));
  ASSERT_EQ(d.size(), mesh.positions.size());
  for (size_t v = 0; v < d.size(); ++v) {
    const Vec3& p = mesh.positions[v];
    const double side = std::min({p.x(), 1.5 - p.x(), p.y(), 1.0 - p.y()});
    EXPECT_NEAR(d[v], side, 1e-12) << "vertex " << v << " at (" << p.x() << ", " << p.y() << ")";
  }
}

TEST(BorderDistance, ClosedSurfacesHaveNoBorderToReach) {
  const TriMesh torus = make_torus(2000);
  for (double x : border_distance(torus, build_topology(torus))) EXPECT_EQ(x, std::numeric_limits<double>::infinity());
  // The density expression sees 1 there: as far as the model is big.
  const std::vector<double> density =
      expression_density(torus, build_topology(torus), Expression::parse("1 + border"), nullptr);
  for (double x : density) EXPECT_EQ(x, 2.0);
}

TEST(BorderDistance, AClosedPartStaysUnreachedBesideAnOpenOne) {
  TriMesh mesh = make_plane(10, 10, 1.0, 1.0);
  const int offset = static_cast<int>(mesh.positions.size());
  const TriMesh torus = make_torus(600);
  for (const Vec3& p : torus.positions) mesh.positions.push_back(p + Vec3(30.0, 0.0, 0.0));
  for (const Triangle& t : torus.triangles) mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  const std::vector<double> d = border_distance(mesh, build_topology(mesh));
  for (size_t v = 0; v < d.size(); ++v) {
    if (static_cast<int>(v) < offset)
      EXPECT_TRUE(std::isfinite(d[v]) && d[v] <= 0.5) << v;
    else
      EXPECT_EQ(d[v], std::numeric_limits<double>::infinity()) << v;
  }
}

TEST(BorderDistance, AnOpeningIsBorderTooAndDistancesAreConsistent) {
  const TriMesh roof = make_roof_with_hole(4000);
  const MeshTopology topology = build_topology(roof);
  const std::vector<double> d = border_distance(roof, topology);
  std::vector<std::array<Vec3, 2>> border;  // the boundary edges' segments
  for (int e = 0; e < topology.num_edges(); ++e) {
    if (!topology.is_boundary_edge(e)) continue;
    const std::array<int, 2>& ends = topology.edge_vertices[static_cast<size_t>(e)];
    for (int v : ends) EXPECT_EQ(d[static_cast<size_t>(v)], 0.0);
    border.push_back({roof.positions[static_cast<size_t>(ends[0])], roof.positions[static_cast<size_t>(ends[1])]});
  }
  ASSERT_FALSE(border.empty());
  const auto to_segment = [](const Vec3& p, const std::array<Vec3, 2>& s) {
    const Vec3 ab = s[1] - s[0];
    const double t = std::clamp((p - s[0]).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return (p - (s[0] + t * ab)).norm();
  };
  // The hole's rim (near the centre of the plan) is border: vertices next to it are close.
  double near_hole = std::numeric_limits<double>::infinity(), worst_ratio = 1.0;
  for (size_t v = 0; v < d.size(); ++v) {
    ASSERT_TRUE(std::isfinite(d[v])) << v;
    double straight = std::numeric_limits<double>::infinity();
    for (const auto& segment : border) straight = std::min(straight, to_segment(roof.positions[v], segment));
    EXPECT_GE(d[v], straight - 1e-12) << "shorter than the straight line, vertex " << v;
    worst_ratio = std::max(worst_ratio, d[v] / std::max(straight, 1e-300));
    EXPECT_LE(d[v], straight * (1 + 1e-12)) << "longer than the straight line, vertex " << v;
    if (std::hypot(roof.positions[v].x(), roof.positions[v].y()) < 6.0) near_hole = std::min(near_hole, d[v]);
  }
  EXPECT_EQ(near_hole, 0.0);
  std::printf("[ border  ] distance over the straight distance to the border: at most %.4f\n", worst_ratio);
  for (const std::array<int, 2>& e : topology.edge_vertices) {
    const double length =
        (roof.positions[static_cast<size_t>(e[0])] - roof.positions[static_cast<size_t>(e[1])]).norm();
    EXPECT_LE(std::abs(d[static_cast<size_t>(e[0])] - d[static_cast<size_t>(e[1])]), length * (1 + 1e-12));
  }
}

TEST(BorderDistance, TheExpressionReadsItOverTheDiagonal) {
  const TriMesh mesh = make_plane(12, 12, 3.0, 4.0);  // diagonal 5
  const std::vector<double> density =
      expression_density(mesh, build_topology(mesh), Expression::parse("1 + border"), nullptr);
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec3& p = mesh.positions[v];
    const double side = std::min({p.x(), 3.0 - p.x(), p.y(), 4.0 - p.y()});
    EXPECT_NEAR(density[v], 1.0 + side / 5.0, 1e-12);
  }
}

}  // namespace
}  // namespace ff
