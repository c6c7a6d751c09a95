#include "core/mesh/curvature.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace ff {

std::vector<Vec3> vertex_normals(const TriMesh& mesh, const MeshTopology& topology) {
  std::vector<Vec3> normals(mesh.positions.size(), Vec3::Zero());
  const size_t num_vertices = std::min(mesh.positions.size(), topology.vertex_face_offsets.size() - 1);
  for (size_t v = 0; v < num_vertices; ++v) {
    Vec3 sum = Vec3::Zero();
    for (int i = topology.vertex_face_offsets[v]; i < topology.vertex_face_offsets[v + 1]; ++i) {
      const Triangle& t = mesh.triangles[static_cast<size_t>(topology.vertex_faces[static_cast<size_t>(i)])];
      const Vec3& a = mesh.positions[static_cast<size_t>(t[0])];
      sum += (mesh.positions[static_cast<size_t>(t[1])] - a).cross(mesh.positions[static_cast<size_t>(t[2])] - a);
    }
    const double len = sum.norm();
    if (len > 0.0 && std::isfinite(len)) normals[v] = sum / len;
  }
  return normals;
}

namespace {

// Any unit vector orthogonal to unit n.
Vec3 any_tangent(const Vec3& n) {
  const Vec3 axis = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return n.cross(axis).normalized();
}

}  // namespace

VertexCurvature vertex_curvature(const TriMesh& mesh, const MeshTopology& topology) {
  const size_t n = mesh.positions.size();
  VertexCurvature out;
  out.normal = vertex_normals(mesh, topology);
  out.k1.assign(n, 0.0);
  out.k2.assign(n, 0.0);
  out.dir1.assign(n, Vec3::UnitX());
  out.dir2.assign(n, Vec3::UnitY());
  const size_t num_vertices = std::min(n, topology.vertex_face_offsets.size() - 1);
  // Ring collection with a stamp per vertex (no clearing, deterministic order).
  std::vector<int> stamp(n, -1);
  std::vector<int> ring;
  const auto add_one_ring = [&](int v, int mark) {
    const size_t vv = static_cast<size_t>(v);
    for (int i = topology.vertex_face_offsets[vv]; i < topology.vertex_face_offsets[vv + 1]; ++i) {
      const Triangle& t = mesh.triangles[static_cast<size_t>(topology.vertex_faces[static_cast<size_t>(i)])];
      for (int q : t) {
        if (stamp[static_cast<size_t>(q)] == mark) continue;
        stamp[static_cast<size_t>(q)] = mark;
        ring.push_back(q);
      }
    }
  };
  for (size_t v = 0; v < num_vertices; ++v) {
    const Vec3& nv = out.normal[v];
    if (nv.squaredNorm() == 0.0) continue;
    const Vec3 t1 = any_tangent(nv), t2 = nv.cross(t1);
    out.dir1[v] = t1;
    out.dir2[v] = t2;
    ring.clear();
    const int mark = static_cast<int>(v);
    stamp[v] = mark;
    add_one_ring(static_cast<int>(v), mark);
    const size_t first_ring = ring.size();
    for (size_t i = 0; i < first_ring; ++i) add_one_ring(ring[i], mark);
    if (ring.size() < 3) continue;
    // Least squares on scaled coordinates (by the ring's mean distance) for conditioning.
    const Vec3& p = mesh.positions[v];
    double scale = 0.0;
    for (int q : ring) scale += (mesh.positions[static_cast<size_t>(q)] - p).norm();
    scale /= static_cast<double>(ring.size());
    if (!(scale > 0.0) || !std::isfinite(scale)) continue;
    // Normal equations of the fit (5x5, or 3x3 without the linear terms on tiny rings).
    const bool linear = ring.size() >= 5;
    Eigen::Matrix<double, 5, 5> ata = Eigen::Matrix<double, 5, 5>::Zero();
    Eigen::Matrix<double, 5, 1> atb = Eigen::Matrix<double, 5, 1>::Zero();
    for (int q : ring) {
      if (q == static_cast<int>(v)) continue;
      const Vec3 d = (mesh.positions[static_cast<size_t>(q)] - p) / scale;
      const double a = d.dot(t1), b = d.dot(t2);
      Eigen::Matrix<double, 5, 1> row;
      row << a * a, a * b, b * b, a, b;
      ata += row * row.transpose();
      atb += row * d.dot(nv);
    }
    if (!linear) {  // unknowns 3 and 4 pinned to 0
      ata.bottomRows<2>().setZero();
      ata.rightCols<2>().setZero();
      ata(3, 3) = ata(4, 4) = 1.0;
      atb(3) = atb(4) = 0.0;
    }
    const Eigen::Matrix<double, 5, 1> c = ata.ldlt().solve(atb);
    if (!c.allFinite()) continue;
    const double fa = c(3), fb = c(4);
    Eigen::Matrix2d first, second;
    first << 1.0 + fa * fa, fa * fb, fa * fb, 1.0 + fb * fb;
    // Bending away from the normal is positive: minus the Hessian, back in world units.
    const double g = -1.0 / (scale * std::sqrt(1.0 + fa * fa + fb * fb));
    second << 2.0 * c(0) * g, c(1) * g, c(1) * g, 2.0 * c(2) * g;
    // Shape operator S = first^-1 second: real eigenvalues (a symmetric pencil), closed form.
    const Eigen::Matrix2d S = first.inverse() * second;
    const double half_trace = 0.5 * (S(0, 0) + S(1, 1));
    const double det = S(0, 0) * S(1, 1) - S(0, 1) * S(1, 0);
    const double root = std::sqrt(std::max(0.0, half_trace * half_trace - det));
    const Eigen::Vector2d k(half_trace - root, half_trace + root);  // ascending
    // Eigenvector of S for k(1) in parameter coordinates; the other is first-orthogonal to it.
    Eigen::Vector2d e1(S(0, 1), k(1) - S(0, 0));
    const Eigen::Vector2d alt(k(1) - S(1, 1), S(1, 0));
    if (alt.squaredNorm() > e1.squaredNorm()) e1 = alt;
    if (!(e1.squaredNorm() > 1e-30 * (1.0 + S.squaredNorm()))) e1 = Eigen::Vector2d(1.0, 0.0);  // umbilic
    const Eigen::Vector2d fe1 = first * e1;
    const Eigen::Vector2d e2(-fe1(1), fe1(0));
    const auto tangent = [&](const Eigen::Vector2d& e) {
      const double alpha = e(0), beta = e(1);
      const Vec3 t = alpha * t1 + beta * t2 + (alpha * fa + beta * fb) * nv;
      const Vec3 proj = t - t.dot(nv) * nv;  // report directions in the vertex tangent plane
      return proj.norm() > 0.0 ? Vec3(proj.normalized()) : t1;
    };
    out.k1[v] = k(1);
    out.k2[v] = k(0);
    out.dir1[v] = tangent(e1);
    out.dir2[v] = tangent(e2);
  }
  return out;
}

}  // namespace ff
