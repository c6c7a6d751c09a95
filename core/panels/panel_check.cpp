#include "core/panels/panel_check.h"

#include "core/panels/polygon2d.h"

namespace ff {

PanelIssues check_panel(const std::vector<Vec3>& points, const std::vector<Vec3>& references, const Plane& plane,
                        double spike_distance, double tolerance) {
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
  const std::vector<Vec2> kernel = area > 0.0 ? polygon_kernel(polygon, tolerance) : std::vector<Vec2>{};
  issues.not_star = kernel.empty();
  const Vec2 reference = kernel.empty() ? polygon_centroid(polygon) : polygon_centroid(kernel);
  issues.flipped = area <= 0.0 || count_flipped_edges(polygon, reference) > 0;
  return issues;
}

}  // namespace ff
