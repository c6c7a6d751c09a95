#include "core/panels/polygon2d.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/util/angles.h"
#include "core/util/error.h"

namespace ff {

namespace {

const Vec2& at(const std::vector<Vec2>& p, size_t i) { return p[i % p.size()]; }

// Distance between segments ab and cd: zero when they cross, else an endpoint is nearest.
double segment_distance(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double o1 = orient2d(a, b, c), o2 = orient2d(a, b, d);
  const double o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) return 0.0;
  return std::min(std::min(distance_point_segment(a, c, d), distance_point_segment(b, c, d)),
                  std::min(distance_point_segment(c, a, b), distance_point_segment(d, a, b)));
}

// Keeps the part of convex `poly` where n.(p - a) >= offset (Sutherland-Hodgman, one plane).
// Clips `poly` to n.(p - a) >= offset into `out` (cleared first; its capacity is reused).
void clip_half_plane(const std::vector<Vec2>& poly, const Vec2& a, const Vec2& n, double offset,
                     std::vector<Vec2>& out) {
  out.clear();
  const size_t m = poly.size();
  for (size_t i = 0; i < m; ++i) {
    const Vec2& p = poly[i];
    const Vec2& q = poly[(i + 1) % m];
    const double dp = n.dot(p - a) - offset, dq = n.dot(q - a) - offset;
    if (dp >= 0.0) out.push_back(p);
    if ((dp >= 0.0) != (dq >= 0.0)) {
      const Vec2 x = p + (dp / (dp - dq)) * (q - p);
      if (out.empty() || out.back() != x) out.push_back(x);
    }
  }
  if (out.size() > 1 && out.front() == out.back()) out.pop_back();
}

std::vector<std::array<int, 3>> fan(int k) {
  std::vector<std::array<int, 3>> tris;
  for (int i = 1; i + 1 < k; ++i) tris.push_back({0, i, i + 1});
  return tris;
}

}  // namespace

PlaneFrame make_plane_frame(const Vec3& origin, const Vec3& unit_normal) {
  const double len = unit_normal.norm();
  if (!std::isfinite(len) || len <= 0.0 || !origin.allFinite()) {
    throw InputError("plane frame: the plane normal is zero or not finite");
  }
  PlaneFrame f;
  f.origin = origin;
  f.normal = unit_normal / len;
  // The axis least aligned with the normal gives the best-conditioned cross product.
  Vec3 axis = Vec3::Zero();
  int least = 0;
  f.normal.cwiseAbs().minCoeff(&least);
  axis[least] = 1.0;
  f.u = axis.cross(f.normal).normalized();
  f.v = f.normal.cross(f.u);
  return f;
}

Vec3 newell_normal(const std::vector<Vec3>& polygon) {
  Vec3 sum = Vec3::Zero();
  if (polygon.empty()) return sum;
  const Vec3& o = polygon[0];  // relative coordinates: less cancellation
  for (size_t i = 1; i + 1 < polygon.size(); ++i) sum += (polygon[i] - o).cross(polygon[i + 1] - o);
  return sum;
}

double signed_area(const std::vector<Vec2>& polygon) {
  const size_t k = polygon.size();
  if (k < 3) return 0.0;
  // Relative to the first vertex: less cancellation far from the origin.
  const Vec2& o = polygon[0];
  double sum = 0.0;
  for (size_t i = 1; i + 1 < k; ++i) sum += orient2d(o, polygon[i], polygon[i + 1]);
  return 0.5 * sum;
}

Vec2 vertex_average(const std::vector<Vec2>& polygon) {
  if (polygon.empty()) return Vec2::Zero();
  Vec2 sum = Vec2::Zero();
  for (const Vec2& p : polygon) sum += p;
  return sum / static_cast<double>(polygon.size());
}

Vec2 polygon_centroid(const std::vector<Vec2>& polygon) {
  if (polygon.empty()) return Vec2::Zero();
  const Vec2 average = vertex_average(polygon);
  double area2 = 0.0;
  Vec2 moment = Vec2::Zero();
  const Vec2& o = polygon[0];
  for (size_t i = 1; i + 1 < polygon.size(); ++i) {
    const double w = orient2d(o, polygon[i], polygon[i + 1]);
    area2 += w;
    moment += w * (o + polygon[i] + polygon[i + 1]) / 3.0;
  }
  // Near-zero area: the moment quotient is noise, the vertex average is not.
  double extent2 = 0.0;
  for (const Vec2& p : polygon) extent2 = std::max(extent2, (p - average).squaredNorm());
  if (std::abs(area2) <= 1e-12 * extent2) return average;
  return moment / area2;
}

