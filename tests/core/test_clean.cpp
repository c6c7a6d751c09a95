#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "core/mesh/clean.h"
#include "core/mesh/mesh_io.h"
#include "core/mesh/topology.h"
#include "core/util/error.h"
#include "input_error_message.h"
#include "synthetic_meshes.h"
#include "test_meshes.h"

namespace ff {
namespace {

using test::consistently_oriented;
using test::signed_volume;

// The message of the InputError clean_mesh throws ("" when it does not throw).
std::string clean_error(const TriMesh& m, const CleanOptions& options = {}) {
  return test::input_error_message([&] { clean_mesh(m, options); });
}

bool listed(const std::vector<std::string>& list, const std::string& s) {
  return std::find(list.begin(), list.end(), s) != list.end();
}

// What every cleaned mesh promises: builds a topology, consistent orientation, maps
// agree with each other.
MeshTopology expect_clean(const TriMesh& input, const CleanMesh& c) {
  const MeshTopology t = build_topology(c.mesh);
  EXPECT_TRUE(consistently_oriented(c.mesh, t));
  EXPECT_EQ(t.num_components, c.report.components);
  EXPECT_EQ(c.face_source.size(), c.mesh.triangles.size());
  EXPECT_EQ(c.input_face_to_clean.size(), input.triangles.size());
  for (size_t f = 0; f < c.face_source.size(); ++f) {
    EXPECT_EQ(c.input_face_to_clean[static_cast<size_t>(c.face_source[f])], static_cast<int>(f));
  }
  EXPECT_EQ(c.input_vertex_to_clean.size(), input.positions.size());
  for (size_t v = 0; v < input.positions.size(); ++v) {
    const int w = c.input_vertex_to_clean[v];
    if (w >= 0 && c.report.welded_vertices == 0) {
      EXPECT_EQ(c.mesh.positions[static_cast<size_t>(w)], input.positions[v]);
    }
  }
  std::vector<char> used(c.mesh.positions.size(), 0);
  for (const Triangle& tri : c.mesh.triangles) {
    for (int v : tri) used[static_cast<size_t>(v)] = 1;
  }
  EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0) << "no unreferenced vertices";
  return t;
}

TEST(CleanMesh, TetrahedronIsUnchanged) {
  const TriMesh m = test::tetrahedron();
  const CleanMesh c = clean_mesh(m);
  expect_clean(m, c);
  EXPECT_EQ(c.mesh.triangles, m.triangles);
  EXPECT_EQ(c.mesh.positions, m.positions);
  EXPECT_EQ(c.face_source, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(c.input_vertex_to_clean, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(c.report.input_vertices, 4);
  EXPECT_EQ(c.report.input_faces, 4);
  EXPECT_EQ(c.report.components, 1);
  EXPECT_TRUE(c.report.messages().empty());
}

TEST(CleanMesh, CubeSoupIsWelded) {
  const TriMesh m = test::cube_soup();
  ASSERT_EQ(m.num_vertices(), 36);
  const CleanMesh c = clean_mesh(m);
  const MeshTopology t = expect_clean(m, c);
  EXPECT_EQ(c.mesh.num_vertices(), 8);
  EXPECT_EQ(c.report.welded_vertices, 28);
  EXPECT_EQ(c.mesh.num_faces(), 12);
  EXPECT_EQ(euler_characteristic(c.mesh, t), 2);
  EXPECT_TRUE(t.boundary_loops.empty());
  EXPECT_NEAR(signed_volume(c.mesh), 1.0, 1e-12);
  EXPECT_EQ(c.report.faces_flipped, 0);
  for (size_t v = 0; v < m.positions.size(); ++v) {
    EXPECT_EQ(c.mesh.positions[static_cast<size_t>(c.input_vertex_to_clean[v])], m.positions[v]);
  }
  EXPECT_EQ(c.report.messages(), (std::vector<std::string>{"welded 28 duplicate vertices"}));
}

TEST(CleanMesh, OneFlippedFaceIsFixed) {
  TriMesh m = test::tetrahedron();
  std::swap(m.triangles[2][1], m.triangles[2][2]);
  const CleanMesh c = clean_mesh(m);
  expect_clean(m, c);
  EXPECT_EQ(c.report.faces_flipped, 1);
  EXPECT_EQ(c.mesh.triangles, test::tetrahedron().triangles);
  EXPECT_GT(signed_volume(c.mesh), 0.0);
  EXPECT_TRUE(listed(c.report.messages(),
                     "flipped 1 face to make the orientation consistent (closed parts facing "
                     "outward)"));

  TriMesh g = test::grid(3, 3);
  std::swap(g.triangles[7][0], g.triangles[7][1]);
  const CleanMesh cg = clean_mesh(g);
  expect_clean(g, cg);
  EXPECT_EQ(cg.report.faces_flipped, 1);
  EXPECT_EQ(cg.mesh.triangles[7], (Triangle{g.triangles[7][0], g.triangles[7][2], g.triangles[7][1]}));
}

TEST(CleanMesh, InsideOutClosedMeshIsTurnedOutward) {
  TriMesh m = test::torus(12, 8);
  for (Triangle& t : m.triangles) std::swap(t[1], t[2]);
  ASSERT_LT(signed_volume(m), 0.0);
  const CleanMesh c = clean_mesh(m);
  const MeshTopology t = expect_clean(m, c);
  EXPECT_EQ(c.report.faces_flipped, m.num_faces());
  EXPECT_GT(signed_volume(c.mesh), 0.0);
  EXPECT_EQ(euler_characteristic(c.mesh, t), 0);

  CleanOptions keep;
  keep.orient_closed_outward = false;
  const CleanMesh k = clean_mesh(m, keep);
  EXPECT_EQ(k.report.faces_flipped, 0);
  EXPECT_LT(signed_volume(k.mesh), 0.0);
}

TEST(CleanMesh, PartsAreOrientedIndependently) {
  // Two tetrahedra, the second inside out, and a grid with most faces pointing down.
  TriMesh m = test::tetrahedron();
  for (const Triangle& t : test::tetrahedron().triangles) m.triangles.push_back({t[0] + 4, t[2] + 4, t[1] + 4});
  for (const Vec3& p : test::tetrahedron().positions) m.positions.push_back(p + Vec3(3, 0, 0));
  TriMesh g = test::grid(2, 2);
  for (size_t f = 0; f < g.triangles.size(); ++f) {
    Triangle t = g.triangles[f];
    if (f != 0) std::swap(t[1], t[2]);
    m.triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
  }
  for (const Vec3& p : g.positions) m.positions.push_back(p + Vec3(0, 0, 5));
  const CleanMesh c = clean_mesh(m);
  const MeshTopology t = expect_clean(m, c);
  EXPECT_EQ(c.report.components, 3);
  EXPECT_EQ(c.report.faces_flipped, 5);  // 4 of the inverted tetrahedron, 1 of the grid
  EXPECT_TRUE(listed(c.report.messages(), "the mesh has 3 disconnected parts"));
  for (int f = 0; f < 8; ++f) {
    EXPECT_GT(face_normal(c.mesh, f).dot(face_centroid(c.mesh, f) -
                                         (f < 4 ? Vec3(0.25, 0.25, 0.25) : Vec3(3.25, 0.25, 0.25))),
              0.0);
  }
  for (int f = 8; f < 16; ++f) EXPECT_LT(face_normal(c.mesh, f).z(), 0.0);
}

TEST(CleanMesh, OpenPartKeepsTheLargerAreaOrientation) {
  // One big face pointing down against two small ones pointing up: by area, down wins.
  TriMesh m;
  m.positions = {Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(0, 10, 0), Vec3(5, -1, 0), Vec3(-1, 5, 0)};
  m.triangles = {{0, 3, 1}, {0, 2, 1}, {0, 2, 4}};
  const CleanMesh c = clean_mesh(m);
  expect_clean(m, c);
  EXPECT_EQ(c.report.faces_flipped, 2);
  for (int f = 0; f < 3; ++f) EXPECT_LT(face_normal(c.mesh, f).z(), 0.0);
}

TEST(CleanMesh, MoebiusStripIsRefused) {
  const std::string error = clean_error(test::moebius(12));
  EXPECT_NE(error.find("not orientable (like a Moebius strip) near vertex "), std::string::npos) << error;
}

TEST(CleanMesh, NonManifoldEdgeIsRefused) {
  TriMesh m;
  m.positions = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 1, 0), Vec3(1, -1, 0), Vec3(1, 0, 1)};
  m.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  EXPECT_EQ(clean_error(m), "non-manifold edge between vertices 0 and 1 at (1, 0, 0): shared by 3 faces");
  // Found after welding, named by the input vertices that remain.
  TriMesh soup;
  for (const Triangle& t : m.triangles) {
    for (int v : t) soup.positions.push_back(m.positions[static_cast<size_t>(v)]);
    const int b = soup.num_vertices() - 3;
    soup.triangles.push_back({b, b + 1, b + 2});
  }
  EXPECT_EQ(clean_error(soup), "non-manifold edge between vertices 0 and 1 at (1, 0, 0): shared by 3 faces");
}

TEST(CleanMesh, NonFiniteCoordinateIsRefused) {
  TriMesh m = test::tetrahedron();
  m.positions[2] = Vec3(std::numeric_limits<double>::quiet_NaN(), 1, 2);
  EXPECT_EQ(clean_error(m), "vertex 2 has a non-finite coordinate (nan, 1, 2)");
  m.positions[2] = Vec3(0, -std::numeric_limits<double>::infinity(), 0.5);
  EXPECT_EQ(clean_error(m), "vertex 2 has a non-finite coordinate (0, -inf, 0.5)");
}

// Squares and fourth powers of a model's size leave a double's range past about 1e+77 (the
// sliver test then passed every face and clustering went on with a mess, exit 0); a model
// outside 1e-30 to 1e+30 across is refused by name, one inside is cleaned at any scale alike.
TEST(CleanMesh, AModelTooLargeOrTooSmallToMeasureIsRefused) {
  for (const double scale : {1e31, 1e39, 1e200, 1e-31, 1e-40, 1e-200}) {
    TriMesh m = test::tetrahedron();
    for (Vec3& p : m.positions) p *= scale;
    const std::string message = clean_error(m);
    EXPECT_NE(message.find("across, outside the 1e-30 to 1e+30 that can be measured"), std::string::npos)
        << scale << ": " << message;
  }
  for (const double scale : {1e29, 1e-29}) {
    TriMesh m = test::tetrahedron();
    for (Vec3& p : m.positions) p *= scale;
    const CleanMesh c = clean_mesh(m);
    EXPECT_EQ(c.mesh.triangles, test::tetrahedron().triangles) << scale;
    EXPECT_EQ(c.report.messages().size(), 0u) << scale;
  }
  TriMesh point = test::tetrahedron();
  for (Vec3& p : point.positions) p = Vec3(1, 2, 3);
  EXPECT_EQ(clean_error(point), "the mesh has no extent: all its vertices coincide");
  // A dense model 2e154 across: its corners' distances overflow a plain norm, which called it
  // a corrupted coordinate ("lies inf times farther"); it is a model in a wrong unit.
  TriMesh huge = test::grid(20, 20);
  for (Vec3& p : huge.positions) p *= 1e153;
  EXPECT_NE(clean_error(huge).find("across, outside the 1e-30 to 1e+30"), std::string::npos) << clean_error(huge);
}

// What makes a model too large is named where one thing does, after welding and after the
// largest part is kept when asked: one corner of a triangle soup (a binary STL) at 3e38 is a
// corrupted coordinate, and a piece 1e31 away is a stray part.
TEST(CleanMesh, WhatMakesAModelTooLargeIsNamed) {
  const TriMesh epcot = test::load_clean("epcot.off");
  TriMesh soup;
  for (const Triangle& t : epcot.triangles) {
    const int base = soup.num_vertices();
    for (int v : t) soup.positions.push_back(epcot.positions[static_cast<size_t>(v)]);
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  soup.positions[40].x() = 3e38;
  EXPECT_EQ(clean_error(soup).rfind("vertex 40 at (3e+38, ", 0), 0u) << clean_error(soup);

  // (Doubles near 1e31 are 2e15 apart, so a triangle there is no smaller than that, and it is
  // the larger part: part_spread names the other one as the stray piece, as it always has.)
  TriMesh far = epcot;
  const int base = far.num_vertices();
  for (const Vec3& p : {Vec3(1e31, 0, 0), Vec3(1e31 + 1e16, 0, 0), Vec3(1e31, 1e16, 0)}) far.positions.push_back(p);
  far.triangles.push_back({base, base + 1, base + 2});
  EXPECT_NE(clean_error(far).find("a stray piece?"), std::string::npos) << clean_error(far);
}

TEST(CleanMesh, OutOfRangeIndexIsRefused) {
  TriMesh m = test::tetrahedron();
  m.triangles[1][2] = 7;
  EXPECT_EQ(clean_error(m), "face 1 refers to vertex 7, but the mesh has only 4 vertices (numbered from 0)");
  m.triangles[1][2] = -1;
  EXPECT_NE(clean_error(m).find("refers to vertex -1"), std::string::npos);
}

TEST(CleanMesh, DuplicateAndDegenerateFacesAreDropped) {
  TriMesh m = test::tetrahedron();
  m.positions.push_back(m.positions[1]);  // vertex 4 welds into 1
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 1, 2}, {0, 3, 2}, {2, 0, 1}, {1, 2, 3}, {0, 4, 1}, {3, 1, 0}, {4, 2, 3}};
  // Faces 2 and 6 are degenerate (6 after welding), 4 repeats 0, 7 repeats 1 reversed,
  // 8 repeats 5 through the welded vertex.
  const CleanMesh c = clean_mesh(m);
  expect_clean(m, c);
  EXPECT_EQ(c.report.degenerate_faces_dropped, 2);
  EXPECT_EQ(c.report.duplicate_faces_dropped, 3);
  EXPECT_EQ(c.report.welded_vertices, 1);
  EXPECT_EQ(c.face_source, (std::vector<int>{0, 1, 3, 5}));
  EXPECT_EQ(c.input_face_to_clean, (std::vector<int>{0, 1, -1, 2, -1, 3, -1, -1, -1}));
  EXPECT_EQ(c.input_vertex_to_clean, (std::vector<int>{0, 1, 2, 3, 1}));
  EXPECT_EQ(c.mesh.triangles, test::tetrahedron().triangles);
  const auto messages = c.report.messages();
  EXPECT_TRUE(listed(messages, "dropped 2 degenerate faces (a corner used twice)"));
  EXPECT_TRUE(listed(messages, "dropped 3 duplicate faces"));
  EXPECT_TRUE(listed(messages, "welded 1 duplicate vertex"));
}

