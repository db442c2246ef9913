#!/usr/bin/env bash
# Configures and builds Collide in ./build (Release, warnings as errors): the command, the tests,
# collide-bench and the Python module, and installs the npm packages the tests read QTI
# packages with (scripts/install-qti-reader.sh).
# Extra arguments go to CMake, e.g. scripts/build.sh -DCOLLIDE_SANITIZE=ON -B build-asan; they
# come after the defaults, so that -DCOLLIDE_BUILD_TESTS=OFF (scripts/demo.sh) leaves the tests
# out, and a later run without it builds them again.
set -euo pipefail
cd "$(dirname "$0")/.."
dir=build
args=()
while [[ $# -gt 0 ]]; do
  if [[ $1 == -B ]]; then dir=$2; shift 2; else args+=("$1"); shift; fi
done
cmake -S . -B "$dir" -DCOLLIDE_WERROR=ON -DCOLLIDE_BUILD_TESTS=ON -DCOLLIDE_BUILD_BENCH=ON -DCOLLIDE_PYTHON=ON \
  "${args[@]}" >/dev/null
cmake --build "$dir" -j "$(nproc)"
# The QTI reader of the qti tests (npm; tests/qti/): without it those tests fail, saying so.
if grep -q '^COLLIDE_BUILD_TESTS:BOOL=ON' "$dir/CMakeCache.txt"; then
  scripts/install-qti-reader.sh "$dir" || echo "build: the QTI reader is not installed: the qti tests will fail" >&2
fi
