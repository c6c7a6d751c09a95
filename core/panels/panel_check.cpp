#include "core/panels/panel_check.h"

#include <cmath>

#include "core/panels/glass_split.h"
#include "core/panels/polygon2d.h"
#include "core/util/angles.h"

namespace ff {

PanelIssues check_panel(const std::vector<Vec3>& points, const std::vector<Vec3>& references, const Plane& plane,
                        double spike_distance, double tolerance, double min_corner_angle_deg, bool glass) {
  PanelIssues issues;
  for (size_t i = 0; i < points.size(); ++i) {
    if (!((points[i] - references[i]).norm() <= spike_distance)) issues.spike_vertices += 1;  // NaN too
  }
  if (points.size() < 3) {
    issues.too_few_vertices = true;
    return issues;
  }
  const PlaneFrame frame = make_plane_frame(plane.offset * plane.normal, plane.normal);
  std::vector<Vec2> polygon;
  polygon.reserve(points.size());
  for (const Vec3& p : points) polygon.push_back(frame.to_2d(p));
  issues.not_simple = !is_simple(polygon, tolerance);
  const double area = signed_area(polygon);
  if (area > 0.0 && clearly_in_kernel(polygon, vertex_average(polygon), tolerance)) {
    // Most panels: their vertex average lies in the kernel with room to spare, so the kernel
    // is not empty, and seen from a point of it no edge is flipped. The clipping below would
    // decide the same, at several times the cost.
    issues.not_star = false;
    issues.flipped = false;
  } else {
    const std::vector<Vec2> kernel = area > 0.0 ? polygon_kernel(polygon, tolerance) : std::vector<Vec2>{};
    issues.not_star = kernel.empty();
    const Vec2 reference = kernel.empty() ? polygon_centroid(polygon) : polygon_centroid(kernel);
    issues.flipped = area <= 0.0 || has_flipped_edge(polygon, reference);
  }
  // Skipped when off, so the default run does no extra work and stays bit-identical.
  if (min_corner_angle_deg > 0.0) {
    const bool split = glass && !issues.not_simple && area > 0.0;
    issues.acute_corner = !acute_corners_after_split(polygon, min_corner_angle_deg, split).empty();
  }
  return issues;
}

double corner_angle_deg(const Vec2& prev, const Vec2& at, const Vec2& next) {
  const Vec2 a = prev - at, b = next - at;
  if (a.squaredNorm() == 0.0 || b.squaredNorm() == 0.0) return 0.0;
  // From the outgoing edge counter-clockwise to the incoming one.
  double angle = std::atan2(b.x() * a.y() - b.y() * a.x(), b.dot(a)) * 180.0 / kPi;
  if (angle < 0.0) angle += 360.0;
  return angle;
}

std::vector<int> acute_corners(const std::vector<Vec2>& polygon, double min_deg) {
  std::vector<int> out;
  const size_t n = polygon.size();
  if (n < 3) return out;
  for (size_t i = 0; i < n; ++i) {
    if (corner_angle_deg(polygon[(i + n - 1) % n], polygon[i], polygon[(i + 1) % n]) < min_deg)
      out.push_back(static_cast<int>(i));
  }
  return out;
}

std::vector<int> reflex_corners(const std::vector<Vec2>& polygon) {
  std::vector<int> out;
  const size_t n = polygon.size();
  if (n < 3) return out;
  for (size_t i = 0; i < n; ++i) {
    if (corner_angle_deg(polygon[(i + n - 1) % n], polygon[i], polygon[(i + 1) % n]) > 180.0 + kReflexSlackDeg)
      out.push_back(static_cast<int>(i));
  }
  return out;
}

}  // namespace ff