TEST(CleanMesh, AllDegenerateIsRefused) {
  TriMesh m;
  m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 0, 0)};
  m.triangles = {{0, 1, 2}, {1, 1, 0}};
  EXPECT_EQ(clean_error(m), "no usable faces left after clean-up (all 2 faces were degenerate)");
  m.triangles.clear();
  EXPECT_EQ(clean_error(m), "the mesh has no faces");
}

TEST(CleanMesh, ZeroAreaFacesAreCountedAndKept) {
  TriMesh m = test::grid(1, 1);
  m.positions.emplace_back(0.5, 0.0, 0.0);  // on the edge from 0 to 1
  m.triangles.push_back({1, 0, 4});
  CleanOptions keep;
  keep.remove_slivers = false;
  const CleanMesh c = clean_mesh(m, keep);
  expect_clean(m, c);
  EXPECT_EQ(c.report.zero_area_faces, 1);
  EXPECT_EQ(c.mesh.num_faces(), 3);
  EXPECT_TRUE(listed(c.report.messages(), "kept 1 face with zero area (it carries no weight)"));
  // By default the sliver goes: its edge 0-1 is flipped into 4-3 (test_repair.cpp).
  const CleanMesh removed = clean_mesh(m);
  expect_clean(m, removed);
  EXPECT_EQ(removed.report.zero_area_faces, 0);
  EXPECT_EQ(removed.report.slivers_removed, 1);
  EXPECT_EQ(removed.mesh.num_faces(), 3);
}

