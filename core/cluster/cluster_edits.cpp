#include "core/cluster/cluster_edits.h"

#include <algorithm>
#include <tuple>

namespace ff {

namespace {

// The split's flood: faces outside the cluster keep their labels, and only the two halves
// may take the cluster's faces (any other offer costs kForbidden, so it never wins while a
// half can reach the face, which it always can: the cluster is edge-connected).
class InsideCluster : public ExtraCost {
 public:
  InsideCluster(const std::vector<int>& labels, int cluster, int added)
      : labels_(labels), cluster_(cluster), added_(added) {}
  double operator()(int face, int k) const override {
    const bool inside = labels_[static_cast<size_t>(face)] == cluster_;
    return inside && k != cluster_ && k != added_ ? kForbidden : 0.0;
  }
  int fixed_label(int face) const override {
    const int l = labels_[static_cast<size_t>(face)];
    return l == cluster_ ? -1 : l;
  }
  static constexpr double kForbidden = 1e30;

 private:
  const std::vector<int>& labels_;
  int cluster_, added_;
};

}  // namespace

int split_cluster(const Metric& metric, const MeshTopology& topology, Clustering& c, int cluster,
                  int sticky_iterations) {
  const FaceData& data = metric.faces();
  std::vector<int> faces;
  Vec3 centre = Vec3::Zero();
  double area = 0.0;
  for (size_t f = 0; f < c.labels.size(); ++f) {
    if (c.labels[f] != cluster) continue;
    faces.push_back(static_cast<int>(f));
    centre += data[f].area * data[f].centroid;
    area += data[f].area;
  }
  if (faces.size() < 2) return -1;
  if (area > 0.0) centre /= area;
  // Two faces far apart, ties to the lowest id; distinct even when every centroid coincides.
  const auto farthest = [&](const Vec3& from, int other) {
    int best = -1;
    double distance = -1.0;
    for (int f : faces) {
      const double d = (data[static_cast<size_t>(f)].centroid - from).squaredNorm();
      if (f != other && d > distance) distance = d, best = f;
    }
    return best;
  };
  const int a = farthest(centre, -1);
  const int b = farthest(data[static_cast<size_t>(a)].centroid, a);
  return split_cluster_at(metric, topology, c, cluster, a, b, sticky_iterations);
}

int split_cluster_at(const Metric& metric, const MeshTopology& topology, Clustering& c, int cluster, int a, int b,
                     int sticky_iterations) {
  const FaceData& data = metric.faces();
  const auto in_cluster = [&](int f) {
    return f >= 0 && static_cast<size_t>(f) < c.labels.size() && c.labels[static_cast<size_t>(f)] == cluster;
  };
  if (a == b || !in_cluster(a) || !in_cluster(b)) return -1;
  const int added = c.num_clusters();
  const Vec3 normal = c.proxies[static_cast<size_t>(cluster)].normal;
  Clustering work = c;
  work.proxies[static_cast<size_t>(cluster)] = single_face_proxy(data, a, normal);
  work.proxies.push_back(single_face_proxy(data, b, normal));
  work.seeds[static_cast<size_t>(cluster)] = a;
  work.seeds.push_back(b);
  // No stickiness during this flood: a sticky neighbour would claim faces next to its seed.
  work.sticky.assign(static_cast<size_t>(added) + 1, 0);
  const InsideCluster inside(c.labels, cluster, added);
  flood(metric, topology, work, &inside, /*with_energy=*/false);
  c.labels = std::move(work.labels);
  c.proxies = std::move(work.proxies);
  c.seeds = std::move(work.seeds);
  c.sticky.push_back(sticky_iterations);
  c.sticky[static_cast<size_t>(cluster)] = std::max(c.sticky[static_cast<size_t>(cluster)], sticky_iterations);
  refit(metric, c);
  return added;
}

int merge_clusters(const Metric& metric, Clustering& c, int a, int b) {
  for (int& l : c.labels) {
    if (l == b) l = a;
    if (l > b) --l;
  }
  c.proxies.erase(c.proxies.begin() + b);
  c.seeds.erase(c.seeds.begin() + b);
  c.sticky.erase(c.sticky.begin() + b);
  refit(metric, c);
  return a > b ? a - 1 : a;
}

bool clusters_share_edge(const MeshTopology& topology, const std::vector<int>& labels, int a, int b) {
  for (size_t f = 0; f < labels.size(); ++f) {
    if (labels[f] != a) continue;
    for (int g : topology.face_neighbors[f]) {
      if (g >= 0 && labels[static_cast<size_t>(g)] == b) return true;
    }
  }
  return false;
}

std::vector<int> cluster_ring(const TriMesh& mesh, const MeshTopology& topology, const std::vector<int>& labels,
                              int cluster) {
  std::vector<int> out;
  for (size_t f = 0; f < labels.size(); ++f) {
    if (labels[f] != cluster) continue;
    for (int v : mesh.triangles[f]) {
      for (int k = topology.vertex_face_offsets[static_cast<size_t>(v)];
           k < topology.vertex_face_offsets[static_cast<size_t>(v) + 1]; ++k) {
        const int l = labels[static_cast<size_t>(topology.vertex_faces[static_cast<size_t>(k)])];
        if (l != cluster) out.push_back(l);
      }
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

namespace {

bool kept(const std::vector<char>& keep, int cluster) {
  return static_cast<size_t>(cluster) < keep.size() && keep[static_cast<size_t>(cluster)];
}

}  // namespace

int worst_free_cluster(const Metric& metric, const Clustering& c, const std::vector<char>& keep) {
  const std::vector<ClusterMoments> moments = cluster_moments(metric.faces(), c.labels, c.num_clusters());
  const std::vector<int> size = cluster_sizes(c);
  int worst = -1;
  double energy = -1.0;
  for (int i = 0; i < c.num_clusters(); ++i) {
    if (kept(keep, i) || size[static_cast<size_t>(i)] < 2) continue;
    const double e = metric.energy(moments[static_cast<size_t>(i)], c.proxies[static_cast<size_t>(i)]).total();
    if (e > energy) energy = e, worst = i;
  }
  return worst;
}

std::pair<int, int> cheapest_free_merge(const Metric& metric, const MeshTopology& topology, const Clustering& c,
                                        const std::vector<char>& keep) {
  const std::vector<ClusterMoments> moments = cluster_moments(metric.faces(), c.labels, c.num_clusters());
  std::tuple<double, int, int> best{0.0, -1, -1};
  for (const auto& [a, b] : adjacent_cluster_pairs(topology, c.labels)) {
    if (kept(keep, a) || kept(keep, b)) continue;
    const size_t ia = static_cast<size_t>(a), ib = static_cast<size_t>(b);
    ClusterMoments merged = moments[ia];
    merged.add(moments[ib]);
    const Proxy p = metric.fit(merged, c.proxies[ia]);
    const double cost = metric.energy(merged, p).total() - metric.energy(moments[ia], c.proxies[ia]).total() -
                        metric.energy(moments[ib], c.proxies[ib]).total();
    const std::tuple<double, int, int> candidate{cost, a, b};
    if (std::get<1>(best) < 0 || candidate < best) best = candidate;
  }
  return {std::get<1>(best), std::get<2>(best)};
}

}  // namespace ff
