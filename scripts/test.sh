#!/usr/bin/env bash
# Builds and runs every test: smoke runs of the benchmark drivers, the native GoogleTest
# suite and CLI checks (Release), the WebAssembly module under Node and the page in headless
# Chromium (registered in the same ctest run), and the native tests again under
# AddressSanitizer + UndefinedBehaviorSanitizer. Installs what is missing first
# (scripts/setup.sh: apt packages, npm ci).
# The last lines are ctest's summary, so CI reads the test count.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
# Each phase says when it starts (seconds since this script began): CI has 90 minutes.
phase() { echo "== $1 (at ${SECONDS} s)"; }

scripts/setup.sh

phase "native build (Release)"
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release -DFF_WEB_TESTS=ON >/dev/null
cmake --build build/release -j"$jobs"

phase "benchmark smoke runs"
build/release/bench/bench_cluster --smoke
build/release/bench/bench_remesh --smoke --seeds 2

phase "WebAssembly and web build (wasm modules, site in web/dist, strict type check)"
npm run --silent build
npm run --silent typecheck

phase "native, wasm (Node) and browser tests"
ctest --test-dir build/release --output-on-failure -j"$jobs"

phase "sanitizer build (ASan + UBSan) of the core tests"
# The core in batches of files here (FF_UNITY_CORE): instrumented file by file it took most of
# this build's 19 minutes on 2 cores.
cmake -S . -B build/sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFF_SANITIZE=ON -DFF_BUILD_BENCH=OFF -DFF_UNITY_CORE=ON >/dev/null
cmake --build build/sanitize -j"$jobs" --target ff_core_tests flatfacet
phase "sanitizer tests"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir build/sanitize --output-on-failure -j"$jobs"
