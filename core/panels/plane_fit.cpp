#include "core/panels/plane_fit.h"

#include <Eigen/Eigenvalues>

#include "core/cluster/metric.h"

namespace ff {

std::vector<Plane> surface_fit_planes(const FaceData& faces, const std::vector<int>& labels,
                                      const MasterPlanes& masters, const std::vector<NodeConstraint>& nodes) {
  std::vector<ClusterMoments> moments(masters.planes.size());
  for (size_t f = 0; f < labels.size(); ++f) {
    moments[static_cast<size_t>(masters.master_of[static_cast<size_t>(labels[f])])].add_face(faces,
                                                                                             static_cast<int>(f));
  }
  RelaxOptions fit;
  fit.node_weight = 0.2;
  return relax_planes(nodes, moments, masters.planes, fit);
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
