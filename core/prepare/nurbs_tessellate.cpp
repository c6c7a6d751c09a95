#include "core/prepare/nurbs_tessellate.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/util/error.h"

namespace ff {

namespace {

constexpr int kProbeSegments = 16;  // per span, to measure length and turning
constexpr int kMaxIsoCurves = 33;   // iso-curves probed across the other direction

// Parameters `count` values spread over the breaks: each break, plus midpoints while few.
std::vector<double> probe_lines(const std::vector<double>& breaks) {
  std::vector<double> out;
  const size_t spans = breaks.size() - 1;
  const size_t per = std::max<size_t>(1, std::min<size_t>(4, kMaxIsoCurves / std::max<size_t>(spans, 1)));
  const size_t stride = std::max<size_t>(1, spans / kMaxIsoCurves);
  for (size_t k = 0; k < spans; k += stride)
    for (size_t m = 0; m < per; ++m) out.push_back(breaks[k] + (breaks[k + 1] - breaks[k]) * double(m) / double(per));
  out.push_back(breaks.back());
  return out;
}

// Grid intervals for each span along u (`along_u`) or v: enough for the edge length along
// the longest probed iso-curve and for the chord tolerance where it turns most.
std::vector<int> span_samples(const NurbsSurface& s, bool along_u, const TessellationOptions& o) {
  const std::vector<double> breaks = nurbs_breaks(s, along_u);
  const std::vector<double> across = probe_lines(nurbs_breaks(s, !along_u));
  std::vector<int> out;
  for (size_t k = 0; k + 1 < breaks.size(); ++k) {
    double need = 1.0;
    for (const double t : across) {
      Vec3 pts[kProbeSegments + 1];
      for (int m = 0; m <= kProbeSegments; ++m) {
        const double a = breaks[k] + (breaks[k + 1] - breaks[k]) * m / kProbeSegments;
        pts[m] = along_u ? evaluate_nurbs(s, a, t).p : evaluate_nurbs(s, t, a).p;
      }
      double length = 0.0, curvature = 0.0;
      for (int m = 0; m < kProbeSegments; ++m) length += (pts[m + 1] - pts[m]).norm();
      for (int m = 1; m < kProbeSegments; ++m) {
        const Vec3 a = pts[m] - pts[m - 1], b = pts[m + 1] - pts[m];
        const double la = a.norm(), lb = b.norm();
        if (la <= 0.0 || lb <= 0.0) continue;
        // Turning angle over the mean segment length: the curvature there.
        const double angle = std::atan2(a.cross(b).norm(), a.dot(b));
        curvature = std::max(curvature, angle / (0.5 * (la + lb)));
      }
      need = std::max(need, length / o.edge_length);
      // An edge of length h on a curve of curvature k is off it by about k h^2 / 8.
      if (curvature > 0.0) need = std::max(need, length / std::sqrt(8.0 * o.chord_tolerance / curvature));
    }
    out.push_back(static_cast<int>(std::min<double>(std::ceil(need - 1e-9), o.max_samples_per_span)));
  }
  return out;
}

std::vector<double> parameters(const std::vector<double>& breaks, const std::vector<int>& samples) {
  std::vector<double> out;
  for (size_t k = 0; k < samples.size(); ++k)
    for (int m = 0; m < samples[k]; ++m)
      out.push_back(breaks[k] + (breaks[k + 1] - breaks[k]) * double(m) / double(samples[k]));
  out.push_back(breaks.back());
  return out;
}

}  // namespace

SurfaceTessellation tessellate_nurbs(const NurbsSurface& s, const TessellationOptions& options,
                                     const std::string& name) {
  TessellationOptions o = options;
  if (!(std::isfinite(o.edge_length) && o.edge_length > 0.0))
    throw InputError(name + ": the tessellation edge length must be positive");
  if (!(o.chord_tolerance > 0.0) || !std::isfinite(o.chord_tolerance)) o.chord_tolerance = o.edge_length / 20.0;
  const std::vector<int> nu = span_samples(s, true, o), nv = span_samples(s, false, o);
  const long long cu = std::accumulate(nu.begin(), nu.end(), 0LL), cv = std::accumulate(nv.begin(), nv.end(), 0LL);
  // cu and cv first: their product could overflow.
  if (cu > o.max_triangles || cv > o.max_triangles || 2 * cu * cv > o.max_triangles)
    throw InputError(name + ": tessellating at edge length " + std::to_string(o.edge_length) +
                     " would make more than " + std::to_string(o.max_triangles) + " triangles (" + std::to_string(cu) +
                     " x " + std::to_string(cv) + " grid)");
  const std::vector<double> us = parameters(nurbs_breaks(s, true), nu);
  const std::vector<double> vs = parameters(nurbs_breaks(s, false), nv);
  const int rows = static_cast<int>(us.size()), cols = static_cast<int>(vs.size());
  SurfaceTessellation out;
  out.samples_u = static_cast<int>(cu);
  out.samples_v = static_cast<int>(cv);
  std::vector<Vec3> grid;
  grid.reserve(static_cast<size_t>(rows) * static_cast<size_t>(cols));
  for (const double u : us)
    for (const double v : vs) grid.push_back(evaluate_nurbs(s, u, v).p);
  auto id = [cols](int i, int j) { return i * cols + j; };

  // Merge coincident border points (seams, poles): sorted by x, each joins the first earlier
  // representative within the tolerance. Deterministic: ties broken by index.
  BoundingBox box;
  box.lo = box.hi = grid.front();
  for (const Vec3& p : grid) {
    box.lo = box.lo.cwiseMin(p);
    box.hi = box.hi.cwiseMax(p);
  }
  const double tol = 1e-9 * std::max((box.hi - box.lo).norm(), 1e-300);
  std::vector<int> border;
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j)
      if (i == 0 || j == 0 || i == rows - 1 || j == cols - 1) border.push_back(id(i, j));
  std::stable_sort(border.begin(), border.end(),
                   [&](int a, int b) { return grid[size_t(a)].x() < grid[size_t(b)].x(); });
  std::vector<int> rep(grid.size());
  std::iota(rep.begin(), rep.end(), 0);
  for (size_t a = 0; a < border.size(); ++a) {
    int best = -1;
    for (size_t b = a; b-- > 0;) {
      const Vec3& pb = grid[size_t(border[b])];
      if (grid[size_t(border[a])].x() - pb.x() > tol) break;
      if (rep[size_t(border[b])] != border[b]) continue;  // only representatives attract
      if ((grid[size_t(border[a])] - pb).norm() <= tol && (best < 0 || border[b] < best)) best = border[b];
    }
    if (best >= 0) {
      rep[size_t(border[a])] = best;
      ++out.seam_vertices_welded;
    }
  }
  // Compact the representatives into the output vertices, in grid order.
  std::vector<int> index(grid.size(), -1);
  for (size_t v = 0; v < grid.size(); ++v)
    if (rep[v] == int(v)) {
      index[v] = out.mesh.num_vertices();
      out.mesh.positions.push_back(grid[v]);
    }
  auto vertex = [&](int i, int j) { return index[size_t(rep[size_t(id(i, j))])]; };
  auto add = [&](int a, int b, int c) {
    if (a == b || b == c || a == c)
      ++out.degenerate_triangles_dropped;
    else
      out.mesh.triangles.push_back({a, b, c});
  };
  for (int i = 0; i + 1 < rows; ++i) {
    for (int j = 0; j + 1 < cols; ++j) {
      // Counter-clockwise in (u, v): normals along dS/du x dS/dv. The shorter diagonal splits.
      const int a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1), d = vertex(i, j + 1);
      const double ac = (grid[size_t(id(i, j))] - grid[size_t(id(i + 1, j + 1))]).squaredNorm();
      const double bd = (grid[size_t(id(i + 1, j))] - grid[size_t(id(i, j + 1))]).squaredNorm();
      if (ac <= bd) {
        add(a, b, c);
        add(a, c, d);
      } else {
        add(a, b, d);
        add(b, c, d);
      }
    }
  }
  return out;
}

