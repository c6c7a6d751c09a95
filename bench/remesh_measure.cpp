#include "bench/remesh_measure.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "bench/child_process.h"
#include "bench/remesh_child.h"

namespace ff::bench {

namespace {

Measured measure_once(const std::string& exe, const std::string& side, const RemeshCase& c, const std::string& meshes,
                      std::uint64_t seed, bool quality, double ratio) {
  char ratio_text[32];
  std::snprintf(ratio_text, sizeof ratio_text, "%.17g", ratio);
  std::vector<std::string> args = {exe, "--only", side, "--case", c.name, "--meshes", meshes};
  args.insert(args.end(), {"--seed", std::to_string(seed), "--subdivision-ratio", ratio_text});
  if (!quality) args.push_back("--no-quality");
  const ChildRun run = run_child(args);
  Measured m;
  const std::string error = read_result(run.out, m);
  m.peak_rss_mib = m.num("rss_mib");
  const bool quality_failed = !run.ok && run.error == "exit code " + std::to_string(kQualityFailed);
  m.ok = (run.ok || quality_failed) && !m.values.empty();
  if (m.ok && quality_failed) m.quality_error = error;
  if (!m.ok) m.error = !error.empty() ? error : (!run.ok ? run.error : "no result");
  if (!run.ok && !error.empty() && run.error.rfind("killed", 0) == 0) m.error += " (" + run.error + ")";
  return m;
}

}  // namespace

Measured measure(const std::string& exe, const std::string& side, const RemeshCase& c, const std::string& meshes,
                 std::uint64_t seed, int repeat, double ratio) {
  Measured first = measure_once(exe, side, c, meshes, seed, true, ratio);
  if (!first.ok) return first;
  Measured best = first;
  for (int r = 1; r < repeat; ++r) {
    const Measured m = measure_once(exe, side, c, meshes, seed, false, ratio);
    if (!m.ok) return m;
    first.peak_rss_mib = std::max(first.peak_rss_mib, m.peak_rss_mib);
    if (m.total() < best.total()) best = m;
  }
  for (const char* key : {"input_s", "solve_s", "prepare_s", "lloyd_s", "panels_s", "build_s", "seed_s", "iterate_s",
                          "extract_s", "cpu_s"}) {
    if (best.has(key)) first.values[key] = best.num(key);
  }
  return first;
}

}  // namespace ff::bench
