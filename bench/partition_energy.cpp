#include "bench/partition_energy.h"

#include <algorithm>

namespace ff::bench {

double l21_energy(const TriMesh& mesh, const std::vector<int>& labels, int n) {
  if (labels.size() != mesh.triangles.size()) return -1.0;
  std::vector<Vec3> sum(static_cast<size_t>(n), Vec3::Zero());
  std::vector<int> count(static_cast<size_t>(n), 0);
  for (size_t f = 0; f < labels.size(); ++f) {
    const int l = labels[f];
    if (l < 0 || l >= n) return -1.0;
    sum[static_cast<size_t>(l)] += face_area(mesh, static_cast<int>(f)) * face_normal(mesh, static_cast<int>(f));
    ++count[static_cast<size_t>(l)];
  }
  if (std::find(count.begin(), count.end(), 0) != count.end()) return -2.0;
  for (Vec3& s : sum) {
    const double len = s.norm();
    s = len > 0.0 ? Vec3(s / len) : Vec3::Zero();
  }
  double e = 0.0;
  for (size_t f = 0; f < labels.size(); ++f) {
    e += face_area(mesh, static_cast<int>(f)) *
         (face_normal(mesh, static_cast<int>(f)) - sum[static_cast<size_t>(labels[f])]).squaredNorm();
  }
  return e;
}

}  // namespace ff::bench
