#include "core/panels/boundary_term.h"

namespace ff {

BoundaryTerm::BoundaryTerm(const FaceData& faces, const PanelLayout& layout, double weight, double diameter)
    : faces_(faces), scale_(diameter > 0.0 ? weight / (kLengthUnit * diameter) : 0.0) {
  const int n = layout.num_clusters();
  frames_.resize(static_cast<size_t>(n));
  polygons_.resize(static_cast<size_t>(n));
  for (int c = 0; c < n; ++c) {
    // Invalid panels keep their term too: a cluster without one would cost nothing to grow
    // into and swallow its neighbours' stray faces (rings around enclosed clusters).
    if (layout.polygon(c).points.size() < 3) continue;
    const Plane& plane = layout.planes().plane_of(c);
    frames_[static_cast<size_t>(c)] = make_plane_frame(plane.offset * plane.normal, plane.normal);
    polygons_[static_cast<size_t>(c)].reserve(layout.polygon(c).points.size());
    for (const Vec3& p : layout.polygon(c).points)
      polygons_[static_cast<size_t>(c)].push_back(frames_[static_cast<size_t>(c)].to_2d(p));
  }
}

void BoundaryTerm::ignore(int cluster) {
  if (cluster >= 0 && static_cast<size_t>(cluster) < polygons_.size()) polygons_[static_cast<size_t>(cluster)].clear();
}

void BoundaryTerm::freeze(const std::vector<char>& settled, const std::vector<int>& labels) {
  settled_ = settled;
  labels_ = labels;
}

int BoundaryTerm::fixed_label(int face) const {
  if (settled_.empty()) return -1;
  const int current = labels_[static_cast<size_t>(face)];
  return current >= 0 && static_cast<size_t>(current) < settled_.size() && settled_[static_cast<size_t>(current)]
             ? current
             : -1;
}

double BoundaryTerm::operator()(int face, int cluster) const {
  if (!settled_.empty()) {
    const int current = labels_[static_cast<size_t>(face)];
    if (current != cluster &&
        ((current >= 0 && static_cast<size_t>(current) < settled_.size() && settled_[static_cast<size_t>(current)]) ||
         (static_cast<size_t>(cluster) < settled_.size() && settled_[static_cast<size_t>(cluster)])))
      return kForbidden;
  }
  if (scale_ == 0.0 || cluster < 0 || static_cast<size_t>(cluster) >= polygons_.size()) return 0.0;
  const std::vector<Vec2>& polygon = polygons_[static_cast<size_t>(cluster)];
  if (polygon.empty()) return 0.0;
  const FaceRecord& r = faces_[static_cast<size_t>(face)];
  const Vec2 p = frames_[static_cast<size_t>(cluster)].to_2d(r.centroid);
  if (point_in_polygon(polygon, p)) return 0.0;
  return r.area * scale_ * distance_to_boundary(polygon, p);
}

}  // namespace ff
