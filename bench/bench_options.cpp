#include "bench/bench_options.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <sstream>

#ifndef FF_DEFAULT_SHARED_MESHES
#define FF_DEFAULT_SHARED_MESHES "../shared/meshes"
#endif

namespace ff::bench {

int bench_main(int argc, char** argv, BenchOptions& o, const BenchMain& m) {
  if (const char* env = std::getenv("FF_SHARED_MESHES"); env && *env)
    o.meshes = env;
  else
    o.meshes = FF_DEFAULT_SHARED_MESHES;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "%s: %s needs a value\n", m.program, a.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--smoke") {
      o.smoke = true;
    } else if (a == "--only") {
      o.only = value();
    } else if (a == "--case") {
      o.case_name = value();
    } else if (a == "--cases") {
      std::istringstream list(value());
      std::string item;
      while (std::getline(list, item, ',')) {
        if (!item.empty()) o.cases.push_back(item);
      }
    } else if (a == "--meshes") {
      o.meshes = value();
    } else if (a == "--repeat") {
      o.repeat = std::atoi(value().c_str());
    } else if (a == "--seed") {
      o.seed = std::strtoull(value().c_str(), nullptr, 10);
    } else if (a == "--help" || a == "-h") {
      m.usage();
      return 0;
    } else if (const Flag f = m.own_flag ? m.own_flag(a, value) : Flag::Unknown; f == Flag::Invalid) {
      return 2;
    } else if (f == Flag::Unknown) {
      std::fprintf(stderr, "%s: unknown argument '%s'\n", m.program, a.c_str());
      m.usage();
      return 2;
    }
  }
  try {
    return !o.only.empty() ? m.run_only() : m.run_table(argv[0]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", m.program, e.what());
    return 1;
  }
}

bool mesh_file_missing(const std::string& meshes, const std::string& file, const std::string& label,
                       std::vector<std::string>& notes) {
  if (file.empty() || access((meshes + "/" + file).c_str(), R_OK) == 0) return false;
  notes.push_back(label + " skipped: " + meshes + "/" + file + " not found (pass --meshes DIR)");
  return true;
}

}  // namespace ff::bench
