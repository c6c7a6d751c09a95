#include "core/panels/plane_relax.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

namespace ff {

std::vector<Plane> relax_planes(const std::vector<NodeConstraint>& nodes, const std::vector<ClusterMoments>& moments,
                                const std::vector<Plane>& start, const RelaxOptions& options,
                                const std::vector<char>& fixed) {
  std::vector<Plane> planes = start;
  const size_t m = planes.size();
  // Per-plane node weight: node_weight * area / (its number of nodes).
  std::vector<int> node_count(m, 0);
  for (const NodeConstraint& k : nodes) {
    for (int i = 0; i < k.count; ++i) node_count[static_cast<size_t>(k.planes[static_cast<size_t>(i)])] += 1;
  }
  std::vector<double> node_weight(m, 0.0);
  for (size_t i = 0; i < m; ++i) {
    if (node_count[i] > 0) node_weight[i] = options.node_weight * moments[i].area / node_count[i];
  }
  std::vector<Vec3> x(nodes.size());
  // Nodes among fixed planes only cannot move anything: leave them out.
  std::vector<size_t> active;
  for (size_t k = 0; k < nodes.size(); ++k) {
    bool free = fixed.empty();
    for (int j = 0; j < nodes[k].count && !free; ++j)
      free = !fixed[static_cast<size_t>(nodes[k].planes[static_cast<size_t>(j)])];
    if (free) active.push_back(k);
  }
  std::vector<double> area(m);
  std::vector<Vec3> first(m), center(m);
  std::vector<Eigen::Matrix3d> scatter(m);
  double w = options.start_weight;
  for (int it = 0; it < options.iterations; ++it, w *= options.growth) {
    // Nodes: minimise c_k |x - p|^2 + W sum_i (n_i.x - d_i)^2, c_k the node's own weight.
    for (size_t k : active) {
      Eigen::Matrix3d A = nodes[k].weight * Eigen::Matrix3d::Identity();
      Vec3 b = nodes[k].weight * nodes[k].corner;
      for (int j = 0; j < nodes[k].count; ++j) {
        const Plane& p = planes[static_cast<size_t>(nodes[k].planes[static_cast<size_t>(j)])];
        A += w * p.normal * p.normal.transpose();
        b += w * p.offset * p.normal;
      }
      x[k] = A.ldlt().solve(b);
    }
    // Planes: least squares over their faces (exact moments) and their nodes (weight W w_i),
    // the scatter formed about the common centre (two passes) to keep its precision at large W.
    for (size_t i = 0; i < m; ++i) area[i] = moments[i].area, first[i] = moments[i].first;
    for (size_t k : active) {
      for (int j = 0; j < nodes[k].count; ++j) {
        const size_t i = static_cast<size_t>(nodes[k].planes[static_cast<size_t>(j)]);
        area[i] += w * node_weight[i];
        first[i] += w * node_weight[i] * x[k];
      }
    }
    for (size_t i = 0; i < m; ++i) {
      if (!fixed.empty() && fixed[i]) continue;  // stays as it is: its scatter is not needed
      center[i] = area[i] > 0.0 ? Vec3(first[i] / area[i]) : Vec3::Zero();
      const ClusterMoments& mo = moments[i];
      const Vec3& c = center[i];
      scatter[i] = mo.second - mo.first * c.transpose() - c * mo.first.transpose() + mo.area * c * c.transpose();
    }
    for (size_t k : active) {
      for (int j = 0; j < nodes[k].count; ++j) {
        const size_t i = static_cast<size_t>(nodes[k].planes[static_cast<size_t>(j)]);
        if (!fixed.empty() && fixed[i]) continue;
        const Vec3 d = x[k] - center[i];
        scatter[i] += w * node_weight[i] * d * d.transpose();
      }
    }
    for (size_t i = 0; i < m; ++i) {
      if (!(area[i] > 0.0) || (!fixed.empty() && fixed[i])) continue;
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(0.5 * (scatter[i] + scatter[i].transpose()));
      Vec3 normal = solver.eigenvectors().col(0);
      if (!normal.allFinite() || normal.norm() < 0.5) continue;
      if (normal.dot(planes[i].normal) < 0.0) normal = -normal;
      planes[i] = Plane::through(center[i], normal.normalized());
    }
  }
  return planes;
}

}  // namespace ff
