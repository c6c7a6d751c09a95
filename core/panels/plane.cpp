#include "core/panels/plane.h"

#include <cmath>

#include "core/util/angles.h"

namespace ff {

bool turn_plane_through(const Plane& plane, const Vec3& p, const Vec3& q, double length, double max_turn_deg,
                        Plane& out) {
  const Vec3 d = q - p;
  if (!(d.norm() > 1e-6 * length)) return false;
  const Vec3 dir = d.normalized();
  Vec3 normal = plane.normal - plane.normal.dot(dir) * dir;  // drop the part along the line
  if (!(normal.norm() > 1e-6)) return false;
  normal.normalize();
  if (!(normal.dot(plane.normal) >= std::cos(max_turn_deg * kPi / 180.0))) return false;
  out = Plane::through(p, normal);
  return true;
}

}  // namespace ff
