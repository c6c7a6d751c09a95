#include "core/panels/panel_crossings.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "core/util/short_number.h"
#include "core/util/union_find.h"

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
void stretches(const std::vector<Vec3>& vertices, const std::vector<int>& panel, const Vec3& origin,
               const Vec3& direction, const Vec3& across, double snap, std::vector<double>& out) {
  out.clear();
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
}

// Two triangles along a common edge: the line of their planes is that edge's, which each meets
// only on its outline, so they cannot cross (most of the pairs a surface's own check meets).
bool triangles_along_an_edge(const std::vector<int>& a, const std::vector<int>& b) {
  if (a.size() != 3 || b.size() != 3) return false;
  int shared = 0;
  for (int u : a) shared += u == b[0] || u == b[1] || u == b[2];
  return shared >= 2;
}

// Pairs of polygons whose boxes overlap, each once, from a grid (sorting the (cell, polygon)
// entries): linear in the number of polygons for a surface, whatever its shape. (A sweep along
// x compared every pair of triangles of a wall across x: 80,000 of them, 17 s, 0.2 s so.) A
// cell is twice the median box's extent along each axis (per axis: a wall of tall thin strips,
// or a cylinder's ring of them, splits across the strips), doubled while the entries outgrow
// 32 per polygon (a few very large polygons). A pair is taken in the one cell that holds the
// larger of its two boxes' lower corners, which both boxes cover exactly when they overlap.
// Returns false, having visited no pair, when the cells would take more than
// `max_tests` box tests in all: boxes that truly overlap by the thousand (a fan of long thin
// triangles around one point, all of whose boxes hold that point) cost their square.
template <typename Visit>
bool overlapping_pairs(const std::vector<Box>& boxes, const std::vector<size_t>& items, double max_tests, Visit visit) {
  if (items.size() < 2) return true;
  Box all{boxes[items[0]].lo, boxes[items[0]].hi};
  for (size_t p : items) {
    all.lo = all.lo.cwiseMin(boxes[p].lo);
    all.hi = all.hi.cwiseMax(boxes[p].hi);
  }
  constexpr uint64_t kSide = uint64_t{1} << 20;  // cells a side at most (keys pack 3 x 21 bits)
  Vec3 cell;
  std::vector<double> extents(items.size());
  for (int axis = 0; axis < 3; ++axis) {
    for (size_t k = 0; k < items.size(); ++k) extents[k] = boxes[items[k]].hi(axis) - boxes[items[k]].lo(axis);
    std::nth_element(extents.begin(), extents.begin() + static_cast<std::ptrdiff_t>(extents.size() / 2), extents.end());
    cell(axis) = std::max({2.0 * extents[extents.size() / 2], (all.hi(axis) - all.lo(axis)) / double(kSide),
                           std::numeric_limits<double>::min()});
  }
  const auto index = [&](double v, int axis) {
    const double t = std::floor((v - all.lo(axis)) / cell(axis));
    if (!(t > 0.0)) return uint64_t{0};  // and NaN (a span beyond the doubles: one cell)
    return t >= double(2 * kSide - 1) ? 2 * kSide - 1 : static_cast<uint64_t>(t);
  };
  const auto key = [&](const Vec3& p) { return index(p.x(), 0) << 42 | index(p.y(), 1) << 21 | index(p.z(), 2); };
  const uint64_t most = 32 * static_cast<uint64_t>(items.size());
  uint64_t total = 0;
  for (;;) {
    total = 0;
    for (size_t p : items) {
      uint64_t count = 1;
      for (int axis = 0; axis < 3; ++axis) count *= index(boxes[p].hi(axis), axis) - index(boxes[p].lo(axis), axis) + 1;
      total += std::min(count, most + 1);  // no wrap: each term is at most 2^58
      if (total > most) break;
    }
    if (total <= most || !(2.0 * cell).allFinite()) break;
    cell *= 2.0;
  }
  std::vector<std::pair<uint64_t, size_t>> entries;
  entries.reserve(static_cast<size_t>(std::min(total, most)));
  for (size_t p : items) {
    const Box& b = boxes[p];
    const uint64_t x0 = index(b.lo.x(), 0), x1 = index(b.hi.x(), 0);
    const uint64_t y0 = index(b.lo.y(), 1), y1 = index(b.hi.y(), 1);
    const uint64_t z0 = index(b.lo.z(), 2), z1 = index(b.hi.z(), 2);
    for (uint64_t x = x0; x <= x1; ++x) {
      for (uint64_t y = y0; y <= y1; ++y) {
        for (uint64_t z = z0; z <= z1; ++z) entries.emplace_back(x << 42 | y << 21 | z, p);
      }
    }
  }
  std::sort(entries.begin(), entries.end());
  // The box tests the cells take, counted before any is made.
  double tests = 0.0;
  for (size_t begin = 0, end = 0; begin < entries.size(); begin = end) {
    while (end < entries.size() && entries[end].first == entries[begin].first) ++end;
    tests += 0.5 * double(end - begin) * double(end - begin - 1);
  }
  if (tests > max_tests) return false;
  for (size_t begin = 0; begin < entries.size();) {
    size_t end = begin;
    while (end < entries.size() && entries[end].first == entries[begin].first) ++end;
    for (size_t i = begin; i < end; ++i) {
      for (size_t j = i + 1; j < end; ++j) {
        const Box& a = boxes[entries[i].second];
        const Box& b = boxes[entries[j].second];
        if ((a.lo.array() > b.hi.array()).any() || (b.lo.array() > a.hi.array()).any()) continue;
        if (key(a.lo.cwiseMax(b.lo)) != entries[begin].first) continue;  // taken in another cell
        visit(entries[i].second, entries[j].second);
      }
    }
    begin = end;
  }
  return true;
}

