#include "core/prepare/mesh_transfer.h"

#include <cmath>
#include <string>

#include "core/prepare/surface_projector.h"
#include "core/quality/closest_point.h"
#include "core/util/error.h"

namespace ff {

namespace {

Vec3 centroid(const TriMesh& mesh, int f) {
  const Triangle& t = mesh.triangles[static_cast<size_t>(f)];
  return (mesh.positions[static_cast<size_t>(t[0])] + mesh.positions[static_cast<size_t>(t[1])] +
          mesh.positions[static_cast<size_t>(t[2])]) /
         3.0;
}

}  // namespace

std::vector<double> transfer_vertex_values(const TriMesh& from, const std::vector<double>& values, const TriMesh& to) {
  if (values.size() != from.positions.size())
    throw InputError("the field has " + std::to_string(values.size()) + " values; expected one per vertex (" +
                     std::to_string(from.positions.size()) + ")");
  if (from.triangles.empty()) throw InputError("no surface to carry the field from");
  for (size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i])) throw InputError("field value " + std::to_string(i + 1) + " is not finite");
  const SurfaceProjector projector(from, {});
  std::vector<double> out(to.positions.size(), 0.0);
  int hint = -1;  // consecutive vertices are usually near each other: a cheaper search
  for (size_t v = 0; v < to.positions.size(); ++v) {
    const SurfaceHit hit = projector.on_surface(to.positions[v], hint);
    hint = hit.element;
    out[v] = SurfaceProjector::interpolate(hit, values);
  }
  return out;
}

std::vector<int> nearest_faces_by_centroid(const TriMesh& from, const std::vector<int>& faces, const TriMesh& to) {
  if (to.triangles.empty()) throw InputError("no triangles to carry the faces to");
  for (const int f : faces)
    if (f < 0 || f >= from.num_faces())
      throw InputError("triangle " + std::to_string(f) + " is not in the mesh (" + std::to_string(from.num_faces()) +
                       " triangles)");
  // The centroids of `to` as degenerate triangles (c, c, c): the tree's closest point is then
  // exactly the nearest centroid.
  std::vector<Vec3> points;
  std::vector<Triangle> dots;
  points.reserve(to.triangles.size());
  dots.reserve(to.triangles.size());
  for (int f = 0; f < to.num_faces(); ++f) {
    points.push_back(centroid(to, f));
    dots.push_back({f, f, f});
  }
  const TriangleTree tree(points, dots);
  std::vector<int> out;
  out.reserve(faces.size());
  for (const int f : faces) out.push_back(tree.closest_point(centroid(from, f)).triangle);
  return out;
}

}  // namespace ff
