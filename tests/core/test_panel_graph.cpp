// The panel graph of hand-made clusterings of a grid and a torus: corners (3+ clusters, the
// boundary as kBoundary) with their clusters in counter-clockwise order, boundary loops that
// start after a corner and run counter-clockwise, the not-a-disk problems, and vertex fans.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <vector>

#include "core/mesh/topology.h"
#include "core/panels/panel_graph.h"
#include "synthetic_meshes.h"

namespace ff {
namespace {

// Per face labels of test::grid(nx, ny) (faces 2 (j nx + i) and +1 are cell (i, j)).
std::vector<int> cell_labels(int nx, int ny, const std::function<int(int, int)>& label) {
  std::vector<int> labels(static_cast<size_t>(2 * nx * ny));
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i)
      labels[static_cast<size_t>(2 * (j * nx + i))] = labels[static_cast<size_t>(2 * (j * nx + i) + 1)] = label(i, j);
  }
  return labels;
}

struct Fixture {
  TriMesh mesh;
  MeshTopology topology;
  std::vector<int> labels;
  PanelGraph graph;

  Fixture(TriMesh m, std::vector<int> l, int clusters)
      : mesh(std::move(m)), topology(build_topology(mesh)), labels(std::move(l)) {
    graph = build_panel_graph(mesh, topology, labels, clusters);
  }
  int tail(int h) const { return mesh.triangles[static_cast<size_t>(h / 3)][static_cast<size_t>(h % 3)]; }
  int head(int h) const { return mesh.triangles[static_cast<size_t>(h / 3)][static_cast<size_t>((h % 3 + 1) % 3)]; }
  const Corner* corner_at(int v) const {
    const int c = graph.corner_of_vertex[static_cast<size_t>(v)];
    return c < 0 ? nullptr : &graph.corners[static_cast<size_t>(c)];
  }
};

// `cycle` is a rotation of `expected`.
bool same_cycle(const std::vector<int>& cycle, const std::vector<int>& expected) {
  if (cycle.size() != expected.size()) return false;
  for (size_t r = 0; r < cycle.size(); ++r) {
    std::vector<int> rotated = cycle;
    std::rotate(rotated.begin(), rotated.begin() + static_cast<long>(r), rotated.end());
    if (rotated == expected) return true;
  }
  return false;
}

// The loop of cluster c is closed, consists of exactly c's boundary half-edges, starts just
// after a corner and runs counter-clockwise (planar mesh in z = 0, normals +z).
void expect_ccw_loop(const Fixture& fx, int c) {
  const std::vector<int>& loop = fx.graph.loops[static_cast<size_t>(c)];
  ASSERT_FALSE(loop.empty()) << "cluster " << c;
  std::set<int> expected;
  for (int h = 0; h < 3 * fx.mesh.num_faces(); ++h) {
    if (fx.labels[static_cast<size_t>(h / 3)] == c && PanelGraph::other_side(fx.topology, fx.labels, h) != c)
      expected.insert(h);
  }
  EXPECT_EQ(std::set<int>(loop.begin(), loop.end()), expected) << "cluster " << c;
  EXPECT_EQ(loop.size(), expected.size()) << "cluster " << c;
  for (size_t k = 0; k < loop.size(); ++k) {
    EXPECT_EQ(fx.head(loop[k]), fx.tail(loop[(k + 1) % loop.size()])) << "cluster " << c << " step " << k;
  }
  EXPECT_GE(fx.graph.corner_of_vertex[static_cast<size_t>(fx.tail(loop.front()))], 0) << "cluster " << c;
  double twice_area = 0.0;
  for (int h : loop) {
    const Vec3& a = fx.mesh.positions[static_cast<size_t>(fx.tail(h))];
    const Vec3& b = fx.mesh.positions[static_cast<size_t>(fx.head(h))];
    twice_area += a.x() * b.y() - a.y() * b.x();
  }
  EXPECT_GT(twice_area, 0.0) << "cluster " << c;
}

// 4 x 4 grid: 0 bottom left, 1 bottom right, 2 the top half.
Fixture three_clusters() {
  return Fixture(test::grid(4, 4), cell_labels(4, 4, [](int i, int j) { return j >= 2 ? 2 : (i < 2 ? 0 : 1); }), 3);
}

