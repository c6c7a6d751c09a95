// The polygon OBJ writer (the panels file, DESIGN.md 4): exact text on a tiny case, and
// round trips through our reader, which triangulates polygons: counts, the polygon each
// triangle came from, and bit-exact coordinates.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>
#include <string>
#include <vector>

#include "core/mesh/mesh_io.h"

namespace ff {
namespace {

void expect_bit_exact(const std::vector<Vec3>& want, const std::vector<Vec3>& got) {
  ASSERT_EQ(want.size(), got.size());
  for (size_t i = 0; i < want.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      const double a = want[i][k], b = got[i][k];
      EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0) << "vertex " << i << " coord " << k << ": " << a << " vs " << b;
    }
  }
}

// A planar patch of a triangle, three quads, a pentagon and a hexagon, all convex and
// counter-clockwise around +z, with coordinates that need all 17 digits.
struct PolygonMesh {
  std::vector<Vec3> vertices;
  std::vector<std::vector<int>> faces;
};

PolygonMesh awkward_polygons() {
  PolygonMesh m;
  const double z = 1.0 / 3.0;
  // A regular hexagon (0..5) around an off-centre point (6, so no polygon has a straight
  // angle there) and an outer ring (7..12).
  for (int i = 0; i < 6; ++i) {
    const double a = M_PI / 3.0 * i;
    m.vertices.push_back(Vec3(std::cos(a), std::sin(a), z));
  }
  m.vertices.push_back(Vec3(0.1, 0.25, z));
  for (int i = 0; i < 6; ++i) {
    const double a = M_PI / 3.0 * i;
    m.vertices.push_back(Vec3(2.0 * std::cos(a), 2.0 * std::sin(a), z));  // 7..12
  }
  m.faces = {
      {6, 0, 1},              // triangle
      {6, 1, 2, 3},           // quad
      {6, 3, 4, 5, 0},        // pentagon
      {0, 7, 8, 1},           // outer quads
      {1, 8, 9, 2},           //
      {7, 8, 9, 10, 11, 12},  // hexagon (over the others: the reader does not mind)
  };
  return m;
}

TEST(PolygonObj, ExactTextWithComments) {
  const std::vector<Vec3> v = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0.5, 2, 0), Vec3(0, 1, 0)};
  const std::string text = write_polygon_obj(v, {{0, 1, 2, 3, 4}, {0, 2, 1}}, "flatfacet remesh\ninput: a.obj\n");
  EXPECT_EQ(text,
            "# flatfacet remesh\n"
            "# input: a.obj\n"
            "v 0 0 0\n"
            "v 1 0 0\n"
            "v 1 1 0\n"
            "v 0.5 2 0\n"
            "v 0 1 0\n"
            "f 1 2 3 4 5\n"
            "f 1 3 2\n");
}

TEST(PolygonObj, NoCommentNoCommentLines) {
  const std::string text = write_polygon_obj({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, {{0, 1, 2}});
  EXPECT_EQ(text, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
}

TEST(PolygonObj, EmptyCommentLinesStayComments) {
  const std::string text = write_polygon_obj({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, {{0, 1, 2}}, "a\n\nb");
  EXPECT_EQ(text.substr(0, 10), "# a\n# \n# b");
  const RawMesh back = read_obj(text);
  EXPECT_EQ(back.mesh.num_vertices(), 3);
  EXPECT_EQ(back.num_polygons, 1);
}

TEST(PolygonObj, EmptyMeshWritesOnlyTheComment) {
  EXPECT_EQ(write_polygon_obj({}, {}, "nothing"), "# nothing\n");
  EXPECT_EQ(write_polygon_obj({}, {}), "");
}

TEST(PolygonObj, RoundTripCountsAndPolygonsThroughTheTriangulatingReader) {
  const PolygonMesh m = awkward_polygons();
  const std::string text = write_polygon_obj(m.vertices, m.faces, "panels: 6");
  const RawMesh back = read_mesh(text, "panels.obj");
  expect_bit_exact(m.vertices, back.mesh.positions);
  ASSERT_EQ(back.num_polygons, static_cast<int>(m.faces.size()));
  size_t triangles = 0;
  for (const auto& f : m.faces) triangles += f.size() - 2;
  ASSERT_EQ(back.mesh.triangles.size(), triangles);
  ASSERT_EQ(back.source_polygon.size(), triangles);
  // Each triangle uses only vertices of the polygon it came from, and keeps its orientation.
  std::vector<int> per_polygon(m.faces.size(), 0);
  for (int t = 0; t < back.mesh.num_faces(); ++t) {
    const int p = back.source_polygon[static_cast<size_t>(t)];
    ASSERT_TRUE(p >= 0 && p < static_cast<int>(m.faces.size()));
    ++per_polygon[static_cast<size_t>(p)];
    const std::set<int> corners(m.faces[static_cast<size_t>(p)].begin(), m.faces[static_cast<size_t>(p)].end());
    for (const int i : back.mesh.triangles[static_cast<size_t>(t)]) EXPECT_TRUE(corners.count(i)) << t;
    EXPECT_GT(face_normal(back.mesh, t).z(), 0.0) << t;
  }
  for (size_t p = 0; p < m.faces.size(); ++p) EXPECT_EQ(per_polygon[p], static_cast<int>(m.faces[p].size()) - 2);
}

TEST(PolygonObj, RoundTripIsBitExactForHardNumbers) {
  const std::vector<Vec3> v = {Vec3(0.1, -0.0, 1e-310), Vec3(1.0 / 3.0, 2e300, -7.123456789012345e-5),
                               Vec3(M_PI, std::nextafter(1.0, 2.0), -123456789.123456789),
                               Vec3(-1e-300, 5e-324, 1.7976931348623157e308)};
  const RawMesh back = read_obj(write_polygon_obj(v, {{0, 1, 2, 3}}));
  expect_bit_exact(v, back.mesh.positions);
  EXPECT_EQ(back.num_polygons, 1);
}

TEST(PolygonObj, LargeMeshRoundTrip) {
  // A 60 x 40 grid of quads: the writer's buffering must not drop or reorder anything.
  PolygonMesh m;
  const int nx = 60, ny = 40;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) m.vertices.push_back(Vec3(i * 0.1, j * 0.7 / 3.0, std::sin(i * 0.3 + j * 0.2)));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = j * (nx + 1) + i;
      m.faces.push_back({a, a + 1, a + nx + 2, a + nx + 1});
    }
  const RawMesh back = read_obj(write_polygon_obj(m.vertices, m.faces));
  expect_bit_exact(m.vertices, back.mesh.positions);
  EXPECT_EQ(back.num_polygons, nx * ny);
  EXPECT_EQ(back.mesh.num_faces(), 2 * nx * ny);
  EXPECT_TRUE(std::is_sorted(back.source_polygon.begin(), back.source_polygon.end()));
}

}  // namespace
}  // namespace ff
