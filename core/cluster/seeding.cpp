#include "core/cluster/seeding.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <string>

#include "core/cluster/quad_heap.h"
#include "core/util/error.h"
#include "core/util/random.h"

namespace ff {

namespace {

// Faces of each component, in increasing face order.
std::vector<std::vector<int>> component_faces(const MeshTopology& topology, int faces) {
  std::vector<std::vector<int>> out(static_cast<size_t>(topology.num_components));
  for (int f = 0; f < faces; ++f)
    out[static_cast<size_t>(topology.face_component[static_cast<size_t>(f)])].push_back(f);
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

// How much each face asks for seeds: its area, times density^w with a density field.
std::vector<double> seed_weights(const FaceData& faces, double density_weight) {
  std::vector<double> w(static_cast<size_t>(faces.num_faces()));
  for (size_t f = 0; f < w.size(); ++f) {
    // pow(1, y) is exactly 1: uniform density skips the call with the same bits.
    const double d = faces[f].density;
    w[f] = faces[f].area * (density_weight == 0.0 || d == 1.0 ? 1.0 : std::pow(d, density_weight));
  }
  return w;
}

void random_seeds(const std::vector<double>& weight, const std::vector<int>& candidates, int count, SplitMix64& rng,
                  std::vector<char>& taken, std::vector<int>& seeds) {
  std::vector<double> cumulative(candidates.size());
  double sum = 0.0;
  for (size_t k = 0; k < candidates.size(); ++k) cumulative[k] = (sum += weight[static_cast<size_t>(candidates[k])]);
  for (int s = 0; s < count; ++s) {
    const int f = random_face(candidates, cumulative, taken, rng);
    taken[static_cast<size_t>(f)] = 1;
    seeds.push_back(f);
  }
}

// Faces filed by distance in equal-width buckets. Distances only shrink as seeds are added,
// so a face is re-filed (appended to a lower bucket, the old entry going stale) only when
// it changes bucket, and the top non-empty bucket only moves down. The farthest face is the
// exact maximum of the top bucket's live entries.
class DistanceBuckets {
 public:
  DistanceBuckets(const std::vector<int>& faces, const std::vector<double>& dist) {
    double max_dist = 0.0;
    for (int f : faces) max_dist = std::max(max_dist, dist[static_cast<size_t>(f)]);
    width_ = max_dist > 0.0 ? max_dist / (kBuckets - 1) : 1.0;
    buckets_.resize(kBuckets);
    // Sized up front: thousands of buckets grown one face at a time cost more than the fill.
    std::vector<int> count(kBuckets, 0);
    for (int f : faces) ++count[static_cast<size_t>(index(dist[static_cast<size_t>(f)]))];
    for (size_t b = 0; b < buckets_.size(); ++b) buckets_[b].reserve(static_cast<size_t>(count[b]) + 2);
    for (int f : faces) buckets_[static_cast<size_t>(index(dist[static_cast<size_t>(f)]))].push_back(f);
    top_ = kBuckets - 1;
  }

  int index(double d) const { return std::min(kBuckets - 1, static_cast<int>(d / width_)); }

  void moved(int face, double old_dist, double new_dist) {
    const int b = index(new_dist);
    if (b != index(old_dist)) buckets_[static_cast<size_t>(b)].push_back(face);
  }

  // The untaken face of largest distance (ties: lowest index), or -1.
  int farthest(const std::vector<double>& dist, const std::vector<char>& taken) {
    for (; top_ >= 0; --top_) {
      std::vector<int>& bucket = buckets_[static_cast<size_t>(top_)];
      int best = -1;
      size_t kept = 0;
      for (int f : bucket) {  // drop stale and taken entries while scanning
        if (taken[static_cast<size_t>(f)] || index(dist[static_cast<size_t>(f)]) != top_) continue;
        bucket[kept++] = f;
        if (best < 0 || dist[static_cast<size_t>(f)] > dist[static_cast<size_t>(best)] ||
            (dist[static_cast<size_t>(f)] == dist[static_cast<size_t>(best)] && f < best)) {
          best = f;
        }
      }
      bucket.resize(kept);
      if (best >= 0) return best;
    }
    return -1;
  }

 private:
  static constexpr int kBuckets = 4096;
  double width_ = 1.0;
  int top_ = 0;
  std::vector<std::vector<int>> buckets_;
};

// Farthest-point sampling on the face graph with incremental Dijkstra: each new seed only
// relaxes the faces it is now closer to.
// Centroid-to-centroid lengths across each face's edges: the Dijkstra runs read these
// (24 bytes a face) instead of whole face records.
// Lengths are stretched by sqrt(density^w) so seeds crowd where panels are to be small.
std::vector<std::array<double, 3>> dual_edge_lengths(const FaceData& faces, const MeshTopology& topology,
                                                     double density_weight) {
  std::vector<std::array<double, 3>> hop(static_cast<size_t>(faces.num_faces()));
  // Once per face, not once per edge side (pow is most of this function's time). pow(1, y)
  // is exactly 1, so uniform density skips it with the same bits.
  std::vector<double> stretches(hop.size(), 1.0);
  if (density_weight != 0.0) {
    for (size_t f = 0; f < hop.size(); ++f) {
      if (faces[f].density != 1.0) stretches[f] = std::pow(faces[f].density, 0.5 * density_weight);
    }
  }
  const auto stretch = [&](size_t f) { return stretches[f]; };
  for (size_t f = 0; f < hop.size(); ++f) {
    for (size_t i = 0; i < 3; ++i) {
      const int g = topology.face_neighbors[f][i];
      if (g < 0) {
        hop[f][i] = 0.0;
        continue;
      }
      const size_t h = static_cast<size_t>(g);
      hop[f][i] = (faces[f].centroid - faces[h].centroid).norm() * 0.5 * (stretch(f) + stretch(h));
    }
  }
  return hop;
}

void farthest_seeds(const std::vector<double>& weight, const MeshTopology& topology,
                    const std::vector<std::array<double, 3>>& hop, const std::vector<int>& candidates, int count,
                    SplitMix64& rng, std::vector<char>& taken, std::vector<double>& dist, std::vector<int>& seeds) {
  std::vector<int> first;
  random_seeds(weight, candidates, 1, rng, taken, first);
  int next = first.front();
  std::unique_ptr<DistanceBuckets> buckets;
  QuadHeap<KeyedItem, KeyedBefore> frontier;  // nearest first; (distance, face) orders it strictly
  for (int s = 0; s < count; ++s) {
    taken[static_cast<size_t>(next)] = 1;
    seeds.push_back(next);
    if (buckets) buckets->moved(next, dist[static_cast<size_t>(next)], 0.0);
    dist[static_cast<size_t>(next)] = 0.0;
    frontier.push({order_key(0.0), next});
    while (!frontier.empty()) {
      const KeyedItem item = frontier.pop();
      const double d = key_value(item.key);
      const int f = item.id;
      if (d > dist[static_cast<size_t>(f)]) continue;
      for (size_t i = 0; i < 3; ++i) {
        const int g = topology.face_neighbors[static_cast<size_t>(f)][i];
        if (g < 0) continue;
        const double nd = d + hop[static_cast<size_t>(f)][i];
        if (nd < dist[static_cast<size_t>(g)]) {
          if (buckets) buckets->moved(g, dist[static_cast<size_t>(g)], nd);
          dist[static_cast<size_t>(g)] = nd;
          frontier.push({order_key(nd), g});
        }
      }
    }
    if (s + 1 == count) break;
    if (!buckets) buckets = std::make_unique<DistanceBuckets>(candidates, dist);
    next = buckets->farthest(dist, taken);
    if (next < 0) break;
  }
}

// Seeds per component for per-face seed weights (see seeds_per_component).
std::vector<int> apportion(const std::vector<double>& weight, const MeshTopology& topology, int n) {
  const int components = topology.num_components;
  const int total_faces = static_cast<int>(weight.size());
  if (n > total_faces) {
    throw InputError("asked for " + std::to_string(n) + " panels but the mesh has only " + std::to_string(total_faces) +
                     " triangles; ask for fewer panels or refine the mesh");
  }
  if (n < components) {
    throw InputError("the mesh has " + std::to_string(components) + " disconnected parts but only " +
                     std::to_string(n) + " panels were asked for; each part needs at least one panel");
  }
  std::vector<double> area(static_cast<size_t>(components), 0.0);  // weighted by density
  std::vector<int> capacity(static_cast<size_t>(components), 0);
  for (int f = 0; f < total_faces; ++f) {
    const size_t c = static_cast<size_t>(topology.face_component[static_cast<size_t>(f)]);
    area[c] += weight[static_cast<size_t>(f)];
    ++capacity[c];
  }
  // Hamilton's method on the area quotas, with at least the part's floor (cluster_floors: four
  // on a closed part when n allows, so a small closed part can still become valid panels; one
  // on an open part) and at most one seed per face; ties go to the lower component index.
  const std::vector<int> floors = cluster_floors(topology, n);
  double total = 0.0;
  for (double a : area) total += a;
  if (!(total > 0.0)) total = 1.0;
  std::vector<double> quota(static_cast<size_t>(components));
  std::vector<int> count(static_cast<size_t>(components));
  int assigned = 0;
  for (size_t c = 0; c < quota.size(); ++c) {
    quota[c] = n * area[c] / total;
    count[c] = std::min(capacity[c], std::max(floors[c], static_cast<int>(quota[c])));
    assigned += count[c];
  }
  // One sort by remainder, then whole passes in that order: linear in the number of parts,
  // which matters for a facade of thousands of separate panels.
  std::vector<size_t> order(quota.size());
  for (size_t c = 0; c < order.size(); ++c) order[c] = c;
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t x, size_t y) { return quota[x] - count[x] > quota[y] - count[y]; });
  while (assigned < n) {  // short: the largest remainders get one more
    const int before = assigned;
    for (size_t k = 0; k < order.size() && assigned < n; ++k) {
      if (count[order[k]] < capacity[order[k]]) {
        ++count[order[k]];
        ++assigned;
      }
    }
    if (assigned == before) break;  // cannot happen for n <= faces
  }
  while (assigned > n) {  // over (parts at their floors): the smallest remainders give one back
    const int before = assigned;
    for (size_t k = order.size(); k-- > 0 && assigned > n;) {
      if (count[order[k]] > std::max(1, floors[order[k]])) {
        --count[order[k]];
        --assigned;
      }
    }
    if (assigned == before) break;  // cannot happen: the floors sum to n or less
  }
  return count;
}

}  // namespace

