#pragma once
// Shared by the cut sheet tests: random convex and concave outlines in arbitrary frames, and an
// independent check of a layout (no overlaps, the spacing kept, inside the margins).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/fabricate/cut_sheets.h"
#include "core/util/angles.h"
#include "core/util/random.h"

namespace ff::cut_sheet_test {

using Poly = std::vector<Vec2>;

inline double uniform(SplitMix64& rng, double lo, double hi) { return lo + (hi - lo) * rng.uniform(); }

// Counter-clockwise polygons in an arbitrary frame (rotated, shifted), so packing has to
// find their orientation: convex ones on an ellipse, concave stars, and combs.
inline Poly random_outline(SplitMix64& rng, int kind) {
  Poly p;
  const double size = uniform(rng, 40.0, 500.0);
  if (kind == 0) {
    const int k = 3 + static_cast<int>(rng.below(8));
    std::vector<double> angles;
    for (int i = 0; i < k; ++i) angles.push_back(uniform(rng, 0.0, 2.0 * kPi));
    std::sort(angles.begin(), angles.end());
    const double ry = size * uniform(rng, 0.2, 1.0);
    for (double a : angles) p.emplace_back(size * std::cos(a), ry * std::sin(a));
  } else if (kind == 1) {
    const int k = 5 + static_cast<int>(rng.below(10));
    for (int i = 0; i < k; ++i) {
      const double a = 2.0 * kPi * (i + uniform(rng, 0.0, 0.6)) / k;
      const double r = size * (i % 2 == 0 ? uniform(rng, 0.7, 1.0) : uniform(rng, 0.3, 0.6));
      p.emplace_back(r * std::cos(a), r * std::sin(a));
    }
  } else {
    const double s = size / 5.0;
    for (const auto& q : {Vec2(0, 0), Vec2(5, 0), Vec2(5, 3), Vec2(4, 3), Vec2(4, 1), Vec2(3, 1), Vec2(3, 3),
                          Vec2(2, 3), Vec2(2, 1), Vec2(1, 1), Vec2(1, 3), Vec2(0, 3)}) {
      p.push_back(q * s);
    }
  }
  const Eigen::Rotation2Dd r(uniform(rng, 0.0, 2.0 * kPi));
  const Vec2 shift(uniform(rng, -1000.0, 1000.0), uniform(rng, -1000.0, 1000.0));
  for (Vec2& q : p) q = r * q + shift;
  return p;
}

inline std::vector<PanelOutline> random_outlines(int n, std::uint64_t seed) {
  SplitMix64 rng(seed);
  std::vector<PanelOutline> outlines;
  for (int i = 0; i < n; ++i) {
    PanelOutline o;
    o.panel = i;
    o.label = "P" + std::to_string(i + 1);
    o.outer = random_outline(rng, i % 3);
    for (std::size_t e = 0; e < o.outer.size(); ++e) o.edges.push_back({1.0, e % 2 ? 22.5 : 0.0, ""});
    outlines.push_back(o);
  }
  return outlines;
}

inline Poly placed(const Poly& p, const PlacedOutline& where) {
  const Eigen::Rotation2Dd r(where.angle_rad);
  Poly out;
  for (const Vec2& q : p) out.push_back(r * q + where.offset);
  return out;
}

inline bool segments_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double d1 = orient2d(a, b, c), d2 = orient2d(a, b, d), d3 = orient2d(c, d, a), d4 = orient2d(c, d, b);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

// Distance between two polygons' regions: 0 when they cross or one contains the other.
inline double polygon_distance(const Poly& a, const Poly& b) {
  if (point_in_polygon(a, b[0]) || point_in_polygon(b, a[0])) return 0.0;
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Vec2 &p = a[i], &q = a[(i + 1) % a.size()];
    for (std::size_t j = 0; j < b.size(); ++j) {
      const Vec2 &r = b[j], &s = b[(j + 1) % b.size()];
      if (segments_cross(p, q, r, s)) return 0.0;
      d = std::min({d, distance_point_segment(p, r, s), distance_point_segment(q, r, s),
                    distance_point_segment(r, p, q), distance_point_segment(s, p, q)});
    }
  }
  return d;
}

// Interiors overlap: edges cross clearly (every end more than 1e-9 off the other edge's
// line, so touching does not count), or a vertex or edge midpoint lies clearly inside the other.
inline bool crosses_clearly(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double ab = (b - a).norm(), cd = (d - c).norm();
  if (ab == 0.0 || cd == 0.0) return false;
  const double d1 = orient2d(a, b, c) / ab, d2 = orient2d(a, b, d) / ab;
  const double d3 = orient2d(c, d, a) / cd, d4 = orient2d(c, d, b) / cd;
  const double eps = 1e-9;
  return ((d1 > eps && d2 < -eps) || (d1 < -eps && d2 > eps)) && ((d3 > eps && d4 < -eps) || (d3 < -eps && d4 > eps));
}

inline bool overlaps(const Poly& a, const Poly& b) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = 0; j < b.size(); ++j) {
      if (crosses_clearly(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()])) return true;
    }
  }
  auto inside = [](const Poly& p, const Vec2& q) {
    return point_in_polygon(p, q) && distance_to_boundary(p, q) > 1e-9;
  };
  // Vertices and edge midpoints: polygons sharing an edge line overlap without crossing.
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (inside(b, a[i]) || inside(b, 0.5 * (a[i] + a[(i + 1) % a.size()]))) return true;
  }
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (inside(a, b[i]) || inside(a, 0.5 * (b[i] + b[(i + 1) % b.size()]))) return true;
  }
  return false;
}

inline void expect_valid_layout(const std::vector<PanelOutline>& outlines, const SheetLayout& layout,
                                const SheetOptions& options) {
  ASSERT_EQ(layout.placed.size(), outlines.size());
  std::vector<Poly> on_sheet;
  for (std::size_t i = 0; i < outlines.size(); ++i) {
    const PlacedOutline& p = layout.placed[i];
    EXPECT_EQ(p.outline, static_cast<int>(i));
    ASSERT_GE(p.sheet, 0);
    ASSERT_LT(p.sheet, layout.sheets);
    on_sheet.push_back(placed(outlines[i].outer, p));
    for (const Vec2& q : on_sheet.back()) {
      EXPECT_GE(q.x(), options.margin - 1e-9) << outlines[i].label;
      EXPECT_GE(q.y(), options.margin - 1e-9) << outlines[i].label;
      EXPECT_LE(q.x(), options.width - options.margin + 1e-9) << outlines[i].label;
      EXPECT_LE(q.y(), options.height - options.margin + 1e-9) << outlines[i].label;
    }
  }
  for (std::size_t i = 0; i < outlines.size(); ++i) {
    for (std::size_t j = i + 1; j < outlines.size(); ++j) {
      if (layout.placed[i].sheet != layout.placed[j].sheet) continue;
      EXPECT_FALSE(overlaps(on_sheet[i], on_sheet[j])) << outlines[i].label << " and " << outlines[j].label;
      EXPECT_GE(polygon_distance(on_sheet[i], on_sheet[j]), options.spacing - 1e-9)
          << outlines[i].label << " and " << outlines[j].label << " on sheet " << layout.placed[i].sheet + 1;
    }
  }
  EXPECT_GT(layout.material_use, 0.0);
  EXPECT_LE(layout.material_use, 1.0);
}

}  // namespace ff::cut_sheet_test
