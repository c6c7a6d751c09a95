#include "core/prepare/isotropic_remesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>

#include "core/prepare/remesh_ops.h"
#include "core/prepare/surface_projector.h"
#include "core/util/angles.h"
#include "core/util/error.h"
#include "core/util/index.h"
#include "core/util/union_find.h"

namespace ff {

using prepare_detail::EditMesh;
using prepare_detail::RemeshState;

namespace {

constexpr double kMaxLengthRatio = 8.0;           // density moves the local target by at most this factor
constexpr double kMinCreaseLength = 3.0;          // crease networks shorter than this many L are noise

// Local targets from the density: L * sqrt(mean / d), clamped.
double length_for(double base, double density, double mean) {
  if (!(density > 0.0) || !(mean > 0.0)) return base;
  const double ratio = std::clamp(std::sqrt(mean / density), 1.0 / kMaxLengthRatio, kMaxLengthRatio);
  return base * ratio;
}

// Marks creases and boundary edges, the vertices on them, and the corners that stay fixed.
// Returns the feature segments (input vertex pairs) in edge order.
std::vector<std::array<int, 2>> mark_features(RemeshState& s, double angle_deg, double min_crease_length) {
  const EditMesh& m = s.mesh;
  const double cos_limit = std::cos(std::min(angle_deg, 180.0) * kPi / 180.0);
  // Creases by angle; zero-area faces have no normal and make none.
  std::vector<char> crease(at(m.num_edges()), 0);
  std::vector<int> parent(at(m.num_vertices()));
  for (int v = 0; v < m.num_vertices(); ++v) parent[at(v)] = v;
  for (int e = 0; e < m.num_edges() && angle_deg < 180.0; ++e) {
    if (m.is_boundary_edge(e)) continue;
    const Vec3 n0 = m.face_normal(m.face(2 * e)), n1 = m.face_normal(m.face(2 * e + 1));
    if (n0.isZero() || n1.isZero() || n0.dot(n1) >= cos_limit) continue;
    crease[at(e)] = 1;
    parent[at(union_find_root(parent, m.to(2 * e)))] = union_find_root(parent, m.to(2 * e + 1));
  }
  // Scanned or coarse surfaces have scattered sharp edges that are noise, not design: crease
  // networks shorter in total than min_crease_length are dropped (boundaries always stay).
  std::vector<double> network_length(at(m.num_vertices()), 0.0);
  for (int e = 0; e < m.num_edges(); ++e)
    if (crease[at(e)]) network_length[at(union_find_root(parent, m.to(2 * e)))] += m.edge_length(e);
  std::vector<std::array<int, 2>> segments;
  std::vector<int> count(at(m.num_vertices()), 0);
  for (int e = 0; e < m.num_edges(); ++e) {
    const bool feature = m.is_boundary_edge(e) ||
                         (crease[at(e)] && network_length[at(union_find_root(parent, m.to(2 * e)))] >= min_crease_length);
    if (!feature) continue;
    s.edge_feature[at(e)] = 1;
    const int a = m.to(2 * e + 1), b = m.to(2 * e);
    ++count[at(a)];
    ++count[at(b)];
    segments.push_back({a, b});
  }
  for (int v = 0; v < m.num_vertices(); ++v) {
    if (count[at(v)] == 0 || m.out(v) < 0) continue;
    s.vertex_feature[at(v)] = 1;
    if (count[at(v)] != 2) {
      s.vertex_locked[at(v)] = 1;
      continue;
    }
    // Two feature edges: a corner when the curve turns by more than the feature angle.
    Vec3 dir[2];
    int k = 0;
    const int h0 = m.out(v);
    int h = h0;
    do {
      if (s.edge_feature[at(EditMesh::edge(h))] && k < 2) dir[k++] = (m.position(m.to(h)) - m.position(v)).normalized();
      h = m.rotate(h);
    } while (h != h0);
    if (dir[0].dot(dir[1]) > -cos_limit) s.vertex_locked[at(v)] = 1;
  }
  return segments;
}

// One step of tangential smoothing, each vertex then projected onto the input (feature
// vertices onto the feature curves); a move that would fold a face is skipped.
void smooth_and_project(RemeshState& s, const SurfaceProjector& projector, const std::vector<double>& input_density,
                        double base_length, double mean_density) {
  EditMesh& m = s.mesh;
  const int nv = m.num_vertices();
  std::vector<Vec3> target(at(nv));
  for (int v = 0; v < nv; ++v) {
    target[at(v)] = m.position(v);
    if (m.vertex_removed(v) || m.out(v) < 0 || s.vertex_locked[at(v)]) continue;
    const Vec3& p = m.position(v);
    const int h0 = m.out(v);
    if (s.vertex_feature[at(v)]) {
      // Slide along the curve toward the midpoint of its two feature neighbours.
      Vec3 w[2];
      int k = 0;
      int h = h0;
      do {
        if (s.edge_feature[at(EditMesh::edge(h))]) {
          if (k < 2) w[k] = m.position(m.to(h));
          ++k;
        }
        h = m.rotate(h);
      } while (h != h0);
      if (k != 2 || (w[1] - w[0]).isZero()) continue;
      const Vec3 t = (w[1] - w[0]).normalized();
      target[at(v)] = p + t * t.dot(0.5 * (w[0] + w[1]) - p);
      continue;
    }
    // Interior: the weighted centroid of the one-ring faces, moved within the tangent
    // plane. Weights are areas relative to the local target, so faces even out in size.
    Vec3 centroid = Vec3::Zero(), normal = Vec3::Zero();
    double weight = 0.0;
    int h = h0;
    do {
      const int f = m.face(h);
      if (f >= 0) {
        const int b = m.to(h), c = m.to(m.next(h));
        const Vec3 n = (m.position(b) - p).cross(m.position(c) - p);
        const double len = (s.vertex_length[at(v)] + s.vertex_length[at(b)] + s.vertex_length[at(c)]) / 3.0;
        const double wgt = 0.5 * n.norm() / (len * len);
        centroid += wgt * (p + m.position(b) + m.position(c)) / 3.0;
        weight += wgt;
        normal += n;
      }
      h = m.rotate(h);
    } while (h != h0);
    if (!(weight > 0.0) || normal.isZero()) continue;
    normal.normalize();
    Vec3 u = centroid / weight - p;
    u -= normal * normal.dot(u);
    target[at(v)] = p + u;
  }
  for (int v = 0; v < nv; ++v) {
    if (m.vertex_removed(v) || m.out(v) < 0 || s.vertex_locked[at(v)]) continue;
    const bool feature = s.vertex_feature[at(v)] != 0;
    const SurfaceHit hit = feature ? projector.on_features(target[at(v)], projector.has_features() ? s.vertex_hint[at(v)] : -1)
                                   : projector.on_surface(target[at(v)], s.vertex_hint[at(v)]);
    const Vec3 p = hit.point;
    bool ok = true;
    const int h0 = m.out(v);
    int h = h0;
    do {
      if (m.face(h) >= 0) {
        const Vec3& b = m.position(m.to(h));
        const Vec3& c = m.position(m.to(m.next(h)));
        const Vec3 after = prepare_detail::triangle_normal(p, b, c);
        if (after.isZero() || after.dot(prepare_detail::triangle_normal(m.position(v), b, c)) <= 0.0) ok = false;
      }
      h = m.rotate(h);
    } while (ok && h != h0);
    if (!ok) continue;
    m.set_position(v, p);
    s.vertex_hint[at(v)] = hit.element;
    if (!input_density.empty()) {
      s.vertex_density[at(v)] = SurfaceProjector::interpolate(hit, input_density);
      s.vertex_length[at(v)] = length_for(base_length, s.vertex_density[at(v)], mean_density);
    }
  }
}

void validate(const TriMesh& mesh, const IsotropicRemeshOptions& o) {
  if (!(o.target_edge_length > 0.0) || !std::isfinite(o.target_edge_length))
    throw InputError("remeshing: the target edge length must be a positive number");
  if (o.iterations < 0 || o.iterations > 1000 || o.smoothing_steps < 0 || o.smoothing_steps > 100)
    throw InputError("remeshing: iterations must be between 0 and 1000, smoothing steps between 0 and 100");
  if (o.max_triangles < 1) throw InputError("remeshing: the triangle limit must be at least 1");
  if (!o.vertex_density.empty()) {
    if (o.vertex_density.size() != mesh.positions.size())
      throw InputError("remeshing: the density has " + std::to_string(o.vertex_density.size()) +
                       " values for " + std::to_string(mesh.positions.size()) + " vertices");
    for (const double d : o.vertex_density)
      if (!(d > 0.0) || !std::isfinite(d)) throw InputError("remeshing: densities must be finite and greater than 0");
  }
}

}  // namespace

IsotropicRemeshResult isotropic_remesh(const TriMesh& mesh, const IsotropicRemeshOptions& options) {
  validate(mesh, options);
  const double L = options.target_edge_length;
  const std::vector<double>& density = options.vertex_density;
  // Area-weighted mean density, and the triangle count the target implies.
  double mean_density = 0.0, area_sum = 0.0, estimate = 0.0;
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const double a = face_area(mesh, f);
    double d = 1.0;
    if (!density.empty()) {
      d = 0.0;
      for (const int v : mesh.triangles[at(f)]) d += density[at(v)] / 3.0;
    }
    mean_density += a * d;
    area_sum += a;
    estimate += a / (std::sqrt(3.0) / 4.0 * L * L);
  }
  mean_density = area_sum > 0.0 ? mean_density / area_sum : 1.0;
  // A density redistributes about the same count (its mean is the mean), so this holds too.
  const double limit = static_cast<double>(options.max_triangles);
  if (estimate > limit)
    throw InputError("remeshing: a target edge length of " + std::to_string(L) + " would need about " +
                     std::to_string(static_cast<long long>(estimate)) + " triangles, more than fit in memory");

