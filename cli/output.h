#pragma once
#include <string>

namespace ff::cli {

// Writes through a temporary file and renames it into place, so a failure never leaves a
// half-written output (or clobbers an old one). Throws UsageError naming the path.
void write_file_atomic(const std::string& path, const std::string& content);

}  // namespace ff::cli