TEST(CleanMesh, WeldTolerance) {
  TriMesh m = test::cube_soup();
  for (size_t v = 0; v < m.positions.size(); ++v) {
    m.positions[v] += Vec3(1e-7, -5e-8, 0.0) * static_cast<double>(v);  // all distinct
  }
  const CleanMesh exact = clean_mesh(m);
  EXPECT_EQ(exact.report.welded_vertices, 0);
  EXPECT_EQ(exact.report.components, 12);
  CleanOptions options;
  options.weld_tolerance = 1e-5;
  const CleanMesh c = clean_mesh(m, options);
  const MeshTopology t = expect_clean(m, c);
  EXPECT_EQ(c.mesh.num_vertices(), 8);
  EXPECT_EQ(c.report.welded_vertices, 28);
  EXPECT_EQ(euler_characteristic(c.mesh, t), 2);
  EXPECT_GT(signed_volume(c.mesh), 0.0);
  options.weld_tolerance = -1.0;
  EXPECT_NE(clean_error(m, options).find("weld tolerance"), std::string::npos);
}

TEST(CleanMesh, StitchedPartsThatTouchAreNotWelded) {
  // A tetrahedron and its copy turned half a turn about the x axis share the positions of
  // edge 0-1 but not its vertices, like the two sides of cow.off at one spot. Welding
  // would make that edge non-manifold; vertices whose edges are all stitched stay apart.
  TriMesh m = test::tetrahedron();
  for (const Triangle& t : test::tetrahedron().triangles) m.triangles.push_back({t[0] + 4, t[1] + 4, t[2] + 4});
  for (const Vec3& p : test::tetrahedron().positions) m.positions.emplace_back(p.x(), -p.y(), -p.z());
  const CleanMesh c = clean_mesh(m);
  const MeshTopology t = expect_clean(m, c);
  EXPECT_EQ(c.report.welded_vertices, 0);
  EXPECT_EQ(c.mesh.num_vertices(), 8);
  EXPECT_EQ(c.report.components, 2);
  EXPECT_EQ(euler_characteristic(c.mesh, t), 4);
  EXPECT_GT(signed_volume(c.mesh), 0.0);

  // As a soup nothing says the sheets are apart: refused, named by the first vertices.
  TriMesh soup;
  for (const Triangle& tri : m.triangles) {
    for (int v : tri) soup.positions.push_back(m.positions[static_cast<size_t>(v)]);
    const int b = soup.num_vertices() - 3;
    soup.triangles.push_back({b, b + 1, b + 2});
  }
  EXPECT_EQ(clean_error(soup), "non-manifold edge between vertices 0 and 2 at (0.5, 0, 0): shared by 4 faces");
}

