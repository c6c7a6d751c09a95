#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "core/mesh/clean.h"
#include "core/mesh/topology.h"
#include "core/prepare/nurbs_surface.h"
#include "core/prepare/nurbs_tessellate.h"
#include "core/util/angles.h"
#include "core/util/error.h"
#include "input_error_message.h"

namespace ff {
namespace {

// A bilinear patch through four corners, Rhino's knot convention (count + degree - 1).
NurbsSurface bilinear(const Vec3& p00, const Vec3& p10, const Vec3& p01, const Vec3& p11) {
  NurbsSurface s;
  s.degree_u = s.degree_v = 1;
  s.count_u = s.count_v = 2;
  s.knots_u = {0.0, 1.0};
  s.knots_v = {0.0, 1.0};
  s.points = {p00, p01, p10, p11};  // (i, j) at i * count_v + j
  return s;
}

// A half cylinder of radius r and height h around z as a rational degree-2 (u) x degree-1
// (v) surface: two quarter-circle arcs, corner weights sqrt(1/2). Textbook knots.
NurbsSurface half_cylinder(double r, double h, bool textbook = true) {
  NurbsSurface s;
  s.degree_u = 2;
  s.degree_v = 1;
  s.count_u = 5;
  s.count_v = 2;
  s.knots_u = textbook ? std::vector<double>{0, 0, 0, 1, 1, 2, 2, 2} : std::vector<double>{0, 0, 1, 1, 2, 2};
  s.knots_v = textbook ? std::vector<double>{0, 0, 1, 1} : std::vector<double>{0, 1};
  const Vec3 ring[5] = {{r, 0, 0}, {r, r, 0}, {0, r, 0}, {-r, r, 0}, {-r, 0, 0}};
  const double w[5] = {1, std::sqrt(0.5), 1, std::sqrt(0.5), 1};
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 2; ++j) {
      s.points.push_back(ring[i] + Vec3(0, 0, h * j));
      s.weights.push_back(w[i]);
    }
  return s;
}

// A full closed cylinder: 9 control points around (4 quarter arcs), seam at u = 0 / 4.
NurbsSurface full_cylinder(double r, double h) {
  NurbsSurface s;
  s.degree_u = 2;
  s.degree_v = 1;
  s.count_u = 9;
  s.count_v = 2;
  s.knots_u = {0, 0, 1, 1, 2, 2, 3, 3, 4, 4};  // Rhino convention
  s.knots_v = {0, 1};
  const double c = std::sqrt(0.5);
  const Vec3 ring[9] = {{r, 0, 0},   {r, r, 0},  {0, r, 0},  {-r, r, 0}, {-r, 0, 0},
                        {-r, -r, 0}, {0, -r, 0}, {r, -r, 0}, {r, 0, 0}};
  const double w[9] = {1, c, 1, c, 1, c, 1, c, 1};
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 2; ++j) {
      s.points.push_back(ring[i] + Vec3(0, 0, h * j));
      s.weights.push_back(w[i]);
    }
  return s;
}

std::string error_of(const NurbsSurface& s) {
  return test::input_error_message([&] { validate_nurbs(s, "Roof"); });
}

TEST(NurbsSurface, BilinearPatchIsExact) {
  const Vec3 a(0, 0, 0), b(2, 0, 1), c(0, 3, -1), d(2, 3, 4);
  const NurbsSurface s = validate_nurbs(bilinear(a, b, c, d), "patch");
  for (double u = 0; u <= 1.0; u += 0.125)
    for (double v = 0; v <= 1.0; v += 0.25) {
      const NurbsPoint p = evaluate_nurbs(s, u, v);
      const Vec3 expected = (1 - u) * (1 - v) * a + u * (1 - v) * b + (1 - u) * v * c + u * v * d;
      EXPECT_LT((p.p - expected).norm(), 1e-14);
      EXPECT_LT((p.du - ((1 - v) * (b - a) + v * (d - c))).norm(), 1e-13);
      EXPECT_LT((p.dv - ((1 - u) * (c - a) + u * (d - b))).norm(), 1e-13);
    }
}

