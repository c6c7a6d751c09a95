#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/prepare/isotropic_remesh.h"
#include "core/quality/closest_point.h"
#include "core/mesh/topology.h"
#include "core/shapes/hard_cases.h"
#include "core/util/angles.h"
#include "core/util/error.h"
#include "remesh_checks.h"
#include "synthetic_meshes.h"
#include "test_meshes.h"

namespace ff {
namespace {

using test::SharedMesh;

// Every shared mesh remeshed to an edge length giving about 12k triangles: the big ones are
// coarsened, the small ones refined.
class RemeshSharedMesh : public ::testing::TestWithParam<SharedMesh> {};

TEST_P(RemeshSharedMesh, EdgeLengthsDistanceAndTopology) {
  const TriMesh input = test::load_clean(GetParam().file);
  const double L = test::edge_length_for(input, 12000);
  IsotropicRemeshOptions options;
  options.target_edge_length = L;
  const IsotropicRemeshResult r = isotropic_remesh(input, options);
  const test::EdgeStats e = test::edge_stats(r.mesh, L);
  const double distance = test::two_sided_distance(input, r.mesh);
  std::printf("[ remesh   ] %-18s %6d -> %6d triangles, L %.4g: %.2f%% of %d edges in [0.6, 1.5] L "
              "(ratios %.3f..%.3f), distance %.3f L, %d feature edges, %d corners\n",
              GetParam().file.c_str(), input.num_faces(), r.mesh.num_faces(), L, 100.0 * e.share(), e.edges,
              e.min_ratio, e.max_ratio, distance / L, r.feature_edges, r.feature_corners);
  // epcot.off is all creases (every dihedral above 50 degrees): every input vertex is a
  // fixed corner and every input edge stays, so only splits can happen there.
  EXPECT_GE(e.share(), GetParam().file == "epcot.off" ? 0.97 : 0.99);
  // Coarsening loses detail thinner than L (camelhead's ears); refining loses nothing.
  EXPECT_LT(distance, 0.75 * L);
  EXPECT_TRUE(test::summarize(r.mesh) == test::summarize(input));
  EXPECT_TRUE(test::consistently_oriented(r.mesh));
}

INSTANTIATE_TEST_SUITE_P(Shared, RemeshSharedMesh, ::testing::ValuesIn(test::shared_meshes()));

// Edges whose faces meet at more than `angle_deg`, as segments.
std::vector<std::array<Vec3, 2>> crease_segments(const TriMesh& m, double angle_deg) {
  const MeshTopology t = build_topology(m);
  std::vector<std::array<Vec3, 2>> out;
  for (int e = 0; e < t.num_edges(); ++e) {
    if (t.is_boundary_edge(e)) continue;
    const auto& f = t.edge_faces[static_cast<size_t>(e)];
    if (face_normal(m, f[0]).dot(face_normal(m, f[1])) < std::cos(angle_deg * kPi / 180.0)) {
      const auto& v = t.edge_vertices[static_cast<size_t>(e)];
      out.push_back({m.positions[static_cast<size_t>(v[0])], m.positions[static_cast<size_t>(v[1])]});
    }
  }
  return out;
}

// Distance from p to the nearest of the segments (degenerate triangles in a TriangleTree).
class SegmentSet {
 public:
  explicit SegmentSet(const std::vector<std::array<Vec3, 2>>& segments) : tree_(points(segments), tris(segments)) {}
  double distance(const Vec3& p) const { return tree_.closest_point(p).distance; }