std::vector<int> seeds_per_component(const FaceData& faces, const MeshTopology& topology, int n,
                                     double density_weight) {
  return apportion(seed_weights(faces, density_weight), topology, n);
}

std::vector<int> place_seeds(const FaceData& faces, const MeshTopology& topology, int n, SeedingMethod method,
                             std::uint64_t seed, double density_weight) {
  const std::vector<double> weight = seed_weights(faces, density_weight);
  const std::vector<int> counts = apportion(weight, topology, n);
  const std::vector<std::vector<int>> members = component_faces(topology, faces.num_faces());
  SplitMix64 rng(seed);
  std::vector<char> taken(static_cast<size_t>(faces.num_faces()), 0);
  std::vector<double> dist;
  std::vector<std::array<double, 3>> hop;
  if (method == SeedingMethod::FarthestPoint) {
    dist.assign(static_cast<size_t>(faces.num_faces()), std::numeric_limits<double>::infinity());
    hop = dual_edge_lengths(faces, topology, density_weight);
  }
  std::vector<int> seeds;
  seeds.reserve(static_cast<size_t>(n));
  for (size_t c = 0; c < counts.size(); ++c) {
    if (method == SeedingMethod::Random) {
      random_seeds(weight, members[c], counts[c], rng, taken, seeds);
    } else {
      farthest_seeds(weight, topology, hop, members[c], counts[c], rng, taken, dist, seeds);
    }
  }
  return seeds;
}

}  // namespace ff
