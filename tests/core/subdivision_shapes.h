#pragma once
// Control meshes for the subdivision tests, built by hand so their limits are known: a cube
// (quads), the octahedron and icosahedron (triangles), a pentagonal prism (mixed polygons),
// a bipyramid with a sharp equator, a planar quad grid with a boundary, a quad torus.
#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "core/mesh/poly_mesh.h"
#include "core/mesh/tri_mesh.h"
#include "synthetic_meshes.h"  // signed_volume

namespace ff::test {

constexpr double kSubdivPi = 3.14159265358979323846;

// [-1, 1]^3, faces counter-clockwise seen from outside; vertex i has coordinates
// (bit0 ? 1 : -1, bit1 ? 1 : -1, bit2 ? 1 : -1).
inline PolyMesh cube_quads() {
  PolyMesh m;
  for (int i = 0; i < 8; ++i) m.positions.emplace_back(i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0);
  for (const std::vector<int>& f : std::vector<std::vector<int>>{
           {0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}})
    m.add_face(f);
  return m;
}

inline TriMesh octahedron() {
  TriMesh m;
  m.positions = {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)};
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

inline TriMesh icosahedron() {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  TriMesh m;
  m.positions = {Vec3(-1, t, 0), Vec3(1, t, 0), Vec3(-1, -t, 0), Vec3(1, -t, 0), Vec3(0, -1, t), Vec3(0, 1, t),
                 Vec3(0, -1, -t), Vec3(0, 1, -t), Vec3(t, 0, -1), Vec3(t, 0, 1), Vec3(-t, 0, -1), Vec3(-t, 0, 1)};
  m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  return m;
}

// Two regular pentagons (z = 0 and z = 1) and five quads: 2 * 5 + 5 * 4 = 30 corners.
inline PolyMesh pentagonal_prism() {
  PolyMesh m;
  for (int z = 0; z < 2; ++z)
    for (int i = 0; i < 5; ++i)
      m.positions.emplace_back(std::cos(2 * kSubdivPi * i / 5), std::sin(2 * kSubdivPi * i / 5), z);
  m.add_face({4, 3, 2, 1, 0});
  m.add_face({5, 6, 7, 8, 9});
  for (int i = 0; i < 5; ++i) m.add_face({i, (i + 1) % 5, 5 + (i + 1) % 5, 5 + i});
  return m;
}

// A hexagon of radius 1 in z = 0 (vertices 0..5) with apexes at z = top (6) and z = -bottom
// (7): the equator is sharp, the apex edges nearly flat.
inline TriMesh hexagonal_bipyramid(double top = 0.3, double bottom = 0.6) {
  TriMesh m;
  for (int i = 0; i < 6; ++i) m.positions.emplace_back(std::cos(kSubdivPi * i / 3), std::sin(kSubdivPi * i / 3), 0.0);
  m.positions.emplace_back(0.0, 0.0, top);
  m.positions.emplace_back(0.0, 0.0, -bottom);
  for (int i = 0; i < 6; ++i) {
    m.triangles.push_back({i, (i + 1) % 6, 6});
    m.triangles.push_back({(i + 1) % 6, i, 7});
  }
  return m;
}

// nx x ny quads on the plane through `origin` spanned by u and v, inner and boundary
// vertices moved along the plane by a fixed pattern (so boundary curves are not straight).
inline PolyMesh planar_grid(int nx, int ny, const Vec3& origin, const Vec3& u, const Vec3& v) {
  PolyMesh m;
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) {
      const bool corner = (i == 0 || i == nx) && (j == 0 || j == ny);
      const double du = corner ? 0.0 : 0.2 * std::sin(1.7 * i + 2.3 * j), dv = corner ? 0.0 : 0.2 * std::cos(2.9 * i + 1.1 * j);
      m.positions.push_back(origin + (i + du) * u + (j + dv) * v);
    }
  }
  const auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) m.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return m;
}

// A torus of n x m quads (Euler characteristic 0).
inline PolyMesh quad_torus(int n, int m, double major = 3.0, double minor = 1.0) {
  PolyMesh t;
  for (int j = 0; j < m; ++j) {
    for (int i = 0; i < n; ++i) {
      const double a = 2 * kSubdivPi * i / n, b = 2 * kSubdivPi * j / m;
      t.positions.emplace_back((major + minor * std::cos(b)) * std::cos(a), (major + minor * std::cos(b)) * std::sin(a),
                               minor * std::sin(b));
    }
  }
  const auto id = [&](int i, int j) { return (j % m) * n + i % n; };
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) t.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return t;
}

}  // namespace ff::test
