// Fabrication settings from the page's JSON (fabrication_params_json.h).
#include <gtest/gtest.h>

#include <string>

#include "core/fabricate/fabrication_params_json.h"
#include "core/util/error.h"
#include "input_error_message.h"

namespace ff {
namespace {

std::string settings_error(const std::string& json) {
  return test::input_error_message([&] { fabrication_settings_from_json(json); });
}

TEST(FabricationParamsJson, DefaultsAsTheCli) {
  const FabricationSettings s = fabrication_settings_from_json("{}");
  EXPECT_EQ(s.options.mesh_units, LengthUnit::Metre);
  EXPECT_EQ(s.options.units, LengthUnit::Metre);
  EXPECT_EQ(s.options.thickness, 0.0);
  EXPECT_EQ(s.options.side, MaterialSide::Inside);
  EXPECT_DOUBLE_EQ(s.sheet.width, 2.44);
  EXPECT_DOUBLE_EQ(s.sheet.height, 1.22);
  EXPECT_EQ(s.sheet.units, "m");
}

TEST(FabricationParamsJson, ReadsEveryField) {
  const FabricationSettings s = fabrication_settings_from_json(
      R"({"thickness": 20, "side": "outside", "units": "mm", "meshUnits": "cm", "sheetWidth": 3000, "sheetHeight": 1500})");
  EXPECT_EQ(s.options.units, LengthUnit::Millimetre);
  EXPECT_EQ(s.options.mesh_units, LengthUnit::Centimetre);
  EXPECT_EQ(s.options.thickness, 20.0);
  EXPECT_EQ(s.options.side, MaterialSide::Outside);
  EXPECT_EQ(s.sheet.width, 3000.0);
  EXPECT_EQ(s.sheet.height, 1500.0);
  EXPECT_DOUBLE_EQ(s.sheet.margin, 10.0);
}

TEST(FabricationParamsJson, ErrorsNameTheField) {
  EXPECT_NE(settings_error(R"({"thickness": -1})").find("'thickness'"), std::string::npos);
  EXPECT_NE(settings_error(R"({"thickness": "20"})").find("'thickness'"), std::string::npos);
  EXPECT_NE(settings_error(R"({"side": "middle"})").find("'side'"), std::string::npos);
  EXPECT_NE(settings_error(R"({"units": "yd"})").find("'units'"), std::string::npos);
  EXPECT_NE(settings_error(R"({"meshUnits": 1})").find("'meshUnits'"), std::string::npos);
  EXPECT_NE(settings_error(R"({"sheetWidth": 0})").find("'sheetWidth'"), std::string::npos);
  EXPECT_NE(settings_error(R"({"sheetHeight": 1e12})").find("'sheetHeight'"), std::string::npos);
  EXPECT_NE(settings_error(R"({"kerf": 3})").find("'kerf'"), std::string::npos);
  EXPECT_NE(settings_error("[]").find("object"), std::string::npos);
}

TEST(FabricationParamsJson, PanelThicknessAndBoundaryCut) {
  const FabricationSettings s = fabrication_settings_from_json(
      R"({"thickness": 20, "panelThickness": {"P3": 30, "P12a": 8}, "boundaryCut": "bevel", "boundaryBevelDeg": -15})");
  ASSERT_EQ(s.options.panel_thickness.size(), 2u);
  EXPECT_EQ(s.options.panel_thickness[0].first, "P3");
  EXPECT_EQ(s.options.panel_thickness[0].second, 30.0);
  EXPECT_EQ(s.options.panel_thickness[1].first, "P12a");
  EXPECT_EQ(s.options.boundary.kind, BoundaryCut::Kind::Bevel);
  EXPECT_EQ(s.options.boundary.bevel_deg, -15.0);
  const FabricationSettings plumb = fabrication_settings_from_json(R"({"boundaryCut": "plumb", "upAxis": "y"})");
  EXPECT_EQ(plumb.options.boundary.kind, BoundaryCut::Kind::Plumb);
  EXPECT_EQ(plumb.options.boundary.up, Vec3::UnitY());
  EXPECT_EQ(fabrication_settings_from_json("{}").options.boundary.kind, BoundaryCut::Kind::Square);
  EXPECT_NE(settings_error(R"({"panelThickness": {"P3": 0}})").find("'panelThickness.P3'"), std::string::npos);
  EXPECT_NE(settings_error(R"({"panelThickness": {"Q3": 1}})").find("not a panel label"), std::string::npos);
  EXPECT_NE(settings_error(R"({"panelThickness": {"P0": 1}})").find("not a panel label"), std::string::npos);
  EXPECT_NE(settings_error(R"({"panelThickness": [1]})").find("'panelThickness'"), std::string::npos);
  EXPECT_NE(settings_error(R"({"boundaryCut": "round"})").find("'boundaryCut'"), std::string::npos);
  EXPECT_NE(settings_error(R"({"boundaryBevelDeg": 70})").find("'boundaryBevelDeg'"), std::string::npos);
  EXPECT_NE(settings_error(R"({"upAxis": "w"})").find("'upAxis'"), std::string::npos);
}

}  // namespace
}  // namespace ff
