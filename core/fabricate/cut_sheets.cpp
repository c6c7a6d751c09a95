// Packing outlines onto sheets: checks the options and outlines, lays each outline's
// rotated bounding box with the skyline packer, turns the boxes back into placements, then
// lets the last sheet's parts nest into earlier sheets' gaps.
#include "core/fabricate/cut_sheets.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/fabricate/number_text.h"
#include "core/fabricate/sheet_drawing.h"
#include "core/fabricate/sheet_nesting.h"
#include "core/fabricate/sheet_packing.h"
#include "core/util/error.h"

namespace ff {
namespace {

// The largest sheet side, in the sheet's units: a kilometre even in millimetres.
constexpr double kMaxSheetSide = 1e9;

void check_options(const SheetOptions& o) {
  auto bad = [](double v) { return !std::isfinite(v); };
  if (bad(o.width) || bad(o.height) || o.width <= 0.0 || o.height <= 0.0) {
    throw InputError("sheet size must be two positive numbers, got " + number_text(o.width, 6) + " x " +
                     number_text(o.height, 6));
  }
  // Past this the drawing's numbers (mm in the SVG) leave what a double holds; no sheet is so big.
  if (o.width > kMaxSheetSide || o.height > kMaxSheetSide) {
    throw InputError("sheet size " + number_text(o.width, 6) + " x " + number_text(o.height, 6) +
                     " is larger than any sheet (at most " + number_text(kMaxSheetSide, 6) + " on a side)");
  }
  if (bad(o.margin) || o.margin < 0.0)
    throw InputError("sheet margin must be zero or more, got " + number_text(o.margin, 6));
  if (bad(o.spacing) || o.spacing < 0.0) {
    throw InputError("spacing between parts must be zero or more, got " + number_text(o.spacing, 6));
  }
  if (2.0 * o.margin >= std::min(o.width, o.height)) {
    throw InputError("sheet margin " + number_text(o.margin, 6) + " leaves no room on a " + number_text(o.width, 6) +
                     " x " + number_text(o.height, 6) + " sheet");
  }
}

std::string name_of(const PanelOutline& o, std::size_t index) {
  return o.label.empty() ? "outline " + std::to_string(index + 1) : "panel " + o.label;
}

// Outer and inner points: a bevelled part needs room for both faces.
std::vector<Vec2> footprint(const PanelOutline& o, std::size_t index) {
  if (o.outer.size() < 3) throw InputError(name_of(o, index) + " has fewer than 3 outline points");
  std::vector<Vec2> points = o.outer;
  points.insert(points.end(), o.inner.begin(), o.inner.end());
  for (const Vec2& p : points) {
    if (!p.allFinite()) throw InputError(name_of(o, index) + " has a point that is not a finite number");
  }
  return points;
}

// The rotated box's lower-left goes to the box corner inside the margin.
PlacedOutline to_placement(int outline, const BoxPlacement& b, const PartOrientation& o, double margin) {
  PlacedOutline p;
  p.outline = outline;
  p.sheet = b.sheet;
  p.angle_rad = o.angle_rad;
  p.offset = Vec2::Constant(margin) + b.corner - o.min;
  return p;
}

// After gap filling moved some of the last sheet's parts away, pack the rest afresh so they
// sit together in a corner and leave one large offcut (kept only if they still take one sheet).
void repack_last_sheet(const std::vector<std::vector<PartOrientation>>& parts, const Vec2& area,
                       const SheetOptions& options, SheetLayout* layout) {
  const int last = layout->sheets - 1;
  std::vector<int> rest;
  std::vector<std::vector<PartOrientation>> rest_parts;
  for (const PlacedOutline& p : layout->placed) {
    if (p.sheet == last) rest.push_back(p.outline), rest_parts.push_back(parts[p.outline]);
  }
  if (rest.empty()) return;
  const std::vector<BoxPlacement> boxes = pack_boxes(rest_parts, area, options.spacing);
  for (const BoxPlacement& b : boxes) {
    if (b.sheet != 0) return;
  }
  for (std::size_t k = 0; k < rest.size(); ++k) {
    BoxPlacement b = boxes[k];
    b.sheet = last;
    layout->placed[rest[k]] = to_placement(rest[k], b, rest_parts[k][b.orientation], options.margin);
  }
}

}  // namespace

SheetLayout pack_outlines(const std::vector<PanelOutline>& outlines, const SheetOptions& options) {
  check_options(options);
  const Vec2 area(options.width - 2.0 * options.margin, options.height - 2.0 * options.margin);
  std::vector<std::vector<PartOrientation>> parts;
  std::vector<std::vector<Vec2>> points;
  for (std::size_t i = 0; i < outlines.size(); ++i) {
    points.push_back(footprint(outlines[i], i));
    parts.push_back(part_orientations(points.back(), area));
  }
  const std::vector<BoxPlacement> boxes = pack_boxes(parts, area, options.spacing);
  SheetLayout layout;
  double outline_area = 0.0;
  for (std::size_t i = 0; i < outlines.size(); ++i) {
    const BoxPlacement& b = boxes[i];
    if (b.sheet < 0) {
      const PartOrientation& o = parts[i][0];
      // Four significant digits: rounded to one decimal, 1.343 x 1.229 m read as fitting 2.44 x 1.22.
      throw InputError(name_of(outlines[i], i) + " (" + number_text(o.size.x(), 4) + " x " +
                       number_text(o.size.y(), 4) + " " + options.units + " at its best orientation) fits no " +
                       number_text(options.width, 4) + " x " + number_text(options.height, 4) + " " + options.units +
                       " sheet with a margin of " + number_text(options.margin, 4) + " " + options.units);
    }
    layout.placed.push_back(to_placement(static_cast<int>(i), b, parts[i][b.orientation], options.margin));
    layout.sheets = std::max(layout.sheets, b.sheet + 1);
    outline_area += std::abs(signed_area(outlines[i].outer));
  }
  fill_gaps(outlines, options, &layout);
  if (layout.sheets > 0) repack_last_sheet(parts, area, options, &layout);
  if (layout.sheets > 0) layout.material_use = outline_area / (layout.sheets * options.width * options.height);
  return layout;
}

}  // namespace ff
