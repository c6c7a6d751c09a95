#include "core/quality/closest_point.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "core/mesh/segment.h"
#include "core/util/error.h"

namespace ff {

namespace {

constexpr int kLeafSize = 4;
constexpr int kSelectDirectly = 64;  // smaller ranges select the exact median
constexpr int kMaxBins = 256;

double box_distance2(const Vec3& q, const Vec3& lo, const Vec3& hi) {
  const Vec3 d = (lo - q).cwiseMax(q - hi).cwiseMax(0.0);
  return d.squaredNorm();
}

// Slivers (sine of every angle below 1e-14) are segments: the region tests of
// closest_on_proper_triangle divide by squared edge lengths and the squared normal.
bool is_sliver(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a;
  return ab.cross(ac).squaredNorm() <= 1e-28 * ab.squaredNorm() * ac.squaredNorm();
}

Vec3 closest_on_sliver(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 candidates[3] = {closest_point_on_segment(p, a, b), closest_point_on_segment(p, b, c), closest_point_on_segment(p, c, a)};
  const Vec3* best = &candidates[0];
  for (const Vec3& x : candidates) {
    if ((x - p).squaredNorm() < (*best - p).squaredNorm()) best = &x;
  }
  return *best;
}

// Ericson's region tests, for a triangle that is not a sliver.
Vec3 closest_on_proper_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a;
  const Vec3 ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;  // vertex region A
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;  // vertex region B
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + (d1 / (d1 - d3)) * ab;  // edge AB
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;  // vertex region C
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + (d2 / (d2 - d6)) * ac;  // edge AC
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {  // edge BC
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  }
  const double denom = va + vb + vc;
  if (!(denom > 0.0)) return closest_point_on_segment(p, a, b);  // unreachable unless rounding
  return a + (vb / denom) * ab + (vc / denom) * ac;        // inside the face
}

}  // namespace

Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  return is_sliver(a, b, c) ? closest_on_sliver(p, a, b, c) : closest_on_proper_triangle(p, a, b, c);
}

// Build-time record, partitioned in place: contiguous, so each level is a streaming pass.
// Float centroids are plenty to choose splits; ties are broken by index.
struct TriangleTree::Item {
  float centroid[3];
  int index;
};

