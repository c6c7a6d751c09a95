#pragma once
// Plane {n, d}: the points x with n.x = d (n unit). The panel phase works with planes in the
// local frame of FaceData (centred, unit-size), where every tolerance below is relative.
#include "core/mesh/tri_mesh.h"

namespace ff {

struct Plane {
  Vec3 normal = Vec3::UnitZ();
  double offset = 0.0;

  double distance(const Vec3& p) const { return normal.dot(p) - offset; }
  Vec3 project(const Vec3& p) const { return p - distance(p) * normal; }
  static Plane through(const Vec3& point, const Vec3& unit_normal) { return {unit_normal, unit_normal.dot(point)}; }
};

// The plane through `p` and `q` whose normal is nearest `plane`'s: a turn about an axis
// through `p` perpendicular to the old normal (the panel mends aim one plane at a point this
// way and keep the rest of it as close as they can). False, `out` untouched, when the points
// are within 1e-6 `length` of each other, the line pq nearly runs along the old normal, or
// the turn would exceed `max_turn_deg`.
bool turn_plane_through(const Plane& plane, const Vec3& p, const Vec3& q, double length, double max_turn_deg,
                        Plane& out);

}  // namespace ff
