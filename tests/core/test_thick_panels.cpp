// Thick panels (thick_panels.h): inner vertices on the offset planes, shared exactly at
// valence-3 nodes, the spread at 4+ nodes, square cuts on the boundary, no blow-up where
// neighbours are coplanar.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/fabricate/thick_panels.h"
#include "core/remesher.h"
#include "core/shapes/shapes.h"
#include "core/util/error.h"
#include "polyhedra.h"

namespace ff {
namespace {

void expect_on_offset_planes(const PanelMesh& pm, const ThickPanels& t) {
  for (size_t p = 0; p < pm.panels.size(); ++p) {
    ASSERT_EQ(t.inner[p].size(), pm.panels[p].size());
    for (const Vec3& x : t.inner[p]) EXPECT_NEAR(t.offset_planes[p].distance(x), 0.0, 1e-9) << "panel " << p;
    const double shift = t.side == MaterialSide::Inside ? -t.thickness : t.thickness;
    EXPECT_NEAR(t.offset_planes[p].offset, pm.plane_offsets[p] + shift, 1e-15);
  }
}

// Every inner vertex of every panel at vertex v is bit-identical.
void expect_shared(const PanelMesh& pm, const ThickPanels& t) {
  std::vector<std::vector<Vec3>> at(pm.vertices.size());
  for (size_t p = 0; p < pm.panels.size(); ++p)
    for (size_t i = 0; i < pm.panels[p].size(); ++i) at[static_cast<size_t>(pm.panels[p][i])].push_back(t.inner[p][i]);
  for (const auto& points : at) {
    ASSERT_EQ(points.size(), 3u);
    EXPECT_EQ(points[0], points[1]);
    EXPECT_EQ(points[0], points[2]);
  }
  EXPECT_EQ(t.max_spread, 0.0);
}

TEST(ThickPanels, CubeInsideShrinksEveryCornerByT) {
  const PanelMesh pm = testing::unit_cube();
  const ThickPanels t = thicken_panels(pm, panel_edges(pm), 0.1);
  expect_on_offset_planes(pm, t);
  expect_shared(pm, t);
  for (size_t p = 0; p < pm.panels.size(); ++p)
    for (size_t i = 0; i < pm.panels[p].size(); ++i) {
      const Vec3 expected = pm.vertices[static_cast<size_t>(pm.panels[p][i])].array() * 0.8 + 0.1;
      EXPECT_LT((t.inner[p][i] - expected).norm(), 1e-12);
    }
  EXPECT_EQ(t.straight_corners + t.projected_corners, 0);
}

TEST(ThickPanels, CubeOutsideGrows) {
  const PanelMesh pm = testing::unit_cube();
  const ThickPanels t = thicken_panels(pm, panel_edges(pm), 0.25, MaterialSide::Outside);
  expect_on_offset_planes(pm, t);
  expect_shared(pm, t);
  EXPECT_LT((t.inner[0][0] - (pm.vertices[static_cast<size_t>(pm.panels[0][0])].array() * 1.5 - 0.25).matrix()).norm(),
            1e-12);
}

TEST(ThickPanels, DodecahedronInnerFacesAreScaledFaces) {
  const PanelMesh pm = testing::dodecahedron();
  const double t = 0.05, inradius = pm.plane_offsets[0];
  const ThickPanels thick = thicken_panels(pm, panel_edges(pm), t);
  expect_on_offset_planes(pm, thick);
  expect_shared(pm, thick);
  const double scale = (inradius - t) / inradius;  // the inner solid is a smaller dodecahedron
  for (size_t p = 0; p < pm.panels.size(); ++p)
    for (size_t i = 0; i < pm.panels[p].size(); ++i)
      EXPECT_LT((thick.inner[p][i] - scale * pm.vertices[static_cast<size_t>(pm.panels[p][i])]).norm(), 1e-12);
}

// An irregular pyramid: four panels meet at the apex, whose offset planes miss one point.
PanelMesh pyramid() {
  std::vector<Vec3> v = {{0, 0, 0}, {2, 0, 0}, {2.5, 1.5, 0}, {-0.5, 1, 0}, {0.7, 0.4, 1.2}};
  PanelMesh pm;
  pm.vertices = v;
  pm.panels = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}, {0, 3, 2, 1}};
  for (const auto& f : pm.panels) {
    const Vec3 n = (v[static_cast<size_t>(f[1])] - v[static_cast<size_t>(f[0])])
                       .cross(v[static_cast<size_t>(f[2])] - v[static_cast<size_t>(f[0])])
                       .normalized();
    pm.plane_normals.push_back(n);
    pm.plane_offsets.push_back(n.dot(v[static_cast<size_t>(f[0])]));
  }
  return pm;
}

TEST(ThickPanels, FourPanelNodeHasASpreadAndEdgesStayFlush) {
  const PanelMesh pm = pyramid();
  const PanelEdges edges = panel_edges(pm);
  const ThickPanels t = thicken_panels(pm, edges, 0.05);
  expect_on_offset_planes(pm, t);
  EXPECT_GT(t.node_spread[4], 1e-4);
  EXPECT_EQ(t.max_spread, t.node_spread[4]);
  for (int v = 0; v < 4; ++v) EXPECT_EQ(t.node_spread[static_cast<size_t>(v)], 0.0);  // valence 3
  // Each side panel's apex lies on its two edge neighbours' offset planes too.
  for (size_t p = 0; p < 4; ++p) {
    EXPECT_NEAR(t.offset_planes[static_cast<size_t>(edges.neighbour[p][1])].distance(t.inner[p][2]), 0.0, 1e-12);
    EXPECT_NEAR(t.offset_planes[static_cast<size_t>(edges.neighbour[p][2])].distance(t.inner[p][2]), 0.0, 1e-12);
  }
}