TEST(NurbsSurface, RationalCylinderPointsOnRadius) {
  const double r = 3.5, h = 2.0;
  const NurbsSurface s = validate_nurbs(half_cylinder(r, h), "vault");
  const NurbsDomain d = nurbs_domain(s);
  EXPECT_EQ(d.u0, 0.0);
  EXPECT_EQ(d.u1, 2.0);
  for (int i = 0; i <= 200; ++i)
    for (int j = 0; j <= 4; ++j) {
      const NurbsPoint p = evaluate_nurbs(s, 2.0 * i / 200, 0.25 * j);
      EXPECT_NEAR(std::hypot(p.p.x(), p.p.y()), r, 1e-12);
      EXPECT_NEAR(p.p.z(), h * 0.25 * j, 1e-12);
      EXPECT_GE(p.p.y(), -1e-12);
      // The tangent along u is horizontal and perpendicular to the radius.
      EXPECT_NEAR(p.du.dot(Vec3(p.p.x(), p.p.y(), 0)), 0.0, 1e-10);
    }
  // The arc's middle is at 90 degrees.
  EXPECT_LT((evaluate_nurbs(s, 1.0, 0.0).p - Vec3(0, r, 0)).norm(), 1e-14);
}

TEST(NurbsSurface, DerivativesMatchFiniteDifferences) {
  NurbsSurface s = half_cylinder(2.0, 1.0);
  // Make it less symmetric: a bulge in v and uneven weights.
  s.degree_v = 2;
  s.count_v = 3;
  s.knots_v = {0, 0, 1, 1};
  std::vector<Vec3> pts;
  std::vector<double> w;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 3; ++j) {
      pts.push_back(s.points[size_t(i * 2)] + Vec3(0.3 * j * j, 0.1 * i, 0.7 * j));
      w.push_back(s.weights[size_t(i * 2)] * (1.0 + 0.2 * j));
    }
  s.points = pts;
  s.weights = w;
  const NurbsSurface v = validate_nurbs(s, "bulge");
  const double e = 1e-6;
  for (const double u : {0.1, 0.7, 1.0, 1.3, 1.9})
    for (const double t : {0.1, 0.5, 0.9}) {
      const NurbsPoint p = evaluate_nurbs(v, u, t);
      const Vec3 fu = (evaluate_nurbs(v, u + e, t).p - evaluate_nurbs(v, u - e, t).p) / (2 * e);
      const Vec3 fv = (evaluate_nurbs(v, u, t + e).p - evaluate_nurbs(v, u, t - e).p) / (2 * e);
      EXPECT_LT((p.du - fu).norm(), 1e-6) << u << " " << t;
      EXPECT_LT((p.dv - fv).norm(), 1e-6) << u << " " << t;
    }
}

TEST(NurbsSurface, KnotConventionsAgree) {
  const NurbsSurface a = validate_nurbs(half_cylinder(1.5, 2.0, true), "a");
  const NurbsSurface b = validate_nurbs(half_cylinder(1.5, 2.0, false), "b");
  EXPECT_EQ(a.knots_u.size(), b.knots_u.size());
  for (double u = 0; u <= 2.0; u += 0.0625) {
    EXPECT_EQ(evaluate_nurbs(a, u, 0.3).p, evaluate_nurbs(b, u, 0.3).p);
  }
  // A periodic-style (unclamped) knot vector: the outer knots differ between conventions but
  // never matter.
  NurbsSurface c = half_cylinder(1.5, 2.0, false), d = half_cylinder(1.5, 2.0, true);
  d.knots_u.front() = -7.0;
  d.knots_u.back() = 9.0;
  const NurbsSurface vc = validate_nurbs(c, "c"), vd = validate_nurbs(d, "d");
  for (double u = 0; u <= 2.0; u += 0.125) EXPECT_EQ(evaluate_nurbs(vc, u, 0.5).p, evaluate_nurbs(vd, u, 0.5).p);
}

