#!/usr/bin/env bash
# Installs what Flatfacet needs to build and test, and only what is missing (idempotent).
# Debian packages: build tools, Eigen, GoogleTest, CGAL (benchmark comparison),
# Emscripten (the wasm build) and Chromium (browser tests); npm packages once package.json
# exists. Safe to run again and again.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(cmake g++ make pkg-config python3 libeigen3-dev libgtest-dev libcgal-dev emscripten chromium)
missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  SUDO=""
  if [ "$(id -u)" != 0 ]; then SUDO="sudo"; fi
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
else
  echo "setup: Debian packages present"
fi

if [ -f package.json ]; then
  stamp=node_modules/.package-lock.stamp
  if [ ! -f "$stamp" ] || ! cmp -s package-lock.json "$stamp"; then
    echo "setup: npm ci"
    npm ci --no-audit --no-fund
    cp package-lock.json "$stamp"
  else
    echo "setup: node_modules up to date"
  fi
fi
