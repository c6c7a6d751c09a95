#pragma once
// Loading what every command starts from: read the file, clean it, map a density file onto
// the cleaned mesh. Shared by `cluster` and (later) `remesh`.
#include <string>
#include <vector>

#include "core/mesh/clean.h"
#include "core/mesh/mesh_io.h"

namespace ff::cli {

struct LoadedInput {
  std::string path;
  RawMesh raw;
  CleanMesh clean;
  double read_seconds = 0.0;
  double clean_seconds = 0.0;
};

LoadedInput load_input(const std::string& path);

// A density file: one value per input vertex (or per input triangle), mapped onto the cleaned
// mesh's vertices (or faces). Throws UsageError/InputError naming the count mismatch.
std::vector<double> load_density(const std::string& path, const LoadedInput& input);

}  // namespace ff::cli
