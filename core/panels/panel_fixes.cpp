// The fixes a PanelLayout can make without reclustering: switching pairings (paper fig. 6),
// tilting spike planes (2.3), trying new planes under a validity guard, grouping the corners
// of flipped chains, and the partial rebuild after plane changes (single-point nodes:
// single_point_nodes.cpp).
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>

#include "core/panels/panel_layout.h"
#include "core/panels/vertex_rule.h"

namespace ff {

int PanelLayout::switch_pairings() {
  int changes = 0;
  std::vector<PanelPolygon> saved_polygons;
  std::vector<PanelIssues> saved_issues;
  std::vector<std::vector<Pairing>> pairings;  // per k, node_pairings(k) once per call
  for (size_t g = 0; g < groups_.groups.size(); ++g) {
    const int k = static_cast<int>(groups_.groups[g].clusters.size());
    if (k < 4 || held_group_[g]) continue;
    const std::vector<int> around = clusters_of_group(static_cast<int>(g));
    int best = 0;
    for (int c : around) best += issues_[static_cast<size_t>(c)].valid() ? 0 : 1;
    if (best == 0) continue;
    // The panels as they are (swapped out, their memory reused by the trials): put back when
    // no other pairing does better, instead of built again.
    if (saved_polygons.size() < around.size()) saved_polygons.resize(around.size());
    saved_issues.resize(around.size());
    for (size_t i = 0; i < around.size(); ++i) {
      std::swap(saved_polygons[i], polygons_[static_cast<size_t>(around[i])]);
      saved_issues[i] = issues_[static_cast<size_t>(around[i])];
    }
    const Pairing original = pairing_[g];
    Pairing best_pairing = original;
    bool built_best = false;  // the panels are those of best_pairing (the last one tried)
    if (pairings.size() <= static_cast<size_t>(k)) pairings.resize(static_cast<size_t>(k) + 1);
    if (pairings[static_cast<size_t>(k)].empty()) pairings[static_cast<size_t>(k)] = node_pairings(k);
    for (const Pairing& p : pairings[static_cast<size_t>(k)]) {
      if (p == original) continue;
      pairing_[g] = p;
      place_group_nodes(static_cast<int>(g));
      // Built one by one, given up once as many are invalid as with the best so far.
      int now = 0;
      size_t built = 0;
      for (; built < around.size() && now < best; ++built) {
        build_panel(around[built]);
        now += issues_[static_cast<size_t>(around[built])].valid() ? 0 : 1;
      }
      built_best = built == around.size() && now < best;
      if (built_best) best = now, best_pairing = p;
    }
    const bool changed = best_pairing != original;
    if (pairing_[g] != best_pairing) {
      pairing_[g] = best_pairing;
      place_group_nodes(static_cast<int>(g));
    }
    if (!changed) {
      for (size_t i = 0; i < around.size(); ++i) {
        std::swap(saved_polygons[i], polygons_[static_cast<size_t>(around[i])]);
        issues_[static_cast<size_t>(around[i])] = saved_issues[i];
      }
    } else if (!built_best) {
      rebuild(around);
    }
    if (changed) ++changes;
  }
  return changes;
}

bool PanelLayout::tilt_spike_planes(const std::vector<char>& fixed_masters, const std::vector<PlaneHinge>& hinges) {
  MasterPlanes tilted = planes_;
  bool any = false;
  const std::vector<char> spikes = spike_nodes();
  for (size_t node = 0; node < node_point_.size(); ++node) {
    if (!spikes[node]) continue;
    const Vec3& at = groups_.groups[static_cast<size_t>(node_group_[node])].reference;
    for (int m : masters_of_node(node)) {
      if (static_cast<size_t>(m) < fixed_masters.size() && fixed_masters[static_cast<size_t>(m)]) continue;
      Plane& plane = tilted.planes[static_cast<size_t>(m)];
      if (static_cast<size_t>(m) < hinges.size() && hinges[static_cast<size_t>(m)].on) {
        // Average with the plane through the hinge's line and the corner: still on the line.
        const PlaneHinge& h = hinges[static_cast<size_t>(m)];
        Vec3 through = h.direction.cross(at - h.point);
        if (through.norm() < 1e-12) continue;
        through.normalize();
        if (through.dot(plane.normal) < 0.0) through = -through;
        Vec3 normal = plane.normal + through;
        normal -= normal.dot(h.direction) * h.direction;  // across the line, exactly
        if (normal.norm() < 1e-12) continue;
        plane = Plane::through(h.point, normal.normalized());
        any = true;
        continue;
      }
      // Average the plane with the nearest plane through its centre and the corner.
      const Vec3& center = planes_.centers[static_cast<size_t>(m)];
      const Vec3 reach = at - center;
      if (reach.norm() < 1e-12) continue;
      const Vec3 u = reach.normalized();
      Vec3 through = plane.normal - plane.normal.dot(u) * u;
      if (through.norm() < 1e-12) continue;
      plane = Plane::through(center, (plane.normal + through.normalized()).normalized());
      any = true;
    }
  }
  if (!any) return false;
  // All tilts together (a spike needs its planes to move), kept only if that helps.
  const int before = num_invalid();
  MasterPlanes saved = planes_;
  planes_ = std::move(tilted);
  rebuild_changed(saved.planes);
  if (num_invalid() < before) return true;
  const std::vector<Plane> tilted_planes = planes_.planes;
  planes_ = std::move(saved);
  rebuild_changed(tilted_planes);
  return false;
}

void PanelLayout::master_reach(int master, std::vector<int>& groups, std::vector<int>& clusters) const {
  groups.clear(), clusters.clear();
  for (size_t c = 0; c < planes_.master_of.size(); ++c) {
    if (planes_.master_of[c] != master) continue;
    clusters.push_back(static_cast<int>(c));
    for (int g : groups_of_cluster_[c]) groups.push_back(g);
  }
  std::sort(groups.begin(), groups.end());
  groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
  for (int g : groups) {
    for (int c : clusters_of_group(g)) clusters.push_back(c);
  }
  std::sort(clusters.begin(), clusters.end());
  clusters.erase(std::unique(clusters.begin(), clusters.end()), clusters.end());
}

int PanelLayout::invalid_among(const std::vector<int>& clusters) const { return faults_among(clusters).invalid; }

PanelLayout::Faults PanelLayout::faults_among(const std::vector<int>& clusters) const {
  Faults faults;
  for (int c : clusters) {
    const PanelIssues& i = issues_[static_cast<size_t>(c)];
    faults.invalid += i.valid() ? 0 : 1;
    faults.collapsed += i.collapsed ? 1 : 0;
  }
  return faults;
}

void PanelLayout::set_master_plane(int m, const Plane& plane, const std::vector<int>& groups,
                                   const std::vector<int>& clusters) {
  planes_.planes[static_cast<size_t>(m)] = plane;
  for (int g : groups) place_group_nodes(g);
  rebuild(clusters);
}

bool PanelLayout::try_master_plane(int m, const Plane& plane, const std::vector<int>& groups,
                                   const std::vector<int>& clusters) {
  const int before = invalid_among(clusters);
  const Plane old = planes_.planes[static_cast<size_t>(m)];
  set_master_plane(m, plane, groups, clusters);
  if (invalid_among(clusters) < before) return true;
  set_master_plane(m, old, groups, clusters);
  return false;
}

int PanelLayout::try_planes(const std::vector<Plane>& candidates, int passes) {
  const size_t masters = planes_.planes.size();
  const std::vector<int> pinned = single_point_masters();  // they must keep their point
  // Per master, its clusters (master_of does not change here): master_reach without a scan
  // over all clusters per master.
  std::vector<int> first(masters + 1, 0), of_master(planes_.master_of.size());
  for (int m : planes_.master_of) ++first[static_cast<size_t>(m) + 1];
  for (size_t m = 0; m < masters; ++m) first[m + 1] += first[m];
  {
    std::vector<int> at(first.begin(), first.end() - 1);
    for (size_t c = 0; c < planes_.master_of.size(); ++c)
      of_master[static_cast<size_t>(at[static_cast<size_t>(planes_.master_of[c])]++)] = static_cast<int>(c);
  }
  // A trial reads only the planes of the clusters it rebuilds and the nodes of their groups,
  // and all of those are rebuilt by any kept change that could alter them. So a plane refused
  // before no panel it reaches changed since is refused again: skipped (same result).
  std::vector<long> refused_at(masters, -1), changed_at(polygons_.size(), -1);
  long clock = 0;
  std::vector<int> groups, clusters;
  std::vector<PanelPolygon> saved_polygons;
  std::vector<PanelIssues> saved_issues;
  int total = 0;
  for (int pass = 0; pass < passes; ++pass) {
    int kept = 0;
    for (size_t m = 0; m < masters; ++m) {
      const Plane old = planes_.planes[m];
      const Plane& cand = candidates[m];
      if (cand.normal == old.normal && cand.offset == old.offset) continue;
      if (std::binary_search(pinned.begin(), pinned.end(), static_cast<int>(m))) continue;
      // The groups and panels this plane reaches (as master_reach).
      groups.clear(), clusters.clear();
      for (int i = first[m]; i < first[m + 1]; ++i) {
        const int c = of_master[static_cast<size_t>(i)];
        clusters.push_back(c);
        for (int g : groups_of_cluster_[static_cast<size_t>(c)]) groups.push_back(g);
      }
      std::sort(groups.begin(), groups.end());
      groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
      for (int g : groups) {
        for (int c : groups_.groups[static_cast<size_t>(g)].clusters) {
          if (c != kBoundary) clusters.push_back(c);
        }
      }
      std::sort(clusters.begin(), clusters.end());
      clusters.erase(std::unique(clusters.begin(), clusters.end()), clusters.end());
      if (refused_at[m] >= 0) {
        bool moved = false;
        for (int c : clusters) moved = moved || changed_at[static_cast<size_t>(c)] > refused_at[m];
        if (!moved) continue;
      }
      const Faults before = faults_among(clusters);
      // The panels as they are, to put back if the plane is refused (swapped, not copied: the
      // vectors' memory is reused by the rebuild).
      if (saved_polygons.size() < clusters.size()) saved_polygons.resize(clusters.size());
      saved_issues.resize(clusters.size());
      for (size_t i = 0; i < clusters.size(); ++i) {
        std::swap(saved_polygons[i], polygons_[static_cast<size_t>(clusters[i])]);
        saved_issues[i] = issues_[static_cast<size_t>(clusters[i])];
      }
      planes_.planes[m] = cand;
      for (int g : groups) place_group_nodes(g);
      // Built one by one, refused as soon as more are invalid than before (the rest would
      // only add to that); a refused trial is undone below either way.
      int after = 0;
      for (size_t i = 0; i < clusters.size() && after <= before.invalid; ++i) {
        build_panel(clusters[i]);
        after += issues_[static_cast<size_t>(clusters[i])].valid() ? 0 : 1;
      }
      ++clock;
      // Not at the cost of a collapsed panel (its plane fit would make a sliver of it).
      if (after <= before.invalid && faults_among(clusters).no_worse_than(before)) {
        ++kept;
        for (int c : clusters) changed_at[static_cast<size_t>(c)] = clock;
      } else {
        // Nodes and panels are functions of the planes: placing the groups again gives back
        // exactly what they were; the panels come back from the saved ones.
        planes_.planes[m] = old;
        for (int g : groups) place_group_nodes(g);
        for (size_t i = 0; i < clusters.size(); ++i) {
          std::swap(saved_polygons[i], polygons_[static_cast<size_t>(clusters[i])]);
          issues_[static_cast<size_t>(clusters[i])] = saved_issues[i];
        }
        refused_at[m] = clock;
      }
    }
    total += kept;
    if (kept == 0) break;
  }
  return total;
}

std::vector<char> PanelLayout::spike_master_clusters() const {
  std::vector<char> out(planes_.master_of.size(), 0);
  const std::vector<char> spikes = spike_nodes();
  for (size_t node = 0; node < node_point_.size(); ++node) {
    if (!spikes[node] || node_planes_[node] < 2 || single_[static_cast<size_t>(node_group_[node])]) continue;
    const int g = node_group_[node];
    const NodeGroup& group = groups_.groups[static_cast<size_t>(g)];
    for (int p : pairing_[static_cast<size_t>(g)][node - static_cast<size_t>(node_offset_[static_cast<size_t>(g)])]) {
      const int c = group.clusters[static_cast<size_t>(p)];
      if (c == kBoundary) continue;
      if (planes_.count[static_cast<size_t>(planes_.master_of[static_cast<size_t>(c)])] > 1)
        out[static_cast<size_t>(c)] = 1;
    }
  }
  return out;
}

std::vector<std::pair<int, int>> PanelLayout::reversed_chains() const {
  std::vector<std::pair<int, int>> out;
  for (size_t c = 0; c < polygons_.size(); ++c) {
    if (issues_[c].valid()) continue;
    const PanelPolygon& poly = polygons_[c];
    const size_t k = poly.points.size();
    for (size_t i = 0; i < k; ++i) {
      const size_t j = (i + 1) % k;
      if (poly.node[i] < 0 || poly.node[j] < 0) continue;
      const NodeGroup& a = groups_.groups[static_cast<size_t>(node_group_[static_cast<size_t>(poly.node[i])])];
      const NodeGroup& b = groups_.groups[static_cast<size_t>(node_group_[static_cast<size_t>(poly.node[j])])];
      if (&a == &b || a.corners.size() != 1 || b.corners.size() != 1) continue;
      if ((poly.points[j] - poly.points[i]).dot(b.reference - a.reference) >= 0.0) continue;
      out.emplace_back(std::min(a.corners[0], b.corners[0]), std::max(a.corners[0], b.corners[0]));
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// Node groups and panels are functions of the planes they use: only those a changed plane
// reaches are placed and built again (later panel rounds relax a few planes among many).
void PanelLayout::rebuild_changed(const std::vector<Plane>& old, bool all_panels) {
  const std::vector<Plane>& now = planes_.planes;
  if (old.size() != now.size()) return rebuild_all();
  std::vector<char> changed(now.size(), 0);
  bool any = false;
  for (size_t m = 0; m < now.size(); ++m) {
    // Compared as values, so a NaN plane always counts as changed.
    changed[m] = !(old[m].normal == now[m].normal && old[m].offset == now[m].offset);
    any = any || changed[m];
  }
  if (!any && !all_panels) return;
  // Nodes placed again only where a plane moved; then the panels there (or all of them).
  std::vector<char> group_marked(groups_.groups.size(), 0), cluster_marked(polygons_.size(), all_panels ? 1 : 0);
  for (size_t c = 0; c < polygons_.size(); ++c) {
    if (!changed[static_cast<size_t>(planes_.master_of[c])]) continue;
    cluster_marked[c] = 1;  // (already, with all_panels)
    for (int g : groups_of_cluster_[c]) group_marked[static_cast<size_t>(g)] = 1;
  }
  for (size_t g = 0; g < group_marked.size(); ++g) {
    if (!group_marked[g]) continue;
    place_group_nodes(static_cast<int>(g));
    for (int c : groups_.groups[g].clusters) {
      if (c != kBoundary) cluster_marked[static_cast<size_t>(c)] = 1;
    }
  }
  for (size_t c = 0; c < polygons_.size(); ++c) {
    if (cluster_marked[c]) build_panel(static_cast<int>(c));
  }
}

}  // namespace ff
