#include "core/density/density_field.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "core/density/border_distance.h"
#include "core/util/error.h"

namespace ff {

namespace {

constexpr double kMaxRatio = 1e6;

std::string ratio_text(double x) {
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}

}  // namespace

std::vector<double> expression_density(const TriMesh& mesh, const MeshTopology& topology, const Expression& expression,
                                       const VertexCurvature* curvature) {
  if (expression.uses_curvature() && curvature == nullptr)
    throw InputError("density expression: curvature is needed but was not computed");
  const size_t n = mesh.positions.size();
  const BoundingBox box = bounding_box(mesh);
  const Vec3 extent = box.hi - box.lo;
  const double diagonal = bbox_diagonal(mesh);
  const std::vector<Vec3> normals = curvature ? curvature->normal : vertex_normals(mesh, topology);
  std::vector<double> border;
  if (expression.uses(ExprVar::Border)) border = border_distance(mesh, topology);
  std::vector<double> out(n, 1.0);
  double lo = 0.0, hi = 0.0;
  for (size_t v = 0; v < n; ++v) {
    const Vec3& p = mesh.positions[v];
    ExprInputs in{};
    const auto set = [&in](ExprVar var, double value) { in[static_cast<size_t>(var)] = value; };
    set(ExprVar::X, p.x());
    set(ExprVar::Y, p.y());
    set(ExprVar::Z, p.z());
    // Per axis 0..1 over the box; a flat axis sits at its middle.
    for (int a = 0; a < 3; ++a) {
      const double t = extent[a] > 0.0 ? (p[a] - box.lo[a]) / extent[a] : 0.5;
      in[static_cast<size_t>(ExprVar::U) + static_cast<size_t>(a)] = std::isfinite(t) ? t : 0.5;
    }
    set(ExprVar::NX, normals[v].x());
    set(ExprVar::NY, normals[v].y());
    set(ExprVar::NZ, normals[v].z());
    if (curvature) {
      const double k1 = curvature->k1[v], k2 = curvature->k2[v];
      set(ExprVar::K1, k1);
      set(ExprVar::K2, k2);
      set(ExprVar::H, 0.5 * (k1 + k2));
      set(ExprVar::K, k1 * k2);
      set(ExprVar::Curv, 0.5 * (std::abs(k1) + std::abs(k2)) * diagonal);
    }
    if (!border.empty()) {
      // Scale-free like u v w and curv, and at most 1 (a straight distance inside the box);
      // no border to reach is as far as the model is big (also a zero diagonal, which the
      // solve refuses as a surface of zero area).
      const double d = border[v] / diagonal;
      set(ExprVar::Border, std::isfinite(d) ? d : 1.0);
    }
    const double value = expression.evaluate(in);
    if (!std::isfinite(value) || !(value > 0.0)) {
      throw InputError("density expression gives " + ratio_text(value) + " at vertex " + std::to_string(v + 1) + " (" +
                       ratio_text(p.x()) + ", " + ratio_text(p.y()) + ", " + ratio_text(p.z()) +
                       "); densities must be finite and greater than 0");
    }
    lo = v == 0 ? value : std::min(lo, value);
    hi = v == 0 ? value : std::max(hi, value);
    out[v] = value;
  }
  if (n > 0 && hi > kMaxRatio * lo) {
    throw InputError("density expression ranges from " + ratio_text(lo) + " to " + ratio_text(hi) +
                     "; keep the largest value within 1e6 times the smallest");
  }
  return out;
}

std::vector<double> expression_density(const TriMesh& mesh, const std::string& expression) {
  const Expression parsed = Expression::parse(expression);
  const MeshTopology topology = build_topology(mesh);
  std::optional<VertexCurvature> curvature;
  if (parsed.uses_curvature()) curvature = vertex_curvature(mesh, topology);
  return expression_density(mesh, topology, parsed, curvature ? &*curvature : nullptr);
}

FaceData make_shaped_face_data(const TriMesh& mesh, const MeshTopology& topology, const std::vector<double>& painted,
                               const std::string& expression, const Anisotropy& anisotropy) {
  validate_anisotropy(anisotropy);
  // The painted or file density within the range the expression has to keep (a file of 1 and
  // 1e300 was taken, the same field as an expression refused).
  if (!painted.empty()) {
    const auto [lo, hi] = std::minmax_element(painted.begin(), painted.end());
    if (std::isfinite(*hi) && *lo > 0.0 && *hi > kMaxRatio * *lo) {
      throw InputError("density ranges from " + ratio_text(*lo) + " to " + ratio_text(*hi) +
                       "; keep the largest value within 1e6 times the smallest");
    }
  }
  std::optional<Expression> parsed;
  if (!expression.empty()) parsed = Expression::parse(expression);
  // Before the product with the expression's values (1e308 times 4 overflowed).
  const std::vector<double> paint = density_ratios(painted);
  const bool need_curvature =
      (parsed && parsed->uses_curvature()) || (anisotropy.active() && anisotropy.uses_curvature());
  std::optional<VertexCurvature> curvature;
  if (need_curvature) curvature = vertex_curvature(mesh, topology);
  const VertexCurvature* k = curvature ? &*curvature : nullptr;
  if (!parsed) {
    FaceData data = make_face_data(mesh, paint);
    data.stretch = face_stretch_vectors(mesh, anisotropy, k);
    return data;
  }
  std::vector<double> density = expression_density(mesh, topology, *parsed, k);
  const size_t vertices = mesh.positions.size(), faces = mesh.triangles.size();
  if (!painted.empty() && painted.size() != vertices && painted.size() != faces) {
    make_face_data(mesh, painted);  // throws its usual message about the count
  }
  if (!painted.empty() && painted.size() != vertices) {
    // Per-face paint: each face's value times the mean of its corners' expression values.
    std::vector<double> per_face(faces);
    for (size_t f = 0; f < faces; ++f) {
      const Triangle& t = mesh.triangles[f];
      const double mean = (density[static_cast<size_t>(t[0])] + density[static_cast<size_t>(t[1])] +
                           density[static_cast<size_t>(t[2])]) /
                          3.0;
      per_face[f] = paint[f] * mean;
    }
    density = std::move(per_face);
  } else if (!painted.empty()) {
    for (size_t v = 0; v < vertices; ++v) density[v] *= paint[v];
  }
  FaceData data = make_face_data(mesh, density);
  data.stretch = face_stretch_vectors(mesh, anisotropy, k);
  return data;
}

}  // namespace ff
