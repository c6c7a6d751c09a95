// Roof with a courtyard: a square roof with a round hole in its middle, meshed as an
// annulus. Each grid column is a ray from the centre, running from the hole's circle out to
// the square; the square is walked at even speed with its corners on grid columns, so both
// boundaries are clean polygons and the seam closes through the index grid.
#include <cmath>

#include "core/shapes/hard_cases.h"
#include "core/shapes/shapes.h"
#include "core/util/angles.h"
#include "core/util/error.h"

namespace ff {

namespace {

// The square [-half, half]^2 walked counter-clockwise from (half, 0) at even speed for q in
// [0, 8): corners at q = 1, 3, 5, 7.
Eigen::Vector2d square_point(double q, double half) {
  if (q < 1.0) return {half, q * half};
  if (q < 3.0) return {(2.0 - q) * half, half};
  if (q < 5.0) return {-half, (4.0 - q) * half};
  if (q < 7.0) return {(q - 6.0) * half, -half};
  return {half, (q - 8.0) * half};
}

}  // namespace

TriMesh make_roof_with_hole(int triangles, double size, double hole_radius, double rise) {
  const double half = size / 2.0;
  if (!(hole_radius > 0.0) || !(hole_radius < half))
    throw InputError("roof with hole: need 0 < hole radius < size / 2");
  // Cells about square: radial depth (between the sides' and the corners') vs the mean of
  // the two boundaries' lengths. A multiple of 8 around puts the corners on grid columns.
  const double depth = (half * (1.0 + std::sqrt(2.0))) / 2.0 - hole_radius;
  const double around = (2.0 * kPi * hole_radius + 8.0 * half) / 2.0;
  const auto [n_radial, n_around] = grid_dims_for(triangles, depth, around, 1, 8);
  // u = radial, v = around (counter-clockwise): d/du x d/dv points up.
  return make_grid_surface(
      n_radial, n_around,
      [&](double u, double v) {
        const Eigen::Vector2d outer = square_point(8.0 * v, half);
        const Eigen::Vector2d inner = hole_radius * outer.normalized();
        const Eigen::Vector2d p = (1.0 - u) * inner + u * outer;
        // A gently domed roof, a little skewed, falling to the eaves (height field: normals up).
        const double xi = p.x() / half, eta = p.y() / half;
        const double z = rise * (1.0 - 0.6 * xi * xi - 0.4 * eta * eta + 0.15 * xi * eta);
        return Vec3(p.x(), p.y(), z);
      },
      false, true);
}

}  // namespace ff
