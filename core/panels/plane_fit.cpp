#include "core/panels/plane_fit.h"

#include <Eigen/Eigenvalues>

#include "core/cluster/metric.h"

namespace ff {

std::vector<Plane> surface_fit_planes(const FaceData& faces, const std::vector<int>& labels,
                                      const MasterPlanes& masters) {
  std::vector<ClusterMoments> moments(masters.planes.size());
  for (size_t f = 0; f < labels.size(); ++f) {
    const int m = masters.master_of[static_cast<size_t>(labels[f])];
    moments[static_cast<size_t>(m)].add_face(faces, static_cast<int>(f));
  }
  std::vector<Plane> out = masters.planes;
  for (size_t m = 0; m < moments.size(); ++m) {
    const ClusterMoments& mo = moments[m];
    if (!(mo.area > 0.0)) continue;
    const Vec3 center = mo.first / mo.area;
    // The exact area covariance about the centroid; its smallest eigenvector is the normal
    // of least integrated squared distance.
    const Eigen::Matrix3d covariance = mo.second - mo.first * mo.first.transpose() / mo.area;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
    Vec3 normal = solver.eigenvectors().col(0);
    if (!normal.allFinite() || normal.norm() < 0.5) continue;
    if (normal.dot(masters.planes[m].normal) < 0.0) normal = -normal;
    out[m] = Plane::through(center, normal.normalized());
  }
  return out;
}

namespace {

// The plane of least squared distance for moments plus weighted points, or `fallback`.
Plane fit_plane(const ClusterMoments& m, const std::vector<Vec3>& points, double point_weight, const Vec3& side,
                const Plane& fallback) {
  double area = m.area;
  Vec3 first = m.first;
  Eigen::Matrix3d second = m.second;
  for (const Vec3& p : points) {
    area += point_weight;
    first += point_weight * p;
    second += point_weight * p * p.transpose();
  }
  if (!(area > 0.0)) return fallback;
  const Vec3 center = first / area;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(second - first * first.transpose() / area);
  Vec3 normal = solver.eigenvectors().col(0);
  if (!normal.allFinite() || normal.norm() < 0.5) return fallback;
  if (normal.dot(side) < 0.0) normal = -normal;
  return Plane::through(center, normal.normalized());
}

}  // namespace

std::vector<Plane> corner_fit_planes(const std::vector<ClusterMoments>& moments,
                                     const std::vector<std::vector<Vec3>>& corners,
                                     const std::vector<Vec3>& orientation, double corner_weight) {
  std::vector<Plane> out(corners.size());
  for (size_t c = 0; c < corners.size(); ++c) {
    const Plane fallback =
        Plane::through(moments[c].area > 0.0 ? Vec3(moments[c].first / moments[c].area) : Vec3::Zero(), orientation[c]);
    const double w =
        corners[c].empty() ? 0.0 : corner_weight * moments[c].area / static_cast<double>(corners[c].size());
    out[c] = fit_plane(moments[c], corners[c], w, orientation[c], fallback);
  }
  return out;
}

}  // namespace ff
