// PolyMesh (mesh/poly_mesh.h): the file's polygons recovered from the reader's triangles,
// the fallback to triangles when a group is no disk, triangulation and normals.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "core/mesh/clean.h"
#include "core/mesh/mesh_io.h"
#include "core/mesh/poly_mesh.h"
#include "core/prepare/subdivision.h"
#include "subdivision_shapes.h"

namespace ff {
namespace {

// The control polygons of a file, as the CLI builds them: read, clean, merge.
PolyMesh polygons_of(const std::string& data, const std::string& name) {
  const RawMesh raw = read_mesh(data, name);
  const CleanMesh clean = clean_mesh(raw.mesh);
  std::vector<int> polygon;
  for (const int source : clean.face_source) polygon.push_back(raw.source_polygon[static_cast<size_t>(source)]);
  return merge_polygons(clean.mesh, polygon);
}

// Face f's corner positions, rotated to start at the smallest (x, y, z).
std::vector<Vec3> loop_positions(const PolyMesh& m, int f) {
  std::vector<Vec3> p;
  for (int i = 0; i < m.face_size(f); ++i) p.push_back(m.positions[static_cast<size_t>(m.corner(f, i))]);
  const auto less = [](const Vec3& a, const Vec3& b) { return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3); };
  std::rotate(p.begin(), std::min_element(p.begin(), p.end(), less), p.end());
  return p;
}

TEST(PolyMesh, RecoversTheFilePolygonsOfAnObj) {
  // An L-shaped (non-convex) hexagon, a quad and a triangle sharing edges, in one plane.
  const std::string obj =
      "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nv 3 0 0\nv 3 1 0\nv 3 2 0\n"
      "f 1 2 3 4 5 6\nf 2 7 8 3\nf 3 8 9\n";
  const PolyMesh m = polygons_of(obj, "l.obj");
  ASSERT_EQ(m.num_faces(), 3);
  EXPECT_FALSE(m.all_triangles());
  const std::vector<std::vector<Vec3>> expected = {
      {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(1, 1, 0), Vec3(1, 2, 0), Vec3(0, 2, 0)},
      {Vec3(2, 0, 0), Vec3(3, 0, 0), Vec3(3, 1, 0), Vec3(2, 1, 0)},
      {Vec3(2, 1, 0), Vec3(3, 1, 0), Vec3(3, 2, 0)}};
  for (int f = 0; f < 3; ++f) EXPECT_EQ(loop_positions(m, f), expected[static_cast<size_t>(f)]) << "face " << f;
  EXPECT_EQ(polygon_normal(m, 0), Vec3(0, 0, 1));
}

TEST(PolyMesh, RecoversAClosedPrismFromOffAndSubdividesItLikeTheOriginal) {
  const PolyMesh prism = test::pentagonal_prism();
  std::string off = "OFF\n10 7 0\n";
  for (const Vec3& p : prism.positions)
    off += std::to_string(p.x()) + " " + std::to_string(p.y()) + " " + std::to_string(p.z()) + "\n";
  for (int f = 0; f < prism.num_faces(); ++f) {
    off += std::to_string(prism.face_size(f));
    for (int i = 0; i < prism.face_size(f); ++i) off += " " + std::to_string(prism.corner(f, i));
    off += "\n";
  }
  const PolyMesh m = polygons_of(off, "prism.off");
  ASSERT_EQ(m.num_faces(), 7);
  std::vector<int> sizes;
  for (int f = 0; f < m.num_faces(); ++f) sizes.push_back(m.face_size(f));
  EXPECT_EQ(sizes, (std::vector<int>{5, 5, 4, 4, 4, 4, 4}));
  const TriMesh fine = catmull_clark(m, 2);
  EXPECT_EQ(fine.num_faces(), 2 * 4 * 30);
  EXPECT_GT(test::signed_volume(fine), 0.0);  // outward, like the file
}

TEST(PolyMesh, KeepsTrianglesWhenAGroupIsNoDisk) {
  TriMesh m;
  // A fan of four triangles around an inner vertex (4), then two triangles touching at a vertex.
  m.positions = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 2, 0), Vec3(0, 2, 0), Vec3(1, 1, 0),
                 Vec3(3, 2, 0), Vec3(3, 3, 0), Vec3(3, 1, 0)};
  m.triangles = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}, {2, 5, 6}, {2, 7, 5}};
  const PolyMesh fan = merge_polygons(m, {0, 0, 0, 0, 1, 1});
  EXPECT_EQ(fan.num_faces(), 5);  // the fan stays 4 triangles; the last two merge into a quad
  EXPECT_EQ(fan.face_size(4), 4);
  const std::vector<int> kite = {fan.corner(4, 0), fan.corner(4, 1), fan.corner(4, 2), fan.corner(4, 3)};
  EXPECT_EQ(kite, (std::vector<int>{5, 6, 2, 7}));  // from the first triangle's first outer edge
  m.triangles[5] = {2, 7, 1};  // a bow tie: the two triangles share vertex 2 only
  const PolyMesh bow = merge_polygons(m, {0, 1, 2, 3, 4, 4});
  EXPECT_EQ(bow.num_faces(), 6);
  EXPECT_TRUE(bow.all_triangles());
}

TEST(PolyMesh, TriangulatesAlongTheShorterDiagonalKeepingOrientation) {
  PolyMesh m;
  m.positions = {Vec3(0, 0, 0), Vec3(3, 0, 0), Vec3(3.5, 1, 0), Vec3(0.5, 1, 0)};  // 1-3 shorter than 0-2
  m.add_face({0, 1, 2, 3});
  TriMesh t = triangulate(m);
  ASSERT_EQ(t.num_faces(), 2);
  EXPECT_EQ(t.triangles[0], (Triangle{0, 1, 3}));
  EXPECT_EQ(t.triangles[1], (Triangle{1, 2, 3}));
  for (int f = 0; f < 2; ++f) EXPECT_GT(face_normal(t, f).z(), 0.0);
  const PolyMesh prism = test::pentagonal_prism();
  t = triangulate(prism);
  EXPECT_EQ(t.num_faces(), 2 * 3 + 5 * 2);
  EXPECT_NEAR(test::signed_volume(t), 2.5 * std::sin(2 * test::kSubdivPi / 5), 1e-12);  // pentagon area x 1
  EXPECT_TRUE(poly_mesh_from_triangles(t).all_triangles());
  EXPECT_FALSE(PolyMesh{}.all_triangles());
}

}  // namespace
}  // namespace ff
