#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/prepare/isotropic_remesh.h"
#include "core/quality/closest_point.h"
#include "core/shapes/shapes.h"
#include "core/util/error.h"
#include "remesh_checks.h"
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

}  // namespace
}  // namespace ff
