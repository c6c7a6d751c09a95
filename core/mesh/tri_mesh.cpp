#include "core/mesh/tri_mesh.h"

#include <Eigen/Geometry>

namespace ff {

namespace {
Vec3 cross_of(const TriMesh& mesh, int face) {
  const Triangle& t = mesh.triangles[static_cast<size_t>(face)];
  const Vec3& a = mesh.positions[static_cast<size_t>(t[0])];
  const Vec3& b = mesh.positions[static_cast<size_t>(t[1])];
  const Vec3& c = mesh.positions[static_cast<size_t>(t[2])];
  return (b - a).cross(c - a);
}
}  // namespace

double face_area(const TriMesh& mesh, int face) { return 0.5 * cross_of(mesh, face).norm(); }

Vec3 face_normal(const TriMesh& mesh, int face) {
  const Vec3 n = cross_of(mesh, face);
  const double len = n.norm();
  return len > 0.0 ? Vec3(n / len) : Vec3::Zero();
}

Vec3 face_centroid(const TriMesh& mesh, int face) {
  const Triangle& t = mesh.triangles[static_cast<size_t>(face)];
  return (mesh.positions[static_cast<size_t>(t[0])] + mesh.positions[static_cast<size_t>(t[1])] +
          mesh.positions[static_cast<size_t>(t[2])]) /
         3.0;
}

BoundingBox bounding_box(const TriMesh& mesh) {
  if (mesh.positions.empty()) return {};
  BoundingBox box{mesh.positions.front(), mesh.positions.front()};
  for (const Vec3& p : mesh.positions) {
    box.lo = box.lo.cwiseMin(p);
    box.hi = box.hi.cwiseMax(p);
  }
  return box;
}

double bbox_diagonal(const TriMesh& mesh) {
  const BoundingBox box = bounding_box(mesh);
  return (box.hi - box.lo).norm();
}

double total_area(const TriMesh& mesh) {
  double sum = 0.0;
  for (int f = 0; f < mesh.num_faces(); ++f) sum += face_area(mesh, f);
  return sum;
}

}  // namespace ff
