// Cut sheets as ASCII DXF R12 (AC1009), the version every CAM program reads: closed
// POLYLINEs for outlines, TEXT for labels and chamfers, layers per sheet, and the sheets
// side by side so they also read as one drawing.
#include <algorithm>
#include <cstdio>
#include <sstream>

#include "core/fabricate/cut_sheets.h"
#include "core/fabricate/sheet_drawing.h"

namespace ff {
namespace {

std::string dxf_number(double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.12g", v == 0.0 ? 0.0 : v);
  return buffer;
}

// TEXT values are one line; "%%" starts a control code, "%%%" is a literal percent.
std::string dxf_text(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '%') {
      out += "%%%";
    } else if (static_cast<unsigned char>(c) < 0x20) {
      out += ' ';
    } else {
      out += c;
    }
  }
  return out;
}

int insunits(const std::string& units) {
  if (units == "in") return 1;
  if (units == "ft") return 2;
  if (units == "mm") return 4;
  if (units == "cm") return 5;
  if (units == "m") return 6;
  return 0;  // unitless
}

struct Writer {
  std::ostringstream out;
  Vec2 shift = Vec2::Zero();  // of the current sheet

  void group(int code, const std::string& value) { out << code << "\n" << value << "\n"; }
  void group(int code, double value) { group(code, dxf_number(value)); }
  void group(int code, int value) { group(code, std::to_string(value)); }

  void polyline(const std::vector<Vec2>& polygon, const std::string& layer) {
    if (polygon.empty()) return;
    group(0, "POLYLINE");
    group(8, layer);
    group(66, 1);  // vertices follow
    group(10, 0.0), group(20, 0.0), group(30, 0.0);
    group(70, 1);  // closed
    for (const Vec2& p : polygon) {
      group(0, "VERTEX");
      group(8, layer);
      group(10, p.x() + shift.x()), group(20, p.y() + shift.y()), group(30, 0.0);
    }
    group(0, "SEQEND");
    group(8, layer);
  }

  void text(const SheetText& t, const std::string& layer, const std::string& suffix) {
    const Vec2 at = t.at + shift;
    group(0, "TEXT");
    group(8, layer);
    group(10, at.x()), group(20, at.y()), group(30, 0.0);
    group(40, t.height);
    group(1, dxf_text(t.text) + suffix);
    if (t.angle_deg != 0.0) group(50, t.angle_deg);
    group(72, 1);  // centred
    group(73, 2);  // middle: the alignment point below is the text's centre
    group(11, at.x()), group(21, at.y()), group(31, 0.0);
  }

  void layer(const std::string& name, int color, const std::string& linetype) {
    group(0, "LAYER");
    group(2, name);
    group(70, 0);
    group(62, color);
    group(6, linetype);
  }
};

}  // namespace

std::string cut_sheets_dxf(const std::vector<PanelOutline>& outlines, const SheetLayout& layout,
                           const SheetOptions& options) {
  const std::vector<DrawnOutline> drawn = draw_outlines(outlines, layout, options);
  const double w = options.width, h = options.height, gap = 0.05 * w;
  const int units = insunits(options.units);
  Writer wr;
  wr.group(0, "SECTION"), wr.group(2, "HEADER");
  wr.group(9, "$ACADVER"), wr.group(1, "AC1009");
  wr.group(9, "$INSUNITS"), wr.group(70, units);
  wr.group(9, "$MEASUREMENT"), wr.group(70, units == 1 || units == 2 ? 0 : 1);
  wr.group(9, "$EXTMIN"), wr.group(10, 0.0), wr.group(20, 0.0), wr.group(30, 0.0);
  const int sheets = std::max(layout.sheets, 1);
  wr.group(9, "$EXTMAX"), wr.group(10, sheets * w + (sheets - 1) * gap), wr.group(20, h), wr.group(30, 0.0);
  wr.group(0, "ENDSEC");

  wr.group(0, "SECTION"), wr.group(2, "TABLES");
  wr.group(0, "TABLE"), wr.group(2, "LTYPE"), wr.group(70, 2);
  wr.group(0, "LTYPE"), wr.group(2, "CONTINUOUS"), wr.group(70, 0), wr.group(3, "Solid line");
  wr.group(72, 65), wr.group(73, 0), wr.group(40, 0.0);
  const double dash = 0.004 * std::max(w, h);
  wr.group(0, "LTYPE"), wr.group(2, "DASHED"), wr.group(70, 0), wr.group(3, "Dashed __ __ __");
  wr.group(72, 65), wr.group(73, 2), wr.group(40, 1.5 * dash), wr.group(49, dash), wr.group(49, -0.5 * dash);
  wr.group(0, "ENDTAB");
  // Per sheet: the cuts (outer outlines), the inner faces, the sheet's frame, the text.
  wr.group(0, "TABLE"), wr.group(2, "LAYER"), wr.group(70, 1 + 4 * layout.sheets);
  wr.layer("0", 7, "CONTINUOUS");
  for (int s = 1; s <= layout.sheets; ++s) {
    const std::string name = "SHEET_" + std::to_string(s);
    wr.layer(name, 7, "CONTINUOUS");
    wr.layer(name + "_INNER", 5, "DASHED");
    wr.layer(name + "_FRAME", 8, "CONTINUOUS");
    wr.layer(name + "_TEXT", 3, "CONTINUOUS");
  }
  wr.group(0, "ENDTAB");
  wr.group(0, "ENDSEC");

  wr.group(0, "SECTION"), wr.group(2, "ENTITIES");
  for (int s = 0; s < layout.sheets; ++s) {
    const std::string name = "SHEET_" + std::to_string(s + 1);
    wr.shift = Vec2(s * (w + gap), 0.0);
    wr.polyline({Vec2(0, 0), Vec2(w, 0), Vec2(w, h), Vec2(0, h)}, name + "_FRAME");
    for (const DrawnOutline& d : drawn) {
      if (d.sheet != s) continue;
      wr.polyline(d.outer, name);
      wr.polyline(d.inner, name + "_INNER");
      if (d.label.height > 0.0) wr.text(d.label, name + "_TEXT", "");
      for (const SheetText& t : d.chamfers) wr.text(t, name + "_TEXT", "%%d");
    }
  }
  wr.group(0, "ENDSEC");
  wr.group(0, "EOF");
  return wr.out.str();
}

}  // namespace ff
