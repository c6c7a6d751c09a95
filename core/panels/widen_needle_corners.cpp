// Needle corners at split nodes (issue 3). Where four or more clusters meet, the pairing
// (node_split.h) is chosen for nodes closest to where they belong (fig. 6); that can leave a
// panel with a corner of a fraction of a degree, a needle no fabricator can cut or glaze,
// although the panel is simple, star-shaped and spike-free. Over the sweep's cases at seeds
// 1-2, 44 of 128 runs had a corner below 1 degree, four in five of them at a split node.
// Another pairing of the same group often has no needle: the nodes move along the same
// planes' lines by about the short edge between them. Where none is, the group becomes one
// vertex (the paper's single-point option, 2.2, here only where it removes a needle): four or
// five panels meet at a point instead of a needle, which a fabricator can make. This runs on a
// layout whose panels are final (Remesher::optimize_planes), so the rounds and which runs end
// valid are unchanged.
#include <algorithm>
#include <vector>

#include "core/panels/panel_check.h"
#include "core/panels/panel_layout.h"
#include "core/panels/polygon2d.h"

namespace ff {

namespace {

// Another pairing must widen the smallest corner by this much (degrees) to be taken. Often the
// smallest corner is one no pairing moves (at a vertex next to the group, its node moving
// along the edge's line), and then the pairings tie to the last bits, which can differ between
// builds (the corner angle is glibc's or musl's atan2; until the core stopped using Eigen's
// SSE2 sums, core/CMakeLists.txt, its arithmetic did too): without a margin
// hyperboloid_s4.off at 500 panels, seed 5 had different panels in the CLI and on the page.
constexpr double kWiderByDeg = 0.01;

}  // namespace

template <typename Take>
double PanelLayout::smallest_corner_among(const std::vector<int>& clusters, Take take) const {
  double smallest = 360.0;
  for (int c : clusters) {
    const PanelPolygon& poly = polygons_[static_cast<size_t>(c)];
    const size_t n = poly.points.size();
    if (n < 3) continue;
    // In the panel's own plane, as the panel checks measure corners (problem_corners).
    const Plane& plane = planes_.plane_of(c);
    const PlaneFrame frame = make_plane_frame(plane.offset * plane.normal, plane.normal);
    for (size_t i = 0; i < n; ++i) {
      const size_t before = (i + n - 1) % n, after = (i + 1) % n;
      if (take(poly, before, i, after))
        smallest = std::min(smallest, corner_angle_deg(frame.to_2d(poly.points[before]), frame.to_2d(poly.points[i]),
                                                       frame.to_2d(poly.points[after])));
    }
  }
  return smallest;
}

double PanelLayout::smallest_corner_near_group(int g, const std::vector<int>& clusters) const {
  const int first = node_offset_[static_cast<size_t>(g)], end = node_offset_[static_cast<size_t>(g) + 1];
  const auto in_group = [&](int node) { return node >= first && node < end; };
  // The group's nodes move with its pairing, and so do the corners at them and at their
  // neighbours along the outline.
  return smallest_corner_among(clusters, [&](const PanelPolygon& poly, size_t before, size_t i, size_t after) {
    return in_group(poly.node[i]) || in_group(poly.node[before]) || in_group(poly.node[after]);
  });
}

double PanelLayout::smallest_corner_deg() const {
  std::vector<int> all(polygons_.size());
  for (size_t c = 0; c < all.size(); ++c) all[c] = static_cast<int>(c);
  return smallest_corner(all);
}

double PanelLayout::smallest_corner(const std::vector<int>& clusters) const {
  return smallest_corner_among(clusters, [](const PanelPolygon&, size_t, size_t, size_t) { return true; });
}

int PanelLayout::widen_needle_corners(double below_deg, const std::vector<char>& fixed_clusters) {
  std::vector<char> fixed_master(planes_.planes.size(), 0);
  for (size_t c = 0; c < fixed_clusters.size() && c < planes_.master_of.size(); ++c) {
    if (fixed_clusters[c]) fixed_master[static_cast<size_t>(planes_.master_of[c])] = 1;
  }
  int changes = 0;
  std::vector<std::vector<Pairing>> pairings;  // per k, node_pairings(k) once per call
  for (size_t g = 0; g < groups_.groups.size(); ++g) {
    const int k = static_cast<int>(groups_.groups[g].clusters.size());
    if (k < 4 || held_group_[g] || single_[g]) continue;
    const int group = static_cast<int>(g);
    const std::vector<int> around = clusters_of_group(group);
    const double now = smallest_corner_near_group(group, around);
    if (!(now < below_deg)) continue;
    const Faults faults = faults_among(around);
    if (pairings.size() <= static_cast<size_t>(k)) pairings.resize(static_cast<size_t>(k) + 1);
    if (pairings[static_cast<size_t>(k)].empty()) pairings[static_cast<size_t>(k)] = node_pairings(k);
    const Pairing original = pairing_[g];
    Pairing best = original;
    double widest = now;
    for (const Pairing& p : pairings[static_cast<size_t>(k)]) {
      if (p == original) continue;
      pairing_[g] = p;
      place_group_nodes(group);
      rebuild(around);
      // A needle is better than an invalid or collapsed panel.
      if (!faults_among(around).no_worse_than(faults)) continue;
      const double angle = smallest_corner_near_group(group, around);
      if (angle > widest + kWiderByDeg) widest = angle, best = p;
    }
    // Nodes and panels are functions of the pairing: back to exactly the kept one's.
    pairing_[g] = best;
    place_group_nodes(group);
    rebuild(around);
    if (best != original) ++changes;
    if (!(widest < below_deg)) continue;
    // No pairing is needle-free: the group as one point (paper 2.2's option, here only where
    // it removes a needle), its planes translated through their least-squares point. That
    // moves every node on those planes, so it is judged on all the panels they reach: none
    // more invalid, none narrower than before (to the margin), and the group's needle wider.
    const std::vector<int> masters = distinct_masters(group);
    if (std::any_of(masters.begin(), masters.end(), [&](int m) { return fixed_master[static_cast<size_t>(m)] != 0; }))
      continue;
    std::vector<int> reach, groups, clusters;
    for (int m : masters) {
      master_reach(m, groups, clusters);
      reach.insert(reach.end(), clusters.begin(), clusters.end());
    }
    std::sort(reach.begin(), reach.end());
    reach.erase(std::unique(reach.begin(), reach.end()), reach.end());
    const Faults faults_reach = faults_among(reach);
    const double narrowest = smallest_corner(reach);
    std::vector<Plane> old;
    if (!make_group_single(group, old)) continue;
    if (faults_among(reach).no_worse_than(faults_reach) && smallest_corner(reach) >= narrowest - kWiderByDeg &&
        smallest_corner_near_group(group, around) > widest + kWiderByDeg) {
      ++changes;
    } else {
      undo_group_single(group, old);
    }
  }
  return changes;
}

}  // namespace ff
