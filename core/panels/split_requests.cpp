#include "core/panels/split_requests.h"

#include <algorithm>
#include <deque>

#include "core/cluster/clustering.h"
#include "core/panels/panel_attempt.h"

namespace ff {

namespace {

// Breadth-first over the cluster's faces from its seed; the last face reached.
int farthest_face(const MeshTopology& topology, const Clustering& c, int cluster) {
  const int seed = c.seeds[static_cast<size_t>(cluster)];
  std::deque<int> queue{seed};
  std::vector<char> seen(c.labels.size(), 0);
  seen[static_cast<size_t>(seed)] = 1;
  int last = seed;
  while (!queue.empty()) {
    last = queue.front();
    queue.pop_front();
    for (int g : topology.face_neighbors[static_cast<size_t>(last)]) {
      if (g < 0 || seen[static_cast<size_t>(g)] || c.labels[static_cast<size_t>(g)] != cluster) continue;
      seen[static_cast<size_t>(g)] = 1;
      queue.push_back(g);
    }
  }
  return last;
}

// A cluster that meets one neighbour in two separate chains (paper fig. 10) is cut across
// neither of them by a split at its far end: on a thin part (a leg) that leaves both halves
// touching the neighbour twice. Seeding the new cluster at the middle of one such chain,
// the one farthest from the seed, cuts it off that chain, so the halves meet the neighbour
// once each. -1 when the loop shows no repeated neighbour (then the far-end split is used).
int two_chain_face(const TriMesh& mesh, const MeshTopology& topology, const Clustering& c, const PanelGraph& graph,
                   int cluster) {
  const std::vector<int>& loop = graph.loops[static_cast<size_t>(cluster)];
  if (loop.empty()) return -1;
  const auto head = [&](int h) {
    return mesh.triangles[static_cast<size_t>(h / 3)][static_cast<size_t>((h % 3 + 1) % 3)];
  };
  // Chains as [begin, end) ranges of the loop (it starts just after a corner).
  std::vector<std::pair<size_t, size_t>> chains;
  std::vector<int> neighbour;
  size_t begin = 0;
  for (size_t k = 0; k < loop.size(); ++k) {
    if (graph.corner_of_vertex[static_cast<size_t>(head(loop[k]))] < 0) continue;
    chains.emplace_back(begin, k + 1);
    neighbour.push_back(PanelGraph::other_side(topology, c.labels, loop[k]));
    begin = k + 1;
  }
  const auto centroid = [&](int f) {
    const Triangle& t = mesh.triangles[static_cast<size_t>(f)];
    return (mesh.positions[static_cast<size_t>(t[0])] + mesh.positions[static_cast<size_t>(t[1])] +
            mesh.positions[static_cast<size_t>(t[2])]) /
           3.0;
  };
  const int seed = c.seeds[static_cast<size_t>(cluster)];
  const Vec3 from = centroid(seed);
  int best = -1;
  double distance = -1.0;
  for (size_t i = 0; i < chains.size(); ++i) {
    if (neighbour[i] == kBoundary || std::count(neighbour.begin(), neighbour.end(), neighbour[i]) < 2) continue;
    const int f = loop[(chains[i].first + chains[i].second) / 2] / 3;
    const double d = (centroid(f) - from).squaredNorm();
    if (f != seed && d > distance) distance = d, best = f;
  }
  return best;
}

}  // namespace

std::vector<int> enclosed_clusters(const PanelAttempt& attempt) {
  std::vector<int> out;
  const std::vector<unsigned>& problems = attempt.graph().problems;
  for (size_t c = 0; c < problems.size(); ++c) {
    if (problems[c] == kEnclosed) out.push_back(static_cast<int>(c));
  }
  return out;
}

std::vector<int> tiny_invalid_clusters(const PanelAttempt& attempt, int share) {
  const Clustering& c = attempt.clustering();
  const PanelLayout& layout = attempt.layout();
  const std::vector<int> size = cluster_sizes(c);
  const size_t faces = c.labels.size();
  std::vector<int> out;
  for (int cluster = 0; cluster < layout.num_clusters() && cluster < c.num_clusters(); ++cluster) {
    const size_t i = static_cast<size_t>(cluster);
    if (layout.issues()[i].valid() || attempt.graph().problems[i] == kEnclosed) continue;
    // size < mean / share, in integers: size * share * n < faces.
    if (static_cast<size_t>(size[i]) * static_cast<size_t>(share) * size.size() >= faces) continue;
    out.push_back(cluster);
  }
  return out;
}

int stall_splits(int num_clusters) {
  constexpr int kPanelsPerSplit = 100;
  constexpr int kMostSplits = 3;
  return std::clamp(num_clusters / kPanelsPerSplit, 1, kMostSplits);
}

ClusterCuts cluster_cuts(const TriMesh& mesh, const MeshTopology& topology, const PanelAttempt& attempt) {
  const Clustering& c = attempt.clustering();
  const PanelGraph& graph = attempt.graph();
  ClusterCuts out;
  for (int cluster = 0; cluster < c.num_clusters(); ++cluster) {
    const unsigned p = graph.problems[static_cast<size_t>(cluster)];
    if (p == 0 || p == kEnclosed) continue;
    const int across = p == kTwoChains ? two_chain_face(mesh, topology, c, graph, cluster) : -1;
    const int face = across >= 0 ? across : farthest_face(topology, c, cluster);
    if (face == c.seeds[static_cast<size_t>(cluster)])
      out.uncuttable.push_back(cluster);
    else
      out.cuts.emplace_back(cluster, face);
  }
  return out;
}

std::vector<std::pair<int, int>> split_requests(const TriMesh& mesh, const MeshTopology& topology,
                                                const PanelAttempt& attempt,
                                                const std::vector<std::pair<int, int>>& cuts, int max_geometric,
                                                const std::vector<char>& keep) {
  const Clustering& c = attempt.clustering();
  std::vector<std::pair<int, int>> out = cuts;
  const PanelLayout* layout = &attempt.layout();
  // Largest invalid panels first: splitting them costs the least detail elsewhere.
  const auto kept = [&](int cluster) {
    return static_cast<size_t>(cluster) < keep.size() && keep[static_cast<size_t>(cluster)];
  };
  std::vector<int> invalid, kept_invalid;
  for (int cluster = 0; cluster < layout->num_clusters(); ++cluster) {
    if (!layout->issues()[static_cast<size_t>(cluster)].valid())
      (kept(cluster) ? kept_invalid : invalid).push_back(cluster);
  }
  const std::vector<int> size = cluster_sizes(c);
  std::stable_sort(invalid.begin(), invalid.end(),
                   [&](int a, int b) { return size[static_cast<size_t>(a)] > size[static_cast<size_t>(b)]; });
  // A kept panel's problem, last: a free cluster at its problem corner splits instead.
  invalid.insert(invalid.end(), kept_invalid.begin(), kept_invalid.end());
  std::vector<char> corner_used(mesh.positions.size(), 0);
  int geometric = 0;
  for (int cluster : invalid) {
    if (geometric >= max_geometric) break;
    for (int v : layout->problem_corners(cluster)) {
      if (corner_used[static_cast<size_t>(v)]) continue;
      // A face of this cluster (of a free one, for a kept cluster) at the corner, not its seed.
      int face = -1;
      for (int k = topology.vertex_face_offsets[static_cast<size_t>(v)];
           k < topology.vertex_face_offsets[static_cast<size_t>(v) + 1]; ++k) {
        const int f = topology.vertex_faces[static_cast<size_t>(k)];
        const int l = c.labels[static_cast<size_t>(f)];
        if ((kept(cluster) ? !kept(l) : l == cluster) && f != c.seeds[static_cast<size_t>(l)]) {
          face = f;
          break;
        }
      }
      if (face < 0) continue;
      corner_used[static_cast<size_t>(v)] = 1;
      out.emplace_back(c.labels[static_cast<size_t>(face)], face);
      ++geometric;
      break;
    }
  }
  return out;
}

}  // namespace ff
