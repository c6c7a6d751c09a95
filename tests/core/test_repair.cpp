// Repairs in clean_mesh() beyond welding and dropping (issue 7): sliver removal, filling
// small holes when asked, and the largest manifold part of a mesh with non-manifold edges.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/mesh/clean.h"
#include "core/mesh/slivers.h"
#include "core/mesh/topology.h"
#include "core/util/error.h"
#include "synthetic_meshes.h"

namespace ff {
namespace {

using test::consistently_oriented;
using test::signed_volume;

struct Shape {
  int euler = 0;
  int loops = 0;
  int components = 0;
};

Shape shape_of(const TriMesh& m) {
  const MeshTopology t = build_topology(m);
  EXPECT_TRUE(consistently_oriented(m, t));
  return {euler_characteristic(m, t), static_cast<int>(t.boundary_loops.size()), t.num_components};
}

int slivers_in(const TriMesh& m) {
  const double diag = bbox_diagonal(m);
  int count = 0;
  for (const Triangle& t : m.triangles) {
    count += detail::is_sliver(m.positions[static_cast<size_t>(t[0])], m.positions[static_cast<size_t>(t[1])],
                               m.positions[static_cast<size_t>(t[2])], diag)
                 ? 1
                 : 0;
  }
  return count;
}

// The maps of a cleaned mesh agree (faces added by filling stand for a face next to them).
void expect_maps(const TriMesh& input, const CleanMesh& c) {
  ASSERT_EQ(c.face_source.size(), c.mesh.triangles.size());
  const size_t own = c.face_source.size() - static_cast<size_t>(c.report.hole_faces_added);
  for (size_t f = 0; f < own; ++f) {
    EXPECT_EQ(c.input_face_to_clean[static_cast<size_t>(c.face_source[f])], static_cast<int>(f));
  }
  for (int f : c.face_source) EXPECT_TRUE(f >= 0 && f < input.num_faces());
  ASSERT_EQ(c.input_vertex_to_clean.size(), input.positions.size());
  for (int v : c.input_vertex_to_clean) EXPECT_LT(v, c.mesh.num_vertices());
  ASSERT_EQ(c.vertex_source.size(), c.mesh.positions.size());
}

// A 3 x 3 grid whose horizontal edge a-b (a = vertex 5, b = 6) carries a cap: vertex p on
// the middle of a-b, the face above split at p, and the zero-area face (a, b, p) between.
TriMesh grid_with_cap() {
  TriMesh m = test::grid(3, 3);
  const int a = 5, b = 6, c = 10;
  const auto above = std::find(m.triangles.begin(), m.triangles.end(), Triangle{a, b, c});
  EXPECT_NE(above, m.triangles.end());
  const int p = m.num_vertices();
  m.positions.push_back(0.5 * (m.positions[5] + m.positions[6]));
  *above = {a, p, c};
  m.triangles.push_back({p, b, c});
  m.triangles.push_back({a, b, p});
  return m;
}

TEST(Repair, CapSliverIsFlipped) {
  const TriMesh m = grid_with_cap();
  ASSERT_EQ(slivers_in(m), 1);
  const Shape before = shape_of(m);
  const CleanMesh c = clean_mesh(m);
  expect_maps(m, c);
  EXPECT_EQ(c.report.slivers_removed, 1);
  EXPECT_EQ(c.report.zero_area_faces, 0);
  EXPECT_EQ(c.mesh.num_faces(), m.num_faces());  // a flip keeps the count
  EXPECT_EQ(slivers_in(c.mesh), 0);
  const Shape after = shape_of(c.mesh);
  EXPECT_EQ(after.euler, before.euler);
  EXPECT_EQ(after.loops, before.loops);
  EXPECT_EQ(c.mesh.positions, m.positions);  // nothing moves
  const auto messages = c.report.messages();
  EXPECT_NE(std::find(messages.begin(), messages.end(),
                      "removed 1 sliver face (zero area or needle-thin) by collapsing or flipping edges"),
            messages.end());
  // Asked not to, the sliver stays and is only counted.
  CleanOptions keep;
  keep.remove_slivers = false;
  const CleanMesh kept = clean_mesh(m, keep);
  EXPECT_EQ(kept.report.slivers_removed, 0);
  EXPECT_EQ(kept.report.zero_area_faces, 1);
  EXPECT_EQ(kept.mesh.triangles, m.triangles);
}

// Vertex q a hair (1e-13) from vertex a = 5 on the interior diagonal 5-10, both faces of the
// diagonal split at q: two needles, which one collapse of q into a removes.
TEST(Repair, NeedleSliversAreCollapsed) {
  const TriMesh grid = test::grid(3, 3);
  TriMesh m = grid;
  const int a = 5, c = 10, q = m.num_vertices();
  m.positions.push_back(m.positions[5] + 1e-13 * (m.positions[10] - m.positions[5]));
  std::vector<Triangle> split;
  for (const Triangle& t : m.triangles) {
    const auto has = [&](int v) { return std::find(t.begin(), t.end(), v) != t.end(); };
    if (!has(a) || !has(c)) {
      split.push_back(t);
      continue;
    }
    // Replace the edge a-c of t (in its direction) by a-q-c.
    for (int i = 0; i < 3; ++i) {
      const int u = t[static_cast<size_t>(i)], w = t[static_cast<size_t>((i + 1) % 3)], x = t[static_cast<size_t>((i + 2) % 3)];
      if ((u == a && w == c) || (u == c && w == a)) {
        split.push_back({u, q, x});
        split.push_back({q, w, x});
      }
    }
  }
  m.triangles = split;
  ASSERT_EQ(m.num_faces(), grid.num_faces() + 2);
  ASSERT_EQ(slivers_in(m), 2);
  const CleanMesh c0 = clean_mesh(m);
  expect_maps(m, c0);
  EXPECT_EQ(c0.report.slivers_removed, 1);
  EXPECT_EQ(c0.mesh.num_faces(), grid.num_faces());
  EXPECT_EQ(c0.mesh.num_vertices(), grid.num_vertices());
  EXPECT_EQ(c0.mesh.positions, grid.positions);  // q went into a: no position moved
  EXPECT_EQ(c0.input_vertex_to_clean[static_cast<size_t>(q)], a);
  EXPECT_EQ(slivers_in(c0.mesh), 0);
  const Shape before = shape_of(m), after = shape_of(c0.mesh);
  EXPECT_EQ(after.euler, before.euler);
  EXPECT_EQ(after.loops, before.loops);
}

// A torus with holes cut: faces removed by index.
TriMesh without_faces(const TriMesh& m, std::vector<int> drop) {
  std::sort(drop.begin(), drop.end());
  TriMesh out;
  out.positions = m.positions;
  for (int f = 0; f < m.num_faces(); ++f) {
    if (!std::binary_search(drop.begin(), drop.end(), f)) out.triangles.push_back(m.triangles[static_cast<size_t>(f)]);
  }
  return out;
}

std::vector<int> faces_around(const TriMesh& m, int v) {
  std::vector<int> out;
  for (int f = 0; f < m.num_faces(); ++f) {
    const Triangle& t = m.triangles[static_cast<size_t>(f)];
    if (std::find(t.begin(), t.end(), v) != t.end()) out.push_back(f);
  }
  return out;
}

CleanMesh fill(const TriMesh& m, int max_edges) {
  CleanOptions o;
  o.fill_holes_max_edges = max_edges;
  return clean_mesh(m, o);
}

TEST(Repair, HolesOfThreeAndSixAreFilledOnlyWhenAskedAndSmallEnough) {
  const TriMesh torus = test::torus(12, 8);
  ASSERT_EQ(shape_of(torus).euler, 0);
  // Hole of 3: one face; hole of 6: the six faces around vertex 50 (far from face 0).
  std::vector<int> drop = faces_around(torus, 50);
  ASSERT_EQ(drop.size(), 6u);
  drop.push_back(0);
  const TriMesh holed = without_faces(torus, drop);
  const CleanMesh off = clean_mesh(holed);
  EXPECT_EQ(off.report.holes_filled, 0);
  EXPECT_EQ(shape_of(off.mesh).loops, 2);
  EXPECT_EQ(shape_of(off.mesh).euler, -2);

  const CleanMesh three = fill(holed, 5);
  expect_maps(holed, three);
  EXPECT_EQ(three.report.holes_filled, 1);
  EXPECT_EQ(three.report.hole_faces_added, 1);
  EXPECT_EQ(shape_of(three.mesh).loops, 1);
  EXPECT_EQ(shape_of(three.mesh).euler, -1);

  const CleanMesh both = fill(holed, 6);
  expect_maps(holed, both);
  EXPECT_EQ(both.report.holes_filled, 2);
  EXPECT_EQ(both.report.hole_faces_added, 1 + 4);
  const Shape closed = shape_of(both.mesh);
  EXPECT_EQ(closed.loops, 0);
  EXPECT_EQ(closed.euler, 0);  // a torus again, without the centre vertex
  EXPECT_GT(signed_volume(both.mesh), 0.0);
  EXPECT_EQ(slivers_in(both.mesh), 0);
  const auto messages = both.report.messages();
  EXPECT_NE(std::find(messages.begin(), messages.end(), "filled 2 holes with 5 faces"), messages.end());
}

TEST(Repair, HolesOfFortyEdgesAreFilledUpToTheLimit) {
  const TriMesh m = test::tube(40, 3, 1.0, 1.5);  // two circles of 40 edges
  EXPECT_EQ(shape_of(clean_mesh(m).mesh).loops, 2);
  const CleanMesh below = fill(m, 39);
  EXPECT_EQ(below.report.holes_filled, 0);
  EXPECT_EQ(below.mesh.triangles, clean_mesh(m).mesh.triangles);
  const CleanMesh capped = fill(m, 40);
  expect_maps(m, capped);
  EXPECT_EQ(capped.report.holes_filled, 2);
  EXPECT_EQ(capped.report.hole_faces_added, 2 * 38);
  const Shape s = shape_of(capped.mesh);
  EXPECT_EQ(s.loops, 0);
  EXPECT_EQ(s.euler, 2);
  EXPECT_GT(signed_volume(capped.mesh), 0.0);  // closed now: outward
  // The caps are flat discs: their area is two circles' polygons, 2 * 20 sin(2 pi / 40).
  double added = 0.0;
  for (size_t f = static_cast<size_t>(m.num_faces()); f < capped.mesh.triangles.size(); ++f)
    added += face_area(capped.mesh, static_cast<int>(f));
  EXPECT_NEAR(added, 2.0 * 20.0 * std::sin(2.0 * kPi / 40.0), 1e-9);
  CleanOptions bad;
  bad.fill_holes_max_edges = 501;
  EXPECT_THROW(clean_mesh(m, bad), InputError);
}

// Unit cube as a soup of 12 triangles, shifted.
TriMesh cube_at(const Vec3& offset) {
  TriMesh m = test::cube_soup();
  for (Vec3& p : m.positions) p += offset;
  return m;
}

TriMesh joined(const std::vector<TriMesh>& parts) {
  TriMesh out;
  for (const TriMesh& part : parts) {
    const int base = out.num_vertices();
    out.positions.insert(out.positions.end(), part.positions.begin(), part.positions.end());
    for (const Triangle& t : part.triangles) out.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
  return out;
}

TEST(Repair, TwoCubesOnAnEdgeNameItAndKeepOneClosedCube) {
  const TriMesh m = joined({cube_at(Vec3(0, 0, 0)), cube_at(Vec3(1, 1, 0))});  // share x = y = 1
  try {
    clean_mesh(m);
    FAIL() << "non-manifold edge not refused";
  } catch (const NonManifoldError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("non-manifold edge between vertices "), std::string::npos) << what;
    EXPECT_NE(what.find(" at (1, 1, 0.5): shared by 4 faces"), std::string::npos) << what;
    EXPECT_EQ(e.nonmanifold_edges, 1);
    EXPECT_EQ(e.largest_part_faces, 12);
    EXPECT_EQ(e.total_faces, 24);
  }
  CleanOptions o;
  o.largest_manifold_part = true;
  const CleanMesh c = clean_mesh(m, o);
  expect_maps(m, c);
  EXPECT_EQ(c.mesh.num_faces(), 12);
  EXPECT_EQ(c.mesh.num_vertices(), 8);
  const Shape s = shape_of(c.mesh);
  EXPECT_EQ(s.euler, 2);
  EXPECT_EQ(s.loops, 0);
  EXPECT_EQ(s.components, 1);
  EXPECT_NEAR(signed_volume(c.mesh), 1.0, 1e-12);
  for (const Vec3& p : c.mesh.positions) EXPECT_LE(p.maxCoeff(), 1.0);  // the first cube (tie)
  EXPECT_EQ(c.report.nonmanifold_edges_cut, 1);
  EXPECT_EQ(c.report.faces_outside_part, 12);
  EXPECT_EQ(c.report.parts_dropped, 1);
  EXPECT_EQ(c.report.unreferenced_vertices_removed, 0);  // the other cube's are not "unused"
  for (int f = 12; f < 24; ++f) EXPECT_EQ(c.input_face_to_clean[static_cast<size_t>(f)], -1);
  const auto messages = c.report.messages();
  EXPECT_NE(std::find(messages.begin(), messages.end(),
                      "kept the largest manifold part (12 of 24 faces): cut at 1 non-manifold edge, dropped 12 "
                      "faces in 1 other part"),
            messages.end());
}

// Two cubes apart, each closed and manifold: kept both unless the largest part is asked for,
// which keeps the larger one whole (a part joined by no edge is dropped, as a cut-off sheet is).
TEST(Repair, LargestPartDropsSeparateParts) {
  TriMesh big = cube_at(Vec3(0, 0, 0));
  for (Vec3& p : big.positions) p *= 2.0;
  const TriMesh m = joined({cube_at(Vec3(5, 0, 0)), big});
  const CleanMesh both = clean_mesh(m);
  EXPECT_EQ(both.mesh.num_faces(), 24);
  EXPECT_EQ(both.report.components, 2);
  EXPECT_EQ(both.report.parts_dropped, 0);
  CleanOptions o;
  o.largest_manifold_part = true;
  const CleanMesh c = clean_mesh(m, o);
  expect_maps(m, c);
  EXPECT_EQ(c.mesh.num_faces(), 12);
  EXPECT_EQ(c.report.components, 1);
  EXPECT_NEAR(signed_volume(c.mesh), 8.0, 1e-12);  // the big cube
  EXPECT_EQ(c.report.nonmanifold_edges_cut, 0);
  EXPECT_EQ(c.report.faces_before_cut, 24);
  EXPECT_EQ(c.report.faces_outside_part, 12);
  EXPECT_EQ(c.report.parts_dropped, 1);
  EXPECT_EQ(c.report.unreferenced_vertices_removed, 0);
  for (int f = 0; f < 12; ++f) EXPECT_EQ(c.input_face_to_clean[static_cast<size_t>(f)], -1);
  const auto messages = c.report.messages();
  EXPECT_NE(std::find(messages.begin(), messages.end(),
                      "kept the largest part (12 of 24 faces): dropped 12 faces in 1 other part"),
            messages.end());
  // A mesh of one part is left exactly as it is.
  const TriMesh one = cube_at(Vec3(0, 0, 0));
  const CleanMesh alone = clean_mesh(one, o);
  EXPECT_EQ(alone.mesh.triangles, clean_mesh(one).mesh.triangles);
  EXPECT_EQ(alone.report.faces_before_cut, 0);
  EXPECT_EQ(alone.report.messages(), clean_mesh(one).report.messages());  // welded, nothing dropped
}

// Three rectangular sheets (two triangles each) on the spine from (0,0,0) to (0,0,1),
// sizes 1, 2 and 1.5 across: the 2 one is the largest part.
TEST(Repair, BookOfThreeSheetsKeepsTheLargest) {
  TriMesh m;
  m.positions = {Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(1, 0, 1),
                 Vec3(0, 2, 0), Vec3(0, 2, 1), Vec3(-1.5, 0, 0), Vec3(-1.5, 0, 1)};
  for (int leaf : {2, 4, 6}) {
    m.triangles.push_back({0, leaf, leaf + 1});
    m.triangles.push_back({0, leaf + 1, 1});
  }
  try {
    clean_mesh(m);
    FAIL() << "non-manifold edge not refused";
  } catch (const NonManifoldError& e) {
    EXPECT_EQ(std::string(e.what()), "non-manifold edge between vertices 0 and 1 at (0, 0, 0.5): shared by 3 faces");
    EXPECT_EQ(e.largest_part_faces, 2);
    EXPECT_EQ(e.total_faces, 6);
  }
  CleanOptions o;
  o.largest_manifold_part = true;
  const CleanMesh c = clean_mesh(m, o);
  expect_maps(m, c);
  EXPECT_EQ(c.mesh.num_faces(), 2);
  EXPECT_EQ(c.face_source, (std::vector<int>{2, 3}));
  const Shape s = shape_of(c.mesh);
  EXPECT_EQ(s.euler, 1);
  EXPECT_EQ(s.loops, 1);
  EXPECT_EQ(c.report.parts_dropped, 2);
  EXPECT_EQ(c.report.faces_outside_part, 4);
  EXPECT_NEAR(total_area(c.mesh), 2.0, 1e-12);
}

}  // namespace
}  // namespace ff