TEST(NurbsSurface, BadInputsAreRejectedByName) {
  NurbsSurface s = half_cylinder(1.0, 1.0);
  auto with = [&](auto change) {
    NurbsSurface t = s;
    change(t);
    return error_of(t);
  };
  EXPECT_EQ(error_of(s), "");
  EXPECT_NE(with([](NurbsSurface& t) { t.knots_u.pop_back(); }).find("Roof: u has 7 knots"), std::string::npos);
  EXPECT_NE(with([](NurbsSurface& t) { t.knots_v[2] = -1; }).find("Roof: v knots decrease"), std::string::npos);
  EXPECT_NE(with([](NurbsSurface& t) { t.knots_u[3] = NAN; }).find("not finite"), std::string::npos);
  EXPECT_NE(with([](NurbsSurface& t) { t.weights[4] = 0.0; }).find("Roof: weight 4 is not positive"),
            std::string::npos);
  EXPECT_NE(with([](NurbsSurface& t) { t.weights[1] = INFINITY; }).find("weight 1"), std::string::npos);
  EXPECT_NE(with([](NurbsSurface& t) { t.points[3].y() = NAN; }).find("control point 3 is not finite"),
            std::string::npos);
  EXPECT_NE(with([](NurbsSurface& t) { t.degree_u = 0; }).find("degree 0 in u"), std::string::npos);
  EXPECT_NE(with([](NurbsSurface& t) { t.degree_v = 12; }).find("degree 12 in v"), std::string::npos);
  EXPECT_NE(with([](NurbsSurface& t) { t.degree_u = 5; }).find("too few for degree 5"), std::string::npos);
  EXPECT_NE(with([](NurbsSurface& t) { t.points.pop_back(); }).find("9 control points given"), std::string::npos);
  EXPECT_NE(with([](NurbsSurface& t) { t.weights.pop_back(); }).find("9 weights"), std::string::npos);
  EXPECT_NE(with([](NurbsSurface& t) { t.knots_v = {0, 0, 0, 0}; }).find("empty parameter domain"), std::string::npos);
  // Degree 1 with an interior knot twice: the surface is torn there.
  NurbsSurface torn = bilinear(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0));
  torn.count_u = 4;
  torn.knots_u = {0, 1, 1, 2};
  torn.points.insert(torn.points.end(), {Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(3, 0, 0), Vec3(3, 1, 0)});
  EXPECT_NE(error_of(torn).find("Roof: u knot 1.000000 is repeated 2 times"), std::string::npos) << error_of(torn);
  EXPECT_NE(with([](NurbsSurface& t) { t.count_u = t.count_v = 2000; }).find("more than this page takes"),
            std::string::npos);
}

TEST(NurbsTessellate, CylinderPointsOnRadiusAndEdgesNearTarget) {
  const double r = 2.0, h = 3.0, edge = 0.1;
  const NurbsSurface s = validate_nurbs(half_cylinder(r, h), "vault");
  TessellationOptions o;
  o.edge_length = edge;
  const SurfaceTessellation t = tessellate_nurbs(s, o, "vault");
  ASSERT_GT(t.mesh.num_faces(), 0);
  for (const Vec3& p : t.mesh.positions) EXPECT_NEAR(std::hypot(p.x(), p.y()), r, 1e-12);
  // Grid edges along u and v (the diagonals are longer by design): at most the target, and
  // not much below it.
  const double arc = kPi * r;
  EXPECT_EQ(t.samples_u, 2 * static_cast<int>(std::ceil(arc / 2 / edge - 1e-9)));
  EXPECT_EQ(t.samples_v, static_cast<int>(std::ceil(h / edge - 1e-9)));
  double lo = 1e9, hi = 0;
  for (const auto& tri : t.mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const double l = (t.mesh.positions[size_t(tri[k])] - t.mesh.positions[size_t(tri[(k + 1) % 3])]).norm();
      lo = std::min(lo, l);
      hi = std::max(hi, l);
    }
  EXPECT_GT(lo, 0.8 * edge);
  EXPECT_LT(hi, 1.5 * edge);  // diagonals: sqrt(2) x the target at most
  // Oriented along du x dv: on this cylinder that is outward.
  for (int f = 0; f < t.mesh.num_faces(); ++f) {
    const Vec3 n = face_normal(t.mesh, f), c = face_centroid(t.mesh, f);
    EXPECT_GT(n.dot(Vec3(c.x(), c.y(), 0)), 0.0);
  }
  EXPECT_EQ(t.seam_vertices_welded, 0);
}

