#include "cli/output.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "cli/args.h"

namespace ff::cli {

void write_files_atomic(const std::vector<OutputFile>& files) {
  std::vector<std::string> written;
  const auto remove_written = [&] {
    for (const std::string& tmp : written) std::remove(tmp.c_str());
  };
  for (const OutputFile& file : files) {
    const std::string tmp = file.path + ".tmp";
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (out) {
      written.push_back(tmp);
      out.write(file.content.data(), static_cast<std::streamsize>(file.content.size()));
      out.close();
    }
    if (!out) {
      remove_written();
      throw UsageError("cannot write '" + file.path + "'");
    }
  }
  for (size_t i = 0; i < files.size(); ++i) {
    if (std::rename(written[i].c_str(), files[i].path.c_str()) != 0) {
      // Renames within one folder do not fail in practice; undo what is left.
      for (size_t j = i; j < written.size(); ++j) std::remove(written[j].c_str());
      throw UsageError("cannot write '" + files[i].path + "'");
    }
  }
}

void require_outputs_spare_inputs(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs) {
  for (const std::string& out : outputs) {
    for (const std::string& in : inputs) {
      if (out.empty() || in.empty()) continue;
      std::error_code error;  // a name that does not exist yet is no input (equivalent: false)
      if (std::filesystem::equivalent(out, in, error))
        throw UsageError("the output '" + out + "' is the input '" + in +
                         "': it would be overwritten; name another file");
    }
  }
}

}  // namespace ff::cli
