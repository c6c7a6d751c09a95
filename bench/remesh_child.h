#pragma once
// bench_remesh's child side: one run of one side on one case in this process, timed, its
// result measured by measure_quality, and told as one "result ..." line on stdout ("error
// ..." when something failed); what `bench_remesh --only` runs.
#include <cstdint>
#include <string>

#include "bench/remesh_case.h"

namespace ff::bench {

constexpr int kCgalIterations = 20;  // as bench_cluster; ours runs its default k1 = 20 as well
// A child's exit code when the solve ran (its "result" line has the times) but measuring the
// result failed: measure_quality refused the panels (e.g. a non-finite vertex).
constexpr int kQualityFailed = 5;

// side: ours or cgal; quality: with the quality report; ratio: CGAL's subdivision_ratio.
// Returns the exit code: 0, kQualityFailed, or another non-zero code when the run failed.
int run_remesh_only(const std::string& side, const RemeshCase& c, const std::string& meshes, std::uint64_t seed,
                    bool quality, double ratio);

}  // namespace ff::bench
