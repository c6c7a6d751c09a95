// Panels of different thickness (thick_panels.h, chamfers.h, parts_list.h): inner vertices on
// each panel's own offset plane, valence-3 nodes still one point, each edge's cut plane
// through the outer edge and the line where the two offset planes meet, and the bevels of
// the formula tan(b_p) = (t_q - t_p cos phi) / (t_p sin phi).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/fabricate/parts_list.h"
#include "core/fabricate/thick_panels.h"
#include "core/util/angles.h"
#include "core/util/error.h"
#include "polyhedra.h"

namespace ff {
namespace {

// The cube with panel 0 at 0.2 and the others at 0.1.
ThickOptions one_thick_face(size_t panels) {
  ThickOptions o;
  o.thickness = 0.1;
  o.panel_thickness.assign(panels, 0.1);
  o.panel_thickness[0] = 0.2;
  return o;
}

TEST(PanelThickness, CubeInnerCornersOnOwnOffsetPlanesAndShared) {
  const PanelMesh pm = testing::unit_cube();
  const ThickOptions o = one_thick_face(pm.panels.size());
  const PanelEdges edges = panel_edges(pm);
  const ThickPanels t = thicken_panels(pm, edges, o);
  EXPECT_EQ(t.straight_corners + t.projected_corners, 0);
  for (size_t p = 0; p < pm.panels.size(); ++p) {
    EXPECT_NEAR(t.offset_planes[p].offset, pm.plane_offsets[p] - o.panel_thickness[p], 1e-15);
    for (const Vec3& x : t.inner[p]) EXPECT_NEAR(t.offset_planes[p].distance(x), 0.0, 1e-12) << "panel " << p;
  }
  // Every node has three panels: their inner corners are one point, on all three planes.
  for (size_t v = 0; v < pm.vertices.size(); ++v) {
    std::vector<Vec3> at;
    std::vector<size_t> around;
    for (size_t p = 0; p < pm.panels.size(); ++p)
      for (size_t i = 0; i < pm.panels[p].size(); ++i)
        if (pm.panels[p][i] == static_cast<int>(v)) {
          at.push_back(t.inner[p][i]);
          around.push_back(p);
        }
    ASSERT_EQ(at.size(), 3u);
    EXPECT_EQ(at[0], at[1]);
    EXPECT_EQ(at[0], at[2]);
    for (const size_t p : around) EXPECT_NEAR(t.offset_planes[p].distance(at[0]), 0.0, 1e-12);
  }
  EXPECT_EQ(t.max_spread, 0.0);
}

TEST(PanelThickness, CutPlanesHoldTheOuterEdgeAndTheInnerLine) {
  const PanelMesh pm = testing::dodecahedron();
  ThickOptions o;
  o.thickness = 0.05;
  o.panel_thickness.assign(pm.panels.size(), 0.05);
  o.panel_thickness[0] = 0.12;
  o.panel_thickness[3] = 0.02;
  const PanelEdges edges = panel_edges(pm);
  const ThickPanels t = thicken_panels(pm, edges, o);
  int unequal = 0;
  for (size_t p = 0; p < pm.panels.size(); ++p) {
    const size_t k = pm.panels[p].size();
    for (size_t i = 0; i < k; ++i) {
      const int q = edges.neighbour[p][i];
      ASSERT_GE(q, 0);
      const Vec3& a = pm.vertices[static_cast<size_t>(pm.panels[p][i])];
      const Vec3& b = pm.vertices[static_cast<size_t>(pm.panels[p][(i + 1) % k])];
      const Vec3& ia = t.inner[p][i];
      const Vec3& ib = t.inner[p][(i + 1) % k];
      // The inner edge lies on both offset planes (the panels meet flush) ...
      EXPECT_NEAR(t.offset_planes[static_cast<size_t>(q)].distance(ia), 0.0, 1e-12);
      EXPECT_NEAR(t.offset_planes[static_cast<size_t>(q)].distance(ib), 0.0, 1e-12);
      // ... parallel to the outer edge, and the four points on one plane (the cut).
      const Vec3 e = (b - a).normalized();
      EXPECT_LT((ib - ia).normalized().cross(e).norm(), 1e-9);
      const Vec3 m = e.cross(ia - a).normalized();
      EXPECT_NEAR(m.dot(ib - a), 0.0, 1e-12);
      unequal += o.panel_thickness[p] != o.panel_thickness[static_cast<size_t>(q)];
    }
  }
  EXPECT_NE(std::find(edges.neighbour[0].begin(), edges.neighbour[0].end(), 3), edges.neighbour[0].end());
  EXPECT_EQ(unequal, 18);  // panels 0 and 3 share an edge: 5 + 5 - 1 edges, seen from both sides
}

// In the flat outline each inner edge is inset from its outer edge by t_p tan(bevel_p).
void expect_insets_match_bevels(const PartsList& list) {
  for (const PartRow& row : list.rows) {
    const PanelOutline& o = row.outline;
    const size_t k = o.outer.size();
    ASSERT_EQ(o.inner.size(), k);
    for (size_t i = 0; i < k; ++i) {
      const Vec2 a = o.outer[i], b = o.outer[(i + 1) % k];
      const Vec2 e = (b - a).normalized();
      const Vec2 left(-e.y(), e.x());  // inwards for a counter-clockwise outline
      const double expected = o.thickness * std::tan(o.edges[i].chamfer_deg / kDegreesPerRadian);
      EXPECT_NEAR((o.inner[i] - a).dot(left), expected, 1e-9) << o.label << " edge " << i;
      EXPECT_NEAR((o.inner[(i + 1) % k] - a).dot(left), expected, 1e-9) << o.label << " edge " << i;
    }
  }
}

TEST(PanelThickness, CubeBevelsFromTheFormula) {
  const PanelMesh pm = testing::unit_cube();
  FabricationOptions options;
  options.thickness = 0.1;
  options.panel_thickness = {{"P1", 0.2}};
  const PartsList list = make_parts_list(pm, options);
  EXPECT_TRUE(list.unmatched_labels.empty());
  EXPECT_EQ(list.rows[0].outline.thickness, 0.2);
  EXPECT_EQ(list.rows[1].outline.thickness, 0.1);
  for (const PartRow& row : list.rows)
    for (const OutlineEdge& e : row.outline.edges) {
      // phi = 90: tan b_p = t_q / t_p, so b = atan(1/2) on P1, atan(2) on its neighbours.
      const bool p1 = row.outline.label == "P1", q1 = e.neighbour == "P1";
      const double expected = p1 ? std::atan(0.5) * kDegreesPerRadian : q1 ? std::atan(2.0) * kDegreesPerRadian : 45.0;
      EXPECT_NEAR(e.chamfer_deg, expected, 1e-9) << row.outline.label << " / " << e.neighbour;
    }
  expect_insets_match_bevels(list);
}

TEST(PanelThickness, FormulaAgreesWithGeometryOnADodecahedron) {
  const PanelMesh pm = testing::dodecahedron();
  FabricationOptions options;
  options.thickness = 0.05;
  options.panel_thickness = {{"P1", 0.12}, {"P4", 0.02}};
  const PartsList list = make_parts_list(pm, options);
  expect_insets_match_bevels(list);
  // The two bevels of an edge add up to the angle between the panels.
  const double phi = 180.0 - std::acos(-1.0 / std::sqrt(5.0)) * kDegreesPerRadian;
  for (const PartRow& row : list.rows)
    for (const OutlineEdge& e : row.outline.edges)
      for (const PartRow& other : list.rows) {
        if (other.outline.label != e.neighbour) continue;
        for (const OutlineEdge& back : other.outline.edges) {
          if (back.neighbour == row.outline.label) {
            EXPECT_NEAR(e.chamfer_deg + back.chamfer_deg, phi, 1e-9);
          }
        }
      }
  EXPECT_NEAR(unequal_chamfer_deg(phi, 0.05, 0.05), phi / 2, 1e-12);
}

TEST(PanelThickness, UniformOverridesChangeNothing) {
  const PanelMesh pm = testing::dodecahedron();
  FabricationOptions plain;
  plain.thickness = 0.05;
  FabricationOptions same = plain;
  same.panel_thickness = {{"P2", 0.05}};
  const PartsList a = make_parts_list(pm, plain), b = make_parts_list(pm, same);
  EXPECT_EQ(parts_list_csv(a), parts_list_csv(b));
}

TEST(PanelThickness, LabelsAndErrors) {
  const PanelMesh pm = testing::unit_cube();
  FabricationOptions options;
  options.thickness = 0.1;
  options.panel_thickness = {{"P9", 0.2}, {"P2", 0.3}};
  const PartsList list = make_parts_list(pm, options);
  ASSERT_EQ(list.unmatched_labels.size(), 1u);
  EXPECT_EQ(list.unmatched_labels[0], "P9");
  EXPECT_EQ(list.rows[1].outline.thickness, 0.3);
  options.panel_thickness = {{"P2", -1.0}};
  EXPECT_THROW(make_parts_list(pm, options), InputError);
  options.thickness = 0.0;
  options.panel_thickness = {{"P2", 0.1}};
  EXPECT_THROW(make_parts_list(pm, options), InputError);
  ThickOptions t;
  t.thickness = 0.1;
  t.panel_thickness = {0.1, 0.1};  // not one per panel
  EXPECT_THROW(thicken_panels(pm, panel_edges(pm), t), InputError);
}

}  // namespace
}  // namespace ff