bool is_simple(const std::vector<Vec2>& polygon, double tol) {
  const size_t k = polygon.size();
  if (k < 3) return false;
  struct Box {
    double lo_x, hi_x, lo_y, hi_y;
    size_t edge;
  };
  std::vector<Box> boxes(k);
  for (size_t i = 0; i < k; ++i) {
    const Vec2& a = polygon[i];
    const Vec2& b = at(polygon, i + 1);
    if (!a.allFinite() || (b - a).norm() <= tol) return false;
    boxes[i] = {std::min(a.x(), b.x()), std::max(a.x(), b.x()), std::min(a.y(), b.y()), std::max(a.y(), b.y()), i};
  }
  std::sort(boxes.begin(), boxes.end(),
            [](const Box& l, const Box& r) { return l.lo_x < r.lo_x || (l.lo_x == r.lo_x && l.edge < r.edge); });
  for (size_t s = 0; s < k; ++s) {
    const Box& e = boxes[s];
    for (size_t t = s + 1; t < k && boxes[t].lo_x <= e.hi_x + tol; ++t) {
      const Box& f = boxes[t];
      if (f.lo_y > e.hi_y + tol || e.lo_y > f.hi_y + tol) continue;
      size_t i = e.edge, j = f.edge;
      if ((i + 1) % k == j || (j + 1) % k == i) {
        if ((j + 1) % k == i) std::swap(i, j);
        // Adjacent edges p->q->r share q; they fold back when an end lies on the other.
        const Vec2& p = polygon[i];
        const Vec2& q = polygon[j];
        const Vec2& r = at(polygon, j + 1);
        if (distance_point_segment(p, q, r) <= tol || distance_point_segment(r, p, q) <= tol) return false;
      } else if (segment_distance(polygon[i], at(polygon, i + 1), polygon[j], at(polygon, j + 1)) <= tol) {
        return false;
      }
    }
  }
  return true;
}

std::vector<Vec2> polygon_kernel(const std::vector<Vec2>& ccw_polygon, double tol) {
  const size_t k = ccw_polygon.size();
  if (k < 3) return {};
  Vec2 lo = ccw_polygon[0], hi = ccw_polygon[0];
  for (const Vec2& p : ccw_polygon) {
    if (!p.allFinite()) return {};
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  // The kernel lies inside the polygon, hence inside its bounding box.
  std::vector<Vec2> kernel = {lo, Vec2(hi.x(), lo.y()), hi, Vec2(lo.x(), hi.y())};
  // Two buffers in turn: a clip per edge without an allocation per clip.
  kernel.reserve(k + 4);
  std::vector<Vec2> clipped;
  clipped.reserve(k + 4);
  for (size_t i = 0; i < k && !kernel.empty(); ++i) {
    const Vec2& a = ccw_polygon[i];
    const Vec2 d = at(ccw_polygon, i + 1) - a;
    const double len = d.norm();
    if (len <= 0.0) continue;
    clip_half_plane(kernel, a, Vec2(-d.y(), d.x()) / len, tol, clipped);  // inward = left
    kernel.swap(clipped);
  }
  if (kernel.size() < 3 || signed_area(kernel) <= tol * tol) return {};
  return kernel;
}

bool is_star_shaped(const std::vector<Vec2>& ccw_polygon, double tol) {
  return !polygon_kernel(ccw_polygon, tol).empty();
}

bool clearly_in_kernel(const std::vector<Vec2>& ccw_polygon, const Vec2& p, double tol) {
  if (!(tol > 0.0) || !p.allFinite()) return false;
  for (size_t i = 0; i < ccw_polygon.size(); ++i) {
    const Vec2& a = ccw_polygon[i];
    const Vec2& b = at(ccw_polygon, i + 1);
    const double len = (b - a).norm();
    if (len <= 0.0) continue;
    if (!(orient2d(a, b, p) >= 4.0 * tol * len)) return false;  // NaN: no
  }
  return true;
}

Vec2 kernel_point(const std::vector<Vec2>& ccw_polygon, double tol) {
  const std::vector<Vec2> kernel = polygon_kernel(ccw_polygon, tol);
  return kernel.empty() ? vertex_average(ccw_polygon) : polygon_centroid(kernel);
}

namespace {
bool edge_flipped(const std::vector<Vec2>& polygon, const Vec2& reference, size_t i) {
  return orient2d(reference, polygon[i], at(polygon, i + 1)) < 0.0;
}
}  // namespace

std::vector<int> flipped_edges(const std::vector<Vec2>& polygon, const Vec2& reference) {
  std::vector<int> flipped;
  for (size_t i = 0; i < polygon.size(); ++i) {
    if (edge_flipped(polygon, reference, i)) flipped.push_back(static_cast<int>(i));
  }
  return flipped;
}

bool has_flipped_edge(const std::vector<Vec2>& polygon, const Vec2& reference) {
  for (size_t i = 0; i < polygon.size(); ++i) {
    if (edge_flipped(polygon, reference, i)) return true;
  }
  return false;
}

bool point_in_polygon(const std::vector<Vec2>& polygon, const Vec2& p) {
  bool inside = false;
  const size_t k = polygon.size();
  for (size_t i = 0, j = k - 1; i < k; j = i++) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x) inside = !inside;
    }
  }
  return inside;
}

double distance_point_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * d)).norm();
}

