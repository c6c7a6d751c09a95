#!/usr/bin/env bash
# Builds the Release configuration and runs the full clustering benchmark (ours vs CGAL's
# Variational Shape Approximation, bench/README.md). The Markdown table goes to stdout and to
# bench/results.md. Extra arguments go to bench_cluster, e.g. --cases roof-1m or --repeat 1.
# FF_BENCH_REPEAT (default 3) sets how many runs of each cell the best is taken from;
# FF_SHARED_MESHES overrides the folder of the shared meshes (hyperboloid_s4.off).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)

echo "== Release build of bench_cluster" >&2
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build/release -j"$jobs" --target bench_cluster >&2

if ! grep -q "FF_HAVE_CGAL" build/release/bench/CMakeFiles/bench_cluster.dir/flags.make 2>/dev/null; then
  echo "bench.sh: CGAL not found at configure time; the table will have no CGAL rows (install libcgal-dev, scripts/setup.sh)" >&2
fi

echo "== bench_cluster (takes a few minutes)" >&2
tmp=$(mktemp bench/results.md.XXXXXX)
trap 'rm -f "$tmp"' EXIT
build/release/bench/bench_cluster --repeat "${FF_BENCH_REPEAT:-3}" "$@" | tee "$tmp"
mv "$tmp" bench/results.md
trap - EXIT
echo "bench.sh: table written to bench/results.md" >&2
