#pragma once
// Gap filling after the bounding-box packing: parts of the last sheet move into the gaps of
// earlier sheets (between and inside the concave parts of others), checked exactly on the
// polygons, so the last sheet empties when it can. Keeps every guarantee of the packing.
#include <vector>

#include "core/fabricate/cut_sheets.h"

namespace ff {

// Whether two polygons' regions (closed, either orientation) come closer than `spacing` (> 0):
// crossing, touching and one containing the other count as distance 0. Answered without
// measuring every pair of edges: the gap filling's candidate checks ask it millions of times.
bool polygons_closer_than(const std::vector<Vec2>& a, const std::vector<Vec2>& b, double spacing);

// Moves parts from the last sheet onto earlier ones wherever their outer and inner faces
// keep the spacing to everything there and stay inside the margins, lowest then leftmost
// first, trying the part's placed angle turned by 0, 90, 180 and 270 degrees, biggest part
// first; drops the last sheet when it empties and repeats, and stops at the first part that
// finds no place (the sheet stays; parts already moved stay moved). Deterministic; the work
// is bounded by a fixed budget of candidate checks. Updates sheets and placements, not
// material_use.
void fill_gaps(const std::vector<PanelOutline>& outlines, const SheetOptions& options, SheetLayout* layout);

}  // namespace ff
