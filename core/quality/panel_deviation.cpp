#include "core/quality/panel_deviation.h"

#include <cmath>
#include <string>

#include "core/quality/closest_point.h"
#include "core/quality/hausdorff.h"
#include "core/util/error.h"
#include "core/util/random.h"

namespace ff {

namespace {

struct Sample {
  Vec3 point;
  int triangle;  // the triangle it lies on
};

// Every referenced vertex once (on the first triangle that refers to it), every centroid, and
// about `target` more points spread by area (each triangle gets the integer part of its share
// and one more with the probability of the rest).
std::vector<Sample> samples_by_triangle(const TriMesh& mesh, int target, std::uint64_t seed) {
  std::vector<Sample> out;
  std::vector<char> seen(mesh.positions.size(), 0);
  for (int f = 0; f < mesh.num_faces(); ++f) {
    for (int v : mesh.triangles[static_cast<size_t>(f)]) {
      if (seen[static_cast<size_t>(v)]) continue;
      seen[static_cast<size_t>(v)] = 1;
      out.push_back({mesh.positions[static_cast<size_t>(v)], f});
    }
  }
  const double total = total_area(mesh);
  SplitMix64 rng(seed);
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const Triangle& t = mesh.triangles[static_cast<size_t>(f)];
    const Vec3& a = mesh.positions[static_cast<size_t>(t[0])];
    const Vec3& b = mesh.positions[static_cast<size_t>(t[1])];
    const Vec3& c = mesh.positions[static_cast<size_t>(t[2])];
    out.push_back({(a + b + c) / 3.0, f});
    const double share = total > 0.0 ? target * face_area(mesh, f) / total : 0.0;
    const int k = static_cast<int>(std::floor(share + rng.uniform()));
    for (int i = 0; i < k; ++i) {
      const double s = std::sqrt(rng.uniform()), r = rng.uniform();
      out.push_back({(1.0 - s) * a + s * (1.0 - r) * b + s * r * c, f});
    }
  }
  return out;
}

// deviation[panel_of(triangle)] = max(..., distance of its samples to `target`); a query may
// stop at any triangle within the panel's maximum so far.
template <typename PanelOf>
void raise_by(const std::vector<Sample>& samples, const TriangleTree& target, PanelOf panel_of,
              std::vector<double>& deviation) {
  std::vector<Vec3> points;
  points.reserve(samples.size());
  for (const Sample& s : samples) points.push_back(s.point);
  int hint = -1;
  for (const int i : morton_order(points)) {  // near one another: the last answer is a good hint
    const Sample& s = samples[static_cast<size_t>(i)];
    const int panel = panel_of(s.triangle);
    if (panel < 0) continue;
    double& d = deviation[static_cast<size_t>(panel)];
    const ClosestPoint c = target.closest_point(s.point, hint, d);
    hint = c.triangle;
    if (c.distance > d) d = c.distance;
  }
}

}  // namespace

std::vector<double> panel_deviation(const TriMesh& input, const PanelMesh& panels, int samples_per_side) {
  if (samples_per_side < 0) throw InputError("panel deviation: the number of samples must not be negative");
  if (input.num_faces() == 0) throw InputError("panel deviation: the input mesh has no triangles");
  const double diagonal = bbox_diagonal(input);
  if (!(diagonal > 0.0) || !std::isfinite(diagonal))
    throw InputError("panel deviation: the input mesh has no extent (all vertices coincide) or is not finite");
  const size_t n = static_cast<size_t>(panels.num_panels());
  if (!panels.face_panel.empty() && panels.face_panel.size() != static_cast<size_t>(input.num_faces())) {
    throw InputError("panel deviation: the panels name a panel for " + std::to_string(panels.face_panel.size()) +
                     " triangles, the input has " + std::to_string(input.num_faces()));
  }
  std::vector<double> deviation(n, 0.0);
  std::vector<int> triangle_panel;
  const TriMesh surface = triangulate_panels(panels, &triangle_panel);
  if (surface.num_faces() == 0) return deviation;
  // Fixed seeds: the same design always gives the same colours.
  raise_by(
      samples_by_triangle(surface, samples_per_side, 0x50616E656C446576ULL), TriangleTree(input),
      [&](int t) { return triangle_panel[static_cast<size_t>(t)]; }, deviation);
  if (!panels.face_panel.empty()) {
    raise_by(
        samples_by_triangle(input, samples_per_side, 0x496E707574446576ULL), TriangleTree(surface),
        [&](int f) {
          const int p = panels.face_panel[static_cast<size_t>(f)];
          return p >= 0 && static_cast<size_t>(p) < n ? p : -1;
        },
        deviation);
  }
  for (double& d : deviation) d /= diagonal;
  return deviation;
}

}  // namespace ff
