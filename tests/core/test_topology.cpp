#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "core/mesh/topology.h"
#include "core/util/error.h"
#include "synthetic_meshes.h"

namespace ff {
namespace {

using test::annulus;
using test::grid;
using test::tetrahedron;
using test::torus;

// Every field agrees with the triangles and with the other fields.
void expect_consistent(const TriMesh& m, const MeshTopology& t) {
  ASSERT_EQ(t.edge_faces.size(), t.edge_vertices.size());
  for (int e = 0; e < t.num_edges(); ++e) {
    const auto& ev = t.edge_vertices[static_cast<size_t>(e)];
    EXPECT_LT(ev[0], ev[1]);
    if (e > 0) {
      EXPECT_LT(t.edge_vertices[static_cast<size_t>(e) - 1], ev) << "edges sorted";
    }
    const auto& ef = t.edge_faces[static_cast<size_t>(e)];
    EXPECT_GE(ef[0], 0);
    if (ef[1] >= 0) {
      EXPECT_LT(ef[0], ef[1]);
    }
  }
  ASSERT_EQ(t.face_edges.size(), m.triangles.size());
  for (int f = 0; f < m.num_faces(); ++f) {
    const Triangle& tri = m.triangles[static_cast<size_t>(f)];
    for (size_t i = 0; i < 3; ++i) {
      const int e = t.face_edges[static_cast<size_t>(f)][i];
      const int a = tri[i], b = tri[(i + 1) % 3];
      EXPECT_EQ(t.edge_vertices[static_cast<size_t>(e)], (std::array<int, 2>{std::min(a, b), std::max(a, b)}));
      const auto& ef = t.edge_faces[static_cast<size_t>(e)];
      EXPECT_TRUE(ef[0] == f || ef[1] == f);
      EXPECT_EQ(t.face_neighbors[static_cast<size_t>(f)][i], ef[0] == f ? ef[1] : ef[0]);
    }
  }
  ASSERT_EQ(t.vertex_face_offsets.size(), m.positions.size() + 1);
  for (int v = 0; v < m.num_vertices(); ++v) {
    std::vector<int> expected;
    for (int f = 0; f < m.num_faces(); ++f) {
      const Triangle& tri = m.triangles[static_cast<size_t>(f)];
      if (std::find(tri.begin(), tri.end(), v) != tri.end()) expected.push_back(f);
    }
    const std::vector<int> got(t.vertex_faces.begin() + t.vertex_face_offsets[static_cast<size_t>(v)],
                               t.vertex_faces.begin() + t.vertex_face_offsets[static_cast<size_t>(v) + 1]);
    EXPECT_EQ(got, expected) << "vertex " << v;
  }
  // Loops follow the faces' direction and start at their smallest vertex, in order.
  for (size_t l = 0; l < t.boundary_loops.size(); ++l) {
    const auto& loop = t.boundary_loops[l];
    ASSERT_GE(loop.size(), 3u);
    EXPECT_EQ(loop.front(), *std::min_element(loop.begin(), loop.end()));
    if (l > 0) {
      EXPECT_LE(t.boundary_loops[l - 1].front(), loop.front());
    }
    for (size_t k = 0; k < loop.size(); ++k) {
      const int a = loop[k], b = loop[(k + 1) % loop.size()];
      bool found = false;
      for (int e = 0; e < t.num_edges(); ++e) {
        if (t.edge_vertices[static_cast<size_t>(e)] == std::array<int, 2>{std::min(a, b), std::max(a, b)}) {
          EXPECT_TRUE(t.is_boundary_edge(e));
          EXPECT_TRUE(test::face_has_directed_edge(m, t.edge_faces[static_cast<size_t>(e)][0], a, b));
          found = true;
        }
      }
      EXPECT_TRUE(found) << a << "-" << b;
    }
  }
  size_t boundary_edges = 0, loop_edges = 0;
  for (int e = 0; e < t.num_edges(); ++e) boundary_edges += t.is_boundary_edge(e) ? 1 : 0;
  for (const auto& loop : t.boundary_loops) loop_edges += loop.size();
  EXPECT_EQ(boundary_edges, loop_edges) << "every boundary edge in exactly one loop";
  ASSERT_EQ(t.face_component.size(), m.triangles.size());
  int highest = -1;
  for (int c : t.face_component) {
    EXPECT_LE(c, highest + 1) << "components numbered by lowest face";
    highest = std::max(highest, c);
  }
  EXPECT_EQ(highest + 1, t.num_components);
}

TEST(Topology, TetrahedronIsClosed) {
  const TriMesh m = tetrahedron();
  const MeshTopology t = build_topology(m);
  expect_consistent(m, t);
  EXPECT_EQ(t.num_edges(), 6);
  EXPECT_TRUE(t.boundary_loops.empty());
  EXPECT_EQ(t.num_components, 1);
  EXPECT_EQ(euler_characteristic(m, t), 2);
  EXPECT_TRUE(test::consistently_oriented(m, t));
}

TEST(Topology, GridHasOneLoop) {
  const TriMesh m = grid(4, 3);
  const MeshTopology t = build_topology(m);
  expect_consistent(m, t);
  EXPECT_EQ(euler_characteristic(m, t), 1);
  ASSERT_EQ(t.boundary_loops.size(), 1u);
  // Counter-clockwise like the +z faces: 0 -> 1 -> ... along y = 0 first.
  const std::vector<int> expected_start = {0, 1, 2, 3, 4, 9};
  EXPECT_TRUE(std::equal(expected_start.begin(), expected_start.end(), t.boundary_loops[0].begin()));
  EXPECT_EQ(t.boundary_loops[0].size(), 14u);
  EXPECT_EQ(t.num_components, 1);
}

TEST(Topology, AnnulusHasTwoLoops) {
  const TriMesh m = annulus(12, 3);
  const MeshTopology t = build_topology(m);
  expect_consistent(m, t);
  EXPECT_EQ(euler_characteristic(m, t), 0);
  ASSERT_EQ(t.boundary_loops.size(), 2u);
  EXPECT_EQ(t.boundary_loops[0].front(), 0);  // inner ring, clockwise seen from +z
  EXPECT_EQ(t.boundary_loops[0][1], 11);
  EXPECT_EQ(t.boundary_loops[1].front(), 36);  // outer ring, counter-clockwise
  EXPECT_EQ(t.boundary_loops[1][1], 37);
}

TEST(Topology, TorusHasEulerZero) {
  const TriMesh m = torus(10, 6);
  const MeshTopology t = build_topology(m);
  expect_consistent(m, t);
  EXPECT_EQ(euler_characteristic(m, t), 0);
  EXPECT_TRUE(t.boundary_loops.empty());
  EXPECT_EQ(t.num_edges(), 3 * 60);
}

// Closed parts (no boundary edge) per component: what the panel count's lower bound reads.
TEST(Topology, ClosedComponents) {
  EXPECT_EQ(closed_components(build_topology(tetrahedron())), std::vector<char>{1});
  EXPECT_EQ(closed_components(build_topology(torus(10, 6))), std::vector<char>{1});
  EXPECT_EQ(closed_components(build_topology(grid(4, 3))), std::vector<char>{0});
  TriMesh two = grid(2, 2);  // component 0: open (lowest faces); component 1: a tetrahedron
  test::append_shifted(two, tetrahedron(), Vec3(10, 0, 0));
  EXPECT_EQ(closed_components(build_topology(two)), (std::vector<char>{0, 1}));
}

TEST(Topology, BowtieHasTwoLoopsAndTwoComponents) {
  TriMesh m;
  m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(-1, 0, 0), Vec3(-1, -1, 0)};
  m.triangles = {{0, 1, 2}, {0, 3, 4}};
  const MeshTopology t = build_topology(m);
  expect_consistent(m, t);
  ASSERT_EQ(t.boundary_loops.size(), 2u);
  EXPECT_EQ(t.boundary_loops[0], (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(t.boundary_loops[1], (std::vector<int>{0, 3, 4}));
  EXPECT_EQ(t.num_components, 2);
  EXPECT_EQ(euler_characteristic(m, t), 1);  // the shared vertex counts once
}

TEST(Topology, HolesPinchedAtAVertexPairByFan) {
  // A 4 x 4 grid without two triangles around interior vertex 12 = (2, 2) that are not
  // next to each other. Boundary edges at a pinched vertex are paired through the fans of
  // faces between them (what splitting the vertex would give), so the two holes form one
  // loop through 12 twice, independent of the geometry.
  TriMesh m = grid(4, 4);
  const auto remove = [&m](Triangle tri) { m.triangles.erase(std::find(m.triangles.begin(), m.triangles.end(), tri)); };
  remove({12, 13, 18});  // (2,2) (3,2) (3,3)
  remove({6, 7, 12});    // (1,1) (2,1) (2,2)
  const MeshTopology t = build_topology(m);
  expect_consistent(m, t);
  EXPECT_EQ(euler_characteristic(m, t), -1);
  ASSERT_EQ(t.boundary_loops.size(), 2u);
  EXPECT_EQ(t.boundary_loops[0].size(), 16u);
  EXPECT_EQ(t.boundary_loops[1], (std::vector<int>{6, 12, 18, 13, 12, 7}));
}

TEST(Topology, StripWithTouchingEndsIsOneLoop) {
  // A band of six squares bent into a ring whose first and last square meet only at
  // inner vertex 0 (the outer side stays open): a disk with two boundary points glued.
  TriMesh m;
  const int n = 6;
  for (int s = 0; s < n; ++s) {
    const double a = 2.0 * kPi * s / n;
    m.positions.emplace_back(std::cos(a), std::sin(a), 0.0);
    m.positions.emplace_back(2 * std::cos(a), 2 * std::sin(a), 0.0);
  }
  m.positions.emplace_back(1.9, -0.2, 0.0);
  for (int s = 0; s < n; ++s) {
    const int a = 2 * s, b = 2 * s + 1;
    const int c = s + 1 < n ? 2 * s + 2 : 0, d = s + 1 < n ? 2 * s + 3 : 12;
    m.triangles.push_back({a, d, b});
    m.triangles.push_back({a, c, d});
  }
  const MeshTopology t = build_topology(m);
  expect_consistent(m, t);
  EXPECT_EQ(euler_characteristic(m, t), 0);
  EXPECT_EQ(t.num_components, 1);
  ASSERT_EQ(t.boundary_loops.size(), 1u);
  EXPECT_EQ(t.boundary_loops[0].size(), 14u);
  EXPECT_EQ(std::count(t.boundary_loops[0].begin(), t.boundary_loops[0].end(), 0), 2);
}

TEST(Topology, MoebiusStripHasOneLoop) {
  // Not orientable, so faces cannot all agree, but the topology is still well defined:
  // loops are paired through the faces, not through their directions.
  const TriMesh m = test::moebius(12);
  const MeshTopology t = build_topology(m);
  EXPECT_EQ(euler_characteristic(m, t), 0);
  ASSERT_EQ(t.boundary_loops.size(), 1u);
  EXPECT_EQ(t.boundary_loops[0].size(), 24u);
  EXPECT_EQ(t.num_components, 1);
  EXPECT_FALSE(test::consistently_oriented(m, t));
}

TEST(Topology, NonManifoldEdgeNamesTheEdge) {
  TriMesh m;
  m.positions = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 1, 0), Vec3(1, -1, 0), Vec3(1, 0, 1)};
  m.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  try {
    build_topology(m);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "non-manifold edge between vertices 0 and 1 at (1, 0, 0): shared by 3 faces");
  }
  m.triangles.push_back({2, 4, 3});
  m.triangles.push_back({4, 2, 1});
  m.triangles.push_back({2, 4, 0});
  try {
    build_topology(m);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("(and 1 more non-manifold edge)"), std::string::npos) << e.what();
  }
}

