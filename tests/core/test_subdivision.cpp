// Subdivision surfaces (prepare/subdivision.h): face counts, convergence to the known limit
// points, creases, boundaries, topology and orientation, validation, and a real quad model
// subdivided and remeshed into far more panels than it has faces.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/mesh/clean.h"
#include "core/mesh/mesh_io.h"
#include "core/mesh/topology.h"
#include "core/prepare/subdivision.h"
#include "core/util/error.h"
#include "input_error_message.h"
#include "panel_checks.h"
#include "subdivision_shapes.h"
#include "test_meshes.h"

namespace ff {
namespace {

using test::kSubdivPi;

// Neighbours of v in a triangle mesh (sorted) and, for quads, the diagonal vertices.
std::vector<int> tri_neighbours(const TriMesh& m, int v) {
  std::vector<int> out;
  for (const Triangle& t : m.triangles)
    for (size_t i = 0; i < 3; ++i)
      if (t[i] == v) out.push_back(t[(i + 1) % 3]), out.push_back(t[(i + 2) % 3]);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// Loop's limit point of an interior vertex: (w v + sum q) / (w + n), w = 3 / (8 beta).
Vec3 loop_limit(const TriMesh& m, int v) {
  const std::vector<int> q = tri_neighbours(m, v);
  const double n = static_cast<double>(q.size()), c = 0.375 + 0.25 * std::cos(2 * kSubdivPi / n);
  const double beta = (0.625 - c * c) / n, w = 3.0 / (8.0 * beta);
  Vec3 sum = Vec3::Zero();
  for (const int u : q) sum += m.positions[static_cast<size_t>(u)];
  return (w * m.positions[static_cast<size_t>(v)] + sum) / (w + n);
}

// Catmull-Clark's limit point of an interior vertex whose faces are all quads:
// (n^2 v + 4 sum(edge neighbours) + sum(diagonal vertices)) / (n (n + 5)).
Vec3 catmull_clark_limit(const PolyMesh& m, int v) {
  Vec3 edges = Vec3::Zero(), diagonals = Vec3::Zero();
  double n = 0.0;
  for (int f = 0; f < m.num_faces(); ++f) {
    EXPECT_EQ(m.face_size(f), 4);
    for (int i = 0; i < 4; ++i) {
      if (m.corner(f, i) != v) continue;
      n += 1.0;
      edges += m.positions[static_cast<size_t>(m.corner(f, (i + 1) % 4))];  // each edge once: the outgoing one
      diagonals += m.positions[static_cast<size_t>(m.corner(f, (i + 2) % 4))];
    }
  }
  return (n * n * m.positions[static_cast<size_t>(v)] + 4.0 * edges + diagonals) / (n * (n + 5.0));
}

// Largest move of the vertices level k has, from level k to level k + 1.
double largest_move(const std::vector<Vec3>& coarse, const std::vector<Vec3>& fine) {
  double d = 0.0;
  for (size_t i = 0; i < coarse.size(); ++i) d = std::max(d, (fine[i] - coarse[i]).norm());
  return d;
}

TEST(Subdivision, LoopQuadruplesTheFacesEachLevel) {
  const TriMesh ico = test::icosahedron();
  for (int level = 0; level <= 3; ++level) {
    const TriMesh s = loop_subdivide(ico, level);
    EXPECT_EQ(s.num_faces(), 20 << (2 * level));
    EXPECT_EQ(s.num_vertices(), 10 * (1 << (2 * level)) + 2);  // V - E + F = 2 with E = 3F / 2
    EXPECT_EQ(subdivided_triangle_count(poly_mesh_from_triangles(ico), SubdivisionScheme::Loop, level), s.num_faces());
  }
}

TEST(Subdivision, CatmullClarkMakesOneQuadPerCornerThenFourPerQuad) {
  const PolyMesh prism = test::pentagonal_prism();  // 2 pentagons + 5 quads: 30 corners
  EXPECT_EQ(catmull_clark_quads(prism, 0).num_faces(), 7);
  for (int level = 1; level <= 3; ++level) {
    const PolyMesh q = catmull_clark_quads(prism, level);
    EXPECT_EQ(q.num_faces(), 30 << (2 * (level - 1)));
    for (int f = 0; f < q.num_faces(); ++f) ASSERT_EQ(q.face_size(f), 4);
    const TriMesh t = catmull_clark(prism, level);
    EXPECT_EQ(t.num_faces(), 2 * q.num_faces());
    EXPECT_EQ(t.positions.size(), q.positions.size());
    EXPECT_EQ(subdivided_triangle_count(prism, SubdivisionScheme::CatmullClark, level), t.num_faces());
  }
  EXPECT_EQ(catmull_clark(prism, 0).num_faces(), 2 * 3 + 5 * 2);  // the control polygons, triangulated
}

TEST(Subdivision, CubeConvergesToTheCatmullClarkLimit) {
  PolyMesh level = test::cube_quads();
  // The limit point of a cube corner (valence 3): (9 v + 4 * 3 edge neighbours + 3 diagonals) / 24.
  const Vec3 corner_limit = catmull_clark_limit(level, 7);
  EXPECT_LT((corner_limit - Vec3(0.5, 0.5, 0.5)).norm(), 1e-15);
  double previous_move = 0.0, previous_error = (level.positions[7] - corner_limit).norm();
  for (int k = 1; k <= 6; ++k) {
    const PolyMesh next = catmull_clark_quads(test::cube_quads(), k);
    // The limit point is a property of the surface: every level predicts the same one.
    for (int v = 0; v < 8; ++v) {
      const Vec3 expected = catmull_clark_limit(test::cube_quads(), v);
      EXPECT_LT((catmull_clark_limit(next, v) - expected).norm(), 1e-12) << "level " << k << " vertex " << v;
    }
    const double error = (next.positions[7] - corner_limit).norm();
    const double move = largest_move(level.positions, next.positions);
    EXPECT_LT(error, previous_error) << "level " << k;
    if (k >= 3) {
      // Geometric convergence: each level moves the points about 4x less than the one before.
      EXPECT_GT(previous_move / move, 3.0) << "level " << k;
      EXPECT_LT(previous_move / move, 5.0) << "level " << k;
    }
    previous_move = move;
    previous_error = error;
    level = next;
  }
  EXPECT_LT(previous_error, 1e-3);
}

void expect_loop_convergence(const TriMesh& control, const char* name) {
  SCOPED_TRACE(name);
  std::vector<Vec3> limits;
  for (int v = 0; v < control.num_vertices(); ++v) limits.push_back(loop_limit(control, v));
  TriMesh level = control;
  double previous_move = 0.0, previous_error = 1e300;
  for (int k = 1; k <= 5; ++k) {
    const TriMesh next = loop_subdivide(control, k);
    double error = 0.0;
    for (int v = 0; v < control.num_vertices(); ++v) {
      EXPECT_LT((loop_limit(next, v) - limits[static_cast<size_t>(v)]).norm(), 1e-12) << "level " << k;
      error = std::max(error, (next.positions[static_cast<size_t>(v)] - limits[static_cast<size_t>(v)]).norm());
    }
    const double move = largest_move(level.positions, next.positions);
    EXPECT_LT(error, previous_error);
    if (k >= 3) {
      EXPECT_GT(previous_move / move, 3.0) << "level " << k;
      EXPECT_LT(previous_move / move, 5.0) << "level " << k;
    }
    previous_move = move;
    previous_error = error;
    level = next;
  }
  EXPECT_LT(previous_error, 1e-2);
}

TEST(Subdivision, OctahedronAndIcosahedronConvergeToTheLoopLimit) {
  expect_loop_convergence(test::octahedron(), "octahedron");
  expect_loop_convergence(test::icosahedron(), "icosahedron");
}

// Distance from p to the surface of the cube [-1, 1]^3.
double off_cube(const Vec3& p) { return std::abs(p.cwiseAbs().maxCoeff() - 1.0) + std::max(0.0, p.cwiseAbs().maxCoeff() - 1.0); }

TEST(Subdivision, FullyCreasedCubeStaysACube) {
  const PolyMesh cube = test::cube_quads();
  const std::vector<VertexPair> creases = crease_edges(cube, 45.0);
  EXPECT_EQ(creases.size(), 12u);
  const TriMesh cc = catmull_clark(cube, 3, creases);
  const TriMesh loop = loop_subdivide(triangulate(cube), 3, crease_edges(poly_mesh_from_triangles(triangulate(cube)), 45.0));
  for (const TriMesh* m : {&cc, &loop}) {
    double worst = 0.0;
    for (const Vec3& p : m->positions) worst = std::max(worst, off_cube(p));
    EXPECT_LT(worst, 1e-12);
    for (int v = 0; v < 8; ++v) EXPECT_EQ(m->positions[static_cast<size_t>(v)], cube.positions[static_cast<size_t>(v)]);
  }
  // Without creases the cube rounds off.
  double inside = 0.0;
  for (const Vec3& p : catmull_clark(cube, 3).positions) inside = std::max(inside, off_cube(p));
  EXPECT_GT(inside, 0.1);
}

// The closed polygon refined k times by the cubic B-spline rules.
std::vector<Vec3> refine_closed_curve(std::vector<Vec3> polygon, int levels) {
  for (int k = 0; k < levels; ++k) {
    const size_t n = polygon.size();
    std::vector<Vec3> next;
    for (size_t i = 0; i < n; ++i) {
      const Vec3 &a = polygon[(i + n - 1) % n], &v = polygon[i], &b = polygon[(i + 1) % n];
      next.push_back((a + 6.0 * v + b) / 8.0);
      next.push_back(0.5 * (v + b));
    }
    polygon = next;
  }
  return polygon;
}

// Largest distance from a point of `curve` to the nearest of `points`.
double farthest_from(const std::vector<Vec3>& curve, const std::vector<Vec3>& points) {
  double worst = 0.0;
  for (const Vec3& c : curve) {
    double best = 1e300;
    for (const Vec3& p : points) best = std::min(best, (p - c).norm());
    worst = std::max(worst, best);
  }
  return worst;
}

TEST(Subdivision, CreaseEdgeFollowsTheCubicBSplineOfItsPolygon) {
  const TriMesh pyramid = test::hexagonal_bipyramid();
  const std::vector<VertexPair> creases = crease_edges(poly_mesh_from_triangles(pyramid), 60.0);
  ASSERT_EQ(creases.size(), 6u);  // the equator only
  for (const VertexPair& e : creases) EXPECT_TRUE(e[0] < 6 && e[1] < 6);
  EXPECT_TRUE(crease_edges(poly_mesh_from_triangles(pyramid), 180.0).empty());
  EXPECT_EQ(crease_edges(poly_mesh_from_triangles(pyramid), 0.0).size(), 18u);

  const std::vector<Vec3> hexagon(pyramid.positions.begin(), pyramid.positions.begin() + 6);
  for (int k = 1; k <= 4; ++k) {
    const TriMesh s = loop_subdivide(pyramid, k, creases);
    std::vector<Vec3> equator;
    for (const Vec3& p : s.positions)
      if (std::abs(p.z()) < 1e-12) equator.push_back(p);
    const std::vector<Vec3> curve = refine_closed_curve(hexagon, k);
    EXPECT_EQ(equator.size(), curve.size()) << "level " << k;
    EXPECT_LT(farthest_from(curve, equator), 1e-12) << "level " << k;
    // Control vertices converge to the B-spline's point (a + 4 v + b) / 6.
    const Vec3 limit = (hexagon[5] + 4.0 * hexagon[0] + hexagon[1]) / 6.0;
    if (k == 4) {
      EXPECT_LT((s.positions[0] - limit).norm(), 2e-3);
    }
  }
  // Without the crease the equator leaves the plane and the curve (the apexes differ).
  const TriMesh smooth = loop_subdivide(pyramid, 2);
  std::vector<Vec3> level2(smooth.positions.begin(), smooth.positions.begin() + 6);
  EXPECT_GT(std::abs(level2[0].z()), 1e-3);
}

TEST(Subdivision, OpenPlanarGridStaysPlanarAndItsBoundaryFollowsTheCurve) {
  const Vec3 origin(1.0, 2.0, 3.0), u = Vec3(1.0, 0.5, 0.2).normalized(), v = Vec3(-0.3, 1.0, 0.7).normalized();
  const Vec3 normal = u.cross(v).normalized();
  const PolyMesh grid = test::planar_grid(4, 3, origin, u, v);
  const TriMesh control = triangulate(grid);
  const MeshTopology control_topology = build_topology(control);
  ASSERT_EQ(control_topology.boundary_loops.size(), 1u);
  std::vector<Vec3> boundary;
  for (const int b : control_topology.boundary_loops[0]) boundary.push_back(control.positions[static_cast<size_t>(b)]);
  const std::vector<int> grid_corners = {0, 4, 15, 19};
  // Boundary vertices of a single face stay put; Loop's control has some corners in two.
  std::vector<int> loop_corners;
  for (const int c : grid_corners) {
    int faces = 0;
    for (const Triangle& t : control.triangles) faces += std::count(t.begin(), t.end(), c) > 0 ? 1 : 0;
    if (faces == 1) loop_corners.push_back(c);
  }
  EXPECT_FALSE(loop_corners.empty());
  EXPECT_LT(loop_corners.size(), grid_corners.size());  // and some corners move along the curve
  for (int k = 1; k <= 3; ++k) {
    for (const bool loop : {false, true}) {
      SCOPED_TRACE(std::string(loop ? "Loop" : "Catmull-Clark") + " level " + std::to_string(k));
      const std::vector<int>& corners = loop ? loop_corners : grid_corners;
      const TriMesh s = loop ? loop_subdivide(control, k) : catmull_clark(grid, k);
      double off_plane = 0.0;
      for (const Vec3& p : s.positions) off_plane = std::max(off_plane, std::abs(normal.dot(p - origin)));
      EXPECT_LT(off_plane, 1e-12);
      const MeshTopology t = build_topology(s);
      ASSERT_EQ(t.boundary_loops.size(), 1u);
      EXPECT_EQ(euler_characteristic(s, t), 1);
      std::vector<Vec3> got;
      for (const int b : t.boundary_loops[0]) got.push_back(s.positions[static_cast<size_t>(b)]);
      // The boundary: the control boundary refined by the curve rules, corners kept.
      std::vector<Vec3> expected = boundary;
      for (int level = 0; level < k; ++level) {
        std::vector<Vec3> next = refine_closed_curve(expected, 1);
        for (size_t i = 0; i < expected.size(); ++i) {
          for (const int c : corners)
            if (expected[i] == grid.positions[static_cast<size_t>(c)]) next[2 * i] = expected[i];
        }
        expected = next;
      }
      EXPECT_EQ(got.size(), expected.size());
      EXPECT_LT(farthest_from(expected, got), 1e-12);
      for (const int c : corners)
        EXPECT_EQ(s.positions[static_cast<size_t>(c)], grid.positions[static_cast<size_t>(c)]);
    }
  }
  // A boundary vertex that is no corner converges to (a + 4 v + b) / 6 of its boundary neighbours.
  const Vec3 limit = (grid.positions[1] + 4.0 * grid.positions[2] + grid.positions[3]) / 6.0;
  const double e4 = (catmull_clark(grid, 4).positions[2] - limit).norm();
  const double e5 = (catmull_clark(grid, 5).positions[2] - limit).norm();
  EXPECT_GT(e4 / e5, 3.5);
  EXPECT_LT(e5, 1e-3);
}

TEST(Subdivision, KeepsTopologyAndOrientation) {
  struct Case {
    const char* name;
    TriMesh control, subdivided;
  };
  const TriMesh bipyramid = test::hexagonal_bipyramid();
  const std::vector<Case> cases = {
      {"cube", triangulate(test::cube_quads()), catmull_clark(test::cube_quads(), 2)},
      {"prism", triangulate(test::pentagonal_prism()), catmull_clark(test::pentagonal_prism(), 2)},
      {"torus", triangulate(test::quad_torus(8, 5)), catmull_clark(test::quad_torus(8, 5), 2)},
      {"icosahedron", test::icosahedron(), loop_subdivide(test::icosahedron(), 2)},
      {"bipyramid creased", bipyramid,
       loop_subdivide(bipyramid, 2, crease_edges(poly_mesh_from_triangles(bipyramid), 60.0))},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const MeshTopology before = build_topology(c.control), after = build_topology(c.subdivided);
    EXPECT_EQ(euler_characteristic(c.subdivided, after), euler_characteristic(c.control, before));
    EXPECT_EQ(after.boundary_loops.size(), before.boundary_loops.size());
    EXPECT_EQ(after.num_components, 1);
    EXPECT_TRUE(test::consistently_oriented(c.subdivided));
    EXPECT_GT(test::signed_volume(c.control), 0.0);
    EXPECT_GT(test::signed_volume(c.subdivided), 0.0);
    const CleanMesh clean = clean_mesh(c.subdivided);
    EXPECT_EQ(clean.report.faces_flipped, 0);
    EXPECT_EQ(clean.report.welded_vertices, 0);
    EXPECT_EQ(clean.mesh.num_faces(), c.subdivided.num_faces());
  }
  EXPECT_EQ(loop_subdivide(bipyramid, 3).positions, loop_subdivide(bipyramid, 3).positions);  // deterministic
}

TEST(Subdivision, RefusesWhatItCannotSubdivide) {
  const auto message_of = [](auto&& call) { return test::input_error_message(call, "no error"); };
  TriMesh fin = test::octahedron();
  fin.positions.emplace_back(0.5, 0.5, 0.0);
  fin.triangles.push_back({0, 2, 6});  // a third face on edge (0, 2)
  EXPECT_NE(message_of([&] { loop_subdivide(fin, 1); }).find("non-manifold"), std::string::npos);
  TriMesh flipped = test::octahedron();
  std::swap(flipped.triangles[0][0], flipped.triangles[0][1]);
  EXPECT_NE(message_of([&] { loop_subdivide(flipped, 1); }).find("orientation"), std::string::npos);
  const std::string too_many = message_of([&] { catmull_clark(test::cube_quads(), 12); });
  EXPECT_NE(too_many.find("201326592 triangles"), std::string::npos) << too_many;  // 24 * 4^11 * 2
  EXPECT_NE(too_many.find("use at most 9 levels"), std::string::npos) << too_many;
  EXPECT_NE(message_of([&] { loop_subdivide(test::octahedron(), 3, {}, 100); }).find("512 triangles"),
            std::string::npos);
  EXPECT_NE(message_of([&] { loop_subdivide(test::octahedron(), -1); }).find("levels"), std::string::npos);
  EXPECT_NE(message_of([&] { loop_subdivide(test::octahedron(), 1, {{0, 1}}); }).find("not an edge"),
            std::string::npos);
  PolyMesh repeated = test::cube_quads();
  repeated.corners[1] = repeated.corners[0];
  EXPECT_NE(message_of([&] { catmull_clark(repeated, 1); }).find("twice"), std::string::npos);
  PolyMesh out_of_range = test::cube_quads();
  out_of_range.corners[3] = 8;
  EXPECT_NE(message_of([&] { catmull_clark(out_of_range, 1); }).find("out of range"), std::string::npos);
  EXPECT_NE(message_of([&] { catmull_clark(PolyMesh{}, 1); }).find("no faces"), std::string::npos);
}

TEST(Subdivision, YasIslandSubdividedThenRemeshedIntoManyMorePanels) {
  const RawMesh raw = read_mesh_file(test::shared_mesh("YasIsland.off"));
  const CleanMesh clean = clean_mesh(raw.mesh);
  std::vector<int> polygon(clean.face_source.size());
  for (size_t f = 0; f < polygon.size(); ++f)
    polygon[f] = raw.source_polygon[static_cast<size_t>(clean.face_source[f])];
  const PolyMesh control = merge_polygons(clean.mesh, polygon);
  ASSERT_EQ(control.num_faces(), raw.num_polygons);  // the file's 976 quads, recovered
  for (int f = 0; f < control.num_faces(); ++f) ASSERT_EQ(control.face_size(f), 4);
  const TriMesh fine = catmull_clark(control, 2);
  EXPECT_EQ(fine.num_faces(), 976 * 16 * 2);
  const CleanMesh fine_clean = clean_mesh(fine);
  EXPECT_EQ(fine_clean.mesh.num_faces(), fine.num_faces());
  EXPECT_EQ(fine_clean.report.faces_flipped, 0);
  const MeshTopology before = build_topology(clean.mesh), after = build_topology(fine_clean.mesh);
  EXPECT_EQ(euler_characteristic(fine_clean.mesh, after), euler_characteristic(clean.mesh, before));
  EXPECT_EQ(after.boundary_loops.size(), before.boundary_loops.size());

  RemeshParams p;
  // Nearly twice the control mesh's faces (and 92% of the file's triangles): one level of
  // subdivision is not enough for so many (1200 leave about 100 panels invalid), two are.
  p.panels = 1800;
  Remesher r(fine_clean.mesh, p);
  r.run();
  EXPECT_TRUE(test::valid_panels(r, p.panels, 0.01 * bbox_diagonal(fine_clean.mesh)));
}

}  // namespace
}  // namespace ff
