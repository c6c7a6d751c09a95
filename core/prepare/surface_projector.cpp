#include "core/prepare/surface_projector.h"

#include <algorithm>

namespace ff {

namespace {

std::vector<Triangle> segment_triangles(const std::vector<std::array<int, 2>>& segments) {
  std::vector<Triangle> out;
  out.reserve(segments.size());
  for (const auto& s : segments) out.push_back({s[0], s[1], s[1]});
  return out;
}

}  // namespace

std::array<double, 3> barycentric(const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 v0 = b - a, v1 = c - a, v2 = q - a;
  const double d00 = v0.dot(v0), d01 = v0.dot(v1), d11 = v1.dot(v1);
  const double d20 = v2.dot(v0), d21 = v2.dot(v1);
  const double denom = d00 * d11 - d01 * d01;
  if (denom > 1e-14 * d00 * d11 && denom > 0.0) {
    const double v = std::clamp((d11 * d20 - d01 * d21) / denom, 0.0, 1.0);
    const double w = std::clamp((d00 * d21 - d01 * d20) / denom, 0.0, 1.0 - v);
    return {1.0 - v - w, v, w};
  }
  // Degenerate: the nearest vertex, or a point on the longest side for a segment.
  const double da = (q - a).squaredNorm(), db = (q - b).squaredNorm(), dc = (q - c).squaredNorm();
  if (d00 > 0.0 && d00 >= d11) {
    const double t = std::clamp(d20 / d00, 0.0, 1.0);
    return {1.0 - t, t, 0.0};
  }
  if (d11 > 0.0) {
    const double t = std::clamp(d21 / d11, 0.0, 1.0);
    return {1.0 - t, 0.0, t};
  }
  if (da <= db && da <= dc) return {1.0, 0.0, 0.0};
  return db <= dc ? std::array<double, 3>{0.0, 1.0, 0.0} : std::array<double, 3>{0.0, 0.0, 1.0};
}

SurfaceProjector::SurfaceProjector(const TriMesh& mesh, const std::vector<std::array<int, 2>>& segments)
    : positions_(mesh.positions),
      triangles_(mesh.triangles),
      segments_(segments),
      surface_(mesh.positions, mesh.triangles),
      features_(mesh.positions, segment_triangles(segments)) {}

SurfaceHit SurfaceProjector::make_hit(const ClosestPoint& cp, bool segment) const {
  SurfaceHit hit;
  hit.point = cp.point;
  hit.element = cp.triangle;
  if (cp.triangle < 0) return hit;
  const size_t e = static_cast<size_t>(cp.triangle);
  if (segment) {
    const auto& s = segments_[e];
    const Vec3& a = positions_[static_cast<size_t>(s[0])];
    const Vec3& b = positions_[static_cast<size_t>(s[1])];
    const double len2 = (b - a).squaredNorm();
    const double t = len2 > 0.0 ? std::clamp((cp.point - a).dot(b - a) / len2, 0.0, 1.0) : 0.0;
    hit.vertices = {s[0], s[1], s[1]};
    hit.weights = {1.0 - t, t, 0.0};
    return hit;
  }
  const Triangle& t = triangles_[e];
  hit.vertices = t;
  hit.weights = barycentric(cp.point, positions_[static_cast<size_t>(t[0])], positions_[static_cast<size_t>(t[1])],
                            positions_[static_cast<size_t>(t[2])]);
  return hit;
}

SurfaceHit SurfaceProjector::on_surface(const Vec3& p, int hint) const {
  return make_hit(surface_.closest_point(p, hint), false);
}

SurfaceHit SurfaceProjector::on_features(const Vec3& p, int hint) const {
  if (segments_.empty()) return on_surface(p, -1);
  return make_hit(features_.closest_point(p, hint), true);
}

double SurfaceProjector::interpolate(const SurfaceHit& hit, const std::vector<double>& per_vertex) {
  double value = 0.0;
  for (int i = 0; i < 3; ++i)
    value += hit.weights[static_cast<size_t>(i)] * per_vertex[static_cast<size_t>(hit.vertices[static_cast<size_t>(i)])];
  return value;
}

}  // namespace ff
