// Remesher: what a locked panel holds (remesher_edits.cpp makes the locks; DESIGN.md 3).
// A lock holds the panel's faces and plane, its neighbours' faces (so its corners and chains
// stay) and their planes, each free to turn about its edge line with the locked plane
// (hinges(): every node of the outline stays on its lines, so the neighbours' other nodes can
// still move), its node pairings, and the spike distance and D it was laid out with
// (locked_limits()), so its own vertices are judged as when it was locked and its border keeps
// its vertices. These turn the locks into what the clustering and the panel phase take: fixed
// faces, fixed planes, hinges, held nodes; held clusters take no part in later Lloyd steps or
// count changes.
#include <algorithm>
#include <array>
#include <vector>

#include "core/cluster/cluster_edits.h"
#include "core/remesher.h"

namespace ff {

std::vector<std::array<int, 3>> Remesher::held_nodes() const {
  std::vector<std::array<int, 3>> out;
  for (const Lock& lock : locks_) {
    for (const std::array<int, 3>& named : lock.nodes) {
      std::array<int, 3> t;
      for (size_t k = 0; k < 3; ++k) t[k] = named[k] < 0 ? kBoundary : clustering_.labels[static_cast<size_t>(named[k])];
      std::sort(t.begin(), t.end());
      out.push_back(t);
    }
  }
  return out;
}

std::vector<std::vector<int>> Remesher::held_single() const {
  std::vector<std::vector<int>> out;
  for (const Lock& lock : locks_) {
    for (const std::vector<int>& named : lock.single_groups) {
      std::vector<int> group;
      for (int face : named) group.push_back(clustering_.labels[static_cast<size_t>(face)]);
      std::sort(group.begin(), group.end());
      out.push_back(std::move(group));
    }
  }
  return out;
}

HeldGrouping Remesher::held_grouping() const {
  HeldGrouping out;
  for (const Lock& lock : locks_) {
    out.together.insert(out.together.end(), lock.grouping.together.begin(), lock.grouping.together.end());
    out.apart.insert(out.apart.end(), lock.grouping.apart.begin(), lock.grouping.apart.end());
  }
  std::sort(out.together.begin(), out.together.end());
  out.together.erase(std::unique(out.together.begin(), out.together.end()), out.together.end());
  std::sort(out.apart.begin(), out.apart.end());
  out.apart.erase(std::unique(out.apart.begin(), out.apart.end()), out.apart.end());
  return out;
}

std::vector<char> Remesher::held_clusters() const {
  if (locks_.empty()) return {};
  std::vector<char> out(static_cast<size_t>(clustering_.num_clusters()), 0);
  for (const Lock& lock : locks_) {
    for (const Held& h : lock.held) out[static_cast<size_t>(clustering_.labels[static_cast<size_t>(h.face)])] = 1;
  }
  return out;
}

void Remesher::hold(std::vector<char>& settled, std::vector<Plane>& planes) const {
  if (locks_.empty()) return;
  const size_t n = static_cast<size_t>(clustering_.num_clusters());
  settled.resize(n, 0);
  planes.resize(n);
  for (const Lock& lock : locks_) {
    for (const Held& h : lock.held) {
      const size_t c = static_cast<size_t>(clustering_.labels[static_cast<size_t>(h.face)]);
      settled[c] = 1;
      planes[c] = h.plane;
    }
  }
}

// A neighbour whose plane makes a node of a locked panel may turn about the line where it
// meets the locked plane: every node of the locked panel on it lies on that line, and its
// other plane there is the locked one or another neighbour turning about a line through the
// node, so the outline stays exactly. Not when it is locked itself or next to two locks.
std::vector<int> Remesher::hinges() const {
  if (locks_.empty()) return {};
  const size_t n = static_cast<size_t>(clustering_.num_clusters());
  std::vector<int> out(n, -1);
  const auto label = [&](int face) { return clustering_.labels[static_cast<size_t>(face)]; };
  for (const Lock& lock : locks_) {
    const int locked = label(lock.held[0].face);
    for (size_t k = 1; k < lock.held.size(); ++k) {
      const int face = lock.held[k].face;
      const bool on_node = std::any_of(lock.nodes.begin(), lock.nodes.end(), [&](const std::array<int, 3>& t) {
        return std::find(t.begin(), t.end(), face) != t.end();
      });
      if (!on_node) continue;
      int& h = out[static_cast<size_t>(label(face))];
      h = h == -1 || h == locked ? locked : -2;
    }
  }
  for (const Lock& lock : locks_) out[static_cast<size_t>(label(lock.held[0].face))] = -2;
  for (int& h : out) h = std::max(h, -1);
  return out;
}

std::vector<int> Remesher::held_labels() const {
  std::vector<int> out(clustering_.labels.size(), -1);
  for (const Lock& lock : locks_) {
    for (const Held& h : lock.held) {
      const int c = clustering_.labels[static_cast<size_t>(h.face)];
      for (int f : h.faces) out[static_cast<size_t>(f)] = c;
    }
  }
  return out;
}

void Remesher::locked_limits(std::vector<double>& spike_distance, std::vector<double>& diameter) const {
  spike_distance.clear(), diameter.clear();
  if (locks_.empty()) return;
  spike_distance.assign(static_cast<size_t>(clustering_.num_clusters()), 0.0);
  diameter.assign(spike_distance.size(), 0.0);
  for (const Lock& lock : locks_) {
    const size_t c = static_cast<size_t>(clustering_.labels[static_cast<size_t>(lock.held[0].face)]);
    spike_distance[c] = lock.spike_distance / faces_.scale;
    diameter[c] = lock.diameter / faces_.scale;
  }
}

std::vector<int> Remesher::locked_clusters() const {
  std::vector<int> out;
  if (clustering_.labels.empty()) return out;
  for (const Lock& lock : locks_) out.push_back(clustering_.labels[static_cast<size_t>(lock.held[0].face)]);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

int Remesher::free_parts_with_locks() const {
  const std::vector<int> held = held_labels();
  std::vector<char> seen(held.size(), 0);
  std::vector<int> stack;
  int parts = 0;
  for (size_t f = 0; f < held.size(); ++f) {
    if (held[f] >= 0 || seen[f]) continue;
    ++parts;
    seen[f] = 1;
    stack.push_back(static_cast<int>(f));
    while (!stack.empty()) {
      const int g = stack.back();
      stack.pop_back();
      for (int h : topology_.face_neighbors[static_cast<size_t>(g)]) {
        if (h < 0 || held[static_cast<size_t>(h)] >= 0 || seen[static_cast<size_t>(h)]) continue;
        seen[static_cast<size_t>(h)] = 1;
        stack.push_back(h);
      }
    }
  }
  return parts;
}

// A Lloyd iteration that leaves held clusters as they are (their faces fixed in the flood).
void Remesher::lloyd_step_held() {
  const int it = lloyd_done_ + 1;
  choose_seeds(metric_, clustering_);
  const std::vector<int> before = clustering_.labels;
  const FixedLabels fixed(held_labels());
  flood(metric_, topology_, clustering_, &fixed, /*with_energy=*/false);
  refit(metric_, clustering_);
  for (int& s : clustering_.sticky) {
    if (s > 0) --s;
  }
  if (before == clustering_.labels) converged_ = true;
  lloyd_done_ = it;
  progress_.iteration = it;
  progress_.energy = clustering_.energy * faces_.area_to_world();
  if (converged_ || it >= params_.lloyd_iterations) after_lloyd();
}

// A new panel count with locks: split the worst or merge the cheapest clusters not held.
void Remesher::change_count_held(int target) {
  const int start = clustering_.num_clusters();
  int n = start;
  while (n < target) {
    const int w = worst_free_cluster(metric_, clustering_, held_clusters());
    if (w < 0) break;
    split_cluster(metric_, topology_, clustering_, w);
    ++n;
  }
  while (n > target) {
    const auto [a, b] = cheapest_free_merge(metric_, topology_, clustering_, held_clusters());
    if (a < 0) break;
    merge_clusters(metric_, clustering_, a, b);
    --n;
  }
  if (n == start) refit(metric_, clustering_);  // proxies and energy under the new metric
}

}  // namespace ff