TEST(CleanMesh, BowtieVertexIsSplit) {
  TriMesh m;
  m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(-1, 0, 0), Vec3(-1, -1, 0)};
  m.triangles = {{0, 1, 2}, {0, 3, 4}};
  const CleanMesh c = clean_mesh(m);
  const MeshTopology t = expect_clean(m, c);
  EXPECT_EQ(c.report.nonmanifold_vertices_split, 1);
  EXPECT_EQ(c.mesh.num_vertices(), 6);
  EXPECT_EQ(c.mesh.positions[5], m.positions[0]);
  EXPECT_EQ(c.mesh.triangles[1], (Triangle{5, 3, 4}));
  EXPECT_EQ(c.input_vertex_to_clean[0], 0);
  EXPECT_EQ(c.report.components, 2);
  EXPECT_EQ(t.boundary_loops.size(), 2u);
  EXPECT_EQ(euler_characteristic(c.mesh, t), 2);
  const auto messages = c.report.messages();
  EXPECT_TRUE(listed(messages, "split 1 non-manifold vertex where parts touched at a single point"));
  EXPECT_TRUE(listed(messages, "the mesh has 2 disconnected parts"));
}

TEST(CleanMesh, CubesTouchingAtACornerAreSplitAndOutward) {
  TriMesh m = test::cube_soup();
  TriMesh second = test::cube_soup();
  for (Triangle& t : second.triangles) std::swap(t[1], t[2]);  // inside out
  test::append_shifted(m, second, Vec3(1, 1, 1));
  const CleanMesh c = clean_mesh(m);
  const MeshTopology t = expect_clean(m, c);
  EXPECT_EQ(c.report.nonmanifold_vertices_split, 1);
  EXPECT_EQ(c.report.components, 2);
  EXPECT_EQ(c.report.faces_flipped, 12);
  EXPECT_EQ(c.mesh.num_vertices(), 16);
  EXPECT_EQ(euler_characteristic(c.mesh, t), 4);
  EXPECT_NEAR(signed_volume(c.mesh), 2.0, 1e-12);
}

