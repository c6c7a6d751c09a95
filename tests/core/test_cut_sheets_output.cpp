// Cut sheets as files: the SVG is well-formed XML with one path per outline, labels escaped
// and chamfers written; the DXF has its sections, closed polylines per layer, text and EOF.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/fabricate/cut_sheets.h"
#include "cut_sheet_checks.h"

namespace ff {
namespace {

using namespace cut_sheet_test;

// A small XML well-formedness check: balanced tags, quoted attributes, entities only
// where expected, one root. Returns "" or what is wrong.
std::string xml_problem(const std::string& xml) {
  std::vector<std::string> stack;
  int roots = 0;
  std::size_t i = 0;
  auto entity_ok = [&](std::size_t at) {
    for (const char* e : {"&amp;", "&lt;", "&gt;", "&quot;", "&apos;"}) {
      if (xml.compare(at, std::string(e).size(), e) == 0) return true;
    }
    return false;
  };
  if (xml.rfind("<?xml", 0) == 0) i = xml.find("?>") + 2;
  while (i < xml.size()) {
    if (xml[i] == '&' && !entity_ok(i)) return "bad entity at " + std::to_string(i);
    if (xml[i] == '>') return "stray > at " + std::to_string(i);
    if (xml[i] != '<') {
      if (stack.empty() && !std::isspace(static_cast<unsigned char>(xml[i]))) return "text outside the root";
      ++i;
      continue;
    }
    const std::size_t end = xml.find('>', i);
    if (end == std::string::npos) return "unclosed tag";
    std::string tag = xml.substr(i + 1, end - i - 1);
    i = end + 1;
    if (tag[0] == '/') {
      if (stack.empty() || stack.back() != tag.substr(1)) return "mismatched </" + tag.substr(1) + ">";
      stack.pop_back();
      continue;
    }
    const bool empty = tag.back() == '/';
    if (empty) tag.pop_back();
    std::size_t k = tag.find_first_of(" \n\t");
    const std::string name = tag.substr(0, k);
    if (name.empty() || !std::isalpha(static_cast<unsigned char>(name[0]))) return "bad tag name " + name;
    // Attributes: name="value" pairs, values free of < and raw &.
    while (k != std::string::npos && k < tag.size()) {
      while (k < tag.size() && std::isspace(static_cast<unsigned char>(tag[k]))) ++k;
      if (k >= tag.size()) break;
      const std::size_t eq = tag.find("=\"", k);
      if (eq == std::string::npos) return "unquoted attribute in <" + name + ">";
      const std::size_t close = tag.find('"', eq + 2);
      if (close == std::string::npos) return "unclosed attribute in <" + name + ">";
      const std::string value = tag.substr(eq + 2, close - eq - 2);
      if (value.find('<') != std::string::npos) return "< in an attribute";
      k = close + 1;
    }
    if (stack.empty()) ++roots;
    if (!empty) stack.push_back(name);
  }
  if (!stack.empty()) return "unclosed <" + stack.back() + ">";
  return roots == 1 ? "" : "not one root";
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

std::vector<PanelOutline> thick_outlines() {
  std::vector<PanelOutline> outlines = random_outlines(30, 11);
  for (PanelOutline& o : outlines) {
    // An inner face a little smaller (towards the centroid), as a thickness offset gives.
    const Vec2 c = polygon_centroid(o.outer);
    for (const Vec2& q : o.outer) o.inner.push_back(c + 0.9 * (q - c));
    o.thickness = 12;
  }
  outlines[0].label = "A<&>\"'";
  return outlines;
}

TEST(CutSheetsOutput, SvgIsWellFormedWithOnePathPerOutline) {
  EXPECT_NE(xml_problem("<a><b></a></b>"), "");
  EXPECT_NE(xml_problem("<a x=\"1\">&</a>"), "");
  const std::vector<PanelOutline> outlines = thick_outlines();
  const SheetOptions options;
  const SheetLayout layout = pack_outlines(outlines, options);
  const std::string svg = cut_sheets_svg(outlines, layout, options);
  EXPECT_EQ(xml_problem(svg), "");
  EXPECT_EQ(count(svg, "<path class=\"outer\""), static_cast<int>(outlines.size()));
  EXPECT_EQ(count(svg, "<path class=\"inner\""), static_cast<int>(outlines.size()));
  EXPECT_EQ(count(svg, "<g id=\"sheet-"), layout.sheets);
  EXPECT_EQ(count(svg, "<rect class=\"sheet\""), layout.sheets);
  EXPECT_NE(svg.find(">A&lt;&amp;&gt;&quot;&apos;</text>"), std::string::npos);
  EXPECT_NE(svg.find(">P2</text>"), std::string::npos);
  EXPECT_NE(svg.find(">22.5\u00b0</text>"), std::string::npos);
  EXPECT_NE(svg.find("height=\"1220mm\""), std::string::npos);
  EXPECT_NE(svg.find("viewBox=\"0 0 "), std::string::npos);
  EXPECT_NE(svg.find("stroke-dasharray"), std::string::npos);
}

// DXF as (code, value) pairs.
std::vector<std::pair<int, std::string>> dxf_groups(const std::string& dxf) {
  std::istringstream in(dxf);
  std::vector<std::pair<int, std::string>> groups;
  std::string code, value;
  while (std::getline(in, code) && std::getline(in, value)) groups.emplace_back(std::stoi(code), value);
  return groups;
}

TEST(CutSheetsOutput, DxfHasSectionsClosedPolylinesTextAndEof) {
  const std::vector<PanelOutline> outlines = thick_outlines();
  const SheetOptions options;
  const SheetLayout layout = pack_outlines(outlines, options);
  const auto groups = dxf_groups(cut_sheets_dxf(outlines, layout, options));
  ASSERT_FALSE(groups.empty());
  EXPECT_EQ(groups.back(), std::make_pair(0, std::string("EOF")));
  std::vector<std::string> sections;
  std::map<std::string, int> closed_per_layer;
  int vertices = 0, texts = 0, open_polylines = 0;
  for (std::size_t i = 0; i + 1 < groups.size(); ++i) {
    if (groups[i] == std::make_pair(0, std::string("SECTION"))) sections.push_back(groups[i + 1].second);
    if (groups[i] == std::make_pair(0, std::string("TEXT"))) ++texts;
    if (groups[i] == std::make_pair(0, std::string("VERTEX"))) ++vertices;
    if (groups[i] != std::make_pair(0, std::string("POLYLINE"))) continue;
    std::string layer;
    bool closed = false;
    for (std::size_t j = i + 1; j < groups.size() && groups[j].first != 0; ++j) {
      if (groups[j].first == 8) layer = groups[j].second;
      if (groups[j].first == 70) closed = std::stoi(groups[j].second) & 1;
    }
    closed ? ++closed_per_layer[layer] : ++open_polylines;
  }
  EXPECT_EQ(sections, (std::vector<std::string>{"HEADER", "TABLES", "ENTITIES"}));
  EXPECT_EQ(open_polylines, 0);
  int outer = 0, inner = 0, frames = 0;
  for (const auto& [layer, n] : closed_per_layer) {
    const bool sheet = layer.rfind("SHEET_", 0) == 0;
    ASSERT_TRUE(sheet) << layer;
    if (layer.find("_INNER") != std::string::npos) {
      inner += n;
    } else if (layer.find("_FRAME") != std::string::npos) {
      frames += n;
    } else {
      outer += n;
    }
  }
  EXPECT_EQ(outer, static_cast<int>(outlines.size()));
  EXPECT_EQ(inner, static_cast<int>(outlines.size()));
  EXPECT_EQ(frames, layout.sheets);
  int chamfers = 0, points = 4 * layout.sheets;
  for (const PanelOutline& o : outlines) {
    points += static_cast<int>(o.outer.size() + o.inner.size());
    for (const OutlineEdge& e : o.edges) chamfers += e.chamfer_deg != 0.0;
  }
  EXPECT_EQ(vertices, points);
  EXPECT_EQ(texts, static_cast<int>(outlines.size()) + chamfers);
  EXPECT_NE(std::find(groups.begin(), groups.end(), std::make_pair(1, std::string("22.5%%d"))), groups.end());
  EXPECT_NE(std::find(groups.begin(), groups.end(), std::make_pair(1, std::string("AC1009"))), groups.end());
}

}  // namespace
}  // namespace ff
