#pragma once
// bench_remesh's table over seeds: one seed is one draw of a chaotic panel phase (on
// bunny.off at 200 panels, seeds 1-16 take 2 to 40 panel rounds), so the time target is
// judged on the median and the worst over several seeds, both sides run at each seed.
#include <string>
#include <vector>

#include "bench/remesh_case.h"

namespace ff::bench {

struct SeedRunOptions {
  int seeds = 0;   // seeds 1..seeds; 0: no table
  int repeat = 1;  // time per seed: the fastest of this many runs
  double subdivision_ratio = 5.0;
  bool with_cgal = false;
};

// Measures every case at each seed (ours, and CGAL when built with it), prints the Markdown
// table and its target line. Failed measurements are counted in `failures` and named in
// `notes`.
void print_seed_table(const std::vector<RemeshCase>& cases, const std::string& meshes, const SeedRunOptions& options,
                      const std::string& exe, std::vector<std::string>& notes, int& failures);

}  // namespace ff::bench
