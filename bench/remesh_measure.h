#pragma once
// bench_remesh's parent side of one measurement: run a side on a case in child processes
// (remesh_child.h) and read back what they said.
#include <cstdint>
#include <string>

#include "bench/remesh_case.h"
#include "bench/result_line.h"

namespace ff::bench {

// What the children of one measurement said (the values of their "result" lines), and how
// they went.
struct Measured : ResultValues {
  bool ok = false;            // the solve ran and reported its times
  std::string error;          // why not
  std::string quality_error;  // the solve ran, but measuring its result failed
  double peak_rss_mib = 0.0;  // largest over the runs, before the quality report

  double total() const { return num("input_s") + num("solve_s"); }
  // Clusters that never became a panel (ours) count as invalid panels too (PanelMesh::num_invalid).
  double unbuilt() const { return has("unbuilt") ? num("unbuilt") : 0.0; }
  double invalid_panels() const { return num("invalid") + unbuilt(); }
};

// The quality numbers from the first run (they are deterministic); the time from the fastest
// of `repeat` runs, the later ones without the quality report; the largest peak RSS. `exe`
// is this benchmark's binary, `ratio` CGAL's subdivision_ratio.
Measured measure(const std::string& exe, const std::string& side, const RemeshCase& c, const std::string& meshes,
                 std::uint64_t seed, int repeat, double ratio);

}  // namespace ff::bench
