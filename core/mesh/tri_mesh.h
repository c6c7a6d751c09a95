#pragma once
// TriMesh: the triangle soup every algorithm reads. Positions and index triples only;
// adjacency lives in MeshTopology (topology.h); the per-face data the clustering reads is
// built by make_face_data() (cluster/face_data.h).
#include <Eigen/Core>
#include <array>
#include <vector>

namespace ff {

using Vec3 = Eigen::Vector3d;
using Triangle = std::array<int, 3>;

struct TriMesh {
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;

  int num_vertices() const { return static_cast<int>(positions.size()); }
  int num_faces() const { return static_cast<int>(triangles.size()); }
};

// Per-face area, unit normal (zero for zero-area faces) and centroid.
double face_area(const TriMesh& mesh, int face);
Vec3 face_normal(const TriMesh& mesh, int face);
Vec3 face_centroid(const TriMesh& mesh, int face);

struct BoundingBox {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Zero();
};
// Of all positions (a zero box for an empty mesh).
BoundingBox bounding_box(const TriMesh& mesh);
// Its diagonal's length: the unit of the Hausdorff distance in the report.
double bbox_diagonal(const TriMesh& mesh);
double total_area(const TriMesh& mesh);

}  // namespace ff
