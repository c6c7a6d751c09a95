#include "core/cluster/seeding.h"

#include <algorithm>
#include <limits>
#include <queue>
#include <string>

#include "core/util/error.h"
#include "core/util/random.h"

namespace ff {

namespace {

// Faces of each component, in increasing face order.
std::vector<std::vector<int>> component_faces(const MeshTopology& topology, int faces) {
  std::vector<std::vector<int>> out(static_cast<size_t>(topology.num_components));
  for (int f = 0; f < faces; ++f) out[static_cast<size_t>(topology.face_component[static_cast<size_t>(f)])].push_back(f);
  return out;
}

// An area-weighted random face of `candidates` not yet taken (uniform over faces when all
// have zero area).
int random_face(const std::vector<int>& candidates, const std::vector<double>& cumulative,
                const std::vector<char>& taken, SplitMix64& rng) {
  const double total = cumulative.back();
  for (int attempt = 0; attempt < 64; ++attempt) {
    size_t k;
    if (total > 0.0) {
      const double r = rng.uniform() * total;
      k = static_cast<size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), r) - cumulative.begin());
      k = std::min(k, candidates.size() - 1);
    } else {
      k = static_cast<size_t>(rng.below(candidates.size()));
    }
    if (!taken[static_cast<size_t>(candidates[k])]) return candidates[k];
  }
  // Dense picks (n close to the face count): the first free face from a random start.
  const size_t start = static_cast<size_t>(rng.below(candidates.size()));
  for (size_t i = 0; i < candidates.size(); ++i) {
    const int f = candidates[(start + i) % candidates.size()];
    if (!taken[static_cast<size_t>(f)]) return f;
  }
  return -1;
}

void random_seeds(const FaceData& faces, const std::vector<int>& candidates, int count, SplitMix64& rng,
                  std::vector<char>& taken, std::vector<int>& seeds) {
  std::vector<double> cumulative(candidates.size());
  double sum = 0.0;
  for (size_t k = 0; k < candidates.size(); ++k) cumulative[k] = (sum += faces[candidates[k]].area);
  for (int s = 0; s < count; ++s) {
    const int f = random_face(candidates, cumulative, taken, rng);
    taken[static_cast<size_t>(f)] = 1;
    seeds.push_back(f);
  }
}

// Farthest-point sampling on the face graph with incremental Dijkstra: each new seed only
// relaxes the faces it is now closest to, and a lazy max-heap finds the farthest face.
void farthest_seeds(const FaceData& faces, const MeshTopology& topology, const std::vector<int>& candidates,
                    int count, SplitMix64& rng, std::vector<char>& taken, std::vector<double>& dist,
                    std::vector<int>& seeds) {
  using Item = std::pair<double, int>;  // (distance, face)
  std::vector<int> first;
  random_seeds(faces, candidates, 1, rng, taken, first);
  int next = first.front();
  std::vector<Item> far_items;
  far_items.reserve(candidates.size());
  std::priority_queue<Item> farthest;  // max-heap; entries may be stale (larger than dist)
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> frontier;
  for (int s = 0; s < count; ++s) {
    taken[static_cast<size_t>(next)] = 1;
    seeds.push_back(next);
    dist[static_cast<size_t>(next)] = 0.0;
    frontier.push({0.0, next});
    while (!frontier.empty()) {
      const auto [d, f] = frontier.top();
      frontier.pop();
      if (d > dist[static_cast<size_t>(f)]) continue;
      for (int g : topology.face_neighbors[static_cast<size_t>(f)]) {
        if (g < 0) continue;
        const double nd = d + (faces[f].centroid - faces[g].centroid).norm();
        if (nd < dist[static_cast<size_t>(g)]) {
          dist[static_cast<size_t>(g)] = nd;
          frontier.push({nd, g});
        }
      }
    }
    if (s + 1 == count) break;
    if (s == 0) {
      for (int f : candidates) far_items.push_back({dist[static_cast<size_t>(f)], f});
      farthest = std::priority_queue<Item>(std::less<Item>(), std::move(far_items));
    }
    next = -1;
    while (!farthest.empty()) {
      const auto [d, f] = farthest.top();
      farthest.pop();
      if (taken[static_cast<size_t>(f)]) continue;
      if (d > dist[static_cast<size_t>(f)]) {  // stale: distances only shrink, re-file it
        farthest.push({dist[static_cast<size_t>(f)], f});
        continue;
      }
      next = f;
      break;
    }
    if (next < 0) break;
  }
}

}  // namespace

