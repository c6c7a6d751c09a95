// Boundary edge cuts (chamfers.h BoundaryCut, thick_panels.h): square by default, a bevel
// from square, or plumb (holding the up axis).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "core/fabricate/parts_list.h"
#include "core/fabricate/thick_panels.h"
#include "core/util/angles.h"

namespace ff {
namespace {

// One square panel of side 1 in the plane z = slope * x (normal up-ish), all edges boundary.
PanelMesh tilted_square(double slope) {
  PanelMesh pm;
  pm.vertices = {{0, 0, 0}, {1, 0, slope}, {1, 1, slope}, {0, 1, 0}};
  pm.panels = {{0, 1, 2, 3}};
  const Vec3 n = Vec3(-slope, 0, 1).normalized();
  pm.plane_normals = {n};
  pm.plane_offsets = {0.0};
  return pm;
}

TEST(BoundaryCut, BevelInsetsTheInnerFace) {
  const PanelMesh pm = tilted_square(0.0);
  for (const double bevel : {0.0, 20.0, -15.0}) {
    FabricationOptions o;
    o.thickness = 0.1;
    o.boundary.kind = bevel == 0.0 ? BoundaryCut::Kind::Square : BoundaryCut::Kind::Bevel;
    o.boundary.bevel_deg = bevel;
    const PartsList list = make_parts_list(pm, o);
    const PanelOutline& out = list.rows[0].outline;
    const double inset = 0.1 * std::tan(bevel / kDegreesPerRadian);
    // The inner face is the square shrunk by the inset on every side.
    double area = 0.0;
    for (size_t i = 0; i < 4; ++i) {
      const Vec2 a = out.inner[i], b = out.inner[(i + 1) % 4];
      area += a.x() * b.y() - a.y() * b.x();
      EXPECT_NEAR(out.edges[i].chamfer_deg, bevel, 1e-9);
    }
    EXPECT_NEAR(0.5 * area, (1 - 2 * inset) * (1 - 2 * inset), 1e-12) << bevel;
  }
}

TEST(BoundaryCut, PlumbCutsHoldTheUpAxis) {
  const PanelMesh pm = tilted_square(0.5);
  ThickOptions o;
  o.thickness = 0.1;
  o.boundary.kind = BoundaryCut::Kind::Plumb;
  const ThickPanels t = thicken_panels(pm, panel_edges(pm), o);
  const std::vector<int>& poly = pm.panels[0];
  for (size_t i = 0; i < 4; ++i) {
    const Vec3& a = pm.vertices[static_cast<size_t>(poly[i])];
    const Vec3& b = pm.vertices[static_cast<size_t>(poly[(i + 1) % 4])];
    const Vec3 m = (b - a).cross(Vec3::UnitZ()).normalized();  // the plumb plane's normal
    EXPECT_NEAR(m.dot(t.inner[0][i] - a), 0.0, 1e-12) << "edge " << i;
    EXPECT_NEAR(m.dot(t.inner[0][(i + 1) % 4] - a), 0.0, 1e-12) << "edge " << i;
    EXPECT_NEAR(t.offset_planes[0].distance(t.inner[0][i]), 0.0, 1e-12);
  }
  // The inner corners sit straight below the outer ones: the panel's edges all hold
  // vertical planes, so each corner's two cut planes meet in the vertical through it.
  for (size_t i = 0; i < 4; ++i) {
    const Vec3 d = t.inner[0][i] - pm.vertices[static_cast<size_t>(poly[i])];
    EXPECT_NEAR(d.x(), 0.0, 1e-12);
    EXPECT_NEAR(d.y(), 0.0, 1e-12);
    EXPECT_NEAR(d.z(), -0.1 * std::sqrt(1.25), 1e-12);  // t / cos(tilt)
  }
  // Bevels: the sloping edges (along x) are square already (their square cut holds both the
  // normal and up), the level ones (along y) lean by the tilt.
  const double tilt = std::atan(0.5) * kDegreesPerRadian;
  const Vec3& n = pm.plane_normals[0];
  EXPECT_NEAR(boundary_bevel_deg(n, Vec3(1, 0, 0.5).normalized(), o.boundary, o.side), 0.0, 1e-9);
  EXPECT_NEAR(std::abs(boundary_bevel_deg(n, Vec3(0, 1, 0), o.boundary, o.side)), tilt, 1e-9);
}

TEST(BoundaryCut, PlumbFallsBackToSquareNearThePanelsPlane) {
  const PanelMesh pm = tilted_square(20.0);  // nearly vertical panel, z up lies almost in it
  BoundaryCut cut;
  cut.kind = BoundaryCut::Kind::Plumb;
  const Vec3& n = pm.plane_normals[0];
  EXPECT_NEAR(boundary_bevel_deg(n, Vec3(0, 1, 0), cut, MaterialSide::Inside), 0.0, 1e-12);
  ThickOptions o;
  o.thickness = 0.1;
  o.boundary = cut;
  const ThickPanels t = thicken_panels(pm, panel_edges(pm), o);
  EXPECT_EQ(t.projected_corners, 0);
  for (const Vec3& x : t.inner[0]) EXPECT_TRUE(x.allFinite());
}

TEST(BoundaryCut, SquareIsTheDefaultBitForBit) {
  const PanelMesh pm = tilted_square(0.3);
  FabricationOptions a;
  a.thickness = 0.1;
  FabricationOptions b = a;
  b.boundary.kind = BoundaryCut::Kind::Bevel;
  b.boundary.bevel_deg = 0.0;
  const PartsList la = make_parts_list(pm, a), lb = make_parts_list(pm, b);
  for (size_t i = 0; i < 4; ++i) EXPECT_NEAR((la.rows[0].outline.inner[i] - lb.rows[0].outline.inner[i]).norm(), 0.0, 1e-15);
}

}  // namespace
}  // namespace ff
