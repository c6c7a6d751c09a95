#pragma once
// The command line both benchmarks share, and the main() around it: the common flags, each
// benchmark's own flags through a callback, then either one measurement in this process
// (--only, what the parent runs in a child) or the whole report, exceptions becoming exit 1.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace ff::bench {

struct BenchOptions {
  bool smoke = false;              // --smoke
  std::string only;                // --only SIDE: one measurement here (the child)
  std::string case_name;           // --case CASE, with --only
  std::vector<std::string> cases;  // --cases a,b,...
  std::string meshes;              // --meshes DIR; $FF_SHARED_MESHES, else the CMake FF_SHARED_MESHES
  int repeat = 1;                  // --repeat R
  std::uint64_t seed = 1;          // --seed S
};

// What a benchmark's own flag handler made of a flag.
enum class Flag {
  Taken,    // its own: read (with its value)
  Unknown,  // not its own: "unknown argument", usage, exit 2
  Invalid,  // its own, with a bad value: the handler said why; exit 2
};

// `value()` takes the flag's value from the command line (none: a message, exit 2).
using FlagHandler = std::function<Flag(const std::string& flag, const std::function<std::string()>& value)>;

struct BenchMain {
  const char* program = "";                         // "bench_cluster": starts every message
  void (*usage)() = nullptr;                        // prints the usage on stderr
  FlagHandler own_flag;                             // the benchmark's own flags
  std::function<int()> run_only;                    // with --only
  std::function<int(const char* argv0)> run_table;  // without
};

// Fills `o` from the command line and runs; returns main()'s exit code.
int bench_main(int argc, char** argv, BenchOptions& o, const BenchMain& m);

// True, with a note "LABEL skipped: ...", when `file` is named but not readable in `meshes`.
bool mesh_file_missing(const std::string& meshes, const std::string& file, const std::string& label,
                       std::vector<std::string>& notes);

}  // namespace ff::bench