  RemeshState s(mesh);
  s.grow();
  IsotropicRemeshResult result;
  const std::vector<std::array<int, 2>> segments = mark_features(s, options.feature_angle_deg, kMinCreaseLength * L);
  const SurfaceProjector projector(mesh, segments);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    s.vertex_length[at(v)] = density.empty() ? L : length_for(L, density[at(v)], mean_density);
    const int h = s.mesh.out(v);
    if (h >= 0) s.vertex_hint[at(v)] = s.mesh.face(h) >= 0 ? s.mesh.face(h) : s.mesh.face(h ^ 1);
    result.feature_corners += s.vertex_locked[at(v)];
  }
  for (int i = 0; i < static_cast<int>(segments.size()); ++i)
    for (const int v : segments[at(i)]) s.vertex_hint[at(v)] = i;
  result.feature_edges = static_cast<int>(segments.size());
  if (!density.empty()) s.vertex_density = density;
  // The area says nothing of slivers: a triangle to a vertex far from the rest has little
  // area for its length, yet each of its long edges is split into at least 3/4 of its
  // length / target pieces, each adding a triangle on either side.
  double split_estimate = mesh.num_faces();
  for (int e = 0; e < s.mesh.num_edges(); ++e)
    split_estimate += 2.0 * std::max(0.0, 0.75 * s.mesh.edge_length(e) / s.target(e) - 1.0);
  if (split_estimate > limit)
    throw InputError("remeshing: a target edge length of " + std::to_string(L) + " would split the long edges into about " +
                     std::to_string(static_cast<long long>(split_estimate)) + " triangles, more than the " +
                     std::to_string(options.max_triangles) + " allowed; " +
                     prepare_detail::longest_edge_phrase(s) + " (a vertex far from the rest of the mesh?)");

  for (int it = 0; it < options.iterations; ++it) {
    prepare_detail::split_long_edges(s, options.max_triangles);
    prepare_detail::collapse_short_edges(s);
    prepare_detail::flip_edges(s);
    for (int k = 0; k < options.smoothing_steps; ++k) smooth_and_project(s, projector, density, L, mean_density);
  }
  std::vector<int> source;
  result.mesh = s.mesh.to_tri_mesh(&source);
  if (!density.empty()) {
    // Carried at the final positions: every vertex at its projection on the input.
    result.vertex_density.resize(source.size());
    for (size_t i = 0; i < source.size(); ++i) {
      const int v = source[i];
      // Input vertices that never moved keep their value; the others are interpolated.
      if (v < mesh.num_vertices() && s.mesh.position(v) == mesh.positions[at(v)]) {
        result.vertex_density[i] = density[at(v)];
        continue;
      }
      const bool feature = s.vertex_feature[at(v)] != 0;
      const SurfaceHit hit = feature ? projector.on_features(s.mesh.position(v), -1) : projector.on_surface(s.mesh.position(v), -1);
      result.vertex_density[i] = SurfaceProjector::interpolate(hit, density);
    }
  }
  return result;
}