double nurbs_area_estimate(const NurbsSurface& s) {
  auto line = [&](bool along_u) {
    const std::vector<double> breaks = nurbs_breaks(s, along_u);
    std::vector<double> out = breaks;
    // Up to 64 samples: knot lines plus evenly spread ones.
    const NurbsDomain d = nurbs_domain(s);
    const double lo = along_u ? d.u0 : d.v0, hi = along_u ? d.u1 : d.v1;
    for (int m = 1; m < 64; ++m) out.push_back(lo + (hi - lo) * m / 64.0);
    std::sort(out.begin(), out.end());
    if (out.size() > 128) {
      std::vector<double> thin;
      for (size_t k = 0; k < out.size(); k += out.size() / 64) thin.push_back(out[k]);
      thin.push_back(out.back());
      out = thin;
    }
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  };
  const std::vector<double> us = line(true), vs = line(false);
  std::vector<Vec3> grid;
  for (const double u : us)
    for (const double v : vs) grid.push_back(evaluate_nurbs(s, u, v).p);
  const size_t cols = vs.size();
  double area = 0.0;
  for (size_t i = 0; i + 1 < us.size(); ++i)
    for (size_t j = 0; j + 1 < cols; ++j) {
      const Vec3& a = grid[i * cols + j];
      const Vec3& b = grid[(i + 1) * cols + j];
      const Vec3& c = grid[(i + 1) * cols + j + 1];
      const Vec3& e = grid[i * cols + j + 1];
      area += 0.5 * (b - a).cross(c - a).norm() + 0.5 * (c - a).cross(e - a).norm();
    }
  return area;
}

}  // namespace ff
