#pragma once
// Projection back onto the input surface for the remesher, and carrying per-vertex fields
// (painted density) from the input to points on it. Reuses the AABB tree of
// core/quality/closest_point.h; feature curves (creases, boundaries) are stored in a second
// tree as degenerate triangles (a, b, b), which closest_point_on_triangle treats exactly as
// segments.
#include <array>
#include <vector>

#include "core/mesh/tri_mesh.h"
#include "core/quality/closest_point.h"

namespace ff {

struct SurfaceHit {
  Vec3 point = Vec3::Zero();
  int element = -1;  // input triangle, or index into the feature segments
  // Barycentric weights of point on that element's vertices (segments: weights[2] == 0).
  std::array<double, 3> weights = {1.0, 0.0, 0.0};
  std::array<int, 3> vertices = {0, 0, 0};  // input vertex indices the weights refer to
};

class SurfaceProjector {
 public:
  // mesh: the input surface (copied into the trees); segments: input vertex pairs of the
  // feature curves (may be empty). Throws InputError on invalid indices.
  SurfaceProjector(const TriMesh& mesh, const std::vector<std::array<int, 2>>& segments);

  // Closest point on the surface; hint: a triangle likely near (or -1).
  SurfaceHit on_surface(const Vec3& p, int hint = -1) const;
  // Closest point on the feature curves (falls back to on_surface when there are none).
  SurfaceHit on_features(const Vec3& p, int hint = -1) const;
  bool has_features() const { return !segments_.empty(); }

  // A per-input-vertex field at a hit: the barycentric interpolation.
  static double interpolate(const SurfaceHit& hit, const std::vector<double>& per_vertex);

 private:
  SurfaceHit make_hit(const ClosestPoint& cp, bool segment) const;

  std::vector<Vec3> positions_;
  std::vector<Triangle> triangles_;
  std::vector<std::array<int, 2>> segments_;
  TriangleTree surface_;
  TriangleTree features_;
};

// Barycentric weights of q (assumed in the plane of abc) in triangle abc; a degenerate
// triangle gives the weights of its nearest vertex.
std::array<double, 3> barycentric(const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace ff