TEST(ThickPanels, BoundaryEdgesAreCutSquare) {
  // A roof: two panels folded along y = 0.5, open all round.
  PanelMesh pm;
  pm.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 0.5, 0.3}, {0, 0.5, 0.3}, {1, 1, 0}, {0, 1, 0}};
  pm.panels = {{0, 1, 2, 3}, {3, 2, 4, 5}};
  pm.plane_normals = {Vec3(0, -0.3, 0.5).normalized(), Vec3(0, 0.3, 0.5).normalized()};
  pm.plane_offsets = {0.0, pm.plane_normals[1].dot(pm.vertices[4])};
  const ThickPanels t = thicken_panels(pm, panel_edges(pm), 0.02);
  expect_on_offset_planes(pm, t);
  // Corner 0 of panel 0 sits on both boundary edges' square cuts: straight below the corner.
  EXPECT_LT((t.inner[0][0] - (pm.vertices[0] - 0.02 * pm.plane_normals[0])).norm(), 1e-12);
  // The ridge end: on the square cut of x = 1 (so x stays 1) and on both offset planes.
  EXPECT_NEAR(t.inner[0][2].x(), 1.0, 1e-12);
  EXPECT_NEAR(t.offset_planes[1].distance(t.inner[0][2]), 0.0, 1e-12);
  EXPECT_LT((t.inner[0][2] - t.inner[1][1]).norm(), 1e-12);  // the same three planes
}

TEST(ThickPanels, CoplanarNeighboursAndStraightCornersDoNotBlowUp) {
  // A flat 2 x 1 sheet in two coplanar panels, the second with a corner halfway along an edge.
  PanelMesh pm;
  pm.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}, {1.5, 1, 0}};
  pm.panels = {{0, 1, 2, 3}, {1, 4, 5, 6, 2}};
  pm.plane_normals = {Vec3::UnitZ(), Vec3::UnitZ()};
  pm.plane_offsets = {0.0, 0.0};
  const ThickPanels t = thicken_panels(pm, panel_edges(pm), 0.01);
  expect_on_offset_planes(pm, t);
  for (size_t p = 0; p < 2; ++p)
    for (size_t i = 0; i < pm.panels[p].size(); ++i)
      EXPECT_LT((t.inner[p][i] - (pm.vertices[static_cast<size_t>(pm.panels[p][i])] - Vec3(0, 0, 0.01))).norm(), 1e-12);
  EXPECT_EQ(t.straight_corners, 1);  // (1.5, 1): both edges on y = 1
  EXPECT_EQ(t.corner_fallback[1][3], 1);
  EXPECT_EQ(t.projected_corners, 0);
}

TEST(ThickPanels, RejectsNonPositiveThickness) {
  const PanelMesh pm = testing::unit_cube();
  EXPECT_THROW(thicken_panels(pm, panel_edges(pm), 0.0), InputError);
  EXPECT_THROW(thicken_panels(pm, panel_edges(pm), -1.0), InputError);
  EXPECT_THROW(thicken_panels(pm, panel_edges(pm), std::nan("")), InputError);
}

// A remeshed roof (open: boundary panels, valence-3 nodes inside): every inner vertex on its
// offset plane, valence-3 interior nodes shared exactly and with no spread.
TEST(ThickPanels, RemeshedRoof) {
  RemeshParams params;
  params.panels = 25;
  Remesher r(make_roof(40, 30), params);
  r.run();
  const PanelMesh& pm = r.panels();
  ASSERT_GT(pm.num_panels(), 0);
  const PanelEdges edges = panel_edges(pm);
  const ThickPanels t = thicken_panels(pm, edges, 0.02);
  expect_on_offset_planes(pm, t);
  EXPECT_EQ(t.projected_corners, 0);
  int shared = 0;
  for (size_t v = 0; v < pm.vertices.size(); ++v) {
    const std::vector<int>& around = edges.vertex_panels[v];
    bool interior = around.size() == 3;
    std::vector<Vec3> points;
    for (const int p : around) {
      const std::vector<int>& poly = pm.panels[static_cast<size_t>(p)];
      const size_t i = static_cast<size_t>(std::find(poly.begin(), poly.end(), static_cast<int>(v)) - poly.begin());
      const size_t k = poly.size();
      interior = interior && edges.neighbour[static_cast<size_t>(p)][i] >= 0 &&
                 edges.neighbour[static_cast<size_t>(p)][(i + k - 1) % k] >= 0;
      points.push_back(t.inner[static_cast<size_t>(p)][i]);
    }
    if (!interior) continue;
    ++shared;
    EXPECT_EQ(points[0], points[1]);
    EXPECT_EQ(points[0], points[2]);
    EXPECT_EQ(t.node_spread[v], 0.0);
  }
  EXPECT_GT(shared, 10);
}

}  // namespace
}  // namespace ff
