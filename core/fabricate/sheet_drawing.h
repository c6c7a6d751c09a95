#pragma once
// What a cut sheet shows, in sheet coordinates (y up, origin at the sheet's lower-left):
// each outline where the packing put it, its label at a roomy inside point, and chamfer
// angles beside their edges. The SVG and DXF writers only serialise this.
#include <string>
#include <vector>

#include "core/fabricate/cut_sheets.h"

namespace ff {

struct SheetText {
  Vec2 at = Vec2::Zero();  // the text's centre
  double height = 0.0;
  double angle_deg = 0.0;  // baseline direction, counter-clockwise from +x, kept readable
  std::string text;        // chamfers: the number only; writers add their degree sign
};

struct DrawnOutline {
  int outline = 0;
  int sheet = 0;
  std::vector<Vec2> outer;  // counter-clockwise, sheet coordinates
  std::vector<Vec2> inner;  // empty without thickness
  SheetText label;
  std::vector<SheetText> chamfers;  // one per edge with a non-zero chamfer
};

// Every placed outline, in the layout's order.
std::vector<DrawnOutline> draw_outlines(const std::vector<PanelOutline>& outlines, const SheetLayout& layout,
                                        const SheetOptions& options);

// A point well inside the polygon for its label (the best of the centroid and a grid of
// samples by distance to the boundary, an approximate pole of inaccessibility), and that
// distance.
Vec2 label_point(const std::vector<Vec2>& polygon, double* clearance);

// Fixed decimals without trailing zeros ("12.5", "3", "-0.25"); "0" for -0.
std::string format_number(double value, int decimals);

}  // namespace ff