// panel_crossings within a budget of box tests (overlapping_pairs); `complete` false when it ran out.
std::vector<PanelCrossing> find_crossings(const std::vector<Vec3>& vertices,
                                          const std::vector<std::vector<int>>& panels, const std::vector<Vec3>& normals,
                                          const std::vector<double>& offsets, double max_tests, bool& complete) {
  complete = true;
  std::vector<PanelCrossing> out;
  const size_t np = panels.size();
  if (normals.size() != np || offsets.size() != np) return out;
  std::vector<Box> boxes(np);
  std::vector<double> size(np, 0.0);
  std::vector<size_t> items;
  for (size_t p = 0; p < np; ++p) {
    if (panels[p].size() < 3) continue;
    Box& b = boxes[p];
    b.lo = b.hi = vertices[static_cast<size_t>(panels[p][0])];
    for (int v : panels[p]) {
      b.lo = b.lo.cwiseMin(vertices[static_cast<size_t>(v)]);
      b.hi = b.hi.cwiseMax(vertices[static_cast<size_t>(v)]);
    }
    if (!b.lo.allFinite() || !b.hi.allFinite()) continue;
    size[p] = diameter(vertices, panels[p]);
    items.push_back(p);
  }
  std::vector<double> sa, sb;  // reused: the check runs for every pair of overlapping boxes
  complete = overlapping_pairs(boxes, items, max_tests, [&](size_t a, size_t b) {
    if (triangles_along_an_edge(panels[a], panels[b])) return;
    const Vec3& na = normals[a];
    const Vec3& nb = normals[b];
    const Vec3 u = na.cross(nb);
    if (!(u.norm() > 1e-9)) return;  // one plane (or parallel ones)
    const Vec3 direction = u.normalized();
    const Vec3 origin = (offsets[a] * nb.cross(u) + offsets[b] * u.cross(na)) / u.squaredNorm();
    const double smaller = std::min(size[a], size[b]);
    const double snap = 1e-9 * std::max(size[a], size[b]);
    stretches(vertices, panels[a], origin, direction, na.cross(direction), snap, sa);
    if (sa.empty()) return;
    stretches(vertices, panels[b], origin, direction, nb.cross(direction), snap, sb);
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
  });
  std::sort(out.begin(), out.end(), [](const PanelCrossing& x, const PanelCrossing& y) {
    return std::make_pair(x.a, x.b) < std::make_pair(y.a, y.b);
  });
  return out;
}

}  // namespace

std::vector<PanelCrossing> panel_crossings(const std::vector<Vec3>& vertices,
                                           const std::vector<std::vector<int>>& panels,
                                           const std::vector<Vec3>& normals, const std::vector<double>& offsets) {
  bool complete = true;
  return find_crossings(vertices, panels, normals, offsets, std::numeric_limits<double>::infinity(), complete);
}

namespace {

// Connected groups of crossing pairs: a union-find over the triangles involved, joined by each
// pair and by shared corners.
int crossing_places(const TriMesh& mesh, const std::vector<PanelCrossing>& pairs) {
  if (pairs.empty()) return 0;  // most surfaces: no forest to build on every load
  std::vector<int> parent(static_cast<size_t>(mesh.num_faces()), -1);  // -1: not involved
  const auto join = [&](int a, int b) {
    a = union_find_root(parent, a), b = union_find_root(parent, b);
    if (a != b) parent[static_cast<size_t>(std::max(a, b))] = std::min(a, b);
  };
  std::vector<int> involved;
  for (const PanelCrossing& c : pairs) {
    for (const int f : {c.a, c.b}) {
      if (parent[static_cast<size_t>(f)] < 0) parent[static_cast<size_t>(f)] = f, involved.push_back(f);
    }
    join(c.a, c.b);
  }
  std::vector<int> at_vertex(mesh.positions.size(), -1);
  for (const int f : involved) {
    for (const int v : mesh.triangles[static_cast<size_t>(f)]) {
      int& other = at_vertex[static_cast<size_t>(v)];
      if (other < 0)
        other = f;
      else
        join(other, f);
    }
  }
  int places = 0;
  for (const int f : involved) places += union_find_root(parent, f) == f ? 1 : 0;
  return places;
}

}  // namespace

std::string crossing_where(int places, const Vec3& point) {
  const std::string near =
      "near (" + short_number(point.x()) + ", " + short_number(point.y()) + ", " + short_number(point.z()) + ")";
  if (places == 1) return "in one place, " + near;
  if (places > 1) return "in " + std::to_string(places) + " places, one " + near;
  return near;
}

SurfaceCrossings surface_crossings(const TriMesh& mesh) {
  std::vector<std::vector<int>> triangles;
  std::vector<Vec3> normals;
  std::vector<double> offsets;
  triangles.reserve(static_cast<size_t>(mesh.num_faces()));
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const Triangle& t = mesh.triangles[static_cast<size_t>(f)];
    triangles.push_back({t[0], t[1], t[2]});
    normals.push_back(face_normal(mesh, f));  // zero for a degenerate one: not compared
    offsets.push_back(normals.back().dot(mesh.positions[static_cast<size_t>(t[0])]));
  }
  SurfaceCrossings out;
  const double max_tests = kSurfaceTestsPerTriangle * mesh.num_faces() + 1e7;
  out.pairs = find_crossings(mesh.positions, triangles, normals, offsets, max_tests, out.checked);
  out.places = crossing_places(mesh, out.pairs);
  return out;
}

}  // namespace ff
