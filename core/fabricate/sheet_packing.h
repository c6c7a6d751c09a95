#pragma once
// Rectangle packing for cut sheets: each part offers a few oriented bounding boxes, and a
// skyline bottom-left packer puts the boxes on as few sheets as it can. Boxes are inflated
// by the spacing, so disjoint boxes keep their parts at least the spacing apart.
#include <vector>

#include "core/panels/polygon2d.h"

namespace ff {

// One way to lay a part: rotate by angle_rad, then its bounding box is [min, min + size].
struct PartOrientation {
  double angle_rad = 0.0;
  Vec2 min = Vec2::Zero();
  Vec2 size = Vec2::Zero();
};

// Where a box went: sheet index, which orientation, and the box's lower-left corner in the
// packing area (the sheet minus its margins).
struct BoxPlacement {
  int sheet = -1;
  int orientation = -1;
  Vec2 corner = Vec2::Zero();
};

// Convex hull, counter-clockwise, no collinear points (monotone chain); deterministic.
std::vector<Vec2> convex_hull(std::vector<Vec2> points);

// The orientations worth trying for a part: the minimum-area bounding rectangle's and that
// turned by 90 degrees. When neither fits in area_size, every hull edge direction (and +90)
// is tried too and the first that fits is added: a long part may fit only along the sheet.
// Empty points give no orientations.
std::vector<PartOrientation> part_orientations(const std::vector<Vec2>& points, const Vec2& area_size);

// Packs the parts (each with its orientations) into areas of area_size, boxes grown by
// spacing; the areas themselves are grown by spacing too, so a box may touch the far border.
// Deterministic. A part none of whose orientations fits gets sheet -1.
std::vector<BoxPlacement> pack_boxes(const std::vector<std::vector<PartOrientation>>& parts, const Vec2& area_size,
                                     double spacing);

}  // namespace ff
