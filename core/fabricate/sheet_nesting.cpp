#include "core/fabricate/sheet_nesting.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/util/angles.h"

namespace ff {
namespace {

// Candidate positions tested (each against every part of a sheet) before giving up: keeps
// huge inputs fast and, being a count, deterministic.
constexpr long long kBudget = 20'000'000;

struct Shape {
  std::vector<std::vector<Vec2>> faces;  // outer, and inner when there is one
  Vec2 lo = Vec2::Zero(), hi = Vec2::Zero();
};

// Into `s`, reusing its vectors' capacity (the candidate checks make one per candidate).
void place_shape(const PanelOutline& o, double angle, const Vec2& offset, Shape& s) {
  const Eigen::Rotation2Dd r(angle);
  s.lo = Vec2::Constant(std::numeric_limits<double>::infinity());
  s.hi = -s.lo;
  std::size_t count = 0;
  for (const std::vector<Vec2>* face : {&o.outer, &o.inner}) {
    if (face->empty()) continue;
    if (s.faces.size() <= count) s.faces.emplace_back();
    std::vector<Vec2>& out = s.faces[count++];
    out.clear();
    for (const Vec2& p : *face) {
      out.push_back(r * p + offset);
      s.lo = s.lo.cwiseMin(out.back());
      s.hi = s.hi.cwiseMax(out.back());
    }
  }
  s.faces.resize(count);
}

Shape make_shape(const PanelOutline& o, double angle, const Vec2& offset) {
  Shape s;
  place_shape(o, angle, offset, s);
  return s;
}

bool segments_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double d1 = orient2d(a, b, c), d2 = orient2d(a, b, d), d3 = orient2d(c, d, a), d4 = orient2d(c, d, b);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

// True when the shapes keep at least `spacing` apart (every face against every face).
bool apart(const Shape& a, const Shape& b, double spacing) {
  if (a.lo.x() >= b.hi.x() + spacing || b.lo.x() >= a.hi.x() + spacing || a.lo.y() >= b.hi.y() + spacing ||
      b.lo.y() >= a.hi.y() + spacing) {
    return true;
  }
  if (a.faces.empty() || b.faces.empty()) return false;
  for (const auto& fa : a.faces) {
    for (const auto& fb : b.faces) {
      if (polygons_closer_than(fa, fb, spacing)) return false;
    }
  }
  return true;
}

// Sorted, deduplicated values within [lo, hi].
std::vector<double> clamp_sorted(std::vector<double> v, double lo, double hi) {
  v.erase(std::remove_if(v.begin(), v.end(), [&](double x) { return !(x >= lo && x <= hi); }), v.end());
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

class GapFiller {
 public:
  GapFiller(const std::vector<PanelOutline>& outlines, const SheetOptions& options, SheetLayout* layout)
      : outlines_(outlines), options_(options), layout_(*layout) {
    shapes_.resize(layout_.sheets);
    for (const PlacedOutline& p : layout_.placed) {
      shapes_[p.sheet].push_back(make_shape(outlines_[p.outline], p.angle_rad, p.offset));
    }
  }

  // Lowest, then leftmost, free spot on `sheet`; false when there is none (or no budget).
  bool find(int part, int sheet, PlacedOutline* where) {
    const PanelOutline& o = outlines_[part];
    const double m = options_.margin, s = options_.spacing;
    for (int turn = 0; turn < 4; ++turn) {
      const double angle = layout_.placed[part].angle_rad + turn * kHalfPi;
      const Shape at_origin = make_shape(o, angle, Vec2::Zero());
      const Vec2 size = at_origin.hi - at_origin.lo;
      // Candidates: against the margins, beside every part's box, and on a grid so parts
      // can reach into others' concave notches.
      std::vector<double> xs{m}, ys{m};
      for (const Shape& q : shapes_[sheet]) {
        xs.push_back(q.hi.x() + s), xs.push_back(q.lo.x() - s - size.x());
        ys.push_back(q.hi.y() + s), ys.push_back(q.lo.y() - s - size.y());
      }
      const double step = std::max(std::min(size.x(), size.y()) / 3.0, 0.01 * options_.width);
      for (double x = m; x < options_.width - m; x += step) xs.push_back(x);
      for (double y = m; y < options_.height - m; y += step) ys.push_back(y);
      xs = clamp_sorted(xs, m, options_.width - m - size.x());
      ys = clamp_sorted(ys, m, options_.height - m - size.y());
      for (double y : ys) {
        for (double x : xs) {
          budget_ -= static_cast<long long>(shapes_[sheet].size()) + 1;
          if (budget_ < 0) return false;
          const Vec2 offset = Vec2(x, y) - at_origin.lo;
          if (fits_at(o, angle, offset, at_origin, sheet)) {
            *where = {part, sheet, angle, offset};
            return true;
          }
        }
      }
    }
    return false;
  }

  void run() {
    while (layout_.sheets > 1 && budget_ > 0) {
      const int last = layout_.sheets - 1;
      std::vector<int> parts;
      for (const PlacedOutline& p : layout_.placed) {
        if (p.sheet == last) parts.push_back(p.outline);
      }
      // Big parts first: they are the hard ones to fit.
      std::stable_sort(parts.begin(), parts.end(), [&](int a, int b) {
        return std::abs(signed_area(outlines_[a].outer)) > std::abs(signed_area(outlines_[b].outer));
      });
      // One part that stays keeps the sheet: stop spending work on it (moved == k).
      std::size_t moved = 0;
      for (std::size_t k = 0; k < parts.size() && moved == k; ++k) {
        const int part = parts[k];
        for (int sheet = 0; sheet < last; ++sheet) {
          PlacedOutline where;
          if (!find(part, sheet, &where)) continue;
          layout_.placed[part] = where;
          shapes_[sheet].push_back(make_shape(outlines_[part], where.angle_rad, where.offset));
          ++moved;
          break;
        }
      }
      if (moved < parts.size()) break;
      layout_.sheets = last;
      shapes_.pop_back();
    }
    // The last sheet's remaining shapes stay as they are: only their records matter.
  }

 private:
  // Boxes first (cheap), the polygons only where the boxes come closer than the spacing.
  bool fits_at(const PanelOutline& o, double angle, const Vec2& offset, const Shape& at_origin, int sheet) {
    Shape box;
    box.lo = at_origin.lo + offset;
    box.hi = at_origin.hi + offset;
    const double m = options_.margin - tol_;
    if (box.lo.x() < m || box.lo.y() < m || box.hi.x() > options_.width - m || box.hi.y() > options_.height - m) {
      return false;
    }
    // Overlapping and touching both measure 0: without spacing, ask for a hair more.
    const double spacing = std::max(options_.spacing - tol_, tol_);
    bool placed = false;
    for (const Shape& q : shapes_[sheet]) {
      if (apart(box, q, spacing)) continue;  // no faces: boxes decide
      if (!placed) place_shape(o, angle, offset, exact_), placed = true;
      if (!apart(exact_, q, spacing)) return false;
    }
    return true;
  }

  Shape exact_;  // fits_at's candidate, kept for its vectors' capacity

  const std::vector<PanelOutline>& outlines_;
  const SheetOptions& options_;
  SheetLayout& layout_;
  std::vector<std::vector<Shape>> shapes_;  // per sheet, the placed parts
  long long budget_ = kBudget;
  // Rounding slack for candidates exactly at the spacing from a neighbour's box, far below
  // any cutting tolerance.
  double tol_ = 1e-14 * std::max(options_.width, options_.height);
};

}  // namespace

// Answers at the first pair of edges that proves it. A pair whose boxes are more than the
// spacing apart on an axis is skipped unmeasured: its four point-segment distances are at
// least that gap. The margin of 1e-9 of the spacing keeps the answer the full measure's
// where rounding could put a measured distance a hair below the gap.
bool polygons_closer_than(const std::vector<Vec2>& a, const std::vector<Vec2>& b, double spacing) {
  if (a.empty() || b.empty()) return false;
  if (point_in_polygon(a, b[0]) || point_in_polygon(b, a[0])) return true;
  const double skip = spacing * (1.0 + 1e-9);
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Vec2 &p = a[i], &q = a[(i + 1) % a.size()];
    const Vec2 lo = p.cwiseMin(q), hi = p.cwiseMax(q);
    for (std::size_t j = 0; j < b.size(); ++j) {
      const Vec2 &r = b[j], &s = b[(j + 1) % b.size()];
      if (std::min(r.x(), s.x()) - hi.x() > skip || lo.x() - std::max(r.x(), s.x()) > skip ||
          std::min(r.y(), s.y()) - hi.y() > skip || lo.y() - std::max(r.y(), s.y()) > skip)
        continue;
      if (segments_cross(p, q, r, s)) return true;
      if (distance_point_segment(p, r, s) < spacing || distance_point_segment(q, r, s) < spacing ||
          distance_point_segment(r, p, q) < spacing || distance_point_segment(s, p, q) < spacing)
        return true;
    }
  }
  return false;
}

void fill_gaps(const std::vector<PanelOutline>& outlines, const SheetOptions& options, SheetLayout* layout) {
  GapFiller(outlines, options, layout).run();
}

}  // namespace ff
