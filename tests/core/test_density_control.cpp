// Density and anisotropy in the solve (paper 3.3, figs. 12-13): a 4:1 density split gives
// panels of about a quarter of the area on the dense side; an expression equals the same
// density given per vertex; a stretch of 3 along x elongates panels along x; both still give
// valid planar panels; the JSON contract of the page.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <string>

#include "core/density/density_field.h"
#include "core/remesh_params_json.h"
#include "core/remesher.h"
#include "core/shapes/shapes.h"
#include "core/util/angles.h"
#include "core/util/error.h"
#include "input_error_message.h"
#include "panel_checks.h"

namespace ff {
namespace {

// Per cluster: area and the area-weighted covariance of its face centroids (world units).
struct ClusterShape {
  double area = 0.0;
  Vec3 centroid = Vec3::Zero();
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
};

std::vector<ClusterShape> cluster_shapes(const TriMesh& mesh, const std::vector<int>& labels, int clusters) {
  std::vector<ClusterShape> out(static_cast<size_t>(clusters));
  std::vector<Eigen::Matrix3d> second(out.size(), Eigen::Matrix3d::Zero());
  for (int f = 0; f < mesh.num_faces(); ++f) {
    ClusterShape& s = out[static_cast<size_t>(labels[static_cast<size_t>(f)])];
    const double a = face_area(mesh, f);
    const Vec3 c = face_centroid(mesh, f);
    s.area += a;
    s.centroid += a * c;
    second[static_cast<size_t>(labels[static_cast<size_t>(f)])] += a * c * c.transpose();
  }
  for (size_t i = 0; i < out.size(); ++i) {
    if (!(out[i].area > 0.0)) continue;
    out[i].centroid /= out[i].area;
    out[i].cov = second[i] / out[i].area - out[i].centroid * out[i].centroid.transpose();
  }
  return out;
}

// Mean cluster area on each side of x = split (clusters wholly on one side: centroid at
// least one typical cluster radius away), dense side first.
std::pair<double, double> mean_areas(const Remesher& r, double split) {
  const std::vector<ClusterShape> shapes =
      cluster_shapes(r.mesh(), r.clustering().labels, r.clustering().num_clusters());
  double area[2] = {0, 0};
  int count[2] = {0, 0};
  for (const ClusterShape& s : shapes) {
    const double radius = std::sqrt(s.area / kPi);
    if (std::abs(s.centroid.x() - split) < radius) continue;
    const int side = s.centroid.x() < split ? 0 : 1;
    area[side] += s.area;
    ++count[side];
  }
  return {area[0] / std::max(1, count[0]), area[1] / std::max(1, count[1])};
}

TEST(DensityControl, FourToOneSplitGivesQuarterSizePanels) {
  // 1.5 x 1 rectangle, 30k triangles; density 4 left of x = 0.75, 1 right of it.
  const TriMesh mesh = make_plane(150, 100, 1.5, 1.0);
  RemeshParams p;
  p.panels = 150;
  p.density_expression = "x < 0.75 ? 4 : 1";
  p.make_panels = false;
  Remesher r(mesh, p);
  r.run();
  const auto [dense, sparse] = mean_areas(r, 0.75);
  const double ratio = dense / sparse;
  RecordProperty("area_ratio", std::to_string(ratio));
  std::printf("[ density ] 4:1 split: mean panel area dense / sparse = %.3f\n", ratio);
  EXPECT_LE(ratio, 0.5);
  EXPECT_GE(ratio, 0.15);

  // The same densities given per vertex: identical clustering.
  RemeshParams q = p;
  q.density_expression.clear();
  for (const Vec3& v : mesh.positions) q.density.push_back(v.x() < 0.75 ? 4.0 : 1.0);
  Remesher s(mesh, q);
  s.run();
  EXPECT_EQ(s.clustering().labels, r.clustering().labels);

  // Both at once multiply: painted 2 everywhere times the expression is the same field.
  RemeshParams both = p;
  both.density.assign(mesh.positions.size(), 2.0);
  Remesher t(mesh, both);
  t.run();
  EXPECT_EQ(t.clustering().labels, r.clustering().labels);
}

TEST(DensityControl, FinerAtTheBorderPresetGivesSmallerPanelsAlongTheEdge) {
  // The "Finer at borders" preset on a unit square: panels along the edge (centroid within
  // 0.1 of it) against those in the middle (over 0.25 from it).
  const TriMesh mesh = make_plane(120, 120, 1.0, 1.0);
  RemeshParams p;
  p.panels = 100;
  p.density_expression = kDensityPresets.back().expression;
  ASSERT_STREQ(kDensityPresets.back().name, "border");
  p.make_panels = false;
  Remesher r(mesh, p);
  r.run();
  double area[2] = {0, 0};
  int count[2] = {0, 0};
  for (const ClusterShape& s : cluster_shapes(mesh, r.clustering().labels, r.clustering().num_clusters())) {
    const Vec3& c = s.centroid;
    const double border = std::min({c.x(), 1.0 - c.x(), c.y(), 1.0 - c.y()});
    if (border > 0.1 && border < 0.25) continue;
    area[border <= 0.1 ? 0 : 1] += s.area;
    ++count[border <= 0.1 ? 0 : 1];
  }
  ASSERT_GT(count[0], 0);
  ASSERT_GT(count[1], 0);
  const double ratio = (area[0] / count[0]) / (area[1] / count[1]);
  std::printf("[ density ] finer at the border: mean panel area edge / middle = %.3f (%d, %d panels)\n", ratio,
              count[0], count[1]);
  EXPECT_LE(ratio, 0.6);
}

TEST(DensityControl, StretchAlongXElongatesPanelsAlongX) {
  const TriMesh mesh = make_plane(150, 150, 1.0, 1.0);
  RemeshParams p;
  p.panels = 100;
  p.make_panels = false;
  p.anisotropy.direction = AnisotropyDirection::Constant;
  p.anisotropy.vector = Vec3(1, 0, 0);
  p.anisotropy.stretch = 3.0;
  double mean_aspect[2] = {0, 0}, mean_angle[2] = {0, 0};
  for (int run = 0; run < 2; ++run) {
    if (run == 1) p.anisotropy.stretch = 1.0;  // the control: isotropic
    Remesher r(mesh, p);
    r.run();
    const std::vector<ClusterShape> shapes = cluster_shapes(mesh, r.clustering().labels, r.clustering().num_clusters());
    int n = 0;
    for (const ClusterShape& s : shapes) {
      if (!(s.area > 0.0)) continue;
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(s.cov);
      const Vec3 l = eig.eigenvalues();  // ascending; l[0] ~ 0 (flat)
      mean_aspect[run] += std::sqrt(l[2] / std::max(l[1], 1e-300));
      mean_angle[run] += std::acos(std::min(1.0, std::abs(eig.eigenvectors().col(2).x()))) * 180.0 / kPi;
      ++n;
    }
    mean_aspect[run] /= n;
    mean_angle[run] /= n;
  }
  std::printf("[ density ] stretch 3 along x: mean aspect %.2f, major axis %.1f deg from x (isotropic: %.2f)\n",
              mean_aspect[0], mean_angle[0], mean_aspect[1]);
  EXPECT_GE(mean_aspect[0], 1.8);
  EXPECT_LE(mean_angle[0], 20.0);
  EXPECT_LE(mean_aspect[1], 1.5);
}

TEST(DensityControl, AnisotropicEnergyFromMomentsIsExactAndTheFitMinimisesIt) {
  // A curved patch with a direction field that varies per face (max curvature).
  const TriMesh mesh = make_grid_surface(
      20, 16, [](double s, double t) { return Vec3(2.0 * s, 1.5 * t, 0.4 * s * s - 0.2 * t * t + 0.1 * s * t); });
  Anisotropy a;
  a.direction = AnisotropyDirection::MaxCurvature;
  a.stretch = 4.0;
  const FaceData fd = make_shaped_face_data(mesh, build_topology(mesh), {}, "1 + u", a);
  ASSERT_EQ(fd.stretch.size(), fd.records.size());
  MetricWeights w;
  w.l2 = 3.0;
  w.l21 = 0.5;
  const Metric metric(fd, w, 4);
  ClusterMoments m;
  for (int f = 0; f < fd.num_faces(); ++f) m.add_face(fd, f);
  const auto summed = [&](const Proxy& p) {
    double sum = 0.0;
    const Metric::Terms t = metric.terms(p);
    for (int f = 0; f < fd.num_faces(); ++f) sum += metric.cost(f, t);
    return sum;
  };
  const Proxy best = metric.fit(m, Proxy{});
  EXPECT_NEAR(metric.energy(m, best).total(), summed(best), 1e-9 * summed(best));
  // Any other centre (or the plain centroid) costs more.
  Proxy at_centroid = best;
  at_centroid.center = m.first / m.area;
  EXPECT_NEAR(metric.energy(m, at_centroid).total(), summed(at_centroid), 1e-9 * summed(at_centroid));
  EXPECT_LT(summed(best), summed(at_centroid));
  for (int axis = 0; axis < 3; ++axis) {
    for (double step : {-1e-3, 1e-3}) {
      Proxy moved = best;
      moved.center[axis] += step;
      EXPECT_GT(summed(moved), summed(best));
    }
  }
}

TEST(DensityControl, MinCurvatureStretchElongatesPanelsAlongACylinder) {
  const TriMesh mesh = make_grid_surface(
      120, 80, [](double s, double t) { return Vec3(std::cos(2 * kPi * s), std::sin(2 * kPi * s), 4.0 * t); },
      /*wrap_u=*/true);
  RemeshParams p;
  p.panels = 60;
  p.make_panels = false;
  p.anisotropy.direction = AnisotropyDirection::MinCurvature;  // along the axis
  double aspect[2] = {0, 0};
  for (int run = 0; run < 2; ++run) {
    p.anisotropy.stretch = run == 0 ? 3.0 : 1.0;  // then the isotropic control
    Remesher r(mesh, p);
    r.run();
    const std::vector<ClusterShape> shapes = cluster_shapes(mesh, r.clustering().labels, r.clustering().num_clusters());
    // Spread along z vs around (the x-y spread of a narrow arc is about its tangential spread).
    double along = 0.0, around = 0.0;
    for (const ClusterShape& s : shapes) {
      along += s.cov(2, 2);
      around += s.cov(0, 0) + s.cov(1, 1);
    }
    aspect[run] = std::sqrt(along / around);
  }
  std::printf("[ density ] minCurvature stretch 3 on a cylinder: along / around %.2f (isotropic %.2f)\n", aspect[0],
              aspect[1]);
  EXPECT_GE(aspect[0], 1.6 * aspect[1]);
}

TEST(DensityControl, DensityAndStretchStillGiveValidPanels) {
  // A gentle doubly curved patch, 2 x 1.5, rising 0.15.
  const TriMesh mesh = make_grid_surface(
      80, 60, [](double s, double t) { return Vec3(2.0 * s, 1.5 * t, 0.15 * std::sin(kPi * s) * std::sin(kPi * t)); });
  RemeshParams p;
  p.panels = 60;
  p.density_expression = "1 + 3 * smoothstep(0.4, 0.6, u)";
  Remesher a(mesh, p);
  a.run();
  EXPECT_TRUE(test::valid_panels(a, 60, 0.05));
  p.density_expression.clear();
  p.anisotropy.direction = AnisotropyDirection::Constant;
  p.anisotropy.stretch = 2.0;
  Remesher b(mesh, p);
  b.run();
  EXPECT_TRUE(test::valid_panels(b, 60, 0.05));
}

TEST(DensityControl, SetParamsWarmStartsOnANewExpression) {
  const TriMesh mesh = make_plane(60, 40, 1.5, 1.0);
  RemeshParams p;
  p.panels = 30;
  p.make_panels = false;
  Remesher r(mesh, p);
  r.run();
  p.density_expression = "1 + 3 * u";
  r.set_params(p);
  EXPECT_EQ(r.progress().stage, Stage::Lloyd);  // warm start, not seeding
  r.run();
  const auto [left, right] = mean_areas(r, 0.75);
  EXPECT_LT(right, left);  // denser on the right: smaller panels there
  // A bad expression throws and leaves everything as it was.
  const std::vector<int> labels = r.clustering().labels;
  RemeshParams bad = p;
  bad.density_expression = "1 - u";  // 0 at u = 1
  try {
    r.set_params(bad);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("density expression gives 0 at vertex"), std::string::npos) << e.what();
  }
  EXPECT_EQ(r.clustering().labels, labels);
  EXPECT_EQ(r.params().density_expression, "1 + 3 * u");
}

TEST(DensityControl, ExpressionErrorsNameTheVertex) {
  const TriMesh mesh = make_plane(4, 4);
  const MeshTopology topology = build_topology(mesh);
  EXPECT_THROW(expression_density(mesh, topology, Expression::parse("x - 0.5"), nullptr), InputError);
  EXPECT_THROW(expression_density(mesh, topology, Expression::parse("log(x)"), nullptr), InputError);
  EXPECT_THROW(expression_density(mesh, topology, Expression::parse("1e-7 + x"), nullptr), InputError);  // ratio
  const std::vector<double> d = expression_density(mesh, topology, Expression::parse("1 + u + 10 * nz"), nullptr);
  EXPECT_DOUBLE_EQ(d.front(), 11.0);
  EXPECT_DOUBLE_EQ(d.back(), 12.0);
}

TEST(DensityControl, ParamsJsonContract) {
  const RemeshParams p = remesh_params_from_json(
      R"j({"densityExpression": "1 + 3 * u", "anisotropy": {"direction": "maxCurvature", "stretch": 2.5}})j");
  EXPECT_EQ(p.density_expression, "1 + 3 * u");
  EXPECT_EQ(p.anisotropy.direction, AnisotropyDirection::MaxCurvature);
  EXPECT_EQ(p.anisotropy.stretch, 2.5);
  const RemeshParams q = remesh_params_from_json(R"j({"anisotropy": {"direction": "y", "stretch": 3}})j");
  EXPECT_EQ(q.anisotropy.direction, AnisotropyDirection::Constant);
  EXPECT_EQ(q.anisotropy.vector, Vec3::UnitY());
  EXPECT_EQ(remesh_params_from_json(R"j({"anisotropy": {"direction": "none"}})j").anisotropy.active(), false);
  EXPECT_EQ(remesh_params_from_json(R"j({"densityExpression": ""})j").density_expression, "");
  const auto message = [](const std::string& json) {
    return test::input_error_message([&] { remesh_params_from_json(json); });
  };
  EXPECT_NE(message(R"j({"densityExpression": "alert(1)"})j").find("unknown name 'alert' at column 1"),
            std::string::npos);
  EXPECT_NE(message(R"j({"densityExpression": "\u0000"})j").find("control character at column 1"), std::string::npos);
  EXPECT_NE(message(R"j({"densityExpression": "</script><script>alert(1)</script>"})j").find("unexpected"),
            std::string::npos);
  EXPECT_NE(message(R"j({"densityExpression": 3})j").find("'densityExpression' must be a string"), std::string::npos);
  EXPECT_NE(message("{\"densityExpression\": \"" + std::string(5000, '1') + "\"}").find("too long"), std::string::npos);
  EXPECT_NE(message(R"j({"anisotropy": {"direction": "diagonal"}})j").find("'anisotropy.direction' must be"),
            std::string::npos);
  EXPECT_NE(message(R"j({"anisotropy": {"stretch": 11}})j").find("'anisotropy.stretch' must be between 1 and 10"),
            std::string::npos);
  EXPECT_NE(message(R"j({"anisotropy": {"angle": 1}})j").find("unknown parameter 'anisotropy.angle'"),
            std::string::npos);
  EXPECT_NE(message(R"j({"anisotropy": "x"})j").find("'anisotropy' must be an object"), std::string::npos);
}

}  // namespace
}  // namespace ff

