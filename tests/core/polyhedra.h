#pragma once
// Convex polyhedra built by hand as PanelMesh (one panel per face, counter-clockwise seen
// from outside, normals outward), for the fabrication tests' analytic cases.
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/panels/panel_mesh.h"

namespace ff::testing {

// One face per direction in `normals`: the vertices furthest along it, sorted
// counter-clockwise around it.
inline PanelMesh convex_polyhedron(const std::vector<Vec3>& vertices, const std::vector<Vec3>& normals) {
  PanelMesh pm;
  pm.vertices = vertices;
  for (const Vec3& raw : normals) {
    const Vec3 n = raw.normalized();
    double top = -1e300;
    for (const Vec3& v : vertices) top = std::max(top, n.dot(v));
    std::vector<int> face;
    Vec3 c = Vec3::Zero();
    for (size_t i = 0; i < vertices.size(); ++i)
      if (n.dot(vertices[i]) > top - 1e-9) face.push_back(static_cast<int>(i)), c += vertices[i];
    c /= static_cast<double>(face.size());
    const Vec3 u = (vertices[static_cast<size_t>(face[0])] - c).normalized(), w = n.cross(u);
    auto angle = [&](int i) {
      const Vec3 d = vertices[static_cast<size_t>(i)] - c;
      return std::atan2(d.dot(w), d.dot(u));
    };
    std::sort(face.begin(), face.end(), [&](int a, int b) { return angle(a) < angle(b); });
    pm.panels.push_back(face);
    pm.plane_normals.push_back(n);
    pm.plane_offsets.push_back(top);
  }
  pm.issues.resize(pm.panels.size());
  return pm;
}

inline PanelMesh unit_cube() {
  std::vector<Vec3> v;
  for (int i = 0; i < 8; ++i) v.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  return convex_polyhedron(
      v, {Vec3::UnitX(), -Vec3::UnitX(), Vec3::UnitY(), -Vec3::UnitY(), Vec3::UnitZ(), -Vec3::UnitZ()});
}

// Equilateral triangle (circumradius 1) extruded from z = 0 to z = 1.
inline PanelMesh triangular_prism() {
  const double pi = 3.14159265358979323846;
  std::vector<Vec3> v;
  std::vector<Vec3> n = {Vec3::UnitZ(), -Vec3::UnitZ()};
  for (int i = 0; i < 3; ++i) {
    const double a = pi / 2 + 2 * pi * i / 3;
    v.emplace_back(std::cos(a), std::sin(a), 0.0);
    v.emplace_back(std::cos(a), std::sin(a), 1.0);
    n.emplace_back(std::cos(a + pi / 3), std::sin(a + pi / 3), 0.0);
  }
  return convex_polyhedron(v, n);
}

// Regular dodecahedron: 20 vertices, faces normal to the icosahedron's vertices.
inline PanelMesh dodecahedron() {
  const double phi = (1 + std::sqrt(5.0)) / 2;
  std::vector<Vec3> v, n;
  for (int i = 0; i < 8; ++i) v.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  for (const double a : {-1.0, 1.0})
    for (const double b : {-1.0, 1.0}) {
      v.emplace_back(0, a / phi, b * phi);
      v.emplace_back(a / phi, b * phi, 0);
      v.emplace_back(a * phi, 0, b / phi);
      n.emplace_back(0, a * phi, b);
      n.emplace_back(a, 0, b * phi);
      n.emplace_back(a * phi, b, 0);
    }
  return convex_polyhedron(v, n);
}

}  // namespace ff::testing
