#include "core/panels/border_vertices.h"

#include <algorithm>
#include <cmath>

#include "core/mesh/segment.h"
#include "core/panels/panel_check.h"
#include "core/util/angles.h"

namespace ff {

namespace {

// cos(kNeedleCornerDeg), computed once rather than per border run.
const double kNeedleCos = std::cos(kNeedleCornerDeg * kPi / 180.0);

// Douglas-Peucker on chain[first..last] (both kept), with an explicit stack.
void simplify(const std::vector<Vec3>& chain, size_t first, size_t last, double tolerance, std::vector<char>& keep) {
  std::vector<std::pair<size_t, size_t>> stack{{first, last}};
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    double worst = -1.0;
    size_t at = a;
    for (size_t i = a + 1; i < b; ++i) {
      const double d = distance_to_segment(chain[i], chain[a], chain[b]);
      if (d > worst) worst = d, at = i;
    }
    if (at == a || worst <= tolerance) continue;
    keep[at] = 1;
    stack.push_back({a, at});
    stack.push_back({at, b});
  }
}

}  // namespace

std::vector<int> thin_border(const Vec3& from, const std::vector<Vec3>& points, const Vec3& to, double tolerance,
                             int min_keep) {
  std::vector<Vec3> chain;
  chain.reserve(points.size() + 2);
  chain.push_back(from);
  chain.insert(chain.end(), points.begin(), points.end());
  chain.push_back(to);
  std::vector<char> keep(chain.size(), 0);
  simplify(chain, 0, chain.size() - 1, tolerance, keep);
  std::vector<int> out;
  for (size_t i = 1; i + 1 < chain.size(); ++i) {
    if (keep[i]) out.push_back(static_cast<int>(i) - 1);
  }
  if (out.empty() && min_keep > 0 && !points.empty()) {
    double worst = -1.0;
    size_t at = 1;
    for (size_t i = 1; i + 1 < chain.size(); ++i) {
      const double d = distance_to_segment(chain[i], from, to);
      if (d > worst) worst = d, at = i;
    }
    out.push_back(static_cast<int>(at) - 1);
  }
  // The end nodes are placed by the vertex rule, near their mesh corner but not on it: one can
  // land short of the last border point (or past the first), and keeping that point sends the
  // panel's border out and straight back, a needle of no width (hyperboloid_s4.off at 300
  // panels, seed 1: a 0.01 degree corner 24 units long). Such an end point goes (a corner
  // below kNeedleCornerDeg).
  const auto needle = [](const Vec3& before, const Vec3& p, const Vec3& after) {
    const Vec3 a = before - p, b = after - p;
    return a.dot(b) > kNeedleCos * a.norm() * b.norm();
  };
  const size_t keep_at_least = static_cast<size_t>(std::max(min_keep, 0));
  while (out.size() > keep_at_least) {
    const Vec3& p = points[static_cast<size_t>(out.back())];
    const Vec3& before = out.size() > 1 ? points[static_cast<size_t>(out[out.size() - 2])] : from;
    if (!needle(before, p, to)) break;
    out.pop_back();
  }
  while (out.size() > keep_at_least) {
    const Vec3& p = points[static_cast<size_t>(out.front())];
    const Vec3& after = out.size() > 1 ? points[static_cast<size_t>(out[1])] : to;
    if (!needle(from, p, after)) break;
    out.erase(out.begin());
  }
  return out;
}

std::vector<int> thin_closed_border(const std::vector<Vec3>& points, double tolerance) {
  const size_t n = points.size();
  if (n <= 3) {
    std::vector<int> all;
    for (size_t i = 0; i < n; ++i) all.push_back(static_cast<int>(i));
    return all;
  }
  // Anchor at point 0 and the point farthest from it; thin both halves.
  size_t far = 0;
  double best = -1.0;
  for (size_t i = 1; i < n; ++i) {
    const double d = (points[i] - points[0]).squaredNorm();
    if (d > best) best = d, far = i;
  }
  std::vector<Vec3> chain(points.begin(), points.end());
  chain.push_back(points[0]);
  std::vector<char> keep(chain.size(), 0);
  keep[0] = keep[far] = 1;
  simplify(chain, 0, far, tolerance, keep);
  simplify(chain, far, n, tolerance, keep);
  std::vector<int> out;
  for (size_t i = 0; i < n; ++i) {
    if (keep[i]) out.push_back(static_cast<int>(i));
  }
  if (out.size() < 3) {
    // A flat sliver: add the point farthest from the chord.
    double worst = -1.0;
    size_t at = 0;
    for (size_t i = 0; i < n; ++i) {
      if (keep[i]) continue;
      const double d = distance_to_segment(points[i], points[0], points[far]);
      if (d > worst) worst = d, at = i;
    }
    out.push_back(static_cast<int>(at));
    std::sort(out.begin(), out.end());
  }
  return out;
}

}  // namespace ff
