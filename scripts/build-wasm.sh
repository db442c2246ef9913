#!/usr/bin/env bash
# Builds the engine as WebAssembly: one file, build/wasm/collide-engine.js (the wasm
# embedded), exporting solve(text) and run(text) (docs/wasm.md).
# `collide material` puts it into the site when it finds it (beside the build: see docs/commands/material.md).
# Needs Debian's emscripten and node-acorn (scripts/install-deps.sh); Debian's package comes
# with emscripten's system libraries built (/usr/share/emscripten/cache), so nothing is fetched.
# Usage: scripts/build-wasm.sh [-B DIR] [CMAKE_ARGS...]   (default DIR: build/wasm, where
# `collide material` of the build in build/ finds it; scripts/build.sh runs this too)
set -euo pipefail
cd "$(dirname "$0")/.."
dir=build/wasm
args=()
while [[ $# -gt 0 ]]; do
  if [[ $1 == -B ]]; then dir=$2; shift 2; else args+=("$1"); shift; fi
done
command -v emcmake >/dev/null || {
  echo "build-wasm: emcmake is missing: install emscripten and node-acorn (scripts/install-deps.sh)" >&2
  exit 2
}
# Node 20 does not look in Debian's /usr/share/nodejs, where node-acorn puts acorn, which
# emscripten's JavaScript optimizer needs (../shared/STACK.md, "Emscripten").
export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}
# Configured once (the build itself re-runs CMake when a CMakeLists.txt changes): the native
# build runs this script every time, and emcmake takes seconds even when nothing changed.
if [[ ! -f $dir/CMakeCache.txt || ${#args[@]} -gt 0 ]]; then
  emcmake cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DCOLLIDE_WERROR=ON "${args[@]}" >/dev/null
fi
cmake --build "$dir" -j "$(nproc)"
ls -l "$dir/collide-engine.js" | awk '{print "build-wasm: " $NF " (" $5 " bytes)"}'
