// Principal curvatures by quadric fit: sphere (k1 = k2 = 1/R), cylinder (1/R around, 0 along
// the axis, with the directions), plane (0), and the sign convention on a concave surface.
#include <gtest/gtest.h>

#include <cmath>

#include "core/mesh/curvature.h"
#include "core/mesh/topology.h"
#include "core/shapes/shapes.h"
#include "core/util/angles.h"

namespace ff {
namespace {

// A latitude band of a sphere (no poles), normals outward.
TriMesh sphere_band(double radius, int nu, int nv) {
  return make_grid_surface(
      nu, nv,
      [radius](double s, double t) {
        const double lon = 2.0 * kPi * s, lat = (-0.4 + 0.8 * t) * kPi / 2.0;
        return Vec3(radius * std::cos(lat) * std::cos(lon), radius * std::cos(lat) * std::sin(lon),
                    radius * std::sin(lat));
      },
      /*wrap_u=*/true);
}

TriMesh cylinder(double radius, double length, int nu, int nv, bool outward = true) {
  return make_grid_surface(
      nu, nv,
      [=](double s, double t) {
        const double a = (outward ? 1.0 : -1.0) * 2.0 * kPi * s;
        return Vec3(radius * std::cos(a), radius * std::sin(a), length * t);
      },
      /*wrap_u=*/true);
}

// Vertices away from the open ends (the fit is one-sided there).
bool interior(const Vec3& p, double lo, double hi) { return p.z() > lo && p.z() < hi; }

TEST(Curvature, SphereHasBothCurvaturesOneOverR) {
  const double R = 2.5;
  const TriMesh mesh = sphere_band(R, 96, 48);
  const VertexCurvature k = vertex_curvature(mesh, build_topology(mesh));
  double worst = 0.0;
  int checked = 0;
  const double zmax = R * std::sin(0.3 * kPi / 2.0);
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    if (!interior(mesh.positions[v], -zmax, zmax)) continue;
    worst = std::max({worst, std::abs(k.k1[v] * R - 1.0), std::abs(k.k2[v] * R - 1.0)});
    EXPECT_GT(k.normal[v].dot(mesh.positions[v]), 0.0);  // outward
    ++checked;
  }
  EXPECT_GT(checked, 1000);
  EXPECT_LT(worst, 0.03) << "relative error of k1, k2 against 1/R";
}

TEST(Curvature, CylinderIsOneOverRAroundAndZeroAlong) {
  const double R = 0.7;
  for (bool outward : {true, false}) {
    const TriMesh mesh = cylinder(R, 3.0, 64, 60, outward);
    const VertexCurvature k = vertex_curvature(mesh, build_topology(mesh));
    double worst_max = 0.0, worst_zero = 0.0, worst_dir = 0.0;
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
      const Vec3& p = mesh.positions[v];
      if (!interior(p, 0.3, 2.7)) continue;
      // Outward: bends away from the normal, +1/R; inward normals (the inside): -1/R.
      const double kmax = outward ? k.k1[v] : k.k2[v];
      const double kzero = outward ? k.k2[v] : k.k1[v];
      const Vec3& dmax = outward ? k.dir1[v] : k.dir2[v];
      worst_max = std::max(worst_max, std::abs(kmax * R - (outward ? 1.0 : -1.0)));
      worst_zero = std::max(worst_zero, std::abs(kzero * R));
      // Around the circumference: orthogonal to the axis and to the radius.
      const Vec3 around = Vec3(-p.y(), p.x(), 0.0).normalized();
      worst_dir = std::max(worst_dir, 1.0 - std::abs(dmax.dot(around)));
    }
    EXPECT_LT(worst_max, 0.03) << (outward ? "outward" : "inward");
    EXPECT_LT(worst_zero, 0.01) << (outward ? "outward" : "inward");
    EXPECT_LT(worst_dir, 1e-3) << "max-curvature direction vs the circumference";
  }
}

TEST(Curvature, PlaneIsFlatEvenAtItsBorder) {
  const TriMesh mesh = make_plane(30, 20, 3.0, 2.0);
  const VertexCurvature k = vertex_curvature(mesh, build_topology(mesh));
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    EXPECT_NEAR(k.k1[v], 0.0, 1e-9);
    EXPECT_NEAR(k.k2[v], 0.0, 1e-9);
    EXPECT_NEAR(k.normal[v].z(), 1.0, 1e-12);
    EXPECT_NEAR(k.dir1[v].dot(k.dir2[v]), 0.0, 1e-9);
  }
}

TEST(Curvature, ScalesInverselyWithTheModel) {
  TriMesh small = cylinder(1.0, 2.0, 48, 30);
  TriMesh big = small;
  for (Vec3& p : big.positions) p *= 1000.0;
  const VertexCurvature a = vertex_curvature(small, build_topology(small));
  const VertexCurvature b = vertex_curvature(big, build_topology(big));
  for (size_t v = 0; v < small.positions.size(); ++v) EXPECT_NEAR(b.k1[v] * 1000.0, a.k1[v], 1e-9);
}

}  // namespace
}  // namespace ff
