#include "core/cluster/clustering.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>

namespace ff {

std::vector<ClusterMoments> cluster_moments(const FaceData& faces, const std::vector<int>& labels, int num_clusters) {
  std::vector<ClusterMoments> moments(static_cast<size_t>(num_clusters));
  for (int f = 0; f < faces.num_faces(); ++f) {
    const int label = labels[static_cast<size_t>(f)];
    if (label >= 0) moments[static_cast<size_t>(label)].add_face(faces, f);
  }
  return moments;
}

Proxy single_face_proxy(const FaceData& faces, int face, const Vec3& fallback_normal) {
  const FaceRecord& r = faces[static_cast<size_t>(face)];
  Proxy p;
  p.center = r.centroid;
  p.normal = r.normal.squaredNorm() > 0.0 ? r.normal : fallback_normal;
  p.density = r.density;
  return p;
}

EnergyTerms refit(const Metric& metric, Clustering& clustering) {
  return refit(metric, clustering, cluster_moments(metric.faces(), clustering.labels, clustering.num_clusters()));
}

EnergyTerms refit(const Metric& metric, Clustering& clustering, const std::vector<ClusterMoments>& moments) {
  for (size_t i = 0; i < moments.size(); ++i) clustering.proxies[i] = metric.fit(moments[i], clustering.proxies[i]);
  const EnergyTerms energy = clustering_energy(metric, moments, clustering.proxies);
  clustering.energy = energy.total();
  return energy;
}

EnergyTerms clustering_energy(const Metric& metric, const std::vector<ClusterMoments>& moments,
                              const std::vector<Proxy>& proxies) {
  EnergyTerms total;
  for (size_t i = 0; i < moments.size(); ++i) total += metric.energy(moments[i], proxies[i]);
  return total;
}

std::vector<int> cluster_sizes(const Clustering& clustering) {
  std::vector<int> size(static_cast<size_t>(clustering.num_clusters()), 0);
  for (int l : clustering.labels) ++size[static_cast<size_t>(l)];
  return size;
}

void choose_seeds(const Metric& metric, Clustering& clustering) {
  const int n = clustering.num_clusters();
  const std::vector<Metric::Terms> terms = metric.terms(clustering.proxies);
  std::vector<double> best(static_cast<size_t>(n), std::numeric_limits<double>::infinity());
  std::vector<int> seeds = clustering.seeds;
  for (int f = 0; f < metric.faces().num_faces(); ++f) {
    const int i = clustering.labels[static_cast<size_t>(f)];
    if (i < 0 || clustering.sticky[static_cast<size_t>(i)] > 0) continue;
    // Cost per unit area, so a sliver is not chosen just for being small.
    const double area = metric.faces()[f].area;
    if (!(area > 0.0)) continue;
    const double c = metric.cost(f, terms[static_cast<size_t>(i)]) / area;
    if (c < best[static_cast<size_t>(i)]) {
      best[static_cast<size_t>(i)] = c;
      seeds[static_cast<size_t>(i)] = f;
    }
  }
  clustering.seeds = std::move(seeds);
}

std::vector<std::pair<int, int>> adjacent_cluster_pairs(const MeshTopology& topology, const std::vector<int>& labels) {
  // Each pair shows up once per edge it shares (tens of times): rather than sort them all,
  // list each smaller label's larger neighbours (a counting sort by the smaller label), keep
  // each once, and sort only those short lists.
  int clusters = 0;
  for (int l : labels) clusters = std::max(clusters, l + 1);
  const auto pair_at = [&](const std::array<int, 2>& ef, int& a, int& b) {
    if (ef[1] < 0) return false;
    a = labels[static_cast<size_t>(ef[0])], b = labels[static_cast<size_t>(ef[1])];
    if (a == b || a < 0 || b < 0) return false;
    if (a > b) std::swap(a, b);
    return true;
  };
  std::vector<int> start(static_cast<size_t>(clusters) + 1, 0);
  int a = 0, b = 0;
  for (const auto& ef : topology.edge_faces) {
    if (pair_at(ef, a, b)) ++start[static_cast<size_t>(a) + 1];
  }
  for (size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
  std::vector<int> larger(static_cast<size_t>(start.back()));
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (const auto& ef : topology.edge_faces) {
    if (pair_at(ef, a, b)) larger[static_cast<size_t>(fill[static_cast<size_t>(a)]++)] = b;
  }
  std::vector<std::pair<int, int>> pairs;
  std::vector<int> listed_by(static_cast<size_t>(clusters), -1);  // the last smaller label that kept b
  for (int i = 0; i < clusters; ++i) {
    const size_t first = pairs.size();
    for (int k = start[static_cast<size_t>(i)]; k < start[static_cast<size_t>(i) + 1]; ++k) {
      const int j = larger[static_cast<size_t>(k)];
      if (listed_by[static_cast<size_t>(j)] == i) continue;
      listed_by[static_cast<size_t>(j)] = i;
      pairs.emplace_back(i, j);
    }
    std::sort(pairs.begin() + static_cast<std::ptrdiff_t>(first), pairs.end());
  }
  return pairs;
}

bool clusters_are_contiguous(const MeshTopology& topology, const std::vector<int>& labels, int num_clusters) {
  const size_t faces = labels.size();
  std::vector<int> first(static_cast<size_t>(num_clusters), -1);
  for (size_t f = 0; f < faces; ++f) {
    const int l = labels[f];
    if (l < 0 || l >= num_clusters) return false;
    if (first[static_cast<size_t>(l)] < 0) first[static_cast<size_t>(l)] = static_cast<int>(f);
  }
  std::vector<char> seen(faces, 0);
  std::vector<int> stack;
  for (int i = 0; i < num_clusters; ++i) {
    if (first[static_cast<size_t>(i)] < 0) return false;  // empty cluster
    stack.push_back(first[static_cast<size_t>(i)]);
    seen[static_cast<size_t>(first[static_cast<size_t>(i)])] = 1;
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      for (int g : topology.face_neighbors[static_cast<size_t>(f)]) {
        if (g >= 0 && !seen[static_cast<size_t>(g)] && labels[static_cast<size_t>(g)] == i) {
          seen[static_cast<size_t>(g)] = 1;
          stack.push_back(g);
        }
      }
    }
  }
  return std::all_of(seen.begin(), seen.end(), [](char s) { return s != 0; });
}

}  // namespace ff
