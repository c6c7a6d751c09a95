#!/usr/bin/env bash
# Sets up what is missing (scripts/setup.sh: Debian packages, npm ci), builds the page with
# its WebAssembly core (npm run build -> web/dist), and serves it on http://localhost:5173
# with an example loaded. Safe to run again; Ctrl-C stops the server.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/setup.sh
npm run build
echo "start: serving web/dist on http://localhost:5173 (Ctrl-C stops)"
exec npx --no-install vite preview --config web/vite.config.ts --host 127.0.0.1 --port 5173 --strictPort
