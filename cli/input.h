#pragma once
// Loading what every command starts from: read the file, clean it, map a density file onto
// the cleaned mesh. Shared by `cluster` and (later) `remesh`.
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "cli/args.h"
#include "core/mesh/clean.h"
#include "core/mesh/mesh_io.h"
#include "core/panels/panel_crossings.h"

namespace ff::cli {

// What `--subdivide` did (levels == 0: nothing).
struct SubdivisionInfo {
  int levels = 0;
  std::string scheme;  // "loop" or "catmull-clark"
  double crease_angle_deg = 180.0;
  int control_vertices = 0, control_faces = 0, crease_edges = 0;
  int triangles = 0;  // out of the subdivision (its time counts in the report's prepare)
};

struct LoadedInput {
  std::string path;
  RawMesh raw;
  CleanMesh clean;
  double read_seconds = 0.0;
  double clean_seconds = 0.0;
  SubdivisionInfo subdivision;
  CleanOptions repair;  // what was asked of clean_mesh()
  // surface_crossings(clean.mesh), checked as it loads (the warning); none once subdivided.
  std::optional<SurfaceCrossings> crossings;
};

// `--fill-holes N` (0..500 edges, 0 = off) and `--largest-part` (remesh and cluster): how
// clean_mesh() repairs the input.
const std::set<std::string>& repair_option_names();  // options with a value
const std::set<std::string>& repair_switch_names();
CleanOptions parse_repair(const Args& args);

// Reads and cleans. A mesh with non-manifold edges is refused with the edge named and the
// offer of the largest manifold part ("rerun with --largest-part ... (N of M faces)"); one
// with a part far from the rest, with the part named and the same offer.
LoadedInput load_input(const std::string& path, const CleanOptions& options = {});

// Replaces in.clean by the subdivided surface: the cleaned triangles merged back into the
// file's polygons form the control mesh (Loop when all are triangles, else Catmull-Clark),
// subdivided request.levels times, then cleaned again. The clean report stays the one of the
// file (what was repaired in the input); face and vertex maps now refer to the subdivided
// mesh, so per-vertex or per-face input data no longer applies. No-op for levels == 0.
void subdivide_input(LoadedInput& in, const SubdivisionRequest& request);

// A density file: one value per input vertex (or per input triangle), mapped onto the cleaned
// mesh's vertices (or faces). Throws UsageError/InputError naming the count mismatch.
std::vector<double> load_density(const std::string& path, const LoadedInput& input);

}  // namespace ff::cli