TriangleTree::TriangleTree(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles) {
  const size_t m = triangles.size();
  const int nv = static_cast<int>(vertices.size());
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (size_t t = 0; t < m; ++t) {
    for (int v : triangles[t]) {
      if (v < 0 || v >= nv) {
        throw InputError("closest point tree: triangle " + std::to_string(t) + " refers to vertex " +
                         std::to_string(v) + " of " + std::to_string(nv));
      }
      const Vec3& p = vertices[static_cast<size_t>(v)];
      if (!p.allFinite()) throw InputError("closest point tree: vertex " + std::to_string(v) + " is not finite");
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
  // Centroids in floats, in the box's own frame (about -0.5 to 0.5): a model at 1e39 or 1e-40
  // in world units would otherwise overflow or vanish in a float, and the splits' bins with it.
  const Vec3 center = m > 0 ? Vec3(0.5 * lo + 0.5 * hi) : Vec3::Zero();
  const double extent = m > 0 ? (0.5 * hi - 0.5 * lo).maxCoeff() : 0.0;
  const double to_unit = extent > 0.0 && std::isfinite(0.5 / extent) ? 0.5 / extent : 1.0;
  std::vector<Item> items(m);
  for (size_t t = 0; t < m; ++t) {
    Vec3 centroid = Vec3::Zero();
    for (int v : triangles[t]) centroid += (vertices[static_cast<size_t>(v)] - center) * (to_unit / 3.0);
    items[t] = {{static_cast<float>(centroid.x()), static_cast<float>(centroid.y()), static_cast<float>(centroid.z())},
                static_cast<int>(t)};
  }
  if (m > 0) {
    nodes_.reserve(m);  // leaves hold >= 2 triangles: fewer than m nodes
    build(0, static_cast<int>(m), items);
  }
  parent_.assign(nodes_.size(), -1);
  leaf_of_.resize(m);
  for (size_t n = 0; n < nodes_.size(); ++n) {
    const Node& node = nodes_[n];
    if (node.count > 0) {
      for (int s = node.first; s < node.first + node.count; ++s) leaf_of_[static_cast<size_t>(s)] = static_cast<int>(n);
    } else {
      parent_[n + 1] = static_cast<int>(n);
      parent_[static_cast<size_t>(node.first)] = static_cast<int>(n);
    }
  }
  order_.resize(m);
  slot_of_.resize(m);
  corners_.resize(3 * m);
  sliver_.resize(m);
  for (size_t s = 0; s < m; ++s) {
    const int t = items[s].index;
    order_[s] = t;
    slot_of_[static_cast<size_t>(t)] = static_cast<int>(s);
    for (size_t j = 0; j < 3; ++j)
      corners_[3 * s + j] = vertices[static_cast<size_t>(triangles[static_cast<size_t>(t)][j])];
    sliver_[s] = is_sliver(corners_[3 * s], corners_[3 * s + 1], corners_[3 * s + 2]);
  }
  // Boxes bottom-up: in depth-first order both children come after their parent.
  for (size_t n = nodes_.size(); n-- > 0;) {
    Node& node = nodes_[n];
    if (node.count > 0) {
      node.lo = node.hi = corners_[3 * static_cast<size_t>(node.first)];
      for (size_t c = 3 * static_cast<size_t>(node.first); c < 3 * static_cast<size_t>(node.first + node.count); ++c) {
        node.lo = node.lo.cwiseMin(corners_[c]);
        node.hi = node.hi.cwiseMax(corners_[c]);
      }
    } else {
      const Node& l = nodes_[n + 1];
      const Node& r = nodes_[static_cast<size_t>(node.first)];
      node.lo = l.lo.cwiseMin(r.lo);
      node.hi = l.hi.cwiseMax(r.hi);
    }
  }
}

int TriangleTree::build(int begin, int end, std::vector<Item>& items) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.push_back({});
  if (end - begin <= kLeafSize) {
    // Canonical leaf order: the tree does not depend on the standard library.
    std::sort(items.begin() + begin, items.begin() + end,
              [](const Item& l, const Item& r) { return l.index < r.index; });
    nodes_[static_cast<size_t>(index)].first = begin;
    nodes_[static_cast<size_t>(index)].count = end - begin;
    return index;
  }
  float lo[3] = {items[static_cast<size_t>(begin)].centroid[0], items[static_cast<size_t>(begin)].centroid[1],
                 items[static_cast<size_t>(begin)].centroid[2]};
  float hi[3] = {lo[0], lo[1], lo[2]};
  for (int s = begin; s < end; ++s) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], items[static_cast<size_t>(s)].centroid[k]);
      hi[k] = std::max(hi[k], items[static_cast<size_t>(s)].centroid[k]);
    }
  }
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    if (hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
  }
  int mid = begin + (end - begin) / 2;
  const auto first = items.begin() + begin, last = items.begin() + end;
  const auto less = [axis](const Item& l, const Item& r) {
    return l.centroid[axis] < r.centroid[axis] || (l.centroid[axis] == r.centroid[axis] && l.index < r.index);
  };
  bool split = false;
  if (end - begin > kSelectDirectly && hi[axis] > lo[axis]) {
    // Large ranges: split at the histogram bin boundary nearest the median, one streaming
    // partition instead of a branchy multi-pass selection (halves within a bin of equal).
    const int bins = end - begin > 4096 ? kMaxBins : 32;
    // In double: a spread of float subnormals would make a float scale infinite (NaN bins).
    const double origin = lo[axis], scale = bins / (static_cast<double>(hi[axis]) - origin);
    const auto bin = [&](const Item& item) {
      return std::min(bins - 1, static_cast<int>((static_cast<double>(item.centroid[axis]) - origin) * scale));
    };
    int counts[kMaxBins] = {};
    for (auto it = first; it != last; ++it) ++counts[bin(*it)];
    int boundary = 0, below = 0;
    for (; below + counts[boundary] <= mid - begin; ++boundary) below += counts[boundary];
    if (below + counts[boundary] - (mid - begin) < (mid - begin) - below) below += counts[boundary++];
    const int n = end - begin;
    if (below >= n / 4 && n - below >= n / 4) {
      std::partition(first, last, [&](const Item& item) { return bin(item) < boundary; });
      mid = begin + below;
      split = true;
    }
  }
  if (!split) std::nth_element(first, items.begin() + mid, last, less);
  build(begin, mid, items);
  const int second = build(mid, end, items);
  nodes_[static_cast<size_t>(index)].first = second;
  nodes_[static_cast<size_t>(index)].count = 0;
  return index;
}

