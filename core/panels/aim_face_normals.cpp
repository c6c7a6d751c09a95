// Turning planes back toward their faces (issue 3). A panel must face the way its faces do:
// the quality report (core/quality/report.cpp) calls it misoriented when its outline's normal
// points away from the sum of its faces' area normals, and once judge_orientation() is on,
// build_panel() flags a plane that does so as flipped (the outline runs counter-clockwise in
// its own plane, so the two tests agree). A plane can end up turned across its faces
// although its outline still runs counter-clockwise in it (face.obj at 574 panels, seed 2:
// a panel 94 degrees from its faces' normal, which this cannot mend); no spike, so tilting
// and aim_node_planes() have nothing to aim at, and aim_edge_order() turns neighbours only.
// Here such a plane turns about its centre toward
// its faces' normal until it is 80, 60, 30 or 0 degrees from it, or is mirrored across the
// plane normal to it (its tilt kept, now facing the faces: a plane tipped over comes back
// with its trace near where it was); the one that leaves the fewest panels around it invalid
// is kept when that is fewer than before (PanelLayout::set_master_plane, invalid_among).
// Runs only in PanelAttempt::mend, so runs that end valid are unchanged.
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/panels/panel_layout.h"
#include "core/util/angles.h"

namespace ff {

int PanelLayout::aim_face_normals(const std::vector<char>& fixed_masters) {
  const std::vector<int> pinned = single_point_masters();  // they must keep their point
  // Per master: the sum of its clusters' face normals (its faces' direction).
  std::vector<Vec3> faces(planes_.planes.size(), Vec3::Zero());
  for (size_t c = 0; c < faces_normal_.size() && c < planes_.master_of.size(); ++c)
    faces[static_cast<size_t>(planes_.master_of[c])] += faces_normal_[c];
  std::vector<int> groups, clusters;
  int kept = 0;
  for (size_t c = 0; c < issues_.size(); ++c) {  // cluster order: deterministic
    if (issues_[c].valid() || issues_[c].not_disk) continue;
    const int m = planes_.master_of[c];
    const size_t mi = static_cast<size_t>(m);
    if (mi < fixed_masters.size() && fixed_masters[mi]) continue;
    if (std::binary_search(pinned.begin(), pinned.end(), m)) continue;
    const Plane old = planes_.planes[mi];
    if (!(faces[mi].norm() > 0.0) || old.normal.dot(faces[mi]) > 0.0) continue;  // faces its faces
    const Vec3 toward = faces[mi].normalized();
    Vec3 axis = old.normal.cross(toward);
    if (!(axis.norm() > 1e-9)) continue;  // exactly opposite: no one way to turn
    axis.normalize();
    const double angle = std::acos(std::max(-1.0, std::min(1.0, old.normal.dot(toward))));
    master_reach(m, groups, clusters);
    const int before = invalid_among(clusters);
    const Vec3 centre = old.project(planes_.centers[mi]);
    // Toward the faces until 80, 60, 30 or 0 degrees from their normal, or mirrored across
    // the plane normal to it (the same tilt, facing the faces); smallest turn first.
    std::vector<std::pair<double, Vec3>> normals;
    for (double left_deg : {80.0, 60.0, 30.0, 0.0})
      normals.emplace_back(0.0, Eigen::AngleAxisd(angle - left_deg * kPi / 180.0, axis) * old.normal);
    normals.emplace_back(0.0, old.normal - 2.0 * old.normal.dot(toward) * toward);
    for (auto& [turn, normal] : normals) normal.normalize(), turn = -normal.dot(old.normal);
    std::stable_sort(normals.begin(), normals.end(), [](const auto& l, const auto& r) { return l.first < r.first; });
    // The turn leaving the fewest panels around it invalid (the smaller turn among equals),
    // kept when that is fewer than before.
    int best = before;
    Plane chosen = old;
    for (const auto& entry : normals) {
      set_master_plane(m, Plane::through(centre, entry.second), groups, clusters);
      const int after = invalid_among(clusters);
      if (after < best) best = after, chosen = planes_.planes[mi];
    }
    set_master_plane(m, chosen, groups, clusters);
    kept += best < before ? 1 : 0;
  }
  return kept;
}

}  // namespace ff
