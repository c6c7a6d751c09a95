#include "core/quality/planarity.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cfloat>
#include <cmath>

namespace ff {

double polygon_planarity(const std::vector<Vec3>& points) {
  if (points.size() < 4) return 0.0;  // three points are always coplanar
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Vec3& p : points) covariance += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  const Vec3 normal = solver.eigenvectors().col(0);  // eigenvalues ascend
  double deviation = 0.0, diameter2 = 0.0;
  for (size_t i = 0; i < points.size(); ++i) {
    deviation = std::max(deviation, std::abs(normal.dot(points[i] - mean)));
    for (size_t j = i + 1; j < points.size(); ++j)
      diameter2 = std::max(diameter2, (points[i] - points[j]).squaredNorm());
  }
  return diameter2 > 0.0 ? deviation / std::sqrt(diameter2) : 0.0;
}

double planarity_rounding_floor(const std::vector<Vec3>& points, const Vec3& origin) {
  if (points.size() < 4) return 0.0;
  double largest = 0.0, diameter2 = 0.0;
  for (size_t i = 0; i < points.size(); ++i) {
    largest = std::max(largest, (points[i] - origin).cwiseAbs().maxCoeff());
    for (size_t j = i + 1; j < points.size(); ++j)
      diameter2 = std::max(diameter2, (points[i] - points[j]).squaredNorm());
  }
  return diameter2 > 0.0 ? DBL_EPSILON * largest / std::sqrt(diameter2) : 0.0;
}

std::vector<double> corner_polygon_planarity(const TriMesh& mesh, const PanelMesh& pm) {
  std::vector<double> out;
  if (pm.vertex_corner.size() != pm.vertices.size()) return out;
  out.reserve(pm.panels.size());
  std::vector<Vec3> points;
  for (const std::vector<int>& panel : pm.panels) {
    points.clear();
    for (const int v : panel) {
      const int corner = pm.vertex_corner[static_cast<size_t>(v)];
      const bool on_mesh = corner >= 0 && corner < mesh.num_vertices();
      points.push_back(on_mesh ? mesh.positions[static_cast<size_t>(corner)] : pm.vertices[static_cast<size_t>(v)]);
    }
    out.push_back(polygon_planarity(points));
  }
  return out;
}

}  // namespace ff