TEST(NurbsTessellate, ClosedCylinderIsWeldedAlongItsSeam) {
  const NurbsSurface s = validate_nurbs(full_cylinder(1.0, 2.0), "tube");
  TessellationOptions o;
  o.edge_length = 0.2;
  const SurfaceTessellation t = tessellate_nurbs(s, o, "tube");
  EXPECT_EQ(t.seam_vertices_welded, t.samples_v + 1);
  const CleanMesh clean = clean_mesh(t.mesh);
  EXPECT_EQ(clean.report.welded_vertices, 0);
  const MeshTopology topo = build_topology(clean.mesh);
  EXPECT_EQ(topo.num_components, 1);
  EXPECT_EQ(topo.boundary_loops.size(), 2u);  // a tube: top and bottom rims only
  EXPECT_EQ(euler_characteristic(clean.mesh, topo), 0);
}

TEST(NurbsTessellate, PoleCollapsesToOneVertex) {
  // A cone: one row of control points all at the apex.
  NurbsSurface s = full_cylinder(1.0, 2.0);
  for (int i = 0; i < 9; ++i) s.points[size_t(i * 2 + 1)] = Vec3(0, 0, 2);
  const NurbsSurface v = validate_nurbs(s, "cone");
  TessellationOptions o;
  o.edge_length = 0.25;
  const SurfaceTessellation t = tessellate_nurbs(v, o, "cone");
  EXPECT_EQ(t.degenerate_triangles_dropped, t.samples_u);
  const MeshTopology topo = build_topology(clean_mesh(t.mesh).mesh);
  EXPECT_EQ(topo.boundary_loops.size(), 1u);  // only the base circle
  EXPECT_EQ(topo.num_components, 1);
}

TEST(NurbsTessellate, ChordToleranceRefinesCurvedSpans) {
  const NurbsSurface s = validate_nurbs(half_cylinder(1.0, 0.1), "arc");
  TessellationOptions o;
  o.edge_length = 10.0;  // longer than the surface: only the chord tolerance refines
  o.chord_tolerance = 1e-3;
  const SurfaceTessellation t = tessellate_nurbs(s, o, "arc");
  EXPECT_EQ(t.samples_v, 1);
  // Sagitta of a chord on the unit circle: 1 - cos(theta / 2) for a step theta.
  const double step = kPi / t.samples_u;
  EXPECT_LE(1.0 - std::cos(step / 2), 1.2e-3);
  EXPECT_GT(1.0 - std::cos(kPi / (t.samples_u - 4) / 2), 0.5e-3);  // and not far finer
}

TEST(NurbsTessellate, RefusesTooManyTriangles) {
  const NurbsSurface s = validate_nurbs(half_cylinder(100.0, 100.0), "Big");
  TessellationOptions o;
  o.edge_length = 0.01;
  o.max_triangles = 1000000;
  EXPECT_THROW(tessellate_nurbs(s, o, "Big"), InputError);
  o.edge_length = -1;
  EXPECT_THROW(tessellate_nurbs(s, o, "Big"), InputError);
}

TEST(NurbsTessellate, AreaEstimate) {
  const NurbsSurface s = validate_nurbs(half_cylinder(2.0, 3.0), "a");
  EXPECT_NEAR(nurbs_area_estimate(s), kPi * 2.0 * 3.0, 0.01 * kPi * 6.0);
}

}  // namespace
}  // namespace ff
