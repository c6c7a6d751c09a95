#include "cli/output.h"

#include <cstdio>
#include <fstream>

#include "cli/args.h"

namespace ff::cli {

void write_file_atomic(const std::string& path, const std::string& content) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw UsageError("cannot write '" + path + "'");
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    if (!out) {
      std::remove(tmp.c_str());
      throw UsageError("failed while writing '" + path + "'");
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw UsageError("cannot write '" + path + "'");
  }
}

}  // namespace ff::cli
