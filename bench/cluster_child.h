#pragma once
// bench_cluster's child side: one method on one case in this process, timed, checked, and
// told as one "result ..." line on stdout; what `bench_cluster --only` runs.
#include <cstdint>
#include <string>

#include "bench/bench_case.h"

namespace ff::bench {

// method: input (make or read the mesh only), ours-l21, ours-default or cgal. Returns the
// exit code: 0, 2 (unknown method, or cgal without CGAL), 3 (a check of the result failed).
int run_cluster_only(const std::string& method, const Case& c, const std::string& meshes, int iterations,
                     std::uint64_t seed);

}  // namespace ff::bench
