#!/usr/bin/env bash
# Builds the Release configuration and runs the benchmarks against CGAL's Variational Shape
# Approximation (bench/README.md):
#   scripts/bench.sh                  both: bench_cluster -> bench/results.md, then
#                                     bench_remesh -> bench/results_remesh.md
#   scripts/bench.sh cluster [ARGS]   bench_cluster only, ARGS passed on (e.g. --cases roof-1m)
#   scripts/bench.sh remesh [ARGS]    bench_remesh only (e.g. --cases hyperboloid)
#   scripts/bench.sh --cases ...      (no selector) as before: bench_cluster only, ARGS passed on
# The tables go to stdout and to their results file. FF_BENCH_REPEAT (default 3) sets how
# many runs each measurement takes the best time of; FF_SHARED_MESHES overrides the folder of
# the shared meshes.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)

which=all
if [[ $# -gt 0 ]]; then
  case "$1" in
    cluster | remesh)
      which=$1
      shift
      ;;
    *) which=cluster ;;
  esac
fi

echo "== Release build of the benchmarks" >&2
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build/release -j"$jobs" --target bench_cluster bench_remesh >&2

if ! grep -q "FF_HAVE_CGAL" build/release/bench/CMakeFiles/bench_cluster.dir/flags.make 2>/dev/null; then
  echo "bench.sh: CGAL not found at configure time; the tables will have no CGAL side (install libcgal-dev, scripts/setup.sh)" >&2
fi

# Times on a busy machine mislead, and not evenly: CGAL's extraction slowed 3-8x under load
# where ours slowed about 2x (bench/README.md), so a loaded run flatters us. Warn above a
# 1-minute load average of 0.5 (the tables record the load at start and end);
# FF_BENCH_STRICT=1 refuses to run instead.
load=$(cut -d' ' -f1 /proc/loadavg 2>/dev/null || echo 0)
if awk -v l="$load" 'BEGIN { exit !(l > 0.5) }'; then
  echo "bench.sh: load average $load > 0.5: other work will distort the times (run on an idle machine)" >&2
  if [[ ${FF_BENCH_STRICT:-0} == 1 ]]; then exit 1; fi
fi

# run NAME RESULTS_FILE ARGS...: the table to stdout and to RESULTS_FILE. A failed measurement
# is a row of the table (FAILED), so the table is kept; the exit status is the benchmark's.
status=0
run() {
  local name=$1 results=$2
  shift 2
  local tmp rc
  tmp=$(mktemp "$results.XXXXXX")
  trap 'rm -f "$tmp"' EXIT
  set +e
  build/release/bench/"$name" --repeat "${FF_BENCH_REPEAT:-3}" "$@" | tee "$tmp"
  rc=${PIPESTATUS[0]}
  set -e
  if [[ -s $tmp ]]; then
    mv "$tmp" "$results"
    echo "bench.sh: table written to $results" >&2
  fi
  rm -f "$tmp"
  trap - EXIT
  if [[ $rc -ne 0 ]]; then
    echo "bench.sh: $name exited with $rc (see the FAILED cells and notes)" >&2
    status=$rc
  fi
}

if [[ $which == all || $which == cluster ]]; then
  echo "== bench_cluster (takes a few minutes)" >&2
  run bench_cluster bench/results.md "$@"
fi
if [[ $which == all || $which == remesh ]]; then
  echo "== bench_remesh (takes a few minutes)" >&2
  run bench_remesh bench/results_remesh.md "$@"
fi
exit "$status"
