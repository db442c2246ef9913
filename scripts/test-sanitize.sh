#!/usr/bin/env bash
# CI, after scripts/test.sh: one clang build with AddressSanitizer + UndefinedBehaviorSanitizer
# and the libFuzzer targets (COLLIDE_FUZZ) in ./build-sanitize; the whole ctest suite under the
# sanitizers; then each fuzzer for a short run (scripts/fuzz.sh). Prints each stage's time.
# Usage: scripts/test-sanitize.sh [FUZZ_SECONDS]   (default 60; 0 skips the fuzzers)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
dir=build-sanitize
scripts/install-deps.sh

stage_start=$SECONDS
times=()
stage_done() { times+=("$(printf '%-28s %4d s' "$1" $((SECONDS - stage_start)))"); stage_start=$SECONDS; }

# -O1, no debug information (engine/ and cli/ get -g1 from COLLIDE_FUZZ for the fuzzers'
# reports): quick to build, asserts stay on. No benchmarks.
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
scripts/build.sh -B "$dir" -DCMAKE_CXX_COMPILER=clang++ -DCOLLIDE_FUZZ=ON \
  -DCOLLIDE_BUILD_BENCH=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1" "${launcher[@]}"
stage_done "sanitized build"

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_stack_use_after_return=0:strict_string_checks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
symbolizer=/usr/lib/llvm-14/bin/llvm-symbolizer
if [[ -x $symbolizer ]]; then export ASAN_SYMBOLIZER_PATH=${ASAN_SYMBOLIZER_PATH:-$symbolizer}; fi
# (-LE exact: byte-for-byte checks of the GCC build, see tests/CMakeLists.txt)
ctest --test-dir "$dir" --output-on-failure -j "$(nproc)" -LE exact
stage_done "sanitized ctest"

if [[ $seconds -gt 0 ]]; then
  scripts/fuzz.sh --build "$dir" --seconds "$seconds"
  stage_done "fuzzers (${seconds} s each)"
fi
echo "test-sanitize: stage times"
printf '  %s\n' "${times[@]}"
