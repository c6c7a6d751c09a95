#pragma once
// Master planes (paper 2.4, fig. 11): neighbouring clusters whose planes differ by less than
// a degree share one plane, so the panel phase never intersects nearly parallel planes.
// "Distinct planes" everywhere downstream means distinct master planes.
#include <utility>
#include <vector>

#include "core/panels/plane.h"

namespace ff {

struct MasterPlanes {
  std::vector<int> master_of;  // per cluster
  std::vector<Plane> planes;   // per master
  std::vector<Vec3> centers;   // per master: the area-weighted centre of its clusters
  std::vector<int> count;      // clusters per master

  const Plane& plane_of(int cluster) const {
    return planes[static_cast<size_t>(master_of[static_cast<size_t>(cluster)])];
  }
};

// Planes of a pair whose line passes closer than this share of their centres' distance to
// the middle between them meet where a curved surface bends, and do not snap (below).
constexpr double kNearLineShare = 0.1;

// Groups `neighbours` (cluster pairs) closer than max_angle_deg, greedily from the closest
// pair, leaving out pairs whose planes meet near them (kNearLineShare): on a smoothly curved
// surface neighbouring planes cross about halfway between their clusters, so their common
// line is well placed however small the angle, while planes that differ by noise (a flat
// region, the strips of a barrel vault) cross far away or not at all. Without that, on a
// shallow dome (rising 1:100, neighbours 0.3 degrees apart at 400 panels) nearly every pair
// snapped, into masters of many panels whose planes, a degree apart, met far from their
// corners: about a third of the panels invalid (README.md, "Shallow surfaces"). The pairs
// left join two groups only while the groups' area-weighted normals stay within the angle
// (so a gently curved strip does not chain into one plane). A group's plane: the
// area-weighted normal through the area-weighted centre. Deterministic.
// `fixed` (per cluster, empty for none): planes kept from an earlier round (settled
// clusters); a group with one keeps that plane exactly, and two groups with different fixed
// planes never join. `alone` (per cluster, empty for none): clusters that keep their own
// plane, in no group.
MasterPlanes snap_master_planes(const std::vector<Plane>& planes, const std::vector<Vec3>& centers,
                                const std::vector<double>& areas, const std::vector<std::pair<int, int>>& neighbours,
                                double max_angle_deg = 1.0, const std::vector<char>& fixed = {},
                                const std::vector<char>& alone = {});

}  // namespace ff
