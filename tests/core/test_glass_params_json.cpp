// Glass mode from the page's parameter JSON (remesh_params_from_json): "glass" and
// "minCornerAngleDeg" (0..60, as the CLI's --glass and --min-angle).
#include <gtest/gtest.h>

#include <string>

#include "core/remesh_params_json.h"
#include "core/util/error.h"
#include "input_error_message.h"

namespace ff {
namespace {

TEST(GlassParamsJson, ReadsGlassAndMinimumAngle) {
  const RemeshParams p = remesh_params_from_json(R"({"glass": true, "minCornerAngleDeg": 12.5})");
  EXPECT_TRUE(p.glass);
  EXPECT_EQ(p.min_corner_angle_deg, 12.5);
  const RemeshParams off = remesh_params_from_json("{}");
  EXPECT_FALSE(off.glass);
  EXPECT_EQ(off.min_corner_angle_deg, 0.0);
}

TEST(GlassParamsJson, RefusesBadValuesByName) {
  auto message = [](const std::string& json) {
    return test::input_error_message([&] { remesh_params_from_json(json); }, "accepted");
  };
  EXPECT_NE(message(R"({"glass": 1})").find("'glass' must be true or false"), std::string::npos);
  EXPECT_NE(message(R"({"minCornerAngleDeg": 61})").find("'minCornerAngleDeg'"), std::string::npos);
  EXPECT_NE(message(R"({"minCornerAngleDeg": -1})").find("'minCornerAngleDeg'"), std::string::npos);
  EXPECT_NE(message(R"({"minCornerAngleDeg": "10"})").find("must be a number"), std::string::npos);
}

}  // namespace
}  // namespace ff
