#include "core/shapes/shapes.h"

#include <algorithm>
#include <cmath>

#include "core/util/angles.h"

namespace ff {

TriMesh make_grid_surface(int nu, int nv, const std::function<Vec3(double, double)>& map, bool wrap_u, bool wrap_v) {
  TriMesh mesh;
  const int cols = wrap_u ? nu : nu + 1;
  const int rows = wrap_v ? nv : nv + 1;
  mesh.positions.reserve(static_cast<size_t>(cols) * static_cast<size_t>(rows));
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < cols; ++i)
      mesh.positions.push_back(map(static_cast<double>(i) / nu, static_cast<double>(j) / nv));
  }
  const auto id = [&](int i, int j) { return (j % rows) * cols + (i % cols); };
  mesh.triangles.reserve(2 * static_cast<size_t>(nu) * static_cast<size_t>(nv));
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      add_split_quad(mesh, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1), (i + j) % 2 == 0);
    }
  }
  return mesh;
}

void add_split_quad(TriMesh& mesh, int a, int b, int c, int d, bool along_ac) {
  if (along_ac) {
    mesh.triangles.push_back({a, b, c});
    mesh.triangles.push_back({a, c, d});
  } else {
    mesh.triangles.push_back({a, b, d});
    mesh.triangles.push_back({b, c, d});
  }
}

TriMesh make_plane(int nu, int nv, double width, double height) {
  return make_grid_surface(nu, nv, [&](double u, double v) { return Vec3(u * width, v * height, 0.0); });
}

TriMesh make_roof(int nu, int nv) {
  return make_grid_surface(nu, nv, [](double u, double v) {
    const double x = 40.0 * u, y = 25.0 * v;
    const double z = 6.0 * std::sin(kPi * u) * std::sin(kPi * v) + 2.0 * std::sin(3.0 * kPi * u) * v * v +
                     1.5 * std::cos(2.0 * kPi * v) * u;
    return Vec3(x, y, z);
  });
}

int grid_resolution_for(int triangles) {
  return std::max(1, static_cast<int>(std::lround(std::sqrt(triangles / 2.0))));
}

}  // namespace ff
