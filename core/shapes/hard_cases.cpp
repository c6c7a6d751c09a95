// The list of hard cases for tests and benchmarks to loop over, and the grid sizing they share.
#include "core/shapes/hard_cases.h"

#include <algorithm>
#include <cmath>

namespace ff {

namespace {

int round_to_multiple(double x, int multiple) {
  const int m = std::max(1, multiple);
  return m * std::max(1, static_cast<int>(std::lround(x / m)));
}

}  // namespace

std::array<int, 2> grid_dims_for(int triangles, double length_u, double length_v, int multiple_u, int multiple_v) {
  const double cells = std::max(1.0, triangles / 2.0);
  const double aspect = (length_u > 0.0 && length_v > 0.0) ? length_u / length_v : 1.0;
  const int nu = round_to_multiple(std::sqrt(cells * aspect), multiple_u);
  // The second count from the first, so the product tracks the request after rounding.
  const int nv = round_to_multiple(cells / nu, multiple_v);
  return {nu, nv};
}

std::vector<NamedShape> hard_cases(int triangles) {
  // Disks: Euler 1, one loop. Annulus: Euler 0, two loops. Torus: Euler 0, no loop.
  std::vector<NamedShape> shapes;
  shapes.push_back({"saddle", make_saddle(triangles), 1, 1});
  shapes.push_back({"helicoid", make_helicoid(triangles), 1, 1});
  shapes.push_back({"twisted_strip", make_twisted_strip(triangles), 1, 1});
  shapes.push_back({"bump", make_bump(triangles), 1, 1});
  shapes.push_back({"torus", make_torus(triangles), 0, 0});
  shapes.push_back({"groin_vault", make_groin_vault(triangles), 1, 1});
  shapes.push_back({"roof_with_hole", make_roof_with_hole(triangles), 2, 0});
  shapes.push_back({"barrel_vault", make_barrel_vault(triangles), 1, 1});
  shapes.push_back({"monkey_saddle", make_monkey_saddle(triangles), 1, 1});
  shapes.push_back({"cone", make_cone(triangles), 1, 1});
  return shapes;
}

}  // namespace ff
