// Panels as files and display triangles: used vertices only, triangulation in each panel's
// own plane (concave panels too), the OBJ comment, the basic parts list, example shapes.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "core/fabricate/parts_list.h"
#include "core/mesh/topology.h"
#include "core/panels/panel_export.h"
#include "core/shapes/example_shapes.h"
#include "core/util/error.h"

namespace ff {
namespace {

// An L-shaped (concave) hexagon of area 3 in the plane z = 1, and a unit square in x = 5,
// with an unused vertex between them.
PanelMesh two_panels() {
  PanelMesh pm;
  pm.vertices = {{0, 0, 1}, {2, 0, 1}, {2, 1, 1}, {1, 1, 1}, {1, 2, 1}, {0, 2, 1}, {9, 9, 9},  // unused
                 {5, 0, 0}, {5, 1, 0}, {5, 1, 1}, {5, 0, 1}};
  pm.panels = {{0, 1, 2, 3, 4, 5}, {7, 8, 9, 10}};
  pm.plane_normals = {Vec3(0, 0, 1), Vec3(1, 0, 0)};
  pm.plane_offsets = {1.0, 5.0};
  return pm;
}

TEST(PanelExport, UsedVerticesOnlyKeepsOrderAndDropsTheRest) {
  const PolygonMesh m = used_vertices_only(two_panels());
  ASSERT_EQ(m.vertices.size(), 10u);
  EXPECT_EQ(m.vertices[6], Vec3(5, 0, 0));
  EXPECT_EQ(m.faces[1], (std::vector<int>{6, 7, 8, 9}));
}

TEST(PanelExport, TrianglesCoverEachPanelWithItsOrientation) {
  const PanelMesh pm = two_panels();
  const PanelTriangles t = triangulate_panels(pm);
  ASSERT_EQ(t.triangles.size(), 4u + 2u);
  double area[2] = {0, 0};
  for (size_t i = 0; i < t.triangles.size(); ++i) {
    const auto& tri = t.triangles[i];
    const Vec3 n = (pm.vertices[tri[1]] - pm.vertices[tri[0]]).cross(pm.vertices[tri[2]] - pm.vertices[tri[0]]);
    const int p = t.panel[i];
    EXPECT_GT(n.dot(pm.plane_normals[p]), 0.0) << "triangle " << i << " faces away from its panel";
    area[p] += 0.5 * n.norm();
  }
  EXPECT_NEAR(area[0], 3.0, 1e-12);  // the concave L: ear clipping, not a fan
  EXPECT_NEAR(area[1], 1.0, 1e-12);
}

TEST(PanelExport, ObjHasCommentUsedVerticesAndPanels) {
  const std::string comment = panels_obj_comment("roof.off", 2, 3, 10, 42, 0);
  EXPECT_EQ(comment.rfind("flatfacet ", 0), 0u);
  EXPECT_NE(comment.find("input: roof.off"), std::string::npos);
  EXPECT_NE(comment.find("panels: 2 (requested 3), vertices: 10, seed: 42, invalid panels: 0"), std::string::npos);
  const std::string obj = panels_obj(two_panels(), comment);
  EXPECT_NE(obj.find("# input: roof.off\n"), std::string::npos);
  EXPECT_NE(obj.find("\nf 1 2 3 4 5 6\nf 7 8 9 10\n"), std::string::npos);
  EXPECT_EQ(obj.find("9 9 9"), std::string::npos);
}

TEST(PartsList, RowsAndTotals) {
  const std::vector<PanelPart> parts = panel_parts(two_panels());
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0].label, "P1");
  EXPECT_EQ(parts[0].sides, 6);
  EXPECT_NEAR(parts[0].area, 3.0, 1e-12);
  EXPECT_NEAR(parts[0].perimeter, 8.0, 1e-12);
  EXPECT_NEAR(parts[1].area, 1.0, 1e-12);
  EXPECT_EQ(parts[1].normal, Vec3(1, 0, 0));
  EXPECT_EQ(parts[1].offset, 5.0);
  const std::string csv = parts_list_csv(two_panels());
  EXPECT_EQ(csv.rfind("panel,label,sides,area,perimeter,normal_x,normal_y,normal_z,offset\n0,P1,6,3,8,0,0,1,1\n", 0),
            0u);
  EXPECT_NE(csv.find("\n,total,,4,12,,,,\n"), std::string::npos);
}

TEST(ExampleShapes, EveryNameBuildsAValidSurfaceNearTheCount) {
  for (const std::string& name : example_shape_names()) {
    const TriMesh m = make_example_shape(name, 4000);
    EXPECT_GT(m.num_faces(), 3000) << name;
    EXPECT_LT(m.num_faces(), 5500) << name;
    EXPECT_NO_THROW(build_topology(m)) << name;
  }
  EXPECT_THROW(make_example_shape("cathedral", 4000), InputError);
  EXPECT_THROW(make_example_shape("saddle", 10), InputError);
  EXPECT_THROW(make_example_shape("saddle", 5'000'000), InputError);
}

}  // namespace
}  // namespace ff
