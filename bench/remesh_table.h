#pragma once
// bench_remesh's report: every case measured on both sides (a child process per run), then
// the Markdown tables on stdout: the comparison, where the time goes, targets and notes.
#include <string>
#include <vector>

#include "bench/bench_options.h"
#include "bench/remesh_case.h"

namespace ff::bench {

// `exe`: this benchmark's binary, run as the children; `subdivision_ratio`: CGAL's, for
// extract_mesh; `seeds`: the table over seeds 1..seeds after the others (remesh_seeds.h; 0:
// none). Returns the exit code: 1 when a measurement failed, else 0.
int print_remesh_report(const std::vector<RemeshCase>& cases, const BenchOptions& o, double subdivision_ratio,
                        const std::string& exe, int seeds = 0);

}  // namespace ff::bench