TEST(PanelGraph, CornersAreWhereThreeClustersOrTheBoundaryMeet) {
  const Fixture fx = three_clusters();
  const auto id = [](int i, int j) { return 5 * j + i; };
  std::set<int> corner_vertices;
  for (const Corner& c : fx.graph.corners) corner_vertices.insert(c.vertex);
  EXPECT_EQ(corner_vertices, (std::set<int>{id(2, 0), id(0, 2), id(2, 2), id(4, 2)}));
  for (size_t k = 0; k < fx.graph.corners.size(); ++k) {
    EXPECT_EQ(fx.graph.corner_of_vertex[static_cast<size_t>(fx.graph.corners[k].vertex)], static_cast<int>(k));
  }
  ASSERT_NE(fx.corner_at(id(2, 2)), nullptr);
  EXPECT_FALSE(fx.corner_at(id(2, 2))->on_boundary);
  // Seen from +z, counter-clockwise: bottom left (0), bottom right (1), top (2).
  EXPECT_TRUE(same_cycle(fx.corner_at(id(2, 2))->clusters, {0, 1, 2}));
  // Boundary corners: counter-clockwise from one boundary edge to the other, then kBoundary.
  ASSERT_NE(fx.corner_at(id(2, 0)), nullptr);
  EXPECT_TRUE(fx.corner_at(id(2, 0))->on_boundary);
  EXPECT_EQ(fx.corner_at(id(2, 0))->clusters, (std::vector<int>{1, 0, kBoundary}));
  EXPECT_EQ(fx.corner_at(id(0, 2))->clusters, (std::vector<int>{0, 2, kBoundary}));
  EXPECT_EQ(fx.corner_at(id(4, 2))->clusters, (std::vector<int>{2, 1, kBoundary}));
  EXPECT_EQ(fx.corner_at(id(0, 0)), nullptr);  // one cluster and the boundary: not a corner
  EXPECT_EQ(fx.corner_at(id(1, 2)), nullptr);  // two clusters: inside a chain
}

TEST(PanelGraph, LoopsStartAfterACornerAndRunCounterClockwise) {
  const Fixture fx = three_clusters();
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(fx.graph.problems[static_cast<size_t>(c)], 0u) << "cluster " << c;
    expect_ccw_loop(fx, c);
  }
  EXPECT_EQ(fx.graph.loops[0].size(), 8u);
  EXPECT_EQ(fx.graph.loops[2].size(), 12u);
}

TEST(PanelGraph, OneClusterIsAllBorderWithoutCorners) {
  const Fixture fx(test::grid(3, 2), std::vector<int>(12, 0), 1);
  EXPECT_TRUE(fx.graph.corners.empty());
  EXPECT_EQ(fx.graph.problems[0], 0u);
  EXPECT_EQ(fx.graph.loops[0].size(), 10u);
}

TEST(PanelGraph, RingAroundAnEnclosedCluster) {
  const Fixture fx(test::grid(7, 7),
                   cell_labels(7, 7, [](int i, int j) { return i >= 2 && i <= 4 && j >= 2 && j <= 4 ? 1 : 0; }), 2);
  EXPECT_TRUE(fx.graph.corners.empty());
  EXPECT_NE(fx.graph.problems[0] & kHole, 0u);
  EXPECT_EQ(fx.graph.problems[0] & kEnclosed, 0u);
  EXPECT_EQ(fx.graph.problems[1], static_cast<unsigned>(kEnclosed));
  EXPECT_TRUE(fx.graph.loops[0].empty());
  EXPECT_TRUE(fx.graph.loops[1].empty());
}

TEST(PanelGraph, TwoSeparateChainsWithOneNeighbour) {
  // A U of 0 holding 2 (middle row) and 1 (top row, between the U's arms): 1 touches 0 left
  // and right, separated by 2 below and the boundary above.
  const Fixture fx(test::grid(5, 3),
                   cell_labels(5, 3, [](int i, int j) { return i == 0 || i == 4 || j == 0 ? 0 : (j == 2 ? 1 : 2); }),
                   3);
  EXPECT_EQ(fx.graph.problems[1], static_cast<unsigned>(kTwoChains));
  EXPECT_NE(fx.graph.problems[0] & kTwoChains, 0u);
  EXPECT_EQ(fx.graph.problems[2], 0u);
  EXPECT_FALSE(fx.graph.loops[1].empty());  // kTwoChains keeps its loop
  expect_ccw_loop(fx, 2);
}