namespace ff {
namespace {

// Only a density's ratios count: a constant 1e308 (or 1e-320, or an expression of either)
// gives the densities of none. 1e308 overflowed the face means and the area-weighted mean and
// crashed the seeding (SIGSEGV in place_seeds), found by an audit of the density inputs; a
// field times an expression overflowed the same way.
TEST(DensityControl, HugeOrTinyConstantDensitiesChangeNothing) {
  const TriMesh mesh = make_grid_surface(12, 10, [](double s, double t) { return Vec3(s, t, 0.3 * s * t); });
  const MeshTopology topology = build_topology(mesh);
  const FaceData plain = make_shaped_face_data(mesh, topology, {}, "", Anisotropy{});
  // The same densities up to the last digits (the mean's normalisation rounds).
  const auto expect_same = [](const FaceData& a, const FaceData& b, const std::string& what) {
    ASSERT_EQ(a.records.size(), b.records.size());
    for (size_t f = 0; f < a.records.size(); ++f) {
      ASSERT_TRUE(std::isfinite(a.records[f].density)) << what;
      EXPECT_NEAR(a.records[f].density, b.records[f].density, 1e-14 * b.records[f].density) << what << ", face " << f;
    }
  };
  for (const double value : {1e308, 1.7e308, 1e-320, 4.9e-324}) {
    const std::vector<double> constant(mesh.positions.size(), value);
    expect_same(make_shaped_face_data(mesh, topology, constant, "", Anisotropy{}), plain, std::to_string(value));
  }
  expect_same(make_shaped_face_data(mesh, topology, {}, "1e308", Anisotropy{}), plain, "expression 1e308");
  // A field of 1e308 times an expression: the expression's ratios, as for a field of 1.
  const std::vector<double> huge(mesh.positions.size(), 1e308), ones(mesh.positions.size(), 1.0);
  expect_same(make_shaped_face_data(mesh, topology, huge, "1 + 3 * u", Anisotropy{}),
              make_shaped_face_data(mesh, topology, ones, "1 + 3 * u", Anisotropy{}), "1e308 times 1 + 3u");
}

// A painted or file density is held to the expression's range (1e6): a file of 1 and 1e300 was
// taken while the same field as an expression was refused.
TEST(DensityControl, APaintedDensityOverAMillionToOneIsRefused) {
  const TriMesh mesh = make_grid_surface(6, 6, [](double s, double t) { return Vec3(s, t, 0.0); });
  std::vector<double> field(mesh.positions.size(), 1.0);
  field[3] = 1e300;
  const std::string message =
      test::input_error_message([&] { make_shaped_face_data(mesh, build_topology(mesh), field, "", Anisotropy{}); });
  EXPECT_NE(message.find("density ranges from 1 to 1e+300; keep the largest value within 1e6 times the smallest"),
            std::string::npos)
      << message;
  field[3] = 1e6;  // at the limit: taken
  EXPECT_NO_THROW(make_shaped_face_data(mesh, build_topology(mesh), field, "", Anisotropy{}));
}

}  // namespace
}  // namespace ff
