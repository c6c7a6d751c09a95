#include "cli/input.h"

#include <chrono>

#include "cli/args.h"
#include "core/mesh/face_map.h"
#include "core/mesh/poly_mesh.h"
#include "core/prepare/subdivision.h"
#include "core/util/error.h"

namespace ff::cli {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

LoadedInput load_input(const std::string& path) {
  LoadedInput in;
  in.path = path;
  auto t0 = std::chrono::steady_clock::now();
  in.raw = read_mesh_file(path);
  in.read_seconds = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  in.clean = clean_mesh(in.raw.mesh);
  in.clean_seconds = seconds_since(t0);
  return in;
}

void subdivide_input(LoadedInput& in, const SubdivisionRequest& request) {
  if (request.levels <= 0) return;
  std::vector<int> polygon(in.clean.face_source.size());
  for (size_t f = 0; f < polygon.size(); ++f) {
    const auto source = static_cast<size_t>(in.clean.face_source[f]);
    polygon[f] = source < in.raw.source_polygon.size() ? in.raw.source_polygon[source] : static_cast<int>(source);
  }
  const PolyMesh control = merge_polygons(in.clean.mesh, polygon);
  const bool loop = control.all_triangles();
  const std::vector<VertexPair> creases = crease_edges(control, request.crease_angle_deg);
  const TriMesh fine =
      loop ? loop_subdivide(in.clean.mesh, request.levels, creases) : catmull_clark(control, request.levels, creases);
  SubdivisionInfo& info = in.subdivision;
  info.levels = request.levels;
  info.scheme = scheme_name(loop ? SubdivisionScheme::Loop : SubdivisionScheme::CatmullClark);
  info.crease_angle_deg = request.crease_angle_deg;
  info.control_vertices = control.num_vertices();
  info.control_faces = control.num_faces();
  info.crease_edges = static_cast<int>(creases.size());
  info.triangles = fine.num_faces();
  const CleanReport file_report = in.clean.report;
  in.clean = clean_mesh(fine);
  in.clean.report = file_report;
}

std::vector<double> load_density(const std::string& path, const LoadedInput& input) {
  const std::vector<double> values = read_numbers_file(path, "--density");
  const size_t vertices = input.raw.mesh.positions.size();
  const size_t faces = input.raw.mesh.triangles.size();
  for (size_t i = 0; i < values.size(); ++i) {
    if (!(values[i] > 0.0)) {
      throw InputError("--density: value " + std::to_string(i + 1) + " is " + std::to_string(values[i]) +
                       "; densities must be greater than 0");
    }
  }
  if (values.size() == vertices) return values_for_clean_vertices(input.clean, values);
  if (values.size() == faces) return values_for_clean_faces(input.clean, values);
  throw InputError("--density: '" + path + "' has " + std::to_string(values.size()) +
                   " values; expected one per vertex (" + std::to_string(vertices) + ") or one per triangle (" +
                   std::to_string(faces) + ")");
}

}  // namespace ff::cli
