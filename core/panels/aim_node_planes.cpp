// Aiming one plane at one node (DESIGN.md 3: an ill-conditioned triple is a spike to fix by
// a tilt, not a point to approximate). Where the three planes of a node nearly share a line
// (near-developable parts: a barrel vault's strips, a face's cheeks), their common point
// moves far along that line for a tiny turn of any one of them, so it lands past the spike
// distance or swaps order with its neighbours (a flipped edge). tilt_spike_planes() turns
// every spike's planes at once and relax_planes() pulls all nodes in one least squares;
// both are kept only when the whole layout improves, and at such nodes they often are not.
// Here one node and one of its planes at a time: the plane turns about its centre (or, when
// that fails, about a near-spike node on it, which then stays put) just enough that the node
// comes within half the spike distance of its corner along the other two planes' line, or
// onto that line's point nearest the corner.
// Near-parallel planes make that a small turn, so the plane's other nodes barely move; each
// turn is kept only when fewer panels around it are invalid. Kept apart from
// panel_fixes.cpp like single_point_nodes.cpp.
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/panels/panel_layout.h"
#include "core/panels/vertex_rule.h"

namespace ff {

namespace {

// The plane nearest `plane` through both its own point nearest `pivot` and `target`
// (a turn about an axis through that point); false when the two points nearly coincide or
// the turn would exceed `max_turn_deg`.
bool turned_through(const Plane& plane, const Vec3& pivot, const Vec3& target, double length, double max_turn_deg,
                    Plane& out) {
  return turn_plane_through(plane, plane.project(pivot), target, length, max_turn_deg, out);
}

}  // namespace

int PanelLayout::aim_node_planes(const std::vector<char>& fixed_masters, double max_turn_deg) {
  // The nodes of invalid panels on three distinct planes, farthest from their corner first
  // (sorted by node index among equals: deterministic).
  std::vector<std::pair<double, int>> nodes;
  for (size_t c = 0; c < polygons_.size(); ++c) {
    if (issues_[c].valid()) continue;
    for (int node : polygons_[c].node) {
      if (node < 0 || node_planes_[static_cast<size_t>(node)] != 3) continue;
      const int g = node_group_[static_cast<size_t>(node)];
      if (single_[static_cast<size_t>(g)] || held_group_[static_cast<size_t>(g)]) continue;
      const double far =
          (node_point_[static_cast<size_t>(node)] - groups_.groups[static_cast<size_t>(g)].reference).norm();
      nodes.emplace_back(-far, node);
    }
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  const std::vector<int> pinned = single_point_masters();  // they must keep their point
  std::vector<int> groups, clusters;
  int kept = 0;
  for (const auto& entry : nodes) {
    const size_t node = static_cast<size_t>(entry.second);
    const NodeMasters masters = node_masters(node);
    if (masters.count != 3) continue;
    // Still next to an invalid panel (an earlier turn may have mended it).
    bool needed = false;
    for (int c : node_clusters(static_cast<int>(node)))
      needed = needed || (c != kBoundary && !issues_[static_cast<size_t>(c)].valid());
    if (!needed) continue;
    const Vec3& reference = groups_.groups[static_cast<size_t>(node_group_[node])].reference;
    for (int i = 0; i < 3; ++i) {
      const int m = masters.m[i];
      if (static_cast<size_t>(m) < fixed_masters.size() && fixed_masters[static_cast<size_t>(m)]) continue;
      if (std::binary_search(pinned.begin(), pinned.end(), m)) continue;
      // Where the other two planes' line passes nearest the corner; too far: no turn helps.
      const std::vector<Plane> others{planes_.planes[static_cast<size_t>(masters.m[(i + 1) % 3])],
                                      planes_.planes[static_cast<size_t>(masters.m[(i + 2) % 3])]};
      const VertexRuleResult line = closest_point_on_planes(others, reference);
      if (!line.exact || !((line.point - reference).norm() <= options_.spike_distance)) continue;
      // The node is on that line too: the shortest turn brings it just within half the
      // spike distance (its neighbours' nodes move least), the full one onto the nearest point.
      const Vec3 along = node_point_[node] - line.point;
      const double off = (line.point - reference).norm(), half = 0.5 * options_.spike_distance;
      std::vector<Vec3> targets;
      if (off < half && along.norm() > std::sqrt(half * half - off * off))
        targets.push_back(line.point + along.normalized() * std::sqrt(half * half - off * off));
      targets.push_back(line.point);
      // Pivots: the plane's centre, or a node on it that is close to being a spike itself
      // (kept in place, so the turn does not push it over).
      master_reach(m, groups, clusters);
      std::vector<std::pair<double, int>> close;
      for (int c : clusters) {
        if (planes_.master_of[static_cast<size_t>(c)] != m) continue;
        for (int other : polygons_[static_cast<size_t>(c)].node) {
          if (other < 0 || static_cast<size_t>(other) == node) continue;
          const double d = (node_point_[static_cast<size_t>(other)] -
                            groups_.groups[static_cast<size_t>(node_group_[static_cast<size_t>(other)])].reference)
                               .norm();
          if (d > 0.5 * options_.spike_distance) close.emplace_back(-d, other);
        }
      }
      std::sort(close.begin(), close.end());
      close.erase(std::unique(close.begin(), close.end()), close.end());
      std::vector<Vec3> pivots{planes_.centers[static_cast<size_t>(m)]};
      for (size_t k = 0; k < close.size() && k < 3; ++k)
        pivots.push_back(node_point_[static_cast<size_t>(close[k].second)]);
      bool done = false;
      for (size_t k = 0; k < pivots.size() * targets.size() && !done; ++k) {
        const Vec3& target = targets[k % targets.size()];
        const Plane& old = planes_.planes[static_cast<size_t>(m)];
        Plane turned;
        if (!turned_through(old, pivots[k / targets.size()], target, options_.diameter, max_turn_deg, turned)) continue;
        done = try_master_plane(m, turned, groups, clusters);
      }
      if (done) {
        ++kept;
        break;
      }
    }
  }
  return kept;
}

}  // namespace ff
