#include "core/fabricate/sheet_packing.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "core/util/angles.h"

namespace ff {
namespace {

PartOrientation orient(const std::vector<Vec2>& points, double angle) {
  const Eigen::Rotation2Dd r(angle);
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity());
  Vec2 hi = -lo;
  for (const Vec2& p : points) {
    const Vec2 q = r * p;
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  return {angle, lo, hi - lo};
}

bool fits(const PartOrientation& o, const Vec2& area) { return o.size.x() <= area.x() && o.size.y() <= area.y(); }

// The skyline of one sheet: segments (x, top, width) covering [0, width) left to right.
class Skyline {
 public:
  explicit Skyline(const Vec2& area) : area_(area), segments_{{0.0, 0.0, area.x()}} {}

  // Bottom-left position for a box: lowest top, then leftmost. False if it does not fit.
  bool find(const Vec2& box, Vec2* corner, double* top) const {
    bool found = false;
    for (std::size_t i = 0; i < segments_.size(); ++i) {
      const double x = segments_[i].x;
      if (x + box.x() > area_.x()) break;
      double y = 0.0;
      for (std::size_t j = i; j < segments_.size() && segments_[j].x < x + box.x(); ++j) {
        y = std::max(y, segments_[j].y);
      }
      if (y + box.y() > area_.y()) continue;
      if (!found || y + box.y() < *top) {
        found = true;
        *top = y + box.y();
        *corner = Vec2(x, y);
      }
    }
    return found;
  }

  void place(const Vec2& corner, const Vec2& box) {
    const double x0 = corner.x(), x1 = corner.x() + box.x();
    const Segment added{x0, corner.y() + box.y(), box.x()};
    std::vector<Segment> next;
    bool inserted = false;
    for (const Segment& s : segments_) {
      const double s1 = s.x + s.w;
      if (s1 <= x0) {
        next.push_back(s);
        continue;
      }
      if (s.x < x0) next.push_back({s.x, s.y, x0 - s.x});
      if (!inserted) next.push_back(added), inserted = true;
      if (s.x >= x1) {
        next.push_back(s);
      } else if (s1 > x1) {
        next.push_back({x1, s.y, s1 - x1});
      }
    }
    if (!inserted) next.push_back(added);
    // Merge neighbours of equal height so later searches see one wide segment.
    segments_.clear();
    for (const Segment& s : next) {
      if (!segments_.empty() && segments_.back().y == s.y) {
        segments_.back().w = s.x + s.w - segments_.back().x;
      } else {
        segments_.push_back(s);
      }
    }
  }

  double height() const {
    double h = 0.0;
    for (const Segment& s : segments_) h = std::max(h, s.y);
    return h;
  }

 private:
  struct Segment {
    double x, y, w;
  };
  Vec2 area_;
  std::vector<Segment> segments_;
};

struct PackResult {
  std::vector<BoxPlacement> placements;
  int sheets = 0;
  double last_height = 0.0;
};

PackResult pack_in_order(const std::vector<std::vector<PartOrientation>>& parts, const std::vector<int>& order,
                         const Vec2& area, double spacing) {
  PackResult result;
  result.placements.assign(parts.size(), BoxPlacement{});
  std::vector<Skyline> sheets;
  for (int part : order) {
    const auto& orientations = parts[part];
    bool placed = false;
    // First sheet that takes the part (a new one last); on it, the orientation with the
    // lowest top.
    auto try_sheet = [&](int s) {
      double best_top = std::numeric_limits<double>::infinity();
      for (int o = 0; o < static_cast<int>(orientations.size()); ++o) {
        const Vec2 box = orientations[o].size + Vec2::Constant(spacing);
        Vec2 corner = Vec2::Zero();
        double top = 0.0;
        if (sheets[s].find(box, &corner, &top) && top < best_top) {
          best_top = top;
          result.placements[part] = {s, o, corner};
          placed = true;
        }
      }
    };
    for (int s = 0; s < static_cast<int>(sheets.size()) && !placed; ++s) try_sheet(s);
    if (!placed) {
      sheets.emplace_back(area);
      try_sheet(static_cast<int>(sheets.size()) - 1);
      if (!placed) sheets.pop_back();  // fits no empty sheet: left unplaced (sheet -1)
    }
    if (placed) {
      const BoxPlacement& p = result.placements[part];
      sheets[p.sheet].place(p.corner, orientations[p.orientation].size + Vec2::Constant(spacing));
    }
  }
  result.sheets = static_cast<int>(sheets.size());
  result.last_height = sheets.empty() ? 0.0 : sheets.back().height();
  return result;
}

}  // namespace

std::vector<Vec2> convex_hull(std::vector<Vec2> points) {
  std::sort(points.begin(), points.end(),
            [](const Vec2& a, const Vec2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  std::vector<Vec2> hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && orient2d(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && orient2d(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

std::vector<PartOrientation> part_orientations(const std::vector<Vec2>& points, const Vec2& area_size) {
  const std::vector<Vec2> hull = convex_hull(points);
  if (hull.empty()) return {};
  // The minimum-area rectangle has a side on a hull edge (Freeman & Shapira), so trying the
  // hull's edge directions finds it.
  std::vector<double> angles;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Vec2 e = hull[(i + 1) % hull.size()] - hull[i];
    if (e.squaredNorm() > 0.0) angles.push_back(-std::atan2(e.y(), e.x()));
  }
  if (angles.empty()) angles.push_back(0.0);
  PartOrientation best = orient(hull, angles[0]);
  for (double a : angles) {
    const PartOrientation o = orient(hull, a);
    if (o.size.prod() < best.size.prod() - 1e-12 * best.size.prod()) best = o;
  }
  std::vector<PartOrientation> result{best, orient(hull, best.angle_rad + kHalfPi)};
  if (fits(result[0], area_size) || fits(result[1], area_size)) return result;
  for (double a : angles) {
    for (double turn : {0.0, kHalfPi}) {
      const PartOrientation o = orient(hull, a + turn);
      if (fits(o, area_size)) {
        result.push_back(o);
        return result;
      }
    }
  }
  return result;
}

std::vector<BoxPlacement> pack_boxes(const std::vector<std::vector<PartOrientation>>& parts, const Vec2& area_size,
                                     double spacing) {
  const Vec2 area = area_size + Vec2::Constant(spacing);
  const int n = static_cast<int>(parts.size());
  auto key = [&](int i, int which) {
    double longest = 0.0, area_key = 0.0, shortest = 0.0;
    for (const PartOrientation& o : parts[i]) {
      longest = std::max(longest, o.size.maxCoeff());
      shortest = std::max(shortest, o.size.minCoeff());
      area_key = std::max(area_key, o.size.prod());
    }
    return which == 0 ? longest : which == 1 ? area_key : shortest;
  };
  // A few orders (longest side, box area, shortest side first); keep the one using the
  // fewest sheets, then the least of the last sheet.
  PackResult best;
  for (int which = 0; which < 3; ++which) {
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key(a, which) > key(b, which); });
    PackResult r = pack_in_order(parts, order, area, spacing);
    if (which == 0 || r.sheets < best.sheets || (r.sheets == best.sheets && r.last_height < best.last_height)) {
      best = std::move(r);
    }
  }
  return best.placements;
}

}  // namespace ff
