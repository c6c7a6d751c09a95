// Cut sheets as SVG: sheets side by side, each a <g> with its frame; y flipped so the
// sheet's lower-left is at the bottom as on the DXF.
#include <algorithm>
#include <sstream>

#include "core/fabricate/cut_sheets.h"
#include "core/fabricate/sheet_drawing.h"

namespace ff {
namespace {

std::string escape_xml(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        // Control characters are not allowed in XML 1.0: drop them.
        if (static_cast<unsigned char>(c) >= 0x20 || c == '\t') out += c;
    }
  }
  return out;
}

// SVG accepts mm, cm, in, pt, pc, px; metres and feet are written in mm and inches.
std::string svg_length(double value, const std::string& units) {
  if (units == "mm" || units == "cm" || units == "in" || units == "pt" || units == "pc" || units == "px") {
    return format_number(value, 6) + units;
  }
  if (units == "m") return format_number(value * 1000.0, 6) + "mm";
  if (units == "ft") return format_number(value * 12.0, 6) + "in";
  return format_number(value, 6);
}

struct Writer {
  std::ostringstream out;
  double height = 0.0;  // of a sheet, to flip y

  std::string point(const Vec2& p) const { return format_number(p.x(), 6) + "," + format_number(height - p.y(), 6); }

  void path(const std::vector<Vec2>& polygon, const char* cls, const char* extra) {
    if (polygon.empty()) return;
    out << "    <path class=\"" << cls << "\" d=\"M";
    for (std::size_t i = 0; i < polygon.size(); ++i) out << (i ? " L" : "") << point(polygon[i]);
    out << " Z\"" << extra << "/>\n";
  }

  void text(const SheetText& t, const char* cls, const std::string& suffix) {
    const std::string at = point(t.at);
    const std::string x = at.substr(0, at.find(',')), y = at.substr(at.find(',') + 1);
    out << "    <text class=\"" << cls << "\" x=\"" << x << "\" y=\"" << y << "\" font-size=\""
        << format_number(t.height, 6) << "\"";
    // SVG turns clockwise with y down: negate the counter-clockwise angle.
    if (t.angle_deg != 0.0)
      out << " transform=\"rotate(" << format_number(-t.angle_deg, 4) << " " << x << " " << y << ")\"";
    out << ">" << escape_xml(t.text + suffix) << "</text>\n";
  }
};

}  // namespace

std::string cut_sheets_svg(const std::vector<PanelOutline>& outlines, const SheetLayout& layout,
                           const SheetOptions& options) {
  const std::vector<DrawnOutline> drawn = draw_outlines(outlines, layout, options);
  const double w = options.width, h = options.height;
  const double gap = 0.05 * w;
  const int sheets = std::max(layout.sheets, 1);
  const double total_w = sheets * w + (sheets - 1) * gap;
  const double stroke = 0.0004 * std::max(w, h);
  Writer wr;
  wr.height = h;
  wr.out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << svg_length(total_w, options.units) << "\" height=\""
         << svg_length(h, options.units) << "\" viewBox=\"0 0 " << format_number(total_w, 6) << " "
         << format_number(h, 6) << "\">\n"
         << "  <title>Flatfacet cut sheets: " << layout.placed.size() << " parts on " << layout.sheets << " sheets of "
         << format_number(w, 6) << " x " << format_number(h, 6) << " " << escape_xml(options.units) << "</title>\n"
         << "  <style>path, rect { fill: none; stroke-width: " << format_number(stroke, 6)
         << "; } .outer { stroke: #000; } "
         << ".inner { stroke: #06c; stroke-dasharray: " << format_number(4 * stroke, 6) << " "
         << format_number(3 * stroke, 6) << "; } .sheet { stroke: #aaa; } "
         << "text { font-family: sans-serif; text-anchor: middle; dominant-baseline: central; } "
         << ".chamfer { fill: #c30; }</style>\n";
  for (int s = 0; s < layout.sheets; ++s) {
    wr.out << "  <g id=\"sheet-" << s + 1 << "\" transform=\"translate(" << format_number(s * (w + gap), 6)
           << " 0)\">\n"
           << "    <rect class=\"sheet\" x=\"0\" y=\"0\" width=\"" << format_number(w, 6) << "\" height=\""
           << format_number(h, 6) << "\"/>\n";
    for (const DrawnOutline& d : drawn) {
      if (d.sheet != s) continue;
      wr.path(d.outer, "outer", "");
      wr.path(d.inner, "inner", "");
      if (d.label.height > 0.0) wr.text(d.label, "label", "");
      for (const SheetText& t : d.chamfers) wr.text(t, "chamfer", "\u00b0");
    }
    wr.out << "  </g>\n";
  }
  wr.out << "</svg>\n";
  return wr.out.str();
}

}  // namespace ff
