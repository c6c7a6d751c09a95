// The coplanar angle (RemeshParams::coplanar_angle_deg, the CLI's --coplanar-angle, the
// page's "coplanarAngleDeg"): neighbouring clusters whose planes differ by less than it
// share a master plane (paper 2.4) unless their planes meet near them (master_planes.h). On
// a shallow dome nearly every pair of neighbours is within the paper's degree at a few
// hundred panels; before pairs that meet near them were left out, 90-340 of 300-800 panels
// ended invalid there (README.md, "Shallow surfaces").
#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

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

// A closed lens: two such domes (up and down) sharing their rim, a knife edge of
// 4 rise / radius radians. Outward normals; Euler characteristic 2.
TriMesh lens(int rings, double radius, double rise) {
  const TriMesh top = shallow_dome(rings, radius, rise);
  const int rim_start = 1 + (rings - 1) * 4 * rings;  // the top's last ring: shared
  TriMesh m = top;
  std::vector<int> id(top.positions.size());
  for (size_t v = 0; v < top.positions.size(); ++v) {
    if (static_cast<int>(v) >= rim_start) {
      id[v] = static_cast<int>(v);
      continue;
    }
    id[v] = static_cast<int>(m.positions.size());
    m.positions.push_back(Vec3(top.positions[v].x(), top.positions[v].y(), -top.positions[v].z()));
  }
  for (const Triangle& t : top.triangles) m.triangles.push_back({id[t[0]], id[t[2]], id[t[1]]});
  return m;
}

// 20 m across, rising 0.2 m (1:100, the slope at the rim 2.3 degrees) and 0.05 m (1:400).
// At 300 and 600 panels neighbouring planes differ by 0.1-0.4 degrees. Valid at the paper's
// degree (the default) and at a quarter of it.
struct DomeCase {
  double rise;
  int panels;
  double angle;
};

void PrintTo(const DomeCase& c, std::ostream* os) {
  *os << "rise " << c.rise << " at " << c.panels << " panels, " << c.angle << " degrees";
}

class ShallowDome : public ::testing::TestWithParam<DomeCase> {};

TEST_P(ShallowDome, ValidPlanarAndTopologyPreserving) {
  const DomeCase& c = GetParam();
  RemeshParams p;
  p.panels = c.panels;
  p.coplanar_angle_deg = c.angle;
  Remesher r(shallow_dome(40, 10.0, c.rise), p);
  r.run();
  EXPECT_TRUE(test::valid_panels(r, c.panels, 0.05));
}

INSTANTIATE_TEST_SUITE_P(Cases, ShallowDome,
                         ::testing::Values(DomeCase{0.2, 300, 1.0}, DomeCase{0.2, 600, 1.0},
                                           DomeCase{0.05, 600, 1.0}, DomeCase{0.2, 600, 0.25}));

// The lens 1:50 thick (a 4.6-degree knife edge) at 800 panels, and 1:100 thick (2.3
// degrees) at 400: 278 and 62 invalid panels while every pair within the degree snapped.
TEST(ShallowLens, ValidAtAKnifeEdgeRim) {
  for (const auto& [rise, panels] : {std::pair<double, int>{0.2, 800}, std::pair<double, int>{0.1, 400}}) {
    RemeshParams p;
    p.panels = panels;
    Remesher r(lens(40, 10.0, rise), p);
    r.run();
    EXPECT_TRUE(test::valid_panels(r, panels, 0.05)) << "rise " << rise << " at " << panels;
  }
}

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
