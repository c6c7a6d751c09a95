#include "core/fabricate/sheet_drawing.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/util/angles.h"
#include "core/util/error.h"

namespace ff {
namespace {

std::vector<Vec2> transform(const std::vector<Vec2>& points, const PlacedOutline& p) {
  const Eigen::Rotation2Dd r(p.angle_rad);
  std::vector<Vec2> out;
  out.reserve(points.size());
  for (const Vec2& q : points) out.push_back(r * q + p.offset);
  return out;
}

// Text reading left to right or bottom to top, never upside down.
double readable_deg(double deg) {
  while (deg > 90.0) deg -= 180.0;
  while (deg <= -90.0) deg += 180.0;
  return deg;
}

}  // namespace

std::string format_number(double value, int decimals) {
  // Sized to the number: "%.*f" of a large value has as many digits as its magnitude.
  const int length = std::snprintf(nullptr, 0, "%.*f", decimals, value);
  std::string s(static_cast<size_t>(std::max(length, 0)) + 1, '\0');
  std::snprintf(s.data(), s.size(), "%.*f", decimals, value);
  s.resize(static_cast<size_t>(std::max(length, 0)));
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  return s;
}

Vec2 label_point(const std::vector<Vec2>& polygon, double* clearance) {
  const Vec2 centroid = polygon_centroid(polygon);
  Vec2 best = centroid;
  double best_d = point_in_polygon(polygon, centroid) ? distance_to_boundary(polygon, centroid) : -1.0;
  const double centroid_d = best_d;
  Vec2 lo = polygon.empty() ? Vec2::Zero() : polygon[0], hi = lo;
  for (const Vec2& p : polygon) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  constexpr int kGrid = 24;
  for (int i = 0; i < kGrid; ++i) {
    for (int j = 0; j < kGrid; ++j) {
      const Vec2 q = lo + (hi - lo).cwiseProduct(Vec2((i + 0.5) / kGrid, (j + 0.5) / kGrid));
      if (!point_in_polygon(polygon, q)) continue;
      const double d = distance_to_boundary(polygon, q);
      if (d > best_d) best_d = d, best = q;
    }
  }
  // The centroid reads best when it is nearly as roomy as the roomiest sample.
  if (centroid_d >= 0.7 * best_d) best = centroid, best_d = centroid_d;
  if (clearance) *clearance = std::max(best_d, 0.0);
  return best;
}

std::vector<DrawnOutline> draw_outlines(const std::vector<PanelOutline>& outlines, const SheetLayout& layout,
                                        const SheetOptions& options) {
  const double max_text = 0.04 * std::min(options.width, options.height);
  std::vector<DrawnOutline> drawn;
  for (const PlacedOutline& p : layout.placed) {
    if (p.outline < 0 || p.outline >= static_cast<int>(outlines.size()) || p.sheet < 0 || p.sheet >= layout.sheets) {
      throw InputError("cut sheet layout does not match its outlines (outline " + std::to_string(p.outline) +
                       ", sheet " + std::to_string(p.sheet) + ")");
    }
    const PanelOutline& o = outlines[p.outline];
    DrawnOutline d;
    d.outline = p.outline;
    d.sheet = p.sheet;
    d.outer = transform(o.outer, p);
    d.inner = transform(o.inner, p);
    double clearance = 0.0;
    d.label.at = label_point(d.outer, &clearance);
    d.label.text = o.label;
    // Fit the label in a box of about 2 clearances wide (characters ~0.6 of the height).
    const double chars = static_cast<double>(std::max<std::size_t>(o.label.size(), 1));
    d.label.height = std::min({max_text, clearance, 2.0 * clearance / (0.6 * chars)});
    const int n = static_cast<int>(d.outer.size());
    for (int i = 0; i < n && i < static_cast<int>(o.edges.size()); ++i) {
      const double deg = o.edges[i].chamfer_deg;
      if (!(std::abs(deg) > 1e-9)) continue;
      const Vec2 a = d.outer[i], b = d.outer[(i + 1) % n];
      const double length = (b - a).norm();
      if (length <= 0.0) continue;
      const Vec2 dir = (b - a) / length;
      const Vec2 inward(-dir.y(), dir.x());  // left of a counter-clockwise edge
      SheetText t;
      t.text = format_number(deg, 1);
      t.height = std::min({0.5 * max_text, 0.15 * length, 0.6 * std::max(clearance, 0.0)});
      t.at = 0.5 * (a + b) + inward * (0.9 * t.height);
      t.angle_deg = readable_deg(std::atan2(dir.y(), dir.x()) * 180.0 / kPi);
      if (t.height > 0.0) d.chamfers.push_back(t);
    }
    drawn.push_back(std::move(d));
  }
  return drawn;
}

}  // namespace ff