std::vector<double> transfer_vertex_field(const TriMesh& input, const std::vector<double>& field,
                                          const std::vector<Vec3>& points) {
  if (field.size() != input.positions.size())
    throw InputError("transfer: the field has " + std::to_string(field.size()) + " values for " +
                     std::to_string(input.positions.size()) + " vertices");
  const SurfaceProjector projector(input, {});
  std::vector<double> out;
  out.reserve(points.size());
  int hint = -1;
  for (const Vec3& p : points) {
    const SurfaceHit hit = projector.on_surface(p, hint);
    hint = hit.element;
    out.push_back(hit.element >= 0 ? SurfaceProjector::interpolate(hit, field) : 0.0);
  }
  return out;
}

std::vector<double> transfer_face_field(const TriMesh& input, const std::vector<double>& field,
                                        const TriMesh& target) {
  if (field.size() != input.triangles.size())
    throw InputError("transfer: the field has " + std::to_string(field.size()) + " values for " +
                     std::to_string(input.triangles.size()) + " faces");
  const SurfaceProjector projector(input, {});
  std::vector<double> out;
  out.reserve(target.triangles.size());
  int hint = -1;
  for (int f = 0; f < target.num_faces(); ++f) {
    const SurfaceHit hit = projector.on_surface(face_centroid(target, f), hint);
    hint = hit.element;
    out.push_back(hit.element >= 0 ? field[at(hit.element)] : 0.0);
  }
  return out;
}

}  // namespace ff
