#include "core/fabricate/thick_panels.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>

#include "core/util/error.h"

namespace ff {

namespace {

// Below this |n_p - n_q| (about the angle in radians) the bisector's direction is rounding
// noise; the square cut it tends to takes over.
constexpr double kParallel = 1e-9;
// Three unit plane normals spanning less volume than this are treated as not meeting in a
// point: their intersection would lie about t / kMinDet away.
constexpr double kMinDet = 1e-6;

bool solve3(const Vec3& n0, double d0, const Vec3& n1, double d1, const Vec3& n2, double d2, Vec3& x) {
  Eigen::Matrix3d a;
  a.row(0) = n0.transpose();
  a.row(1) = n1.transpose();
  a.row(2) = n2.transpose();
  if (std::abs(a.determinant()) < kMinDet) return false;
  x = a.colPivHouseholderQr().solve(Vec3(d0, d1, d2));
  return x.allFinite();
}

}  // namespace

Plane edge_cut_plane(const Vec3& n, const Vec3* neighbour, const Vec3& a, const Vec3& b) {
  const Vec3 e = (b - a).normalized();
  Vec3 m = Vec3::Zero();
  if (neighbour) {
    m = n - *neighbour;
    m -= m.dot(e) * e;  // the edge lies on both planes only up to rounding
  }
  if (m.norm() < kParallel) m = n.cross(e);
  m.normalize();
  return Plane{m, m.dot(0.5 * (a + b))};
}

Plane unequal_cut_plane(const Vec3& n, const Plane& own_offset, const Plane& other_offset, const Vec3& a,
                        const Vec3& b) {
  const Vec3 e = (b - a).normalized();
  const Vec3 mid = 0.5 * (a + b);
  Vec3 y;
  if (!solve3(own_offset.normal, own_offset.offset, other_offset.normal, other_offset.offset, e, e.dot(mid), y))
    return edge_cut_plane(n, nullptr, a, b);
  Vec3 d = y - mid;
  d -= d.dot(e) * e;
  const Vec3 m = e.cross(d).normalized();
  if (!m.allFinite()) return edge_cut_plane(n, nullptr, a, b);
  return Plane{m, m.dot(mid)};
}

ThickPanels thicken_panels(const PanelMesh& pm, const PanelEdges& edges, double thickness, MaterialSide side) {
  ThickOptions options;
  options.thickness = thickness;
  options.side = side;
  return thicken_panels(pm, edges, options);
}

ThickPanels thicken_panels(const PanelMesh& pm, const PanelEdges& edges, const ThickOptions& options) {
  const double thickness = options.thickness;
  const MaterialSide side = options.side;
  auto check = [](double t) {
    if (!(t > 0.0) || !std::isfinite(t))
      throw InputError("thickness: expected a positive number, got " + std::to_string(t));
  };
  check(thickness);
  ThickPanels out;
  out.thickness = thickness;
  out.side = side;
  const size_t np = pm.panels.size();
  if (!options.panel_thickness.empty() && options.panel_thickness.size() != np)
    throw InputError("panel thickness: expected one per panel (" + std::to_string(np) + "), got " +
                     std::to_string(options.panel_thickness.size()));
  out.panel_thickness = options.panel_thickness.empty() ? std::vector<double>(np, thickness) : options.panel_thickness;
  for (size_t p = 0; p < np; ++p) {
    check(out.panel_thickness[p]);
    const double shift = side == MaterialSide::Inside ? -out.panel_thickness[p] : out.panel_thickness[p];
    out.offset_planes.push_back({pm.plane_normals[p], pm.plane_offsets[p] + shift});
  }
  // The cut plane of panel p's edge a -> b against panel q (-1: boundary).
  auto cut_plane = [&](size_t p, int q, const Vec3& a, const Vec3& b) {
    const Vec3& n = pm.plane_normals[p];
    if (q < 0) {
      if (options.boundary.kind == BoundaryCut::Kind::Square) return edge_cut_plane(n, nullptr, a, b);
      const Vec3 e = (b - a).normalized();
      const Vec3 m = e.cross(boundary_cut_direction(n, e, options.boundary, side)).normalized();
      return Plane{m, m.dot(0.5 * (a + b))};
    }
    const size_t qi = static_cast<size_t>(q);
    if (out.panel_thickness[p] == out.panel_thickness[qi]) return edge_cut_plane(n, &pm.plane_normals[qi], a, b);
    return unequal_cut_plane(n, out.offset_planes[p], out.offset_planes[qi], a, b);
  };
  out.inner.resize(np);
  out.corner_fallback.resize(np);
  out.node_spread.assign(pm.vertices.size(), 0.0);

  auto corner_index = [&](size_t p, int v) {
    const std::vector<int>& poly = pm.panels[p];
    return static_cast<size_t>(std::find(poly.begin(), poly.end(), v) - poly.begin());
  };
  // Both edges of panel p at corner i have a neighbour.
  auto interior_corner = [&](size_t p, size_t i) {
    const size_t k = pm.panels[p].size();
    return edges.neighbour[p][i] >= 0 && edges.neighbour[p][(i + k - 1) % k] >= 0;
  };

  // Valence-3 interior nodes: one solve in panel order, so all three panels get the very
  // same point.
  std::vector<char> shared(pm.vertices.size(), 0);
  std::vector<Vec3> shared_point(pm.vertices.size(), Vec3::Zero());
  for (size_t v = 0; v < pm.vertices.size(); ++v) {
    const std::vector<int>& around = edges.vertex_panels[v];
    if (around.size() != 3) continue;
    bool interior = true;
    for (const int p : around) {
      const size_t i = corner_index(static_cast<size_t>(p), static_cast<int>(v));
      interior = interior && interior_corner(static_cast<size_t>(p), i);
    }
    if (!interior) continue;
    const Plane& a = out.offset_planes[static_cast<size_t>(around[0])];
    const Plane& b = out.offset_planes[static_cast<size_t>(around[1])];
    const Plane& c = out.offset_planes[static_cast<size_t>(around[2])];
    if (solve3(a.normal, a.offset, b.normal, b.offset, c.normal, c.offset, shared_point[v])) shared[v] = 1;
  }

  for (size_t p = 0; p < np; ++p) {
    const std::vector<int>& poly = pm.panels[p];
    const size_t k = poly.size();
    const Vec3& n = pm.plane_normals[p];
    const Plane& own = out.offset_planes[p];
    out.inner[p].resize(k);
    out.corner_fallback[p].assign(k, 0);
    for (size_t i = 0; i < k; ++i) {
      const size_t v = static_cast<size_t>(poly[i]);
      if (shared[v]) {
        out.inner[p][i] = shared_point[v];
        continue;
      }
      const Vec3& x = pm.vertices[v];
      const Vec3& prev = pm.vertices[static_cast<size_t>(poly[(i + k - 1) % k])];
      const Vec3& next = pm.vertices[static_cast<size_t>(poly[(i + 1) % k])];
      const int qp = edges.neighbour[p][(i + k - 1) % k], qn = edges.neighbour[p][i];
      const Plane cut_prev = cut_plane(p, qp, prev, x);
      const Plane cut_next = cut_plane(p, qn, x, next);
      Vec3& y = out.inner[p][i];
      if (solve3(n, own.offset, cut_prev.normal, cut_prev.offset, cut_next.normal, cut_next.offset, y)) continue;
      // Straight corner: the edges run on (nearly) one line, so cut across it at the corner.
      const Vec3 along = ((x - prev).normalized() + (next - x).normalized()).normalized();
      if (along.allFinite() && solve3(n, own.offset, cut_prev.normal, cut_prev.offset, along, along.dot(x), y)) {
        out.corner_fallback[p][i] = 1;
        ++out.straight_corners;
        continue;
      }
      y = own.project(x);
      out.corner_fallback[p][i] = 2;
      ++out.projected_corners;
    }
  }

  // Spread: how far apart the panels' inner vertices at one node are.
  for (size_t v = 0; v < pm.vertices.size(); ++v) {
    std::vector<Vec3> points;
    for (const int pi : edges.vertex_panels[v]) {
      const size_t p = static_cast<size_t>(pi);
      const size_t i = corner_index(p, static_cast<int>(v));
      if (interior_corner(p, i) && out.corner_fallback[p][i] == 0) points.push_back(out.inner[p][i]);
    }
    double spread = 0.0;
    for (size_t a = 0; a < points.size(); ++a)
      for (size_t b = a + 1; b < points.size(); ++b) spread = std::max(spread, (points[a] - points[b]).norm());
    out.node_spread[v] = spread;
    out.max_spread = std::max(out.max_spread, spread);
  }
  return out;
}

}  // namespace ff