std::vector<int> seeds_per_component(const FaceData& faces, const MeshTopology& topology, int n) {
  const int components = topology.num_components;
  const int total_faces = faces.num_faces();
  if (n > total_faces) {
    throw InputError("asked for " + std::to_string(n) + " panels but the mesh has only " +
                     std::to_string(total_faces) + " triangles; ask for fewer panels or refine the mesh");
  }
  if (n < components) {
    throw InputError("the mesh has " + std::to_string(components) + " disconnected parts but only " +
                     std::to_string(n) + " panels were asked for; each part needs at least one panel");
  }
  std::vector<double> area(static_cast<size_t>(components), 0.0);
  std::vector<int> capacity(static_cast<size_t>(components), 0);
  for (int f = 0; f < total_faces; ++f) {
    const size_t c = static_cast<size_t>(topology.face_component[static_cast<size_t>(f)]);
    area[c] += faces[f].area;
    ++capacity[c];
  }
  // Hamilton's method on the area quotas, with at least one seed per part and at most one
  // per face; ties go to the lower component index.
  const double total = faces.total_area > 0.0 ? faces.total_area : 1.0;
  std::vector<double> quota(static_cast<size_t>(components));
  std::vector<int> count(static_cast<size_t>(components));
  int assigned = 0;
  for (size_t c = 0; c < quota.size(); ++c) {
    quota[c] = n * area[c] / total;
    count[c] = std::min(capacity[c], std::max(1, static_cast<int>(quota[c])));
    assigned += count[c];
  }
  std::vector<size_t> order(quota.size());
  for (size_t c = 0; c < order.size(); ++c) order[c] = c;
  const auto remainder = [&](size_t c) { return quota[c] - count[c]; };
  while (assigned != n) {
    // Largest remainder gets one more (when short), smallest gives one back (when over).
    std::stable_sort(order.begin(), order.end(), [&](size_t x, size_t y) { return remainder(x) > remainder(y); });
    bool changed = false;
    if (assigned < n) {
      for (size_t c : order) {
        if (count[c] < capacity[c]) {
          ++count[c];
          ++assigned;
          changed = true;
          break;
        }
      }
    } else {
      for (auto it = order.rbegin(); it != order.rend(); ++it) {
        if (count[*it] > 1) {
          --count[*it];
          --assigned;
          changed = true;
          break;
        }
      }
    }
    if (!changed) break;  // cannot happen for components <= n <= faces
  }
  return count;
}

std::vector<int> place_seeds(const FaceData& faces, const MeshTopology& topology, int n, SeedingMethod method,
                             std::uint64_t seed) {
  const std::vector<int> counts = seeds_per_component(faces, topology, n);
  const std::vector<std::vector<int>> members = component_faces(topology, faces.num_faces());
  SplitMix64 rng(seed);
  std::vector<char> taken(static_cast<size_t>(faces.num_faces()), 0);
  std::vector<double> dist;
  if (method == SeedingMethod::FarthestPoint)
    dist.assign(static_cast<size_t>(faces.num_faces()), std::numeric_limits<double>::infinity());
  std::vector<int> seeds;
  seeds.reserve(static_cast<size_t>(n));
  for (size_t c = 0; c < counts.size(); ++c) {
    if (method == SeedingMethod::Random) {
      random_seeds(faces, members[c], counts[c], rng, taken, seeds);
    } else {
      farthest_seeds(faces, topology, members[c], counts[c], rng, taken, dist, seeds);
    }
  }
  return seeds;
}

}  // namespace ff
