#pragma once
#include <string>
#include <vector>

namespace ff::cli {

struct OutputFile {
  std::string path;
  std::string content;
};

// Writes every file to a temporary beside it, and only when all of them are written renames
// them into place: a failure leaves no output at all (and no old output clobbered). Throws
// UsageError naming the path that failed.
void write_files_atomic(const std::vector<OutputFile>& files);

// Throws UsageError when an output names a file the command reads (the mesh, a density or
// edits file), through any path to it: the run would overwrite the designer's input. Empty
// names are skipped.
void require_outputs_spare_inputs(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs);

}  // namespace ff::cli
