// core/prepare/mesh_transfer.h: per-vertex values and triangle ids carried from one
// preparation of a surface to another.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/mesh/tri_mesh.h"
#include "core/prepare/mesh_transfer.h"
#include "core/prepare/prepare.h"
#include "core/util/error.h"
#include "synthetic_meshes.h"

namespace ff {
namespace {

using test::grid;
using test::torus;

// A grid of n x n squares scaled onto the unit square.
TriMesh unit_grid(int n) {
  TriMesh m = grid(n, n);
  for (Vec3& p : m.positions) p /= static_cast<double>(n);
  return m;
}

TEST(MeshTransfer, ALinearFieldOnAPlaneIsCarriedExactly) {
  const TriMesh coarse = unit_grid(4);
  const TriMesh fine = unit_grid(13);
  const auto f = [](const Vec3& p) { return 2.0 * p.x() - 3.0 * p.y() + 0.5; };
  std::vector<double> values;
  for (const Vec3& p : coarse.positions) values.push_back(f(p));
  const std::vector<double> out = transfer_vertex_values(coarse, values, fine);
  ASSERT_EQ(out.size(), fine.positions.size());
  for (size_t v = 0; v < out.size(); ++v) EXPECT_NEAR(out[v], f(fine.positions[v]), 1e-12) << "vertex " << v;
}

TEST(MeshTransfer, ValuesStayWithinTheirRangeOnACurvedRefinedSurface) {
  // A coarse torus refined by the page's own preparation: a step field (0 on one half, 4 on
  // the other) carries over within [0, 4], and the points far from the step keep their value.
  const TriMesh coarse = torus(16, 8);
  const TriMesh fine = prepare_surface(coarse, 200, {}).mesh;
  ASSERT_GT(fine.num_faces(), coarse.num_faces());
  std::vector<double> values;
  for (const Vec3& p : coarse.positions) values.push_back(p.x() > 0.0 ? 4.0 : 0.0);
  const std::vector<double> out = transfer_vertex_values(coarse, values, fine);
  int far_checked = 0;
  for (size_t v = 0; v < out.size(); ++v) {
    EXPECT_GE(out[v], -1e-12);
    EXPECT_LE(out[v], 4.0 + 1e-12);
    const double x = fine.positions[v].x();
    if (std::abs(x) > 2.2) {
      EXPECT_NEAR(out[v], x > 0.0 ? 4.0 : 0.0, 1e-9) << "vertex " << v;
      ++far_checked;
    }
  }
  EXPECT_GT(far_checked, 100);
}

TEST(MeshTransfer, FacesGoToTheTriangleWithTheNearestCentroid) {
  const TriMesh coarse = unit_grid(4);
  const TriMesh fine = unit_grid(12);
  std::vector<int> all;
  for (int f = 0; f < coarse.num_faces(); ++f) all.push_back(f);
  EXPECT_EQ(nearest_faces_by_centroid(coarse, all, coarse), all) << "the same mesh: every face is its own";
  const std::vector<int> mapped = nearest_faces_by_centroid(coarse, all, fine);
  ASSERT_EQ(mapped.size(), all.size());
  for (size_t i = 0; i < all.size(); ++i) {
    const Vec3 c = face_centroid(coarse, all[i]);
    const double found = (face_centroid(fine, mapped[i]) - c).norm();
    for (int g = 0; g < fine.num_faces(); ++g) EXPECT_LE(found, (face_centroid(fine, g) - c).norm() + 1e-15);
  }
}

TEST(MeshTransfer, BadInputIsRefusedByName) {
  const TriMesh m = unit_grid(2);
  EXPECT_THROW(transfer_vertex_values(m, {1.0, 2.0}, m), InputError);
  std::vector<double> values(m.positions.size(), 1.0);
  values[3] = std::nan("");
  EXPECT_THROW(transfer_vertex_values(m, values, m), InputError);
  EXPECT_THROW(transfer_vertex_values(TriMesh{}, {}, m), InputError);
  EXPECT_THROW(nearest_faces_by_centroid(m, {m.num_faces()}, m), InputError);
  EXPECT_THROW(nearest_faces_by_centroid(m, {-1}, m), InputError);
  EXPECT_THROW(nearest_faces_by_centroid(m, {0}, TriMesh{}), InputError);
  EXPECT_TRUE(nearest_faces_by_centroid(m, {}, m).empty());
}

}  // namespace
}  // namespace ff
