#pragma once
// FaceData: what the clustering metric needs of each triangle, computed once per mesh in a
// local frame: centred on the bounding box and scaled to its size. Second moments then keep
// their precision on georeferenced coordinates far from the origin, and neither overflow
// (sizes ~1e80 and up) nor underflow (~1e-80) whatever units the file uses. Clustering is
// invariant under this similarity, so nothing else changes.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff {

// One face's record, laid out together (two cache lines) because flooding reads all of it
// for faces in no particular order: one miss instead of five.
struct alignas(64) FaceRecord {
  // First cache line: everything the euclidean and L2,1 terms read.
  Vec3 normal = Vec3::Zero();  // unit, zero for zero-area faces
  double area = 0.0;
  // Normalised to an area-weighted mean of 1 over the mesh (1 everywhere when none is given).
  double density = 1.0;
  Vec3 centroid = Vec3::Zero();  // local frame
  // Second line, read by the L2 term only: the per-unit-area spread of the triangle about
  // its centroid, (1/12) sum_j (p_j-c)(p_j-c)^T, stored as xx, yy, zz, xy, xz, yz; the exact
  // L2 integral of a plane's squared distance is area * ((N.(c-x))^2 + N^T spread N).
  std::array<double, 6> spread{};
};
static_assert(sizeof(FaceRecord) == 128, "a face record is two cache lines");

struct FaceData {
  // Local frame: local = (world - origin) / scale.
  Vec3 origin = Vec3::Zero();
  double scale = 1.0;
  std::vector<FaceRecord> records;
  double total_area = 0.0;  // local frame
  // Anisotropy (density/anisotropy.h): empty, or per face e_f with the euclidean term
  // measured by I - e_f e_f^T (|e_f| < 1). Unitless, so the local frame does not change it.
  std::vector<Vec3> stretch;

  Vec3 to_world(const Vec3& local) const { return origin + scale * local; }
  // Local areas (and the energies, which are areas) times this are world areas.
  double area_to_world() const { return scale * scale; }

  int num_faces() const { return static_cast<int>(records.size()); }
  const FaceRecord& operator[](size_t face) const { return records[face]; }
};

// Positive densities shifted by one power of two so that the largest lies in [0.5, 1): the
// same ratios exactly (only ratios matter: make_face_data normalises the mean to 1), in a
// range where sums and products of a few of them neither overflow nor underflow.
std::vector<double> density_ratios(const std::vector<double>& values);

// Builds FaceData. `density` is empty (uniform), one value per vertex (a face gets the mean
// of its corners) or one per face; values must be finite and > 0. Throws InputError with
// the count or the first bad value otherwise.
FaceData make_face_data(const TriMesh& mesh, const std::vector<double>& density = {});

}  // namespace ff