void TriangleTree::test_triangle(const Vec3& q, int slot, ClosestPoint& best, double& best2) const {
  const size_t s = static_cast<size_t>(slot);
  const Vec3 &a = corners_[3 * s], &b = corners_[3 * s + 1], &c = corners_[3 * s + 2];
  const Vec3 x = sliver_[s] ? closest_on_sliver(q, a, b, c) : closest_on_proper_triangle(q, a, b, c);
  const double d2 = (x - q).squaredNorm();
  if (d2 < best2) {
    best2 = d2;
    best.point = x;
    best.triangle = order_[s];
  }
}

void TriangleTree::search(const Vec3& q, int root, double enough2, ClosestPoint& best, double& best2) const {
  // Every split leaves at most 3/4 of a range on each side, so depth <= log(m) / log(4/3)
  // (48 for a million triangles), and each level leaves at most one pending node.
  std::array<std::pair<int, double>, 128> stack;
  int top = 0;
  const Node& start = nodes_[static_cast<size_t>(root)];
  stack[static_cast<size_t>(top++)] = {root, box_distance2(q, start.lo, start.hi)};
  while (top > 0 && best2 > enough2) {
    const auto [index, d2] = stack[static_cast<size_t>(--top)];
    if (d2 >= best2) continue;
    const Node& node = nodes_[static_cast<size_t>(index)];
    if (node.count > 0) {
      for (int s = node.first; s < node.first + node.count; ++s) test_triangle(q, s, best, best2);
      continue;
    }
    int near = index + 1, far = node.first;
    double dn = box_distance2(q, nodes_[static_cast<size_t>(near)].lo, nodes_[static_cast<size_t>(near)].hi);
    double df = box_distance2(q, nodes_[static_cast<size_t>(far)].lo, nodes_[static_cast<size_t>(far)].hi);
    if (df < dn) {
      std::swap(near, far);
      std::swap(dn, df);
    }
    // Far first, so the near child is popped (and tightens the bound) first.
    if (df < best2) stack[static_cast<size_t>(top++)] = {far, df};
    if (dn < best2) stack[static_cast<size_t>(top++)] = {near, dn};
  }
}

ClosestPoint TriangleTree::closest_point(const Vec3& q, int hint, double good_enough) const {
  ClosestPoint best;
  double best2 = std::numeric_limits<double>::infinity();
  if (nodes_.empty()) {
    best.distance = best2;
    return best;
  }
  const double enough2 = good_enough > 0.0 ? good_enough * good_enough : -1.0;
  if (hint >= 0 && hint < num_triangles()) {
    const int slot = slot_of_[static_cast<size_t>(hint)];
    test_triangle(q, slot, best, best2);
    if (enough2 >= 0.0 && best2 > enough2) {
      // Any triangle within good_enough will do, and one is most likely near the hint:
      // search the smallest subtree above the hint's leaf whose box holds q first. The
      // answer is still exact when none is good enough (the whole tree is searched next).
      int node = parent_[static_cast<size_t>(leaf_of_[static_cast<size_t>(slot)])];
      while (node > 0) {
        const Node& n = nodes_[static_cast<size_t>(node)];
        if (box_distance2(q, n.lo, n.hi) == 0.0) break;
        node = parent_[static_cast<size_t>(node)];
      }
      if (node > 0) search(q, node, enough2, best, best2);
    }
  }
  if (best2 > enough2) search(q, 0, enough2, best, best2);
  best.distance = std::sqrt(best2);
  return best;
}

}  // namespace ff
