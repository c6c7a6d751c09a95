// Chamfer angles (chamfers.h) on analytic cases: half the angle between the panels' normals.
#include <gtest/gtest.h>

#include <cmath>

#include "core/fabricate/chamfers.h"
#include "core/util/angles.h"
#include "polyhedra.h"

namespace ff {
namespace {

void expect_all_edges(const PanelMesh& pm, double dihedral, double chamfer) {
  const auto chamfers = edge_chamfers(pm, panel_edges(pm));
  for (size_t p = 0; p < chamfers.size(); ++p)
    for (const EdgeChamfer& c : chamfers[p]) {
      ASSERT_GE(c.neighbour, 0);
      EXPECT_TRUE(c.convex);
      EXPECT_NEAR(c.dihedral_deg, dihedral, 1e-9);
      EXPECT_NEAR(c.chamfer_deg, chamfer, 1e-9);
    }
}

TEST(Chamfers, CubeEdgesAre45) { expect_all_edges(testing::unit_cube(), 90.0, 45.0); }

TEST(Chamfers, DodecahedronEdges) {
  const double dihedral = std::acos(-1.0 / std::sqrt(5.0)) * kDegreesPerRadian;  // 116.565 deg
  EXPECT_NEAR(dihedral, 116.565, 1e-3);
  expect_all_edges(testing::dodecahedron(), dihedral, (180.0 - dihedral) / 2);  // 31.717
}

TEST(Chamfers, TriangularPrismSidesAndCaps) {
  const PanelMesh pm = testing::triangular_prism();
  const auto chamfers = edge_chamfers(pm, panel_edges(pm));
  int side_side = 0, side_cap = 0;
  for (size_t p = 0; p < chamfers.size(); ++p)
    for (const EdgeChamfer& c : chamfers[p]) {
      const bool cap = std::abs(pm.plane_normals[p].z()) > 0.5 ||
                       std::abs(pm.plane_normals[static_cast<size_t>(c.neighbour)].z()) > 0.5;
      EXPECT_NEAR(c.dihedral_deg, cap ? 90.0 : 60.0, 1e-9);
      EXPECT_NEAR(c.chamfer_deg, cap ? 45.0 : 60.0, 1e-9);
      ++(cap ? side_cap : side_side);
    }
  EXPECT_EQ(side_side, 6);  // each of 3 edges seen from both sides
  EXPECT_EQ(side_cap, 12);
}

TEST(Chamfers, ValleysAreConcaveAndBoundariesSquare) {
  // A V-shaped open strip: two panels folded 90 deg along x = 0, normals up-ish (a valley).
  PanelMesh pm;
  pm.vertices = {{-1, 0, 1}, {0, 0, 0}, {0, 1, 0}, {-1, 1, 1}, {1, 0, 1}, {1, 1, 1}};
  pm.panels = {{0, 1, 2, 3}, {1, 4, 5, 2}};
  const double s = std::sqrt(0.5);
  pm.plane_normals = {Vec3(s, 0, s), Vec3(-s, 0, s)};
  pm.plane_offsets = {0.0, 0.0};
  const auto chamfers = edge_chamfers(pm, panel_edges(pm));
  EXPECT_EQ(chamfers[0][1].neighbour, 1);
  EXPECT_FALSE(chamfers[0][1].convex);
  EXPECT_NEAR(chamfers[0][1].dihedral_deg, 270.0, 1e-9);
  EXPECT_NEAR(chamfers[0][1].chamfer_deg, 45.0, 1e-9);
  EXPECT_FALSE(chamfers[1][3].convex);
  EXPECT_EQ(chamfers[0][0].neighbour, -1);
  EXPECT_EQ(chamfers[0][0].chamfer_deg, 0.0);
}

TEST(Chamfers, CoplanarNeighboursGetASquareCut) {
  const EdgeChamfer c = chamfer_between(Vec3::UnitZ(), Vec3::UnitZ(), Vec3::UnitX());
  EXPECT_EQ(c.chamfer_deg, 0.0);
  EXPECT_EQ(c.dihedral_deg, 180.0);
}

}  // namespace
}  // namespace ff
