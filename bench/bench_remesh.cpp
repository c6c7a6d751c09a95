// bench_remesh: the whole remeshing process, ours against CGAL's Variational Shape
// Approximation with its mesh extraction, at equal panel count (bench/README.md).
//
//   bench_remesh                  full run, Markdown tables on stdout (with the table over
//                                 seeds 1-8; --seeds N for another count, 0 for none)
//   bench_remesh --smoke          a ~3k-triangle saddle into 40 panels, one run of each side;
//                                 exits non-zero when either side fails (scripts/test.sh)
//   bench_remesh --only ours|cgal --case CASE [--no-quality]
//                                 one run in this process, one "result ..." line; what the
//                                 parent runs in a child per measurement, and what to profile
//
// Ours: read + clean the mesh, ff::Remesher with the default RemeshParams but panels and seed,
// stepped to Done, then ff::measure_quality against the cleaned input. CGAL: the same read +
// clean, then Surface_mesh + L21 metric, random seeds, 20 x run(1), extract_mesh(); its
// anchor polygons become an ff::PanelMesh measured by the same measure_quality. Every run is
// a fresh child process (fork + exec of this binary): a CGAL crash is contained there and
// recorded as "failed", and each peak RSS is the child's own.
//
// This file is the command line; the cases are remesh_case.cpp, the child's run
// remesh_child.cpp, the parent's measuring remesh_measure.cpp, the tables remesh_table.cpp.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "bench/bench_options.h"
#include "bench/child_process.h"
#include "bench/remesh_case.h"
#include "bench/remesh_child.h"
#include "bench/remesh_table.h"

namespace {

using namespace ff::bench;

struct Options : BenchOptions {
  bool quality = true;             // --no-quality: the child skips the quality report
  double subdivision_ratio = 5.0;  // CGAL's default for extract_mesh
  int seeds = -1;                  // --seeds N: the table over seeds 1..N; default 8, none with --smoke
};

void usage() {
  std::fprintf(stderr,
               "usage: bench_remesh [--smoke] [--cases a,b,...] [--meshes DIR] [--seed S] [--repeat R]\n"
               "                    [--subdivision-ratio R] [--seeds N]\n"
               "       bench_remesh --only ours|cgal --case CASE [--meshes DIR] [--seed S] [--no-quality]\n"
               "                    [--subdivision-ratio R]\n"
               "cases: hyperboloid inspired bunny fandisk face saddle torus, or saddle:TRIANGLES:PANELS,\n"
               "       torus:TRIANGLES:PANELS, mesh:FILE:PANELS\n");
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  const auto own_flag = [&](const std::string& flag, const std::function<std::string()>& value) {
    if (flag == "--no-quality") {
      o.quality = false;
    } else if (flag == "--subdivision-ratio") {
      o.subdivision_ratio = std::strtod(value().c_str(), nullptr);
      if (!(o.subdivision_ratio > 0.0)) {
        std::fprintf(stderr, "bench_remesh: --subdivision-ratio must be positive\n");
        return Flag::Invalid;
      }
    } else if (flag == "--seeds") {
      o.seeds = std::atoi(value().c_str());
      if (o.seeds < 0 || o.seeds > 1000) {
        std::fprintf(stderr, "bench_remesh: --seeds must be between 0 and 1000\n");
        return Flag::Invalid;
      }
    } else {
      return Flag::Unknown;
    }
    return Flag::Taken;
  };
  const auto run_only = [&] {
    RemeshCase c;
    if (!parse_remesh_case(o.case_name, c)) {
      std::fprintf(stderr, "bench_remesh: --only needs --case (see --help)\n");
      return 2;
    }
    return run_remesh_only(o.only, c, o.meshes, o.seed, o.quality, o.subdivision_ratio);
  };
  const auto table = [&](const char* argv0) {
    const std::string exe = self_path(argv0);
    std::vector<std::string> names = o.cases;
    if (names.empty()) names = o.smoke ? std::vector<std::string>{kRemeshSmokeCase} : kRemeshFullRun;
    std::vector<RemeshCase> cases(names.size());
    for (size_t i = 0; i < names.size(); ++i) {
      if (!parse_remesh_case(names[i], cases[i])) {
        std::fprintf(stderr, "bench_remesh: unknown case '%s'\n", names[i].c_str());
        usage();
        return 2;
      }
    }
    const int seeds = o.seeds >= 0 ? o.seeds : (o.smoke ? 0 : 8);
    return print_remesh_report(cases, o, o.subdivision_ratio, exe, seeds);
  };
  return bench_main(argc, argv, o, {"bench_remesh", usage, own_flag, run_only, table});
}
