// Single-point nodes (paper 2.2, the option to make 4+ planes meet in one point): every
// 4+-cluster corner as one point, and the last mend that does it only at invalid corners,
// turning planes through the points already fixed. Kept apart from panel_fixes.cpp, the
// other fixes a PanelLayout makes without reclustering.
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>

#include "core/panels/panel_layout.h"
#include "core/panels/vertex_rule.h"

namespace ff {

namespace {

// The least-squares point of the masters' planes, held to `reference` by a small weight (so
// it is defined when the planes do not pin a point).
Vec3 least_squares_point(const std::vector<Plane>& planes, const std::vector<int>& masters, const Vec3& reference) {
  Eigen::Matrix3d A = 1e-6 * Eigen::Matrix3d::Identity();
  Vec3 b = 1e-6 * reference;
  for (int m : masters) {
    const Plane& p = planes[static_cast<size_t>(m)];
    A += p.normal * p.normal.transpose();
    b += p.offset * p.normal;
  }
  return A.ldlt().solve(b);
}

// The plane nearest `plane` through every point (at most three; an empty list: false),
// oriented like it; false when the points do not pin it down well (two nearly equal points,
// three nearly on a line, the plane's own normal along the line) or it would turn by more
// than about 20 degrees. `length`: the scale below which points count as the same.
bool through_points(const Plane& plane, const std::vector<Vec3>& points, double length, Plane& out) {
  constexpr double kMinCosine = 0.94;  // about 20 degrees
  if (points.empty() || points.size() > 3) return false;
  Vec3 normal = plane.normal;
  if (points.size() >= 2) {
    const Vec3 u = points[1] - points[0];
    if (!(u.norm() > 1e-6 * length)) return false;
    if (points.size() == 2) {
      normal -= normal.dot(u.normalized()) * u.normalized();
    } else {
      normal = u.cross(points[2] - points[0]);
      // Nearly on a line: the plane would turn on noise.
      if (!(normal.norm() > 1e-3 * u.norm() * (points[2] - points[0]).norm())) return false;
      if (normal.dot(plane.normal) < 0.0) normal = -normal;
    }
  }
  if (!(normal.norm() > 1e-6)) return false;
  normal.normalize();
  if (!(normal.dot(plane.normal) >= kMinCosine)) return false;
  out = Plane::through(points[0], normal);
  return true;
}

}  // namespace

int PanelLayout::make_single_point_nodes(const std::vector<char>& fixed_clusters) {
  std::vector<std::vector<Vec3>> through(planes_.planes.size());  // points each plane must contain
  // Planes already pinned through a single point (single_point_fix) count as full: they stay,
  // as do the fixed ones.
  for (int m : single_point_masters()) through[static_cast<size_t>(m)].assign(2, Vec3::Zero());
  for (size_t c = 0; c < fixed_clusters.size() && c < planes_.master_of.size(); ++c) {
    if (fixed_clusters[c]) through[static_cast<size_t>(planes_.master_of[c])].assign(2, Vec3::Zero());
  }
  int made = 0;
  for (size_t g = 0; g < groups_.groups.size(); ++g) {
    const NodeGroup& group = groups_.groups[g];
    if (group.on_boundary || single_[g] || held_group_[g]) continue;
    std::vector<int> masters;
    for (int c : clusters_of_group(static_cast<int>(g))) {
      const int m = planes_.master_of[static_cast<size_t>(c)];
      if (std::find(masters.begin(), masters.end(), m) == masters.end()) masters.push_back(m);
    }
    if (masters.size() < 4) continue;
    bool room = true;
    for (int m : masters) room = room && through[static_cast<size_t>(m)].size() < 2;
    if (!room) continue;
    const Vec3 x = least_squares_point(planes_.planes, masters, group.reference);
    if (!x.allFinite() || !((x - group.reference).norm() <= options_.spike_distance)) continue;
    // A plane already pinned through a point can turn to contain x only about a real line.
    bool turnable = true;
    for (int m : masters) {
      const std::vector<Vec3>& fixed = through[static_cast<size_t>(m)];
      if (fixed.empty()) continue;
      const Vec3 along = x - fixed[0];
      const Vec3& normal = planes_.planes[static_cast<size_t>(m)].normal;
      turnable = turnable && along.norm() > 1e-9 * options_.diameter &&
                 (normal - normal.dot(along.normalized()) * along.normalized()).norm() > 1e-6;
    }
    if (!turnable) continue;
    const MasterPlanes saved = planes_;
    const Faults before = faults();
    for (int m : masters) {
      Plane& p = planes_.planes[static_cast<size_t>(m)];
      const std::vector<Vec3>& fixed = through[static_cast<size_t>(m)];
      if (fixed.empty()) {
        p = Plane::through(x, p.normal);
      } else {
        // Rotate about the line through the first point so the plane also contains x.
        const Vec3 u = (x - fixed[0]).normalized();
        const Vec3 n = (p.normal - p.normal.dot(u) * u).normalized();
        p = Plane::through(fixed[0], n);
      }
    }
    single_[g] = 1;
    single_point_[g] = x;
    rebuild_all();
    if (!faults().no_worse_than(before)) {
      planes_ = saved;
      single_[g] = 0;
      rebuild_all();
      continue;
    }
    for (int m : masters) through[static_cast<size_t>(m)].push_back(x);
    ++made;
  }
  return made;
}

int PanelLayout::single_point_fix(const std::vector<char>& fixed_masters) {
  // Interior groups of four or more clusters at the corners of invalid panels.
  std::vector<int> candidates;
  for (size_t c = 0; c < polygons_.size(); ++c) {
    if (issues_[c].valid()) continue;
    for (int node : polygons_[c].node) {
      if (node >= 0) candidates.push_back(node_group_[static_cast<size_t>(node)]);
    }
  }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  // Per master: the points of single groups its plane must keep passing through. A panel
  // whose corners are several such groups (a short panel between three 4-plane groups) needs
  // its plane through all of them: through a second point it turns about the line from the
  // first, through a third it is the plane of the three (through_points()).
  std::vector<std::vector<Vec3>> through(planes_.planes.size());
  for (size_t g = 0; g < single_.size(); ++g) {
    if (!single_[g]) continue;
    for (int m : distinct_masters(static_cast<int>(g))) through[static_cast<size_t>(m)].push_back(single_point_[g]);
  }
  // A panel may need several of its groups made single: each is kept while it adds no
  // invalid panel, and all of them go back when together they mend none.
  const int start = num_invalid();
  const std::vector<Plane> start_planes = planes_.planes;
  const std::vector<char> start_single = single_;
  int made = 0;
  for (int g : candidates) {
    const NodeGroup& group = groups_.groups[static_cast<size_t>(g)];
    if (group.on_boundary || single_[static_cast<size_t>(g)] || held_group_[static_cast<size_t>(g)]) continue;
    const std::vector<int> masters = distinct_masters(g);
    // Three distinct planes at a group of four or more clusters (two of them share a master):
    // the planes already meet in one point, while the group's nodes on only two of them run
    // along their line. That point, when near, is the group's vertex, no plane moving.
    const bool three = masters.size() == 3 && clusters_of_group(g).size() >= 4;
    if (masters.size() < 4 && !three) continue;
    // Still next to an invalid panel (an earlier fix may have mended it).
    bool needed = false;
    for (int c : clusters_of_group(g)) needed = needed || !issues_[static_cast<size_t>(c)].valid();
    if (!needed) continue;
    // The point: least squares on the planes, held to the reference by a small weight; on
    // the one fixed plane if there is one (two or more: no point).
    std::vector<int> fixed, free;
    for (int m : masters) {
      const bool keep = static_cast<size_t>(m) < fixed_masters.size() && fixed_masters[static_cast<size_t>(m)];
      (keep ? fixed : free).push_back(m);
    }
    Vec3 x = least_squares_point(planes_.planes, masters, group.reference);
    if (three) {
      std::vector<Plane> meeting;
      for (int m : masters) meeting.push_back(planes_.planes[static_cast<size_t>(m)]);
      const VertexRuleResult r = closest_point_on_planes(meeting, group.reference);
      if (!r.exact) continue;
      x = r.point;
      free.clear();
    } else {
      if (fixed.size() > 1) continue;
      if (!fixed.empty()) x = planes_.planes[static_cast<size_t>(fixed[0])].project(x);
    }
    if (!x.allFinite() || !((x - group.reference).norm() <= options_.spike_distance)) continue;
    const std::vector<Plane> old = planes_.planes;
    bool moved = true;
    for (int m : free) {
      std::vector<Vec3> points = through[static_cast<size_t>(m)];
      points.push_back(x);
      Plane& plane = planes_.planes[static_cast<size_t>(m)];
      moved = moved && through_points(plane, points, options_.diameter, plane);
    }
    if (!moved) {
      planes_.planes = old;
      continue;
    }
    const int before = num_invalid();
    single_[static_cast<size_t>(g)] = 1;
    single_point_[static_cast<size_t>(g)] = x;
    rebuild_changed(old);
    place_group_nodes(g);
    rebuild(clusters_of_group(g));
    if (num_invalid() <= before) {
      for (int m : masters) through[static_cast<size_t>(m)].push_back(x);
      ++made;
      continue;
    }
    undo_group_single(g, old);
  }
  if (made > 0 && num_invalid() >= start) {
    planes_.planes = start_planes;
    single_ = start_single;
    rebuild_all();
    return 0;
  }
  return made;
}

bool PanelLayout::make_group_single(int g, std::vector<Plane>& old) {
  const NodeGroup& group = groups_.groups[static_cast<size_t>(g)];
  if (group.on_boundary || single_[static_cast<size_t>(g)] || held_group_[static_cast<size_t>(g)]) return false;
  const std::vector<int> masters = distinct_masters(g);
  if (masters.size() < 4) return false;
  // A plane through another group's point already would have to turn to keep it.
  const std::vector<int> pinned = single_point_masters();
  for (int m : masters) {
    if (std::binary_search(pinned.begin(), pinned.end(), m)) return false;
  }
  const Vec3 x = least_squares_point(planes_.planes, masters, group.reference);
  if (!x.allFinite() || !((x - group.reference).norm() <= options_.spike_distance)) return false;
  old = planes_.planes;
  for (int m : masters) {
    Plane& p = planes_.planes[static_cast<size_t>(m)];
    p = Plane::through(x, p.normal);
  }
  single_[static_cast<size_t>(g)] = 1;
  single_point_[static_cast<size_t>(g)] = x;
  rebuild_changed(old);
  place_group_nodes(g);
  rebuild(clusters_of_group(g));
  return true;
}

void PanelLayout::undo_group_single(int g, const std::vector<Plane>& old) {
  const std::vector<Plane> changed = planes_.planes;
  planes_.planes = old;
  single_[static_cast<size_t>(g)] = 0;
  rebuild_changed(changed);
  place_group_nodes(g);
  rebuild(clusters_of_group(g));
}

std::vector<int> PanelLayout::distinct_masters(int group) const {
  std::vector<int> masters;
  for (int c : clusters_of_group(group)) {
    const int m = planes_.master_of[static_cast<size_t>(c)];
    if (std::find(masters.begin(), masters.end(), m) == masters.end()) masters.push_back(m);
  }
  return masters;
}

std::vector<int> PanelLayout::single_point_masters() const {
  std::vector<int> out;
  for (size_t g = 0; g < single_.size(); ++g) {
    if (!single_[g]) continue;
    for (int c : clusters_of_group(static_cast<int>(g))) out.push_back(planes_.master_of[static_cast<size_t>(c)]);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace ff
