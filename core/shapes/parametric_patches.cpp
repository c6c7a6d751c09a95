// The hard cases that are one map of a rectangle (make_grid_surface): saddle, helicoid,
// twisted strip, bump, torus, barrel vault, monkey saddle, cone (smooth but at its apex).
// The parameter directions are picked so d/du x d/dv, hence the face normals, points up
// (outward for the torus).
#include <algorithm>
#include <cmath>
#include <string>

#include "core/shapes/hard_cases.h"
#include "core/shapes/shapes.h"
#include "core/util/angles.h"
#include "core/util/error.h"

namespace ff {

namespace {

void require(bool ok, const std::string& message) {
  if (!ok) throw InputError(message);
}

// A height field z = height(x, y) over the square [-size/2, size/2]^2, u along x and v along
// y (so the normals point up). Even counts put a vertex on the middle (x, y) = (0, 0).
template <typename Height>
TriMesh height_field_on_square(int triangles, double size, const Height& height) {
  const double half = size / 2.0;
  const auto [nu, nv] = grid_dims_for(triangles, size, size, 2, 2);
  return make_grid_surface(nu, nv, [&](double u, double v) {
    const double x = (2.0 * u - 1.0) * half, y = (2.0 * v - 1.0) * half;
    return Vec3(x, y, height(x, y));
  });
}

}  // namespace

TriMesh make_saddle(int triangles, double size, double rise) {
  require(size > 0.0, "saddle: the size must be positive");
  const double half = size / 2.0;
  return height_field_on_square(triangles, size,
                                [&](double x, double y) { return rise * (x * x - y * y) / (half * half); });
}

TriMesh make_helicoid(int triangles, double inner_radius, double outer_radius, double turns, double rise_per_turn) {
  require(inner_radius > 0.0 && outer_radius > inner_radius,
          "helicoid: need 0 < inner radius < outer radius (a band off the axis)");
  require(turns > 0.0, "helicoid: the number of turns must be positive");
  const double sweep = 2.0 * kPi * turns;
  const double pitch = rise_per_turn / (2.0 * kPi);
  // Cells about square: across the band vs along its middle helix.
  const double mid = (inner_radius + outer_radius) / 2.0;
  const double along = sweep * std::hypot(mid, pitch);
  const auto [nu, nv] = grid_dims_for(triangles, outer_radius - inner_radius, along);
  // u = radius, v = angle: d/dr x d/dt = (p sin t, -p cos t, r) points up.
  return make_grid_surface(nu, nv, [&](double u, double v) {
    const double r = inner_radius + u * (outer_radius - inner_radius);
    const double t = v * sweep;
    return Vec3(r * std::cos(t), r * std::sin(t), pitch * t);
  });
}

TriMesh make_twisted_strip(int triangles, double length, double width, double twist) {
  require(length > 0.0 && width > 0.0, "twisted strip: length and width must be positive");
  const auto [nu, nv] = grid_dims_for(triangles, length, width, 1, 2);
  // u along x, v across: the normal is (-t twist/length, -sin phi, cos phi), up while |phi| < pi/2.
  return make_grid_surface(nu, nv, [&](double u, double v) {
    const double phi = (u - 0.5) * twist;
    const double t = (v - 0.5) * width;
    return Vec3((u - 0.5) * length, t * std::cos(phi), t * std::sin(phi));
  });
}

TriMesh make_bump(int triangles, double size, double height, double sigma) {
  require(size > 0.0 && sigma > 0.0, "bump: size and sigma must be positive");
  return height_field_on_square(
      triangles, size, [&](double x, double y) { return height * std::exp(-(x * x + y * y) / (2.0 * sigma * sigma)); });
}

TriMesh make_monkey_saddle(int triangles, double size, double rise) {
  require(size > 0.0, "monkey saddle: the size must be positive");
  const double half = size / 2.0;
  return height_field_on_square(
      triangles, size, [&](double x, double y) { return rise * x * (x * x - 3.0 * y * y) / (half * half * half); });
}

TriMesh make_cone(int triangles, double size, double rise) {
  require(size > 0.0, "cone: the size must be positive");
  const double half = size / 2.0;
  return height_field_on_square(triangles, size,
                                [&](double x, double y) { return rise * (1.0 - std::hypot(x, y) / half); });
}

TriMesh make_torus(int triangles, double major_radius, double minor_radius) {
  require(minor_radius > 0.0 && major_radius > minor_radius, "torus: need 0 < minor radius < major radius");
  const auto [nu, nv] = grid_dims_for(triangles, 2.0 * kPi * major_radius, 2.0 * kPi * minor_radius, 2, 2);
  // Both directions wrap in the index grid, so the seams are exact; at least 3 around each
  // circle keeps it a manifold.
  const int around = std::max(nu, 4), tube = std::max(nv, 4);
  return make_grid_surface(
      around, tube,
      [&](double u, double v) {
        const double a = 2.0 * kPi * u, b = 2.0 * kPi * v;
        const double ring = major_radius + minor_radius * std::cos(b);
        return Vec3(ring * std::cos(a), ring * std::sin(a), minor_radius * std::sin(b));
      },
      true, true);
}

TriMesh make_barrel_vault(int triangles, double length, double span, double rise) {
  const double half = span / 2.0;
  require(length > 0.0 && span > 0.0, "barrel vault: length and span must be positive");
  require(rise > 0.0 && rise <= half, "barrel vault: need 0 < rise <= span / 2");
  // The arc through (+-half, 0) and (0, rise): radius and half opening angle.
  const double radius = (half * half + rise * rise) / (2.0 * rise);
  const double opening = 2.0 * std::atan(rise / half);
  const auto [nu, nv] = grid_dims_for(triangles, length, 2.0 * opening * radius, 1, 2);
  // u along x, v across the arc: the normal (0, sin a, cos a) points away from the axis.
  return make_grid_surface(nu, nv, [&](double u, double v) {
    const double a = (2.0 * v - 1.0) * opening;
    return Vec3((u - 0.5) * length, radius * std::sin(a), radius * std::cos(a) - (radius - rise));
  });
}

}  // namespace ff
