// Procedural anisotropy direction (issue 6, paper fig. 12): "-y, x, 0" on a plane elongates
// panels around the origin (tangential); "1, 0, 0" is exactly direction x; faces where the
// expression is zero or along the normal stay isotropic and are counted; hostile or broken
// expressions are refused naming the component and the column; the params JSON contract.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/density/anisotropy.h"
#include "core/density/direction_expression.h"
#include "core/remesh_params_json.h"
#include "core/remesher.h"
#include "core/shapes/shapes.h"
#include "core/util/angles.h"
#include "core/util/error.h"
#include "input_error_message.h"

namespace ff {
namespace {

std::string direction_error(const std::string& text) {
  try {
    parse_direction_expression(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// The square [-1, 1]^2 in the z = 0 plane, centred on the vortex's axis.
TriMesh centred_square(int n) {
  TriMesh mesh = make_plane(n, n, 2.0, 2.0);
  for (Vec3& p : mesh.positions) p -= Vec3(1.0, 1.0, 0.0);
  return mesh;
}

TEST(DirectionExpression, VortexElongatesPanelsTangentially) {
  const TriMesh mesh = centred_square(grid_resolution_for(30000));
  ASSERT_GE(mesh.num_faces(), 28000);
  RemeshParams p;
  p.panels = 100;
  p.make_panels = false;
  ASSERT_TRUE(set_anisotropy_direction(p.anisotropy, "expression"));
  p.anisotropy.expression = "-y, x, 0";
  double mean_aspect[2] = {0, 0}, mean_angle[2] = {0, 0};
  for (int run = 0; run < 2; ++run) {
    p.anisotropy.stretch = run == 0 ? 3.0 : 1.0;  // then the isotropic control
    Remesher r(mesh, p);
    r.run();
    // Per panel: area-weighted covariance of its face centroids; its major axis against the
    // tangential direction (-cy, cx) at the panel's centroid.
    const int k = r.clustering().num_clusters();
    std::vector<double> area(static_cast<size_t>(k), 0.0);
    std::vector<Vec3> first(static_cast<size_t>(k), Vec3::Zero());
    std::vector<Eigen::Matrix3d> second(static_cast<size_t>(k), Eigen::Matrix3d::Zero());
    for (int f = 0; f < mesh.num_faces(); ++f) {
      const size_t c = static_cast<size_t>(r.clustering().labels[static_cast<size_t>(f)]);
      const double a = face_area(mesh, f);
      const Vec3 x = face_centroid(mesh, f);
      area[c] += a;
      first[c] += a * x;
      second[c] += a * x * x.transpose();
    }
    int n = 0;
    for (size_t c = 0; c < area.size(); ++c) {
      if (!(area[c] > 0.0)) continue;
      const Vec3 centre = first[c] / area[c];
      // A panel around the axis has no tangential direction to follow.
      if (centre.head<2>().norm() < std::sqrt(area[c] / kPi)) continue;
      const Eigen::Matrix3d cov = second[c] / area[c] - centre * centre.transpose();
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
      const Vec3 l = eig.eigenvalues();  // ascending; l[0] ~ 0 (flat)
      const Vec3 tangent = Vec3(-centre.y(), centre.x(), 0.0).normalized();
      mean_aspect[run] += std::sqrt(l[2] / std::max(l[1], 1e-300));
      mean_angle[run] += std::acos(std::min(1.0, std::abs(eig.eigenvectors().col(2).dot(tangent)))) * 180.0 / kPi;
      ++n;
    }
    ASSERT_GE(n, 90);
    mean_aspect[run] /= n;
    mean_angle[run] /= n;
  }
  std::printf("[ direction ] '-y, x, 0' stretch 3: mean aspect %.2f, major axis %.1f deg from tangential "
              "(isotropic: aspect %.2f, %.1f deg)\n",
              mean_aspect[0], mean_angle[0], mean_aspect[1], mean_angle[1]);
  EXPECT_GT(mean_aspect[0], 2.0);
  EXPECT_LE(mean_angle[0], 15.0);
  EXPECT_LE(mean_aspect[1], 1.5);  // the control: the elongation is the expression's doing
}

TEST(DirectionExpression, ConstantExpressionIsExactlyTheAxis) {
  // Curved, so the projection into each face matters.
  const TriMesh mesh = make_grid_surface(40, 30, [](double s, double t) {
    return Vec3(2.0 * s, 1.5 * t, 0.3 * std::sin(kPi * s) * std::cos(kPi * t));
  });
  RemeshParams p;
  p.panels = 25;
  p.anisotropy.stretch = 3.0;
  ASSERT_TRUE(set_anisotropy_direction(p.anisotropy, "x"));
  Remesher axis(mesh, p);
  axis.run();
  ASSERT_TRUE(set_anisotropy_direction(p.anisotropy, "expression"));
  p.anisotropy.expression = "1, 0, 0";
  Remesher expr(mesh, p);
  expr.run();
  EXPECT_EQ(axis.metric().faces().stretch, expr.metric().faces().stretch);
  EXPECT_EQ(axis.clustering().labels, expr.clustering().labels);
  // And a different expression does change them (the comparison can fail).
  p.anisotropy.expression = "0, 1, 0";
  Remesher other(mesh, p);
  other.run();
  EXPECT_NE(axis.clustering().labels, other.clustering().labels);
}

TEST(DirectionExpression, ZeroOrNormalDirectionsStayIsotropicAndAreCounted) {
  const TriMesh mesh = centred_square(20);  // 800 faces, z = 0
  Anisotropy a;
  a.stretch = 4.0;
  ASSERT_TRUE(set_anisotropy_direction(a, "expression"));
  a.expression = "0, 0, 1";  // along every normal
  std::vector<Vec3> e = face_stretch_vectors(mesh, a, nullptr);
  EXPECT_EQ(count_isotropic_faces(e, a), mesh.num_faces());
  a.expression = "if(x > 0, 1, 0), 0, 0";  // zero on the left half
  e = face_stretch_vectors(mesh, a, nullptr);
  EXPECT_EQ(count_isotropic_faces(e, a), mesh.num_faces() / 2);
  const double full = std::sqrt(1.0 - 1.0 / 16.0);
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const bool right = face_centroid(mesh, f).x() > 0.0;
    EXPECT_NEAR(e[static_cast<size_t>(f)].norm(), right ? full : 0.0, 1e-12);
  }
  // The magnitude does not matter: "100 * x" stretches as much as "x" (unit after the value).
  a.expression = "nz * 1e300, -nz * 1e300, 0";  // huge but finite: no overflow in the norm
  e = face_stretch_vectors(mesh, a, nullptr);
  EXPECT_EQ(count_isotropic_faces(e, a), 0);
  EXPECT_NEAR(e[0].norm(), full, 1e-12);
  // Values that are not finite name the component and the face.
  a.expression = "1, log(x - 5), 0";
  try {
    face_stretch_vectors(mesh, a, nullptr);
    ADD_FAILURE() << "no error";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("component 2 (y) gives NaN at face 1"), std::string::npos) << err.what();
  }
}

TEST(DirectionExpression, HostileOrBrokenExpressionsAreRefused) {
  EXPECT_EQ(direction_error("-y, x, 0"), "");
  EXPECT_EQ(direction_error("atan2(y, x), min(x, y, z), clamp(z, 0, 1)"), "");  // commas inside calls
  EXPECT_EQ(direction_error("if(z > 1, 1, 0), 0, 1"), "");
  const auto has = [](const std::string& text, const std::string& part) {
    const std::string e = direction_error(text);
    EXPECT_NE(e.find(part), std::string::npos) << "'" << text.substr(0, 60) << "' gave '" << e << "'";
  };
  has("-y, x", "needs three components");
  has("x", "needs three components");
  has("x, y, z, 1", "more than three components (a third comma at column 8)");
  has("x, , z", "component 2 (y) is empty (column 3)");
  has("x, y, alert(1)", "component 3 (z) has unknown name 'alert' at column 7");
  has("x, y +* 2, z", "component 2 (y) has unexpected '*' at column 7");
  has("x, (y, z", "has a '(' at column 4 that is not closed");
  has("x, y, z)", "has an unmatched ')' at column 8");
  has("x), y, z", "has an unmatched ')' at column 2");
  has("x, y, z +", "component 3 (z) ends early: expected a value at column 10");
  has("x, y\x01, z", "component 2 (y) has a control character at column 5");
  has("x, \xc3\xa9, z", "component 2 (y) has a non-ASCII character at column 4");
  has("x, y, z = 1", "component 3 (z) has '=' at column 9");
  has("x, border, 0", "component 2 (y) uses border, which only density expressions have");
  has(std::string(Expression::kMaxLength + 1, ' '), "too long (4097 characters; at most 4096)");
  std::string deep = "x, y, ";
  for (int i = 0; i < Expression::kMaxDepth + 5; ++i) deep += "(";
  deep += "z";
  for (int i = 0; i < Expression::kMaxDepth + 5; ++i) deep += ")";
  has(deep, "component 3 (z) is nested too deeply");
  // Each component under the term limit, the three together over it.
  std::string sum = "x";
  for (int i = 0; i < 350; ++i) sum += "+x";  // 701 terms
  has(sum + "," + sum + "," + sum, "too many terms (2103 in its three components; at most 2000)");
  has("x, y, " + sum + sum.substr(1) + sum.substr(1), "component 3 (z) has too many terms");
}

TEST(DirectionExpression, ParamsJsonContract) {
  const RemeshParams p =
      remesh_params_from_json(R"j({"anisotropy": {"direction": "expression", "expression": "-y, x, 0", "stretch": 3}})j");
  EXPECT_EQ(p.anisotropy.direction, AnisotropyDirection::Expression);
  EXPECT_EQ(p.anisotropy.expression, "-y, x, 0");
  EXPECT_EQ(p.anisotropy.stretch, 3.0);
  EXPECT_STREQ(anisotropy_direction_name(p.anisotropy), "expression");
  // Another direction on top clears the expression.
  const RemeshParams q = remesh_params_from_json(R"j({"anisotropy": {"direction": "x"}})j", p);
  EXPECT_EQ(q.anisotropy.direction, AnisotropyDirection::Constant);
  EXPECT_EQ(q.anisotropy.expression, "");
  const auto message = [](const std::string& json) {
    return test::input_error_message([&] { remesh_params_from_json(json); });
  };
  EXPECT_NE(message(R"j({"anisotropy": {"direction": "expression", "stretch": 2}})j")
                .find("'anisotropy.expression' is missing"),
            std::string::npos);
  EXPECT_NE(message(R"j({"anisotropy": {"direction": "x", "expression": "1, 0, 0", "stretch": 2}})j")
                .find("'anisotropy.expression' is only for direction \"expression\""),
            std::string::npos);
  EXPECT_NE(message(R"j({"anisotropy": {"direction": "expression", "expression": 3}})j")
                .find("'anisotropy.expression' must be a string"),
            std::string::npos);
  EXPECT_NE(message(R"j({"anisotropy": {"direction": "expression", "expression": "x, q, 0"}})j")
                .find("'anisotropy.expression': direction expression, component 2 (y) has unknown name 'q' at column 4"),
            std::string::npos);
}

}  // namespace
}  // namespace ff
