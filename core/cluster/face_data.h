#pragma once
// FaceData: what the clustering metric needs of each triangle, computed once per mesh in a
// local frame centred on the bounding box (so second moments do not lose precision on
// georeferenced coordinates far from the origin).
#include <Eigen/Core>
#include <array>
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff {

struct FaceData {
  Vec3 origin = Vec3::Zero();  // local frame: local = world - origin
  std::vector<double> area;
  std::vector<Vec3> centroid;  // local frame
  std::vector<Vec3> normal;    // unit, zero for zero-area faces
  // Per-unit-area spread of the triangle about its centroid, (1/12) sum_j (p_j-c)(p_j-c)^T,
  // stored as xx, yy, zz, xy, xz, yz: the exact L2 integral of a plane's squared distance is
  // area * ((N.(c-x))^2 + N^T spread N).
  std::vector<std::array<double, 6>> spread;
  // Density per face, normalised to an area-weighted mean of 1 (all 1 when none is given).
  std::vector<double> density;
  double total_area = 0.0;

  int num_faces() const { return static_cast<int>(area.size()); }
};

// Builds FaceData. `density` is empty (uniform), one value per vertex (a face gets the mean
// of its corners) or one per face; values must be finite and > 0. Throws InputError with
// the count or the first bad value otherwise.
FaceData make_face_data(const TriMesh& mesh, const std::vector<double>& density = {});

}  // namespace ff
