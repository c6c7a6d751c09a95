#include "core/panels/panel_crossings.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace ff {

namespace {

struct Box {
  Vec3 lo, hi;
};

double segment_distance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

double outline_distance(const std::vector<Vec3>& vertices, const std::vector<int>& panel, const Vec3& p) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < panel.size(); ++k) {
    best = std::min(best, segment_distance(p, vertices[static_cast<size_t>(panel[k])],
                                           vertices[static_cast<size_t>(panel[(k + 1) % panel.size()])]));
  }
  return best;
}

double diameter(const std::vector<Vec3>& vertices, const std::vector<int>& panel) {
  double d = 0.0;
  for (size_t i = 0; i < panel.size(); ++i) {
    for (size_t j = i + 1; j < panel.size(); ++j)
      d = std::max(d, (vertices[static_cast<size_t>(panel[i])] - vertices[static_cast<size_t>(panel[j])]).norm());
  }
  return d;
}

// The stretches [t0, t1], [t2, t3], ... of the line origin + t direction inside the panel,
// which lies in a plane through the line; `across`: the unit vector in that plane across the
// line. A vertex within `snap` of the line counts as on it, and on the line counts as on the
// side across does not point to: an edge along the line (a shared edge) then adds nothing,
// and the stretches are the open interior's.
std::vector<double> stretches(const std::vector<Vec3>& vertices, const std::vector<int>& panel, const Vec3& origin,
                              const Vec3& direction, const Vec3& across, double snap) {
  std::vector<double> out;
  const size_t n = panel.size();
  for (size_t k = 0; k < n; ++k) {
    const Vec3& p = vertices[static_cast<size_t>(panel[k])];
    const Vec3& q = vertices[static_cast<size_t>(panel[(k + 1) % n])];
    double sp = (p - origin).dot(across), sq = (q - origin).dot(across);
    if (std::abs(sp) <= snap) sp = 0.0;
    if (std::abs(sq) <= snap) sq = 0.0;
    if ((sp > 0.0) == (sq > 0.0)) continue;
    const Vec3 x = p + (q - p) * (sp / (sp - sq));
    out.push_back((x - origin).dot(direction));
  }
  std::sort(out.begin(), out.end());
  if (out.size() % 2 != 0) out.pop_back();  // cannot happen for a closed outline; kept safe
  return out;
}

}  // namespace

std::vector<PanelCrossing> panel_crossings(const std::vector<Vec3>& vertices,
                                           const std::vector<std::vector<int>>& panels,
                                           const std::vector<Vec3>& normals, const std::vector<double>& offsets) {
  std::vector<PanelCrossing> out;
  const size_t np = panels.size();
  if (normals.size() != np || offsets.size() != np) return out;
  std::vector<Box> boxes(np);
  std::vector<double> size(np, 0.0);
  std::vector<size_t> order;
  for (size_t p = 0; p < np; ++p) {
    if (panels[p].size() < 3) continue;
    Box& b = boxes[p];
    b.lo = b.hi = vertices[static_cast<size_t>(panels[p][0])];
    for (int v : panels[p]) {
      b.lo = b.lo.cwiseMin(vertices[static_cast<size_t>(v)]);
      b.hi = b.hi.cwiseMax(vertices[static_cast<size_t>(v)]);
    }
    size[p] = diameter(vertices, panels[p]);
    order.push_back(p);
  }
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return boxes[a].lo.x() < boxes[b].lo.x() || (boxes[a].lo.x() == boxes[b].lo.x() && a < b);
  });
  for (size_t i = 0; i < order.size(); ++i) {
    const size_t a = order[i];
    for (size_t j = i + 1; j < order.size() && boxes[order[j]].lo.x() <= boxes[a].hi.x(); ++j) {
      const size_t b = order[j];
      if ((boxes[a].lo.array() > boxes[b].hi.array()).any() || (boxes[b].lo.array() > boxes[a].hi.array()).any())
        continue;
      const Vec3& na = normals[a];
      const Vec3& nb = normals[b];
      const Vec3 u = na.cross(nb);
      if (!(u.norm() > 1e-9)) continue;  // one plane (or parallel ones)
      const Vec3 direction = u.normalized();
      const Vec3 origin = (offsets[a] * nb.cross(u) + offsets[b] * u.cross(na)) / u.squaredNorm();
      const double smaller = std::min(size[a], size[b]);
      const double snap = 1e-9 * std::max(size[a], size[b]);
      const std::vector<double> sa = stretches(vertices, panels[a], origin, direction, na.cross(direction), snap);
      const std::vector<double> sb = stretches(vertices, panels[b], origin, direction, nb.cross(direction), snap);
      PanelCrossing best;
      for (size_t x = 0; x + 1 < sa.size(); x += 2) {
        for (size_t y = 0; y + 1 < sb.size(); y += 2) {
          const double lo = std::max(sa[x], sb[y]), hi = std::min(sa[x + 1], sb[y + 1]);
          if (!(hi > lo)) continue;
          // The deepest of a few points along the overlap, its middle among them (a lower
          // bound of the deepest: enough to tell a crossing from rounding).
          constexpr int kSamples = 9;
          for (int s = 0; s < kSamples; ++s) {
            const Vec3 p = origin + (lo + (hi - lo) * (s + 0.5) / kSamples) * direction;
            const double depth =
                std::min(outline_distance(vertices, panels[a], p), outline_distance(vertices, panels[b], p));
            if (depth > best.depth) best.depth = depth, best.point = p;
          }
        }
      }
      if (best.depth > kCrossingDepthShare * smaller) {
        best.depth_share = best.depth / smaller;
        best.a = static_cast<int>(std::min(a, b));
        best.b = static_cast<int>(std::max(a, b));
        out.push_back(best);
      }
    }
  }
  std::sort(out.begin(), out.end(), [](const PanelCrossing& x, const PanelCrossing& y) {
    return std::make_pair(x.a, x.b) < std::make_pair(y.a, y.b);
  });
  return out;
}

}  // namespace ff
