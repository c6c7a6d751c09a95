// Putting a short edge's two nodes back in order (issue 3; the "flipped edge without a
// spike" case of DESIGN.md 3). An edge of a panel on plane P is the trace of a neighbour's
// plane Q; its nodes a and b sit where that trace crosses the lines of P with two further
// planes A and B. Those two lines cross at X = P n A n B. When the cluster's outline is
// narrow there (on cow.off at 46 panels a tooth of one panel between two others, where the
// straight corner-to-corner edges themselves almost cross), the trace of Q can pass X on
// the wrong side: a lies beyond X on its line while b does not, the edge crosses the next
// one and the panel is flipped and not simple, although every node is well conditioned and
// near its corner (no spike, so tilting and aim_node_planes() see nothing to aim at).
// Here Q turns so its trace passes through chosen points just before or after X on the two
// lines (each node kept where it is, or moved to one side of X), the smallest turn that
// holds that trace (its normal stays as close to the old one as it can). Setting an edge's
// direction in P takes a large turn of Q (on the cow, 25.6 degrees of a small neighbour
// panel), so the limit is wide (30 degrees by default) and what bounds the change is the
// rest: Q must still pass within half the spike distance of its centre (it stays on its
// faces), every node it moves is still judged by the spike test, and each turn, smallest
// first, is kept only when fewer panels around Q are invalid, as in aim_node_planes.cpp.
// Runs only in PanelAttempt::mend, so runs that end valid are unchanged.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "core/panels/panel_layout.h"
#include "core/panels/vertex_rule.h"

namespace ff {

namespace {

// The master of `masters` (three distinct) that is neither `x` nor `y`, or -1.
int third_master(const int (&masters)[3], int x, int y) {
  for (int m : masters) {
    if (m != x && m != y) return m;
  }
  return -1;
}

}  // namespace

int PanelLayout::aim_edge_order(const std::vector<char>& fixed_masters, double max_turn_deg) {
  const std::vector<int> pinned = single_point_masters();  // they must keep their point
  // Candidate spots for a node: kept, or this share of the spike distance either side of X.
  const double shares[] = {0.1, 0.3};
  std::vector<int> groups, clusters;
  int kept = 0;
  for (size_t c = 0; c < polygons_.size(); ++c) {
    if (issues_[c].valid() || !(issues_[c].flipped || issues_[c].not_simple)) continue;
    const int p = planes_.master_of[c];
    const std::vector<int> ring = polygons_[c].node;  // copied: rebuild() replaces the polygon
    for (size_t i = 0; i < ring.size() && !issues_[c].valid(); ++i) {
      const int a = ring[i], b = ring[(i + 1) % ring.size()];
      if (a < 0 || b < 0 || a == b) continue;
      const size_t na = static_cast<size_t>(a), nb = static_cast<size_t>(b);
      if (node_planes_[na] != 3 || node_planes_[nb] != 3) continue;
      bool frozen = false;
      for (size_t n : {na, nb}) {
        const size_t g = static_cast<size_t>(node_group_[n]);
        frozen = frozen || single_[g] || held_group_[g];
      }
      if (frozen) continue;
      const NodeMasters ma = node_masters(na), mb = node_masters(nb);
      if (ma.count != 3 || mb.count != 3) continue;
      // The edge's plane: the master both nodes share besides P (one, or the edge is ambiguous).
      int q = -1, shared = 0;
      for (int m : ma.m) {
        if (m != p && std::find(std::begin(mb.m), std::end(mb.m), m) != std::end(mb.m)) q = m, ++shared;
      }
      if (shared != 1 || std::find(std::begin(ma.m), std::end(ma.m), p) == std::end(ma.m)) continue;
      const int ea = third_master(ma.m, p, q), eb = third_master(mb.m, p, q);
      if (ea < 0 || eb < 0 || ea == eb) continue;
      if (static_cast<size_t>(q) < fixed_masters.size() && fixed_masters[static_cast<size_t>(q)]) continue;
      if (std::binary_search(pinned.begin(), pinned.end(), q)) continue;
      const Plane& pp = planes_.planes[static_cast<size_t>(p)];
      const Plane& pa = planes_.planes[static_cast<size_t>(ea)];
      const Plane& pb = planes_.planes[static_cast<size_t>(eb)];
      const Vec3& reference = groups_.groups[static_cast<size_t>(node_group_[na])].reference;
      const VertexRuleResult cross = closest_point_on_planes({pp, pa, pb}, reference);
      if (!cross.exact || !((cross.point - reference).norm() <= options_.spike_distance)) continue;
      const Vec3 x = cross.point;
      const Vec3 ua = pp.normal.cross(pa.normal).normalized(), ub = pp.normal.cross(pb.normal).normalized();
      if (!ua.allFinite() || !ub.allFinite()) continue;
      // Spots for a and b: where they are, or either side of X along their lines.
      std::vector<Vec3> spots_a{node_point_[na]}, spots_b{node_point_[nb]};
      for (double share : shares) {
        for (double sign : {1.0, -1.0}) {
          spots_a.push_back(x + sign * share * options_.spike_distance * ua);
          spots_b.push_back(x + sign * share * options_.spike_distance * ub);
        }
      }
      // The turns that hold each pair of spots, smallest first; the plane must still pass
      // within half the spike distance of its master's centre (it keeps its faces).
      const Plane old = planes_.planes[static_cast<size_t>(q)];
      const Vec3& centre = planes_.centers[static_cast<size_t>(q)];
      std::vector<std::pair<double, Plane>> turns;
      for (size_t s = 1; s < spots_a.size() * spots_b.size(); ++s) {
        Plane turned;
        if (!turn_plane_through(old, spots_a[s / spots_b.size()], spots_b[s % spots_b.size()], options_.diameter,
                                max_turn_deg, turned))
          continue;
        if (!(std::abs(turned.distance(centre)) <= 0.5 * options_.spike_distance)) continue;
        turns.emplace_back(-turned.normal.dot(old.normal), turned);
      }
      std::stable_sort(turns.begin(), turns.end(), [](const auto& l, const auto& r) { return l.first < r.first; });
      master_reach(q, groups, clusters);
      bool done = false;
      for (size_t t = 0; t < turns.size() && !done; ++t) done = try_master_plane(q, turns[t].second, groups, clusters);
      if (done) ++kept;
    }
  }
  return kept;
}

}  // namespace ff
