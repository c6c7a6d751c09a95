// The coplanar angle (RemeshParams::coplanar_angle_deg, the CLI's --coplanar-angle, the
// page's "coplanarAngleDeg"): neighbouring clusters whose planes differ by less than it
// share a master plane (paper 2.4). On a shallow dome nearly every pair of neighbours does
// at a few hundred panels; the paper's 1 degree then leaves 90-340 of 300-800 panels invalid
// (README.md, "Shallow surfaces"), a quarter of a degree none.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/remesh_params_json.h"
#include "core/remesher.h"
#include "core/util/error.h"
#include "input_error_message.h"
#include "panel_checks.h"

namespace ff {
namespace {

// A shallow dome z = rise (1 - (r / radius)^2) on a polar grid: a centre, `rings` rings of
// 4 * rings vertices. Normals up; one boundary loop.
TriMesh shallow_dome(int rings, double radius, double rise) {
  const int around = 4 * rings;
  TriMesh m;
  m.positions.push_back(Vec3(0.0, 0.0, rise));
  for (int i = 1; i <= rings; ++i) {
    const double r = radius * i / rings;
    for (int j = 0; j < around; ++j) {
      const double t = 2.0 * 3.14159265358979323846 * j / around;
      m.positions.push_back(Vec3(r * std::cos(t), r * std::sin(t), rise * (1.0 - (r / radius) * (r / radius))));
    }
  }
  const auto at = [&](int ring, int j) { return 1 + (ring - 1) * around + (j % around); };
  for (int j = 0; j < around; ++j) m.triangles.push_back({0, at(1, j), at(1, j + 1)});
  for (int i = 1; i < rings; ++i) {
    for (int j = 0; j < around; ++j) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return m;
}

// 20 m across, rising 0.2 m: 1:100, the slope at the rim 2.3 degrees. At 300 and 600 panels
// neighbouring planes differ by 0.3-0.4 degrees.
class ShallowDome : public ::testing::TestWithParam<int> {};

TEST_P(ShallowDome, ValidWithAQuarterDegree) {
  RemeshParams p;
  p.panels = GetParam();
  p.coplanar_angle_deg = 0.25;
  Remesher r(shallow_dome(40, 10.0, 0.2), p);
  r.run();
  EXPECT_TRUE(test::valid_panels(r, GetParam(), 0.05)) << "at " << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Counts, ShallowDome, ::testing::Values(300, 600));

TEST(CoplanarAngle, OutOfRangeIsRefusedByName) {
  for (const double bad : {-0.5, 10.5, std::nan("")}) {
    RemeshParams p;
    p.panels = 10;
    p.coplanar_angle_deg = bad;
    const std::string message = test::input_error_message([&] { Remesher(shallow_dome(8, 10.0, 0.2), p); }, "accepted");
    EXPECT_NE(message.find("coplanar angle must be between 0 and 10 degrees"), std::string::npos) << bad;
  }
}

TEST(CoplanarAngle, ReadFromTheParameterJson) {
  EXPECT_EQ(remesh_params_from_json(R"({"coplanarAngleDeg": 0.25})").coplanar_angle_deg, 0.25);
  EXPECT_EQ(remesh_params_from_json("{}").coplanar_angle_deg, 1.0);
  const std::string message =
      test::input_error_message([] { remesh_params_from_json(R"({"coplanarAngleDeg": 11})"); }, "accepted");
  EXPECT_NE(message.find("'coplanarAngleDeg'"), std::string::npos);
}

}  // namespace
}  // namespace ff
