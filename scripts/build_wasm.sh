#!/usr/bin/env bash
# Builds the WebAssembly modules with Debian's Emscripten 3.1.6 (build/wasm) and puts the
# page's ES module where Vite picks it up (web/src/generated/, not committed).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=${FF_JOBS:-2}
# Emscripten's JS optimiser needs acorn, which this Node only finds here (toolchain.md 1).
export NODE_PATH=/usr/share/nodejs
# Eigen is header-only: the host's copy serves the wasm build too.
emcmake cmake -S . -B build/wasm -DCMAKE_BUILD_TYPE=Release -DEigen3_DIR=/usr/share/eigen3/cmake >/dev/null
cmake --build build/wasm -j"$jobs"
mkdir -p web/src/generated
cp build/wasm/web/flatfacet.mjs build/wasm/web/flatfacet.wasm web/src/generated/
cp wasm/flatfacet.d.ts web/src/generated/flatfacet.d.mts
echo "build_wasm: web/src/generated/flatfacet.{mjs,wasm}, build/wasm/node/flatfacet_node.{cjs,wasm}"