TEST(PanelGraph, PinchAtAVertex) {
  // 0 everywhere but the centre cell (1) and the top left cell (2): around vertex (1, 2) the
  // clusters read 0, 2, 0, 1, so 0 touches itself there.
  const Fixture fx(test::grid(3, 3),
                   cell_labels(3, 3, [](int i, int j) { return i == 1 && j == 1 ? 1 : (i == 0 && j == 2 ? 2 : 0); }),
                   3);
  EXPECT_NE(fx.graph.problems[0] & kPinch, 0u);
  EXPECT_EQ(fx.graph.problems[1] & kPinch, 0u);
  EXPECT_EQ(fx.graph.problems[2] & kPinch, 0u);
  const Corner* c = fx.corner_at(4 * 2 + 1);
  ASSERT_NE(c, nullptr);
  EXPECT_TRUE(same_cycle(c->clusters, {0, 2, 0, 1}));
}

TEST(PanelGraph, TorusClustersThatAreNotDisks) {
  const int nu = 12, nv = 6;
  // test::torus numbers its faces like test::grid.
  const auto torus_labels = [&](const std::function<int(int, int)>& label) { return cell_labels(nu, nv, label); };
  // Two halves, each a tube wrapping around the torus tube: annuli with two loops.
  const Fixture halves(test::torus(nu, nv), torus_labels([&](int i, int) { return i < nu / 2 ? 0 : 1; }), 2);
  for (unsigned p : halves.graph.problems) EXPECT_NE(p & (kHole | kHandle), 0u);
  EXPECT_NE(halves.graph.problems[0] & kHole, 0u);
  // The torus minus one cell: one loop but genus 1 (a handle); the cell is enclosed.
  const Fixture punctured(test::torus(nu, nv), torus_labels([](int i, int j) { return i == 3 && j == 2 ? 1 : 0; }), 2);
  EXPECT_EQ(punctured.graph.problems[0], static_cast<unsigned>(kHandle));
  EXPECT_EQ(punctured.graph.problems[1], static_cast<unsigned>(kEnclosed));
  // The whole torus as one cluster: no loop at all, not a disk.
  const Fixture whole(test::torus(nu, nv), std::vector<int>(static_cast<size_t>(2 * nu * nv), 0), 1);
  EXPECT_NE(whole.graph.problems[0] & kHandle, 0u);
}

// The cube [0, n]^3 with n x n squares per side, outward; labels: one cluster per side,
// whose outward normal is normals[label].
TriMesh subdivided_cube(int n, std::vector<int>& labels, std::vector<Vec3>& normals) {
  TriMesh m;
  std::map<std::array<int, 3>, int> index;
  const auto vertex = [&](const std::array<int, 3>& p) {
    const auto [it, added] = index.emplace(p, m.num_vertices());
    if (added) m.positions.emplace_back(p[0], p[1], p[2]);
    return it->second;
  };
  for (int a = 0; a < 3; ++a) {
    for (int s : {1, -1}) {
      // (u, v) with u x v = s e_a.
      const int u = s > 0 ? (a + 1) % 3 : (a + 2) % 3, v = s > 0 ? (a + 2) % 3 : (a + 1) % 3;
      const auto at = [&](int i, int j) {
        std::array<int, 3> p{};
        p[static_cast<size_t>(a)] = s > 0 ? n : 0;
        p[static_cast<size_t>(u)] = i;
        p[static_cast<size_t>(v)] = j;
        return vertex(p);
      };
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
          m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
          m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
          labels.insert(labels.end(), 2, static_cast<int>(normals.size()));
        }
      }
      normals.push_back(s * Vec3::Unit(a));
    }
  }
  return m;
}

int local(const TriMesh& mesh, int f, int v) {
  const Triangle& t = mesh.triangles[static_cast<size_t>(f)];
  return t[0] == v ? 0 : (t[1] == v ? 1 : 2);
}

