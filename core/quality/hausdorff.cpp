#include "core/quality/hausdorff.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "core/quality/closest_point.h"
#include "core/util/error.h"
#include "core/util/random.h"

namespace ff {

namespace {

const Vec3& panel_vertex(const PanelMesh& panels, int panel, int v) {
  if (v < 0 || v >= static_cast<int>(panels.vertices.size())) {
    throw InputError("panel " + std::to_string(panel) + " refers to vertex " + std::to_string(v) + " of " +
                     std::to_string(panels.vertices.size()));
  }
  return panels.vertices[static_cast<size_t>(v)];
}

struct OneSided {
  double distance = 0.0;
  Vec3 worst = Vec3::Zero();
};

// The low 10 bits of v, spread out to every third bit (bit k goes to bit 3k).
std::uint32_t spread_bits(std::uint32_t v) {
  v = (v | (v << 16)) & 0x030000FFu;
  v = (v | (v << 8)) & 0x0300F00Fu;
  v = (v | (v << 4)) & 0x030C30C3u;
  v = (v | (v << 2)) & 0x09249249u;
  return v;
}

// Max over samples of the distance to the tree. A sample only matters if it is farther
// than the maximum so far, so each query may stop at any triangle within that maximum. The
// samples are visited along a Morton curve, so consecutive ones are near each other and the
// previous answer is usually within the maximum already (bunny.off at 200 panels, panels to
// input: 26 ms in sample order, 5 ms in this one). The result is the sample order's: the
// maximum is exact either way, and on a tie the first sample in sample order is the worst.
OneSided directed(const std::vector<Vec3>& samples, const TriangleTree& tree) {
  OneSided out;
  if (samples.empty()) return out;
  if (tree.num_triangles() == 0) {
    out.distance = std::numeric_limits<double>::infinity();
    out.worst = samples.front();
    return out;
  }
  int hint = -1, worst = -1;
  for (const int i : morton_order(samples)) {
    const Vec3& s = samples[static_cast<size_t>(i)];
    const ClosestPoint c = tree.closest_point(s, hint, out.distance);
    hint = c.triangle;
    // A distance equal to the maximum may be any triangle's within it: measure exactly.
    const bool tie =
        c.distance == out.distance && worst >= 0 && i < worst && tree.closest_point(s).distance == out.distance;
    if (c.distance > out.distance || tie) {
      out.distance = c.distance;
      out.worst = s;
      worst = i;
    }
  }
  return out;
}

}  // namespace

std::vector<int> morton_order(const std::vector<Vec3>& points) {
  if (points.empty()) return {};
  Vec3 lo = points.front(), hi = points.front();
  for (const Vec3& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const Vec3 extent = hi - lo;
  double scale[3];
  for (int k = 0; k < 3; ++k) scale[k] = extent[k] > 0.0 ? 1023.0 / extent[k] : 0.0;
  const size_t n = points.size();
  std::vector<std::uint32_t> code(n);
  for (size_t i = 0; i < n; ++i) {
    std::uint32_t c = 0;
    for (int k = 0; k < 3; ++k) {
      const double t = std::clamp((points[i][k] - lo[k]) * scale[k], 0.0, 1023.0);
      c |= spread_bits(static_cast<std::uint32_t>(t)) << (2 - k);
    }
    code[i] = c;
  }
  std::vector<int> order(n), next(n);
  for (size_t i = 0; i < n; ++i) order[i] = static_cast<int>(i);
  for (int shift = 0; shift < 30; shift += 10) {
    std::vector<size_t> start(1025, 0);
    for (size_t i = 0; i < n; ++i) ++start[((code[i] >> shift) & 1023u) + 1];
    for (size_t b = 1; b < start.size(); ++b) start[b] += start[b - 1];
    for (const int i : order) next[start[(code[static_cast<size_t>(i)] >> shift) & 1023u]++] = i;
    order.swap(next);
  }
  return order;
}

PlaneFrame panel_frame(const PanelMesh& panels, int panel) {
  const std::vector<int>& poly = panels.panels[static_cast<size_t>(panel)];
  std::vector<Vec3> points;
  points.reserve(poly.size());
  Vec3 average = Vec3::Zero();
  for (int v : poly) {
    points.push_back(panel_vertex(panels, panel, v));
    average += points.back();
  }
  if (!points.empty()) average /= static_cast<double>(points.size());
  Vec3 normal = Vec3::Zero();
  if (static_cast<size_t>(panel) < panels.plane_normals.size())
    normal = panels.plane_normals[static_cast<size_t>(panel)];
  if (!normal.allFinite() || normal.norm() <= 0.0) normal = newell_normal(points);
  if (!normal.allFinite() || normal.norm() <= 0.0) normal = Vec3::UnitZ();
  return make_plane_frame(average.allFinite() ? average : Vec3::Zero(), normal);
}

std::vector<Vec2> panel_polygon_2d(const PanelMesh& panels, int panel, const PlaneFrame& frame) {
  std::vector<Vec2> out;
  for (int v : panels.panels[static_cast<size_t>(panel)]) out.push_back(frame.to_2d(panel_vertex(panels, panel, v)));
  return out;
}

TriMesh triangulate_panels(const PanelMesh& panels, std::vector<int>* triangle_panel) {
  TriMesh mesh;
  mesh.positions = panels.vertices;
  if (triangle_panel) triangle_panel->clear();
  for (int p = 0; p < panels.num_panels(); ++p) {
    const std::vector<int>& poly = panels.panels[static_cast<size_t>(p)];
    if (poly.size() < 3) continue;
    const PlaneFrame frame = panel_frame(panels, p);
    for (const auto& t : triangulate_polygon(panel_polygon_2d(panels, p, frame))) {
      mesh.triangles.push_back(
          {poly[static_cast<size_t>(t[0])], poly[static_cast<size_t>(t[1])], poly[static_cast<size_t>(t[2])]});
      if (triangle_panel) triangle_panel->push_back(p);
    }
  }
  return mesh;
}

std::vector<Vec3> sample_surface(const TriMesh& mesh, int target, std::uint64_t seed, std::vector<int>* triangle) {
  std::vector<Vec3> samples;
  std::vector<int> first_triangle(mesh.positions.size(), -1);  // -1: no triangle uses the vertex
  for (int f = 0; f < mesh.num_faces(); ++f) {
    for (int v : mesh.triangles[static_cast<size_t>(f)]) {
      if (v < 0 || v >= mesh.num_vertices()) throw InputError("sampling: a triangle refers to a missing vertex");
      if (first_triangle[static_cast<size_t>(v)] < 0) first_triangle[static_cast<size_t>(v)] = f;
    }
  }
  if (triangle) triangle->clear();
  for (size_t v = 0; v < first_triangle.size(); ++v) {
    if (first_triangle[v] < 0) continue;
    samples.push_back(mesh.positions[v]);
    if (triangle) triangle->push_back(first_triangle[v]);
  }
  const double total = total_area(mesh);
  const long long fixed = static_cast<long long>(samples.size()) + mesh.num_faces();
  const long long random = total > 0.0 ? std::max(0LL, static_cast<long long>(target) - fixed) : 0;
  samples.reserve(static_cast<size_t>(fixed + random));

  // Jittered strata: sample j sits at area position (j + r_j) / random * total, so the
  // positions increase and one pass over the triangles places them.
  SplitMix64 rng(seed);
  long long j = 0;
  double next_position = random > 0 ? rng.uniform() / static_cast<double>(random) * total : 0.0;
  double cumulative = 0.0;
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const Triangle& t = mesh.triangles[static_cast<size_t>(f)];
    const Vec3& a = mesh.positions[static_cast<size_t>(t[0])];
    const Vec3& b = mesh.positions[static_cast<size_t>(t[1])];
    const Vec3& c = mesh.positions[static_cast<size_t>(t[2])];
    samples.push_back((a + b + c) / 3.0);
    if (triangle) triangle->push_back(f);
    cumulative += face_area(mesh, f);
    const bool last = f + 1 == mesh.num_faces();
    while (j < random && (next_position < cumulative || last)) {
      // Uniform in the triangle: sqrt warps the first coordinate so density is even.
      const double s = std::sqrt(rng.uniform()), r = rng.uniform();
      samples.push_back((1.0 - s) * a + s * (1.0 - r) * b + s * r * c);
      if (triangle) triangle->push_back(f);
      ++j;
      next_position = (static_cast<double>(j) + rng.uniform()) / static_cast<double>(random) * total;
    }
  }
  return samples;
}

HausdorffResult hausdorff_distance(const TriMesh& a, const TriMesh& b, int samples_per_side) {
  if (samples_per_side < 0) throw InputError("hausdorff: the number of samples must not be negative");
  // Fixed seeds: the same meshes always give the same number.
  const OneSided ab = directed(sample_surface(a, samples_per_side, 0x48617573646F7266ULL), TriangleTree(b));
  const OneSided ba = directed(sample_surface(b, samples_per_side, 0x6F72666653696465ULL), TriangleTree(a));
  HausdorffResult r;
  r.input_to_panels = ab.distance;
  r.panels_to_input = ba.distance;
  r.input_worst_point = ab.worst;
  r.panels_worst_point = ba.worst;
  r.two_sided = std::max(ab.distance, ba.distance);
  r.worst_point = ab.distance >= ba.distance ? ab.worst : ba.worst;
  return r;
}

HausdorffResult hausdorff_distance(const TriMesh& input, const PanelMesh& panels, int samples_per_side) {
  if (input.num_faces() == 0) throw InputError("hausdorff: the input mesh has no triangles");
  const double diagonal = bbox_diagonal(input);
  if (!(diagonal > 0.0) || !std::isfinite(diagonal)) {
    throw InputError("hausdorff: the input mesh has no extent (all vertices coincide) or is not finite");
  }
  HausdorffResult r = hausdorff_distance(input, triangulate_panels(panels), samples_per_side);
  r.input_to_panels /= diagonal;
  r.panels_to_input /= diagonal;
  r.two_sided /= diagonal;
  return r;
}

}  // namespace ff
