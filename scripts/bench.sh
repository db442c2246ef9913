#!/usr/bin/env bash
# Builds collide-bench twice, portable (./build-bench) and for this CPU (./build-bench-native,
# -march=native), and runs both side by side: median of 5 repetitions. Extra arguments go to
# collide-bench, e.g. scripts/bench.sh --benchmark_filter=response/3d
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh >/dev/null
common=(-DCOLLIDE_BUILD_TESTS=OFF -DCMAKE_BUILD_TYPE=Release -DCOLLIDE_WASM=OFF)
scripts/build.sh -B build-bench "${common[@]}" -DCOLLIDE_NATIVE=OFF >/dev/null
scripts/build.sh -B build-bench-native "${common[@]}" -DCOLLIDE_NATIVE=ON >/dev/null
for dir in build-bench build-bench-native; do
  echo "== $dir ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(nproc) cores)"
  "$dir/bench/collide-bench" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
    --benchmark_display_aggregates_only=true --benchmark_min_time=0.3 "$@" 2>/dev/null | grep -E '_median|^Benchmark'
done