TEST(CleanMesh, UnreferencedVerticesAreRemovedInOrder) {
  TriMesh m = test::tetrahedron();
  m.positions.insert(m.positions.begin() + 1, Vec3(9, 9, 9));
  m.positions.emplace_back(8, 8, 8);
  for (Triangle& t : m.triangles) {
    for (int& v : t) v += v >= 1 ? 1 : 0;
  }
  const CleanMesh c = clean_mesh(m);
  expect_clean(m, c);
  EXPECT_EQ(c.report.unreferenced_vertices_removed, 2);
  EXPECT_EQ(c.input_vertex_to_clean, (std::vector<int>{0, -1, 1, 2, 3, -1}));
  EXPECT_EQ(c.mesh.positions, test::tetrahedron().positions);
  EXPECT_TRUE(listed(c.report.messages(), "removed 2 unused vertices"));
}

TEST(CleanMesh, TorusAndAnnulusKeepTheirTopology) {
  const TriMesh torus = test::torus(16, 9);
  const CleanMesh ct = clean_mesh(torus);
  const MeshTopology tt = expect_clean(torus, ct);
  EXPECT_EQ(euler_characteristic(ct.mesh, tt), 0);
  EXPECT_TRUE(ct.report.messages().empty());

  const TriMesh ring = test::annulus(20, 4);
  const CleanMesh ca = clean_mesh(ring);
  const MeshTopology ta = expect_clean(ring, ca);
  EXPECT_EQ(euler_characteristic(ca.mesh, ta), 0);
  EXPECT_EQ(ta.boundary_loops.size(), 2u);
}

