#pragma once
// The benchmarks' clock: wall time on std::chrono::steady_clock, read in seconds.
#include <chrono>

namespace ff::bench {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace ff::bench