namespace ff {
namespace {

// Slivers everywhere: whatever sliver removal can or cannot do, the result keeps the topology,
// stays oriented and edge-manifold, and nothing throws.
TEST(Repair, ManySliversKeepTheTopology) {
  for (int variant = 0; variant < 3; ++variant) {
    SCOPED_TRACE(variant);
    TriMesh m = test::grid(8, 8);
    for (size_t v = 0; v < m.positions.size(); ++v) {
      Vec3& p = m.positions[v];
      if (variant == 0) p.y() = 0.0;                                    // every face flat: all zero area
      if (variant == 1 && v % 3 == 0) p.x() = std::floor(p.x() / 2) * 2;  // needles and caps
      if (variant == 2 && v % 2 == 0) p += Vec3(1e-12, -1e-12, 0.0) * static_cast<double>(v % 5);
      if (variant == 2 && v % 4 == 1) p.y() = std::floor(p.y() / 4) * 4;
    }
    CleanOptions keep;
    keep.remove_slivers = false;
    const CleanMesh before = clean_mesh(m, keep);
    const CleanMesh after = clean_mesh(m);
    expect_maps(m, after);
    const Shape a = shape_of(before.mesh), b = shape_of(after.mesh);
    EXPECT_EQ(b.euler, a.euler);
    EXPECT_EQ(b.loops, a.loops);
    EXPECT_EQ(b.components, a.components);
    EXPECT_LE(slivers_in(after.mesh), slivers_in(before.mesh));
    if (variant > 0) {
      EXPECT_GT(after.report.slivers_removed, 0);
    }
  }
}

}  // namespace
}  // namespace ff
