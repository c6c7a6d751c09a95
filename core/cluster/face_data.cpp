#include "core/cluster/face_data.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>

#include "core/util/error.h"

namespace ff {

namespace {

std::vector<double> face_density(const TriMesh& mesh, const std::vector<double>& values) {
  const size_t faces = mesh.triangles.size();
  std::vector<double> density(faces, 1.0);
  if (values.empty()) return density;
  const size_t vertices = mesh.positions.size();
  if (values.size() != vertices && values.size() != faces) {
    throw InputError("density has " + std::to_string(values.size()) + " values; expected one per vertex (" +
                     std::to_string(vertices) + ") or one per face (" + std::to_string(faces) + ")");
  }
  for (size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i]) || values[i] <= 0.0) {
      throw InputError("density value " + std::to_string(i + 1) + " is " + std::to_string(values[i]) +
                       "; densities must be finite and greater than 0");
    }
  }
  // A density of 1e308 overflowed the sums below and the area-weighted mean (it crashed the
  // seeding); 1e-320 underflowed.
  const std::vector<double> shifted = density_ratios(values);
  // When the counts coincide, per vertex wins: it is what painting and --density produce.
  if (values.size() != vertices) return shifted;
  for (size_t f = 0; f < faces; ++f) {
    const Triangle& t = mesh.triangles[f];
    density[f] =
        (shifted[static_cast<size_t>(t[0])] + shifted[static_cast<size_t>(t[1])] + shifted[static_cast<size_t>(t[2])]) /
        3.0;
  }
  return density;
}

}  // namespace

std::vector<double> density_ratios(const std::vector<double>& values) {
  if (values.empty()) return {};
  int exponent = 0;
  std::frexp(*std::max_element(values.begin(), values.end()), &exponent);
  std::vector<double> shifted(values.size());
  for (size_t i = 0; i < values.size(); ++i) shifted[i] = std::ldexp(values[i], -exponent);
  return shifted;
}

FaceData make_face_data(const TriMesh& mesh, const std::vector<double>& density) {
  FaceData data;
  const size_t faces = mesh.triangles.size();
  if (!mesh.positions.empty()) {
    const BoundingBox box = bounding_box(mesh);
    // Halves first: hi - lo may overflow for coordinates near the largest double.
    data.origin = 0.5 * box.lo + 0.5 * box.hi;
    const double half_extent = (0.5 * box.hi - 0.5 * box.lo).maxCoeff();
    if (half_extent > 0.0 && std::isfinite(half_extent)) data.scale = half_extent;
  }
  const double inv_scale = 1.0 / data.scale;
  const auto local = [&](int v) {
    return Vec3(mesh.positions[static_cast<size_t>(v)] * inv_scale - data.origin * inv_scale);
  };
  data.records.resize(faces);
  const std::vector<double> density_per_face = face_density(mesh, density);
  for (size_t f = 0; f < faces; ++f) {
    FaceRecord& r = data.records[f];
    const Triangle& t = mesh.triangles[f];
    const Vec3 a = local(t[0]), b = local(t[1]), c = local(t[2]);
    const Vec3 cross = (b - a).cross(c - a);
    const double len = cross.norm();
    r.area = 0.5 * len;
    r.normal = len > 0.0 ? Vec3(cross / len) : Vec3::Zero();
    r.centroid = (a + b + c) / 3.0;
    const Vec3 da = a - r.centroid, db = b - r.centroid, dc = c - r.centroid;
    const auto s = [&](int i, int j) { return (da[i] * da[j] + db[i] * db[j] + dc[i] * dc[j]) / 12.0; };
    r.spread = {s(0, 0), s(1, 1), s(2, 2), s(0, 1), s(0, 2), s(1, 2)};
    r.density = density_per_face[f];
    data.total_area += r.area;
  }
  // Normalise to an area-weighted mean of 1 so the expected cluster diameter keeps its meaning.
  double weighted = 0.0;
  for (const FaceRecord& r : data.records) weighted += r.area * r.density;
  if (weighted > 0.0 && data.total_area > 0.0) {
    const double scale = data.total_area / weighted;
    for (FaceRecord& r : data.records) r.density *= scale;
  }
  return data;
}

}  // namespace ff