TEST(CleanMesh, SameInputSameOutput) {
  TriMesh m = test::cube_soup();
  std::swap(m.triangles[3][0], m.triangles[3][1]);
  CleanOptions options;
  options.weld_tolerance = 1e-9;
  const CleanMesh a = clean_mesh(m, options), b = clean_mesh(m, options);
  EXPECT_EQ(a.mesh.positions, b.mesh.positions);
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
  EXPECT_EQ(a.report.messages(), b.report.messages());
}

TEST(CleanMesh, MessagesOnePerRepair) {
  CleanReport r;
  r.input_vertices = 100;
  r.input_faces = 50;
  r.components = 1;
  EXPECT_TRUE(r.messages().empty());
  r.welded_vertices = 120;
  r.degenerate_faces_dropped = 3;
  r.faces_flipped = 40;
  r.components = 2;
  EXPECT_EQ(r.messages(), (std::vector<std::string>{
                              "welded 120 duplicate vertices", "dropped 3 degenerate faces (a corner used twice)",
                              "flipped 40 faces to make the orientation consistent (closed parts facing outward)",
                              "the mesh has 2 disconnected parts"}));
  CleanReport one;
  one.welded_vertices = one.degenerate_faces_dropped = one.duplicate_faces_dropped = 1;
  one.zero_area_faces = one.nonmanifold_vertices_split = one.faces_flipped = 1;
  one.unreferenced_vertices_removed = one.components = 1;
  EXPECT_EQ(one.messages(),
            (std::vector<std::string>{"welded 1 duplicate vertex", "dropped 1 degenerate face (a corner used twice)",
                                      "dropped 1 duplicate face", "kept 1 face with zero area (it carries no weight)",
                                      "split 1 non-manifold vertex where parts touched at a single point",
                                      "flipped 1 face to make the orientation consistent (closed parts facing outward)",
                                      "removed 1 unused vertex"}));
}

// The shared meshes, worked out independently of this code: every one is a single part,
// so chi = 2 - 2 genus - boundary loops (genus 0 except 3holes.off, genus 3). All are
// already clean: single parts, consistently oriented, closed ones outward, nothing to
// weld or drop. cow.off has one duplicate vertex (2761 on 621) where its two sides touch
// along an edge: welding it would make that edge non-manifold, so it must stay apart.
TEST(CleanMesh, SharedMeshesCleanToTheirTopology) {
  const std::map<std::string, int> euler = {
      {"inspired_mesh.obj", 1}, {"hyperboloid_s4.off", 0}, {"YasIsland.off", -1}, {"epcot.off", 2},
      {"Moomoo.off", 2},        {"bunny.off", 2},          {"bumpy.off", 2},      {"fandisk.off", 2},
      {"3holes.off", -4},       {"camelhead.off", 1},      {"cow.off", 2},        {"face.obj", 1},
      {"lilium.obj", 1}};
  ASSERT_EQ(test::shared_meshes().size(), euler.size());
  for (const test::SharedMesh& expected : test::shared_meshes()) {
    SCOPED_TRACE(expected.file);
    const RawMesh raw = read_mesh_file(test::shared_mesh(expected.file));
    EXPECT_EQ(raw.mesh.num_faces(), expected.faces);
    const CleanMesh c = clean_mesh(raw.mesh);
    const MeshTopology t = expect_clean(raw.mesh, c);
    EXPECT_EQ(t.boundary_loops.empty(), expected.closed);
    EXPECT_EQ(static_cast<int>(t.boundary_loops.size()), expected.boundary_loops);
    EXPECT_EQ(t.num_components, 1);
    EXPECT_EQ(euler_characteristic(c.mesh, t), euler.at(expected.file));
    EXPECT_EQ(c.report.messages(), std::vector<std::string>{});
    EXPECT_EQ(c.report.slivers_removed, 0);  // none has slivers: cleaned exactly as before
    EXPECT_EQ(c.mesh.num_vertices(), raw.mesh.num_vertices());
    if (expected.closed) {
      EXPECT_GT(signed_volume(c.mesh), 0.0);
    }
  }
}

}  // namespace
}  // namespace ff
