// The border term of the final plane fit (plane_fit.h: border_moments, surface_fit_planes'
// border_weight, planes_toward) and the bound it buys on a shared mesh with a long border.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/cluster/face_data.h"
#include "core/mesh/topology.h"
#include "core/panels/plane_fit.h"
#include "core/quality/hausdorff.h"
#include "core/remesher.h"
#include "remesh_checks.h"

namespace ff {
namespace {

// A strip of a cylinder of radius r (axis z), angles 0..angle, height h, cols x rows quads:
// its border runs along two arcs and two straight sides.
TriMesh cylinder_strip(double r, double angle, double h, int cols, int rows) {
  TriMesh m;
  for (int j = 0; j <= rows; ++j) {
    for (int i = 0; i <= cols; ++i) {
      const double a = angle * i / cols;
      m.positions.push_back(Vec3(r * std::cos(a), r * std::sin(a), h * j / rows));
    }
  }
  const auto id = [&](int i, int j) { return j * (cols + 1) + i; };
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < cols; ++i) {
      m.triangles.push_back({id(i, j), id(i, j + 1), id(i + 1, j)});
      m.triangles.push_back({id(i + 1, j), id(i, j + 1), id(i + 1, j + 1)});
    }
  }
  return m;
}

TEST(PlaneFitBorder, BorderMomentsAreTheBorderCurvesLineIntegrals) {
  // A unit square in z = 0 as two triangles, one cluster each: cluster 0 owns the bottom and
  // left sides, cluster 1 the top and right.
  TriMesh m;
  m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  m.triangles = {{0, 1, 3}, {1, 2, 3}};
  const MeshTopology t = build_topology(m);
  const std::vector<ClusterMoments> b = border_moments(t, m.positions, {0, 1}, 2);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_NEAR(b[0].area, 2.0, 1e-12);  // length
  EXPECT_NEAR(b[1].area, 2.0, 1e-12);
  // Bottom side (0,0)-(1,0) and left side (0,0)-(0,1): centroid of the two sides (0.25, 0.25).
  EXPECT_NEAR((b[0].first / b[0].area - Vec3(0.25, 0.25, 0)).norm(), 0.0, 1e-12);
  // integral of x^2 along the bottom side is 1/3, along the left side 0.
  EXPECT_NEAR(b[0].second(0, 0), 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(b[0].second(2, 2), 0.0, 1e-12);
  // An inside cluster gets nothing; a label out of range is ignored.
  const std::vector<ClusterMoments> none = border_moments(t, m.positions, {0, 7}, 3);
  EXPECT_NEAR(none[2].area, 0.0, 0.0);
  EXPECT_NEAR(none[0].area, 2.0, 1e-12);
}

// Squared distance of `plane` integrated over moments (faces: area, the border: length).
double integrated_squared_distance(const ClusterMoments& m, const Plane& plane) {
  const Vec3& n = plane.normal;
  return n.dot(m.second * n) - 2.0 * plane.offset * n.dot(m.first) + plane.offset * plane.offset * m.area;
}

TEST(PlaneFitBorder, BorderWeightTradesTheFacesFitForTheBorders) {
  // One cluster over a 90 degree strip of a cylinder. Least squares with the border weighed
  // must lower the border's mean squared distance to the plane and raise the faces' (else the
  // weight does nothing, or the fit is not the optimum of the weighted sum).
  const TriMesh m = cylinder_strip(1.0, M_PI / 2, 2.0, 32, 8);
  const MeshTopology t = build_topology(m);
  const FaceData faces = make_face_data(m);
  const std::vector<int> labels(static_cast<size_t>(m.num_faces()), 0);
  MasterPlanes masters;
  masters.planes = {Plane{Vec3(1, 1, 0).normalized(), 0.0}};  // a start and the normal's side
  masters.master_of = {0};
  std::vector<Vec3> local;  // the mesh in FaceData's local frame
  for (const Vec3& p : m.positions) local.push_back((p - faces.origin) / faces.scale);
  const std::vector<ClusterMoments> border = border_moments(t, local, labels, 1);
  ClusterMoments inside;
  for (int f = 0; f < m.num_faces(); ++f) inside.add_face(faces, f);
  const Plane plain = surface_fit_planes(faces, labels, masters, {}, border, 0.0)[0];
  const Plane hugging = surface_fit_planes(faces, labels, masters, {}, border, kBorderFitWeight)[0];
  const double border_plain = integrated_squared_distance(border[0], plain) / border[0].area;
  const double border_hugging = integrated_squared_distance(border[0], hugging) / border[0].area;
  const double faces_plain = integrated_squared_distance(inside, plain) / inside.area;
  const double faces_hugging = integrated_squared_distance(inside, hugging) / inside.area;
  EXPECT_LT(border_hugging, 0.9 * border_plain);
  EXPECT_GT(faces_hugging, faces_plain);
  // Weighted sum: the hugging plane is the better one for it.
  EXPECT_LT(faces_hugging + kBorderFitWeight * border_hugging, faces_plain + kBorderFitWeight * border_plain);
  // By symmetry the normal stays the same.
  EXPECT_GT(std::abs(hugging.normal.dot(plain.normal)), 1.0 - 1e-9);
}

TEST(PlaneFitBorder, PlanesTowardBlendsAndKeepsUnitNormals) {
  const std::vector<Plane> from = {Plane{Vec3::UnitZ(), 1.0}, Plane{Vec3::UnitX(), 0.0}, Plane{Vec3::UnitX(), 2.0}};
  const std::vector<Plane> to = {Plane{Vec3::UnitY(), 3.0}, Plane{-Vec3::UnitX(), 0.0}, Plane{Vec3::UnitX(), 2.0}};
  const std::vector<Plane> half = planes_toward(from, to, 0.5);
  EXPECT_NEAR((half[0].normal - Vec3(0, 1, 1).normalized()).norm(), 0.0, 1e-12);
  EXPECT_NEAR(half[0].offset, 2.0, 1e-12);
  EXPECT_EQ(half[1].normal, Vec3::UnitX());  // opposite normals: no blend, stays
  EXPECT_EQ(half[2].offset, 2.0);
  const std::vector<Plane> all = planes_toward(from, to, 1.0);
  EXPECT_NEAR((all[0].normal - Vec3::UnitY()).norm(), 0.0, 1e-12);
  EXPECT_NEAR(all[0].offset, 3.0, 1e-12);
}

// Issue 3: the worst distance of the panels sat on the input's border (bench/hausdorff_where),
// where the border panels' planes hugged their clusters' inside. inspired_mesh.obj at 100
// panels (default parameters) measured 0.01494 of the diagonal before the border term and the
// second fit passes, 0.01101 after; CGAL VSA measures 0.0391 there (bench/results_remesh.md).
TEST(PlaneFitBorder, InspiredMeshHausdorffBound) {
  TriMesh input = test::load_clean("inspired_mesh.obj");
  RemeshParams params;
  params.panels = 100;
  Remesher remesher(input, params);
  remesher.run();
  const PanelMesh& panels = remesher.panels();
  EXPECT_EQ(panels.num_invalid(), 0);
  const HausdorffResult h = hausdorff_distance(input, panels, 50000);
  EXPECT_LT(h.two_sided, 0.0125);
}

}  // namespace
}  // namespace ff
