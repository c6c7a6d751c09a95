#include "core/panels/plane_fit.h"

#include <Eigen/Eigenvalues>
#include <algorithm>

#include "core/cluster/metric.h"

namespace ff {

std::vector<Plane> surface_fit_planes(const FaceData& faces, const std::vector<int>& labels,
                                      const MasterPlanes& masters, const std::vector<NodeConstraint>& nodes,
                                      const std::vector<ClusterMoments>& border, double border_weight) {
  std::vector<ClusterMoments> moments(masters.planes.size());
  for (size_t f = 0; f < labels.size(); ++f) {
    moments[static_cast<size_t>(masters.master_of[static_cast<size_t>(labels[f])])].add_face(faces,
                                                                                             static_cast<int>(f));
  }
  if (border_weight > 0.0 && !border.empty()) {
    // The border's line moments per master, scaled by border_weight * area / length: the
    // border then weighs border_weight times the faces, whatever its length.
    std::vector<ClusterMoments> line(masters.planes.size());
    for (size_t c = 0; c < border.size() && c < masters.master_of.size(); ++c) {
      line[static_cast<size_t>(masters.master_of[c])].add(border[c]);
    }
    for (size_t m = 0; m < line.size(); ++m) {
      if (!(line[m].area > 0.0) || !(moments[m].area > 0.0)) continue;
      moments[m].add(line[m], border_weight * moments[m].area / line[m].area);
    }
  }
  RelaxOptions fit;
  fit.node_weight = 0.2;
  // The relaxation stops once the planes have settled (RelaxOptions::settled_step), with the
  // rest of their geometric tail added: what is left is far below what the Hausdorff distance
  // or the panels' checks can see.
  return relax_planes(nodes, moments, masters.planes, fit);
}

std::vector<ClusterMoments> border_moments(const MeshTopology& topology,
                                           const std::vector<Vec3>& positions, const std::vector<int>& labels,
                                           int num_clusters) {
  std::vector<ClusterMoments> out(static_cast<size_t>(std::max(0, num_clusters)));
  for (int e = 0; e < topology.num_edges(); ++e) {
    if (!topology.is_boundary_edge(e)) continue;
    const int label = labels[static_cast<size_t>(topology.edge_faces[static_cast<size_t>(e)][0])];
    if (label < 0 || label >= num_clusters) continue;
    const Vec3& a = positions[static_cast<size_t>(topology.edge_vertices[static_cast<size_t>(e)][0])];
    const Vec3& b = positions[static_cast<size_t>(topology.edge_vertices[static_cast<size_t>(e)][1])];
    const double length = (b - a).norm();
    // Integrals along the segment p(t) = a + t (b - a), ds = length dt.
    ClusterMoments& m = out[static_cast<size_t>(label)];
    m.area += length;
    m.first += 0.5 * length * (a + b);
    m.second += length / 6.0 * (2.0 * a * a.transpose() + 2.0 * b * b.transpose() + a * b.transpose() +
                                b * a.transpose());
  }
  return out;
}

std::vector<Plane> planes_toward(const std::vector<Plane>& from, const std::vector<Plane>& to, double t) {
  std::vector<Plane> out = from;
  for (size_t m = 0; m < out.size() && m < to.size(); ++m) {
    if (from[m].normal == to[m].normal && from[m].offset == to[m].offset) continue;
    const Vec3 n = from[m].normal + t * (to[m].normal - from[m].normal);
    if (!(n.norm() > 1e-12) || !n.allFinite()) continue;
    out[m] = Plane{n.normalized(), from[m].offset + t * (to[m].offset - from[m].offset)};
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
