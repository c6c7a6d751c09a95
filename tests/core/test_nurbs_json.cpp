#include <gtest/gtest.h>

#include <string>

#include "core/prepare/nurbs_json.h"
#include "core/util/error.h"
#include "input_error_message.h"

namespace ff {
namespace {

const std::string kPatch =
    R"({"name": "'Roof'", "degreeU": 1, "degreeV": 1, "countU": 2, "countV": 2, "knotsU": [0, 1], "knotsV": [0, 1],)"
    R"( "points": [0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 1])";

std::string surface_set_error(const std::string& json) {
  return test::input_error_message([&] { surface_set_from_json(json); });
}

TEST(NurbsJson, ReadsASurfaceSet) {
  const SurfaceSet set = surface_set_from_json(R"({"targetTriangles": 5000, "weldTolerance": 0.001, "surfaces": [)" +
                                               kPatch + R"(, "weights": [1, 2, 1, 1]}]})");
  ASSERT_EQ(set.surfaces.size(), 1u);
  EXPECT_EQ(set.surfaces[0].name, "'Roof'");
  EXPECT_EQ(set.target_triangles, 5000);
  EXPECT_EQ(set.weld_tolerance, 0.001);
  EXPECT_EQ(set.surfaces[0].surface.knots_u.size(), 4u);  // made textbook
  EXPECT_EQ(set.surfaces[0].surface.points[3], Vec3(1, 1, 1));
  EXPECT_EQ(set.surfaces[0].surface.weights[1], 2.0);
}

TEST(NurbsJson, RefusesBadDescriptionsByName) {
  auto with = [](const std::string& extra) { return R"({"surfaces": [)" + kPatch + extra + "}]}"; };
  EXPECT_EQ(surface_set_error(with("")), "");
  EXPECT_EQ(surface_set_error(with(R"(, "colour": 1)")), "'Roof': unknown key 'colour'");
  EXPECT_EQ(surface_set_error(with(R"(, "weights": [1, 1, -1, 1])")), "'Roof': weight 2 is not positive and finite");
  EXPECT_EQ(surface_set_error(with(R"(, "weights": [1, 1, "a", 1])")), "'Roof' 'weights'[2] must be a number");
  EXPECT_EQ(surface_set_error(R"({"surfaces": [{"degreeU": 1}]})"), "surface 0: 'degreeV' is missing");
  EXPECT_EQ(surface_set_error(R"({"surfaces": 3})"), "the surface description needs a 'surfaces' array");
  EXPECT_EQ(surface_set_error(R"({"surfaces": [], "edgeLength": 0})"), "'edgeLength' must be above 0");
  EXPECT_EQ(surface_set_error(R"({"surfaces": [], "targetTriangles": 1e9})"),
            "'targetTriangles' must be a whole number from 100 to 2000000");
  EXPECT_EQ(surface_set_error(R"({"surfaces": [], "x": 1})"), "unknown key 'x' in the surface description");
  EXPECT_NE(surface_set_error("[1, 2"), "");
  std::string points = "[0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1]";
  EXPECT_EQ(
      surface_set_error(
          R"({"surfaces": [{"name": "R", "degreeU": 1, "degreeV": 1, "countU": 2, "countV": 2, "knotsU": [0, 1], "knotsV": [0, 1], "points": )" +
          points + "}]}"),
      "R: 'points' must hold x, y, z triples");
}

}  // namespace
}  // namespace ff