double distance_to_boundary(const std::vector<Vec2>& polygon, const Vec2& p) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < polygon.size(); ++i) {
    best = std::min(best, distance_point_segment(p, polygon[i], at(polygon, i + 1)));
  }
  return best;
}

std::vector<std::array<int, 3>> triangulate_polygon(const std::vector<Vec2>& polygon) {
  const int k = static_cast<int>(polygon.size());
  if (k < 3) return {};
  if (k == 3) return {{0, 1, 2}};
  const double area = signed_area(polygon);
  if (area == 0.0 || !is_simple(polygon, 0.0)) return fan(k);

  // Ear clipping on a linked ring; `sign` makes "convex" mean "turns like the polygon".
  const double sign = area > 0.0 ? 1.0 : -1.0;
  std::vector<int> prev(static_cast<size_t>(k)), next(static_cast<size_t>(k));
  for (int i = 0; i < k; ++i) {
    prev[static_cast<size_t>(i)] = (i + k - 1) % k;
    next[static_cast<size_t>(i)] = (i + 1) % k;
  }
  const auto pt = [&](int i) -> const Vec2& { return polygon[static_cast<size_t>(i)]; };
  const auto turn = [&](int i) {
    return sign * orient2d(pt(prev[static_cast<size_t>(i)]), pt(i), pt(next[static_cast<size_t>(i)]));
  };
  std::vector<char> convex(static_cast<size_t>(k));
  for (int i = 0; i < k; ++i) convex[static_cast<size_t>(i)] = turn(i) > 0.0;

  // An ear: a convex corner whose triangle holds no other non-convex vertex (a convex
  // vertex inside implies a non-convex one inside, so only those need testing).
  const auto is_ear = [&](int i) {
    if (!convex[static_cast<size_t>(i)]) return false;
    const int ia = prev[static_cast<size_t>(i)], ic = next[static_cast<size_t>(i)];
    const Vec2 &a = pt(ia), &b = pt(i), &c = pt(ic);
    for (int j = next[static_cast<size_t>(ic)]; j != ia; j = next[static_cast<size_t>(j)]) {
      if (convex[static_cast<size_t>(j)]) continue;
      const Vec2& p = pt(j);
      if (sign * orient2d(a, b, p) >= 0.0 && sign * orient2d(b, c, p) >= 0.0 && sign * orient2d(c, a, p) >= 0.0) {
        return false;
      }
    }
    return true;
  };

  std::vector<std::array<int, 3>> tris;
  tris.reserve(static_cast<size_t>(k - 2));
  const auto clip = [&](int i) {
    const int a = prev[static_cast<size_t>(i)], c = next[static_cast<size_t>(i)];
    tris.push_back({a, i, c});
    next[static_cast<size_t>(a)] = c;
    prev[static_cast<size_t>(c)] = a;
    convex[static_cast<size_t>(a)] = turn(a) > 0.0;
    convex[static_cast<size_t>(c)] = turn(c) > 0.0;
    return c;
  };
  int remaining = k, i = 0, misses = 0;
  while (remaining > 3) {
    if (is_ear(i)) {
      i = clip(i);
      --remaining;
      misses = 0;
      continue;
    }
    i = next[static_cast<size_t>(i)];
    if (++misses < remaining) continue;
    // A full round without an ear: only rounding can do that; clip the most convex corner.
    int best = i;
    for (int j = next[static_cast<size_t>(i)]; j != i; j = next[static_cast<size_t>(j)]) {
      if (turn(j) > turn(best)) best = j;
    }
    i = clip(best);
    --remaining;
    misses = 0;
  }
  tris.push_back({prev[static_cast<size_t>(i)], i, next[static_cast<size_t>(i)]});
  return tris;
}

PolygonCorner smallest_interior_angle(const std::vector<Vec2>& polygon) {
  const size_t k = polygon.size();
  if (k < 3) return {};
  const double sign = signed_area(polygon) >= 0.0 ? 1.0 : -1.0;
  PolygonCorner best{360.0, -1};
  for (size_t i = 0; i < k; ++i) {
    const Vec2& b = polygon[i];
    const Vec2 to_next = at(polygon, i + 1) - b;
    const Vec2 to_prev = at(polygon, i + k - 1) - b;
    if (to_next.squaredNorm() == 0.0 || to_prev.squaredNorm() == 0.0) return {0.0, static_cast<int>(i)};
    // Interior angle: from the outgoing edge, turning towards the interior, to the incoming one.
    const double cross = sign * (to_next.x() * to_prev.y() - to_next.y() * to_prev.x());
    double angle = std::atan2(cross, to_next.dot(to_prev));
    if (angle < 0.0) angle += 2.0 * kPi;
    const double deg = angle * 180.0 / kPi;
    if (deg < best.angle_deg) best = {deg, static_cast<int>(i)};
  }
  return best;
}

double min_interior_angle_deg(const std::vector<Vec2>& polygon) { return smallest_interior_angle(polygon).angle_deg; }

}  // namespace ff