// Every fan holds each face at v once, in counter-clockwise order: the vertex after v in a
// face is the vertex before v in the previous one (they share that edge through v).
void expect_ccw_fans(const TriMesh& mesh, bool planar) {
  const MeshTopology topology = build_topology(mesh);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    bool on_boundary = true;
    const std::vector<int> fan = vertex_fan(mesh, topology, v, on_boundary);
    std::vector<int> incident(topology.vertex_faces.begin() + topology.vertex_face_offsets[static_cast<size_t>(v)],
                              topology.vertex_faces.begin() + topology.vertex_face_offsets[static_cast<size_t>(v) + 1]);
    std::vector<int> sorted = fan;
    std::sort(sorted.begin(), sorted.end());
    ASSERT_EQ(sorted, incident) << "vertex " << v;
    const auto prev_of = [&](int f) {
      return mesh.triangles[static_cast<size_t>(f)][static_cast<size_t>((local(mesh, f, v) + 2) % 3)];
    };
    const auto next_of = [&](int f) {
      return mesh.triangles[static_cast<size_t>(f)][static_cast<size_t>((local(mesh, f, v) + 1) % 3)];
    };
    const size_t steps = on_boundary ? fan.size() - 1 : fan.size();
    for (size_t k = 0; k < steps; ++k) EXPECT_EQ(next_of(fan[(k + 1) % fan.size()]), prev_of(fan[k])) << "vertex " << v;
    bool boundary_vertex = false;
    for (int f : incident) {
      const int i = local(mesh, f, v);
      boundary_vertex = boundary_vertex ||
                        topology.face_neighbors[static_cast<size_t>(f)][static_cast<size_t>(i)] < 0 ||
                        topology.face_neighbors[static_cast<size_t>(f)][static_cast<size_t>((i + 2) % 3)] < 0;
    }
    EXPECT_EQ(on_boundary, boundary_vertex) << "vertex " << v;
    if (on_boundary) {
      EXPECT_LT(
          topology.face_neighbors[static_cast<size_t>(fan.front())][static_cast<size_t>(local(mesh, fan.front(), v))],
          0);
      EXPECT_LT(topology.face_neighbors[static_cast<size_t>(fan.back())]
                                       [static_cast<size_t>((local(mesh, fan.back(), v) + 2) % 3)],
                0);
    }
    if (planar) {
      // Geometrically: the centroid angles about v increase, by less than a full turn.
      double prev = 0.0, total = 0.0;
      for (size_t k = 0; k < fan.size(); ++k) {
        const Vec3 d = face_centroid(mesh, fan[k]) - mesh.positions[static_cast<size_t>(v)];
        const double angle = std::atan2(d.y(), d.x());
        if (k > 0) {
          const double step = std::remainder(angle - prev, 2 * kPi);
          EXPECT_GT(step, 0.0) << "vertex " << v;
          total += step;
        }
        prev = angle;
      }
      EXPECT_LT(total, 2 * kPi);
    }
  }
}

TEST(PanelGraph, VertexFansAreCounterClockwise) {
  expect_ccw_fans(test::grid(4, 3), true);
  expect_ccw_fans(test::annulus(10, 2), true);
  expect_ccw_fans(test::torus(8, 5), false);
}

TEST(PanelGraph, CubeSidesMeetAtEightCornersInCounterClockwiseOrder) {
  std::vector<int> labels;
  std::vector<Vec3> normals;
  TriMesh cube = subdivided_cube(3, labels, normals);
  ASSERT_GT(test::signed_volume(cube), 0.0);  // outward
  const Fixture fx(std::move(cube), labels, 6);
  ASSERT_EQ(fx.graph.corners.size(), 8u);
  const Vec3 centre(1.5, 1.5, 1.5);
  for (const Corner& c : fx.graph.corners) {
    EXPECT_FALSE(c.on_boundary);
    ASSERT_EQ(c.clusters.size(), 3u);
    const Vec3 out = fx.mesh.positions[static_cast<size_t>(c.vertex)] - centre;
    EXPECT_NEAR(out.cwiseAbs().minCoeff(), 1.5, 1e-12);  // a corner of the cube
    for (size_t k = 0; k < 3; ++k) {
      const Vec3& a = normals[static_cast<size_t>(c.clusters[k])];
      const Vec3& b = normals[static_cast<size_t>(c.clusters[(k + 1) % 3])];
      EXPECT_GT(a.cross(b).dot(out), 0.0) << "corner at " << out.transpose();
    }
  }
  for (int side = 0; side < 6; ++side) {
    EXPECT_EQ(fx.graph.problems[static_cast<size_t>(side)], 0u);
    EXPECT_EQ(fx.graph.loops[static_cast<size_t>(side)].size(), 12u);
    EXPECT_GE(fx.graph.corner_of_vertex[static_cast<size_t>(fx.tail(fx.graph.loops[static_cast<size_t>(side)][0]))], 0);
  }
  expect_ccw_fans(fx.mesh, false);
}

}  // namespace
}  // namespace ff
