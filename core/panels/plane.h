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

}  // namespace ff