 private:
  static std::vector<Vec3> points(const std::vector<std::array<Vec3, 2>>& s) {
    std::vector<Vec3> out;
    for (const auto& seg : s) out.insert(out.end(), {seg[0], seg[1]});
    return out;
  }
  static std::vector<Triangle> tris(const std::vector<std::array<Vec3, 2>>& s) {
    std::vector<Triangle> out;
    for (int i = 0; i < static_cast<int>(s.size()); ++i) out.push_back({2 * i, 2 * i + 1, 2 * i + 1});
    return out;
  }
  TriangleTree tree_;
};

// fandisk's creases (dihedral angles of 70-100 degrees) survive as edges: every input crease
// is covered by output crease edges and every output crease lies on an input crease.
TEST(IsotropicRemesh, FandiskCreasesStayEdges) {
  const TriMesh input = test::load_clean("fandisk.off");
  for (const double triangles : {4000.0, 40000.0}) {  // coarser and finer than the input
    const double L = test::edge_length_for(input, triangles);
    IsotropicRemeshOptions options;
    options.target_edge_length = L;
    const IsotropicRemeshResult r = isotropic_remesh(input, options);
    const auto in_creases = crease_segments(input, 60.0);
    const auto out_creases = crease_segments(r.mesh, 60.0);
    ASSERT_GT(in_creases.size(), 100u);
    const SegmentSet in_set(in_creases), out_set(out_creases);
    // Output crease vertices sit on the input creases (projected there); input creases are
    // within the chord error of a curved crease followed by edges of length about L.
    // (Coarser than the input, a few smooth but tight fillets become new sharp edges too.)
    double in_to_out = 0.0, out_to_in = 0.0;
    int on = 0, ends = 0;
    for (const auto& s : in_creases) in_to_out = std::max(in_to_out, out_set.distance(0.5 * (s[0] + s[1])));
    for (const auto& s : out_creases) {
      for (const Vec3& p : s) {
        const double d = in_set.distance(p);
        out_to_in = std::max(out_to_in, d);
        on += d <= 1e-6 * L;
        ++ends;
      }
    }
    std::printf("[ remesh   ] fandisk at %.0f triangles: %zu -> %zu crease edges; input creases within %.3g L of "
                "the output's, output crease vertices within %.3g L of the input's (%.1f%% on them)\n",
                triangles, in_creases.size(), out_creases.size(), in_to_out / L, out_to_in / L, 100.0 * on / ends);
    EXPECT_LT(in_to_out, 0.2 * L);
    EXPECT_LT(out_to_in, 0.2 * L);
    EXPECT_GE(on, 0.95 * ends);
  }
}

TEST(IsotropicRemesh, DeterministicAndCarriesADensity) {
  const TriMesh input = test::load_clean("bumpy.off");
  IsotropicRemeshOptions options;
  options.target_edge_length = test::edge_length_for(input, 5000);
  // A linear field is reproduced exactly by the interpolation at the projected points.
  for (const Vec3& p : input.positions) options.vertex_density.push_back(2.0 + 0.1 * p.x());
  const IsotropicRemeshResult a = isotropic_remesh(input, options);
  const IsotropicRemeshResult b = isotropic_remesh(input, options);
  EXPECT_EQ(a.mesh.positions, b.mesh.positions);
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
  ASSERT_EQ(a.vertex_density.size(), a.mesh.positions.size());
  for (size_t v = 0; v < a.vertex_density.size(); ++v) {
    // Exact for points on the input; the projection leaves them within rounding of it.
    EXPECT_NEAR(a.vertex_density[v], 2.0 + 0.1 * a.mesh.positions[v].x(), 0.02 * options.target_edge_length);
  }
}

TEST(IsotropicRemesh, ARoofKeepsItsCornersAndBoundary) {
  // make_roof_with_hole: a square outline with corner vertices and a round courtyard.
  const TriMesh roof = make_roof_with_hole(150);
  IsotropicRemeshOptions options;
  options.target_edge_length = test::edge_length_for(roof, 3000);
  const IsotropicRemeshResult r = isotropic_remesh(roof, options);
  EXPECT_TRUE(test::summarize(r.mesh) == test::summarize(roof));
  const BoundingBox in_box = bounding_box(roof), out_box = bounding_box(r.mesh);
  EXPECT_LT((in_box.lo - out_box.lo).head<2>().norm() + (in_box.hi - out_box.hi).head<2>().norm(), 1e-9);
  // The four outline corners are still vertices.
  int corners = 0;
  for (const Vec3& p : r.mesh.positions)
    if (std::abs(std::abs(p.x()) - 15.0) < 1e-9 && std::abs(std::abs(p.y()) - 15.0) < 1e-9) ++corners;
  EXPECT_EQ(corners, 4);
  EXPECT_GE(test::edge_stats(r.mesh, options.target_edge_length).share(), 0.99);
}

// A vertex moved far from the rest (a typo in a coordinate: 1e9 on a grid 10 across) makes
// slivers whose area is modest for their length: a target from the area (as the preparation
// chooses it) passes the area estimate, yet splitting their edges would make hundreds of
// millions of triangles. Refused before any splitting, naming the edge.
TEST(IsotropicRemesh, AStrayVertexIsRefusedUpFrontAndNamed) {
  TriMesh stray = test::grid(10, 10);
  stray.positions[60].z() = 1e9;  // (5, 5): six slivers 1e9 long
  IsotropicRemeshOptions options;
  options.target_edge_length = test::edge_length_for(stray, 2000);
  try {
    isotropic_remesh(stray, options);
    FAIL() << "a stray vertex was remeshed";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("would split the long edges into about"), std::string::npos) << message;
    EXPECT_NE(message.find("(5, 5, 1e+09)"), std::string::npos) << message;
    EXPECT_NE(message.find("a vertex far from the rest of the mesh?"), std::string::npos) << message;
  }
}

// The splitting itself stops at the limit, whatever the estimates said: a sliver 100 long and
// 1 wide, to a target of 1, estimates 116 triangles by area and 297 by its edges, yet its
// splits (cross edges to the far corner are long too) pass 300 before the collapses.
TEST(IsotropicRemesh, SplittingStopsAtTheTriangleLimit) {
  TriMesh sliver;
  sliver.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 100, 0)};
  sliver.triangles = {{0, 1, 2}};
  IsotropicRemeshOptions options;
  options.target_edge_length = 1.0;
  options.iterations = 1;
  EXPECT_GT(isotropic_remesh(sliver, options).mesh.num_faces(), 100);  // no limit in the way
  options.max_triangles = 300;
  try {
    isotropic_remesh(sliver, options);
    FAIL() << "the splitting went past the limit";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("splitting the long edges went past 300 triangles"), std::string::npos) << e.what();
  }
  options.max_triangles = 0;
  EXPECT_THROW(isotropic_remesh(sliver, options), InputError);
}

TEST(IsotropicRemesh, BadOptionsThrow) {
  const TriMesh roof = make_roof_with_hole(150);
  IsotropicRemeshOptions options;
  EXPECT_THROW(isotropic_remesh(roof, options), InputError);  // no target
  options.target_edge_length = std::nan("");
  EXPECT_THROW(isotropic_remesh(roof, options), InputError);
  options.target_edge_length = 1e-7;  // far too many triangles
  EXPECT_THROW(isotropic_remesh(roof, options), InputError);
  options.target_edge_length = 1.0;
  options.vertex_density = {1.0, 2.0};
  EXPECT_THROW(isotropic_remesh(roof, options), InputError);
  options.vertex_density.assign(roof.positions.size(), -1.0);
  EXPECT_THROW(isotropic_remesh(roof, options), InputError);
}

}  // namespace
}  // namespace ff