TEST(Topology, RefusesBadIndicesAndRepeatedVertices) {
  TriMesh m = tetrahedron();
  m.triangles[1][2] = 9;
  EXPECT_THROW(build_topology(m), InputError);
  m = tetrahedron();
  m.triangles[1] = {1, 1, 2};
  EXPECT_THROW(build_topology(m), InputError);
}

TEST(Topology, ComponentsNumberedByLowestFace) {
  TriMesh a = tetrahedron(), m;
  m.positions = a.positions;
  for (const Vec3& p : a.positions) m.positions.push_back(p + Vec3(5, 0, 0));
  // Faces of the second tetrahedron come first.
  for (const Triangle& t : a.triangles) m.triangles.push_back({t[0] + 4, t[1] + 4, t[2] + 4});
  for (const Triangle& t : a.triangles) m.triangles.push_back(t);
  const MeshTopology t = build_topology(m);
  expect_consistent(m, t);
  EXPECT_EQ(t.num_components, 2);
  EXPECT_EQ(t.face_component[0], 0);
  EXPECT_EQ(t.face_component[4], 1);
  EXPECT_EQ(euler_characteristic(m, t), 4);
}

TEST(Topology, UnreferencedVerticesDoNotCount) {
  TriMesh m = tetrahedron();
  m.positions.emplace_back(7, 7, 7);
  const MeshTopology t = build_topology(m);
  expect_consistent(m, t);
  EXPECT_EQ(euler_characteristic(m, t), 2);
}

TEST(Topology, EmptyMesh) {
  const TriMesh m;
  const MeshTopology t = build_topology(m);
  EXPECT_EQ(t.num_edges(), 0);
  EXPECT_EQ(t.num_components, 0);
  EXPECT_EQ(euler_characteristic(m, t), 0);
}

}  // namespace
}  // namespace ff
