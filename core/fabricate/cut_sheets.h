#pragma once
// Cut sheets: panel outlines laid flat and packed onto sheets of a given size (e.g. 2440 x
// 1220 mm plywood), with labels and edge chamfer annotations, written as SVG or DXF.
#include <string>
#include <vector>

#include "core/fabricate/panel_outline.h"

namespace ff {

struct SheetOptions {
  double width = 2440.0;  // sheet size, in the outlines' units
  double height = 1220.0;
  double margin = 10.0;  // kept free along the sheet's border
  double spacing = 5.0;  // at least this between two outlines (saw kerf and handling)
  std::string units = "mm";
};

struct PlacedOutline {
  int outline = 0;  // index into the outlines given
  int sheet = 0;
  // Where the outline's points went: sheet coordinates = rotation(angle_rad) * p + offset.
  double angle_rad = 0.0;
  Vec2 offset = Vec2::Zero();
};

struct SheetLayout {
  int sheets = 0;
  std::vector<PlacedOutline> placed;  // one per outline, in the outlines' order
  double material_use = 0.0;          // outline area / (sheets * sheet area)
};

// Packs every outline onto as few sheets as it can: the bounding box of each part (outer and
// inner faces) in its minimum-area orientation or turned by 90 degrees, on a skyline,
// bottom-left; then the last sheet's parts move into gaps of earlier sheets (exact polygon
// checks, so they may reach into concave notches) until it empties or nothing fits;
// deterministic. Guarantees every outline inside the sheet minus the margin and
// at least the spacing from every other outline on its sheet. Throws InputError naming the
// first outline that does not fit on an empty sheet in any orientation (with its size and
// the sheet's), for an outline with fewer than 3 or non-finite points, and for bad sheet
// options (non-positive or non-finite size, negative margin or spacing, margins leaving no
// room). No outlines: no sheets.
SheetLayout pack_outlines(const std::vector<PanelOutline>& outlines, const SheetOptions& options);

// One document holding every sheet, side by side (a gap of 5% of the width), sheet y up from
// its lower-left corner; outlines closed, labels at a roomy point inside each outline (the
// centroid when it is roomy enough), chamfer angles beside their edges, inside.
// SVG: a <g id="sheet-N"> per sheet with its frame <rect>, <path class="outer"> per outline,
// dashed <path class="inner">, <text>; width/height in the units (m and ft as mm and in).
// DXF: ASCII R12 (AC1009), $INSUNITS from the units; per sheet the layers SHEET_N (outer
// outlines: the cuts), SHEET_N_INNER (dashed), SHEET_N_FRAME, SHEET_N_TEXT; closed
// POLYLINEs and centred TEXT. Both throw InputError when the layout does not match the outlines.
std::string cut_sheets_svg(const std::vector<PanelOutline>& outlines, const SheetLayout& layout,
                           const SheetOptions& options);
std::string cut_sheets_dxf(const std::vector<PanelOutline>& outlines, const SheetLayout& layout,
                           const SheetOptions& options);

}  // namespace ff
