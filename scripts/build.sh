#!/usr/bin/env bash
# Configures and builds Collide in ./build (Release, warnings as errors).
# Extra arguments go to CMake, e.g. scripts/build.sh -DCOLLIDE_SANITIZE=ON -B build-asan
set -euo pipefail
cd "$(dirname "$0")/.."
dir=build
args=()
while [[ $# -gt 0 ]]; do
  if [[ $1 == -B ]]; then dir=$2; shift 2; else args+=("$1"); shift; fi
done
cmake -S . -B "$dir" -DCOLLIDE_WERROR=ON "${args[@]}" >/dev/null
cmake --build "$dir" -j "$(nproc)"
