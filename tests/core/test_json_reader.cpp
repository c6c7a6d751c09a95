// The JSON reader and the browser's parameter objects: valid documents, and hostile text
// (deep nesting, huge input, bad numbers, unknown or mistyped fields) refused by name.
#include <gtest/gtest.h>

#include <string>

#include "core/remesh_params_json.h"
#include "core/util/error.h"
#include "core/util/json_reader.h"
#include "input_error_message.h"

namespace ff {
namespace {

TEST(JsonReader, ReadsEveryKind) {
  const JsonValue v = parse_json(R"( {"a": [1, -2.5e3, true, false, null], "b": {"c": "x\"y\u00e9\n"}} )");
  ASSERT_EQ(v.type, JsonValue::Type::Object);
  const JsonValue* a = v.find("a");
  ASSERT_NE(a, nullptr);
  ASSERT_EQ(a->array.size(), 5u);
  EXPECT_EQ(a->array[0].number, 1.0);
  EXPECT_EQ(a->array[1].number, -2500.0);
  EXPECT_TRUE(a->array[2].boolean);
  EXPECT_EQ(a->array[3].type, JsonValue::Type::Boolean);
  EXPECT_EQ(a->array[4].type, JsonValue::Type::Null);
  EXPECT_EQ(v.find("b")->find("c")->string, "x\"y\xc3\xa9\n");
  EXPECT_EQ(v.find("missing"), nullptr);
}

TEST(JsonReader, RefusesWhatIsNotJson) {
  for (const char* bad : {"", "{", "[1,]", "{\"a\" 1}", "01x", "NaN", "Infinity", "+1", "0x10", ".5", "1.", "1e",
                          "\"\\q\"", "\"abc", "[1] 2", "{\"a\":1,}", "tru", "\"\x01\"", "01", "-00.5"}) {
    EXPECT_THROW(parse_json(bad), InputError) << bad;
  }
}

TEST(JsonReader, BoundsNestingAndSize) {
  const std::string deep = std::string(100, '[') + std::string(100, ']');
  EXPECT_THROW(parse_json(deep), InputError);
  EXPECT_NO_THROW(parse_json(std::string(10, '[') + std::string(10, ']')));
  EXPECT_THROW(parse_json("[" + std::string(2000, ' ') + "]", 16, 1000), InputError);
}

TEST(RemeshParamsJson, ReadsEveryField) {
  const RemeshParams p = remesh_params_from_json(
      R"({"panels": 120, "seed": 9007199254740991, "weights": {"euclidean": 2, "l2": 0, "l21": 0.5,
          "density": 3, "boundary": 4}, "lloydIterations": 7, "panelRounds": 9, "seeding": "random",
          "teleport": false, "singlePointNodes": true, "optimizePlanes": false})");
  EXPECT_EQ(p.panels, 120);
  EXPECT_EQ(p.seed, 9007199254740991ull);
  EXPECT_EQ(p.weights.euclidean, 2.0);
  EXPECT_EQ(p.weights.l2, 0.0);
  EXPECT_EQ(p.weights.l21, 0.5);
  EXPECT_EQ(p.weights.density, 3.0);
  EXPECT_EQ(p.weights.boundary, 4.0);
  EXPECT_EQ(p.lloyd_iterations, 7);
  EXPECT_EQ(p.panel_rounds, 9);
  EXPECT_EQ(p.seeding, SeedingMethod::Random);
  EXPECT_EQ(p.teleport_interval, 0);
  EXPECT_TRUE(p.single_point_nodes);
  EXPECT_FALSE(p.optimize_planes);
}

TEST(RemeshParamsJson, MissingFieldsKeepTheBase) {
  RemeshParams base;
  base.panels = 33;
  base.seed = 4;
  const RemeshParams p = remesh_params_from_json(R"({"weights": {"l2": 2}})", base);
  EXPECT_EQ(p.panels, 33);
  EXPECT_EQ(p.seed, 4u);
  EXPECT_EQ(p.weights.l2, 2.0);
  EXPECT_EQ(p.weights.euclidean, 1.0);
}

TEST(RemeshParamsJson, RefusesBadFieldsByName) {
  auto message = [](const std::string& json) {
    return test::input_error_message([&] { remesh_params_from_json(json); }, "accepted");
  };
  EXPECT_NE(message(R"({"panels": 0})").find("'panels'"), std::string::npos);
  EXPECT_NE(message(R"({"panels": 1.5})").find("whole number"), std::string::npos);
  EXPECT_NE(message(R"({"panels": "12"})").find("'panels' must be a number"), std::string::npos);
  EXPECT_NE(message(R"({"seed": -1})").find("'seed'"), std::string::npos);
  EXPECT_NE(message(R"({"seed": 1e300})").find("'seed'"), std::string::npos);
  EXPECT_NE(message(R"({"weights": {"l21": 1e9}})").find("weights.l21"), std::string::npos);
  EXPECT_NE(message(R"({"weights": {"euclidean": 0, "l2": 0, "l21": 0}})").find("at least one"), std::string::npos);
  EXPECT_NE(message(R"({"weights": {"shiny": 1}})").find("unknown parameter 'weights.shiny'"), std::string::npos);
  EXPECT_NE(message(R"({"teleport": 1})").find("true or false"), std::string::npos);
  EXPECT_NE(message(R"({"panelRounds": 0})").find("'panelRounds'"), std::string::npos);
  EXPECT_NE(message(R"({"seeding": "best"})").find("'seeding'"), std::string::npos);
  EXPECT_NE(message(R"({"__proto__": {}})").find("unknown parameter"), std::string::npos);
  EXPECT_NE(message("[]").find("object"), std::string::npos);
}

}  // namespace
}  // namespace ff
