#include "cli/input.h"

#include <chrono>

#include "cli/args.h"
#include "core/mesh/face_map.h"
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
