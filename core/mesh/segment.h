#pragma once
// The point of segment ab nearest to p, and the distance to it: the border walk
// (density/border_distance), the border simplification (panels/border_vertices) and the
// closest points on degenerate triangles (quality/closest_point) share it.
#include <algorithm>

#include "core/mesh/tri_mesh.h"

namespace ff {

// a for a zero-length segment.
inline Vec3 closest_point_on_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return a + t * ab;
}

inline double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  return (closest_point_on_segment(p, a, b) - p).norm();
}

}  // namespace ff
