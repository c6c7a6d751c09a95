#pragma once
// Small synthetic meshes with known topology, shared by the core tests.
#include <Eigen/Geometry>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "core/mesh/topology.h"
#include "core/mesh/tri_mesh.h"
#include "core/util/angles.h"

namespace ff::test {

// Appends `part`, moved by `shift`, to `mesh` as a separate component.
inline void append_shifted(TriMesh& mesh, const TriMesh& part, const Vec3& shift) {
  const int offset = static_cast<int>(mesh.positions.size());
  for (const Vec3& v : part.positions) mesh.positions.push_back(v + shift);
  for (const Triangle& t : part.triangles) mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
}

// Regular tetrahedron, outward (positive signed volume).
inline TriMesh tetrahedron() {
  TriMesh m;
  m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

// nx x ny squares in the xy plane, two triangles each, normals +z. Vertex (i, j) is
// j * (nx + 1) + i.
inline TriMesh grid(int nx, int ny) {
  TriMesh m;
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) m.positions.emplace_back(i, j, 0.0);
  }
  const auto id = [nx](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return m;
}

// Flat ring between radii 1 and 2, `segments` around and `rings` across, normals +z.
inline TriMesh annulus(int segments, int rings) {
  TriMesh m;
  for (int r = 0; r <= rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const double radius = 1.0 + static_cast<double>(r) / rings;
      const double a = 2.0 * kPi * s / segments;
      m.positions.emplace_back(radius * std::cos(a), radius * std::sin(a), 0.0);
    }
  }
  const auto id = [segments](int s, int r) { return r * segments + s % segments; };
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      m.triangles.push_back({id(s, r), id(s + 1, r + 1), id(s + 1, r)});
      m.triangles.push_back({id(s, r), id(s, r + 1), id(s + 1, r + 1)});
    }
  }
  return m;
}

// Torus with nu x nv quads (major radius 3, minor 1), outward.
inline TriMesh torus(int nu, int nv) {
  TriMesh m;
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      const double u = 2.0 * kPi * i / nu, v = 2.0 * kPi * j / nv;
      m.positions.emplace_back((3.0 + std::cos(v)) * std::cos(u), (3.0 + std::cos(v)) * std::sin(u), std::sin(v));
    }
  }
  const auto id = [nu, nv](int i, int j) { return (j % nv) * nu + i % nu; };
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return m;
}

// An open tube along z (radius `radius`, from z = 0 to `length`), `segments` around and
// `rings` along, normals outward. Vertex (s, r) is r * segments + s % segments.
inline TriMesh tube(int segments, int rings, double radius, double length) {
  TriMesh m;
  for (int r = 0; r <= rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const double a = 2.0 * kPi * s / segments;
      m.positions.emplace_back(radius * std::cos(a), radius * std::sin(a), length * r / rings);
    }
  }
  const auto id = [segments](int s, int r) { return r * segments + s % segments; };
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      m.triangles.push_back({id(s, r), id(s + 1, r), id(s + 1, r + 1)});
      m.triangles.push_back({id(s, r), id(s + 1, r + 1), id(s, r + 1)});
    }
  }
  return m;
}

// A unit cube as an STL-like soup: 12 triangles with 3 vertices of their own each,
// outward.
inline TriMesh cube_soup() {
  const Vec3 c[8] = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0),
                     Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0, 1, 1)};
  const int quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  TriMesh m;
  for (const auto& q : quads) {
    for (const auto& tri : {std::array<int, 3>{q[0], q[1], q[2]}, {q[0], q[2], q[3]}}) {
      const int base = m.num_vertices();
      for (int k : tri) m.positions.push_back(c[k]);
      m.triangles.push_back({base, base + 1, base + 2});
    }
  }
  return m;
}

// Moebius strip: `segments` quads along a half-twisted band.
inline TriMesh moebius(int segments) {
  TriMesh m;
  for (int s = 0; s < segments; ++s) {
    const double u = 2.0 * kPi * s / segments;
    for (double w : {-0.3, 0.3}) {
      m.positions.emplace_back((2.0 + w * std::cos(u / 2)) * std::cos(u), (2.0 + w * std::cos(u / 2)) * std::sin(u),
                               w * std::sin(u / 2));
    }
  }
  for (int s = 0; s < segments; ++s) {
    const int a = 2 * s, b = 2 * s + 1;
    // Closing the band swaps the two sides: the half twist.
    const int c = s + 1 < segments ? 2 * s + 2 : 1, d = s + 1 < segments ? 2 * s + 3 : 0;
    m.triangles.push_back({a, c, d});
    m.triangles.push_back({a, d, b});
  }
  return m;
}

inline double signed_volume(const TriMesh& m) {
  double v = 0.0;
  for (const Triangle& t : m.triangles) {
    v += m.positions[static_cast<size_t>(t[0])].dot(
        m.positions[static_cast<size_t>(t[1])].cross(m.positions[static_cast<size_t>(t[2])]));
  }
  return v / 6.0;
}

// The half-edge from a to b appears in face f.
inline bool face_has_directed_edge(const TriMesh& m, int f, int a, int b) {
  const Triangle& t = m.triangles[static_cast<size_t>(f)];
  for (size_t i = 0; i < 3; ++i) {
    if (t[i] == a && t[(i + 1) % 3] == b) return true;
  }
  return false;
}

// Every directed edge used at most once: faces agree on the orientation of each shared edge.
inline bool consistently_oriented(const TriMesh& m) {
  std::set<std::pair<int, int>> directed;
  for (const Triangle& t : m.triangles)
    for (size_t i = 0; i < 3; ++i)
      if (!directed.insert({t[i], t[(i + 1) % 3]}).second) return false;
  return true;
}

// Every interior edge is run in opposite directions by its two faces.
inline bool consistently_oriented(const TriMesh& m, const MeshTopology& topo) {
  for (int e = 0; e < topo.num_edges(); ++e) {
    if (topo.is_boundary_edge(e)) continue;
    const auto& ev = topo.edge_vertices[static_cast<size_t>(e)];
    const auto& ef = topo.edge_faces[static_cast<size_t>(e)];
    const bool first_forward = face_has_directed_edge(m, ef[0], ev[0], ev[1]);
    const bool second_forward = face_has_directed_edge(m, ef[1], ev[0], ev[1]);
    if (first_forward == second_forward) return false;
  }
  return true;
}

}  // namespace ff::test
