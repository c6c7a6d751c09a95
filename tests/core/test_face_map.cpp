// Carrying values between the input file's faces/vertices and the cleaned mesh.
#include <gtest/gtest.h>

#include "core/mesh/clean.h"
#include "core/mesh/face_map.h"
#include "synthetic_meshes.h"

namespace ff {
namespace {

TEST(FaceMap, DroppedFacesTakeTheirTwinsValueAndKeptFacesTheirOwn) {
  TriMesh in;
  in.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  in.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 1, 2}, {1, 1, 2}};  // a duplicate and a degenerate face
  const CleanMesh clean = clean_mesh(in);
  ASSERT_EQ(clean.mesh.num_faces(), 2);
  const MeshTopology topo = build_topology(clean.mesh);
  const std::vector<int> labels = {7, 9};
  const std::vector<int> out = values_for_input_faces(clean, in, topo, labels);
  ASSERT_EQ(out.size(), 4u);
  EXPECT_EQ(out[0], labels[static_cast<size_t>(clean.input_face_to_clean[0])]);
  EXPECT_EQ(out[1], labels[static_cast<size_t>(clean.input_face_to_clean[1])]);
  EXPECT_EQ(out[2], out[0]);  // the duplicate of face 0 shares its vertices' faces
  EXPECT_TRUE(out[3] == 7 || out[3] == 9);
}

// A part left out by largest_manifold_part is no cluster's: -1, not a neighbour's value (the
// second cube shares an edge with the first, so its faces there have kept neighbours).
TEST(FaceMap, FacesOfADroppedPartTakeMinusOne) {
  TriMesh in = test::cube_soup();
  const TriMesh second = test::cube_soup();
  const int base = in.num_vertices();
  for (const Vec3& p : second.positions) in.positions.push_back(p + Vec3(1, 1, 0));
  for (const Triangle& t : second.triangles) in.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  CleanOptions largest;
  largest.largest_manifold_part = true;
  const CleanMesh clean = clean_mesh(in, largest);
  ASSERT_EQ(clean.mesh.num_faces(), 12);
  const MeshTopology topo = build_topology(clean.mesh);
  std::vector<int> labels(12);
  for (int f = 0; f < 12; ++f) labels[static_cast<size_t>(f)] = 100 + f;
  const std::vector<int> out = values_for_input_faces(clean, in, topo, labels);
  ASSERT_EQ(out.size(), 24u);
  for (int f = 0; f < 12; ++f)
    EXPECT_EQ(out[static_cast<size_t>(f)], 100 + clean.input_face_to_clean[static_cast<size_t>(f)]);
  for (int f = 12; f < 24; ++f) EXPECT_EQ(out[static_cast<size_t>(f)], -1) << f;
  // Without the option nothing is outside a part.
  EXPECT_TRUE(clean_mesh(test::cube_soup()).input_face_outside_part.empty());
}

TEST(FaceMap, WeldedVerticesAverageAndSplitCopiesKeepTheirOriginalsValue) {
  // Two triangles touching at one vertex (a bowtie): the vertex is split in two.
  TriMesh bowtie;
  bowtie.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(-1, 0, 0), Vec3(0, -1, 0)};
  bowtie.triangles = {{0, 1, 2}, {0, 3, 4}};
  const CleanMesh clean = clean_mesh(bowtie);
  ASSERT_EQ(clean.mesh.num_vertices(), 6);
  const std::vector<double> values = {5, 1, 2, 3, 4};
  const std::vector<double> out = values_for_clean_vertices(clean, values);
  for (int v = 0; v < clean.mesh.num_vertices(); ++v) {
    EXPECT_EQ(out[static_cast<size_t>(v)], values[static_cast<size_t>(clean.vertex_source[static_cast<size_t>(v)])]);
  }
  // An STL-like soup: welded copies average.
  TriMesh soup;
  soup.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  soup.triangles = {{0, 1, 2}, {3, 4, 5}};
  const CleanMesh welded = clean_mesh(soup);
  ASSERT_EQ(welded.mesh.num_vertices(), 4);
  const std::vector<double> w = values_for_clean_vertices(welded, {1, 2, 3, 4, 5, 6});
  EXPECT_DOUBLE_EQ(w[static_cast<size_t>(welded.input_vertex_to_clean[1])], 3.0);  // (2 + 4) / 2
  EXPECT_DOUBLE_EQ(w[static_cast<size_t>(welded.input_vertex_to_clean[2])], 4.5);  // (3 + 6) / 2
}

}  // namespace
}  // namespace ff
