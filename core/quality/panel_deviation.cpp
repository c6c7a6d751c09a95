#include "core/quality/panel_deviation.h"

#include <cmath>
#include <string>

#include "core/quality/closest_point.h"
#include "core/quality/hausdorff.h"
#include "core/util/error.h"

namespace ff {

namespace {

// deviation[panel_of(triangle of the sample)] = max(..., distance of the sample to `target`),
// over sample_surface's samples of `mesh`; a query may stop at any triangle within the panel's
// maximum so far.
template <typename PanelOf>
void raise_by(const TriMesh& mesh, int samples, std::uint64_t seed, const TriangleTree& target, PanelOf panel_of,
              std::vector<double>& deviation) {
  std::vector<int> triangle;
  const std::vector<Vec3> points = sample_surface(mesh, samples, seed, &triangle);
  int hint = -1;
  for (const int i : morton_order(points)) {  // near one another: the last answer is a good hint
    const int panel = panel_of(triangle[static_cast<size_t>(i)]);
    if (panel < 0) continue;
    double& d = deviation[static_cast<size_t>(panel)];
    const ClosestPoint c = target.closest_point(points[static_cast<size_t>(i)], hint, d);
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
      surface, samples_per_side, 0x50616E656C446576ULL, TriangleTree(input),
      [&](int t) { return triangle_panel[static_cast<size_t>(t)]; }, deviation);
  if (!panels.face_panel.empty()) {
    raise_by(
        input, samples_per_side, 0x496E707574446576ULL, TriangleTree(surface),
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
