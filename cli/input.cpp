#include "cli/input.h"

#include <chrono>
#include <cstdio>

#include "cli/args.h"
#include "core/mesh/face_map.h"
#include "core/mesh/poly_mesh.h"
#include "core/panels/panel_crossings.h"
#include "core/prepare/subdivision.h"
#include "core/util/error.h"

namespace ff::cli {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

const std::set<std::string>& repair_option_names() {
  static const std::set<std::string> names = {"fill-holes"};
  return names;
}

const std::set<std::string>& repair_switch_names() {
  static const std::set<std::string> names = {"largest-part"};
  return names;
}

CleanOptions parse_repair(const Args& args) {
  CleanOptions o;
  o.fill_holes_max_edges = static_cast<int>(args.get_int("fill-holes", 0, 0, 500));
  o.largest_manifold_part = args.flags.count("largest-part") != 0;
  return o;
}

LoadedInput load_input(const std::string& path, const CleanOptions& options) {
  LoadedInput in;
  in.path = path;
  in.repair = options;
  auto t0 = std::chrono::steady_clock::now();
  in.raw = read_mesh_file(path);
  in.read_seconds = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  try {
    in.clean = clean_mesh(in.raw.mesh, options);
  } catch (const NonManifoldError& e) {
    throw InputError(std::string(e.what()) + "; rerun with --largest-part to keep the largest manifold part (" +
                     std::to_string(e.largest_part_faces) + " of " + std::to_string(e.total_faces) + " faces)");
  } catch (const LargestPartError& e) {  // a stray part far off
    throw InputError(std::string(e.what()) + ", or rerun with --largest-part to keep only the largest part (" +
                     std::to_string(e.largest_part_faces) + " of " + std::to_string(e.total_faces) + " faces)");
  }
  in.clean_seconds = seconds_since(t0);
  // Said at once, not only in the report: the run would otherwise panel the wrong part in silence.
  const std::string doubt = in.clean.report.kept_part_doubt();
  if (!doubt.empty()) std::fprintf(stderr, "flatfacet: warning: --largest-part: %s\n", doubt.c_str());
  // A surface that passes through itself gives panels that do too, at any count: said before
  // the solve, so the designer knows to mend the model rather than to try other counts.
  in.crossings = surface_crossings(in.clean.mesh);
  const SurfaceCrossings& own = *in.crossings;
  if (!own.checked) {
    std::fprintf(stderr,
                 "flatfacet: warning: %s: not checked whether the surface passes through itself: its triangles overlap "
                 "too much in space (long thin triangles around one point?)\n",
                 path.c_str());
  } else if (!own.pairs.empty()) {
    std::fprintf(
        stderr,
        "flatfacet: warning: %s: the surface passes through itself (%zu %s of its triangles cross%s%s): panels "
        "made from it can pass through each other there, whatever their count; mend the model there\n",
        path.c_str(), own.pairs.size(), own.pairs.size() == 1 ? "pair" : "pairs", own.places > 0 ? " " : ", ",
        crossing_where(own.places, own.first_point()).c_str());
  }
  return in;
}

void subdivide_input(LoadedInput& in, const SubdivisionRequest& request) {
  if (request.levels <= 0) return;
  in.crossings.reset();  // of the control mesh
  const std::vector<int> polygon = cleaned_face_polygons(in.clean.face_source, in.raw.source_polygon);
  const ControlSubdivision fine = subdivide_control_mesh(in.clean.mesh, polygon, request.levels, request.crease_angle_deg);
  SubdivisionInfo& info = in.subdivision;
  info.levels = request.levels;
  info.scheme = scheme_name(fine.scheme);
  info.crease_angle_deg = request.crease_angle_deg;
  info.control_vertices = fine.control_vertices;
  info.control_faces = fine.control_faces;
  info.crease_edges = fine.crease_edges;
  info.triangles = fine.mesh.num_faces();
  const CleanReport file_report = in.clean.report;
  in.clean = clean_mesh(fine.mesh);
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
