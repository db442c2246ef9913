#!/usr/bin/env bash
# Runs the libFuzzer targets of a COLLIDE_FUZZ build for a while each. See
# docs/fuzzing.md.
set -euo pipefail
cd "$(dirname "$0")/.."

usage() {
  cat <<'USAGE'
Usage: scripts/fuzz.sh [--build DIR] [--seconds N] [--jobs J] [TARGET...]

Runs each fuzz target (scene, solve, lesson, step; default: all) for N seconds, J at a time,
from a seed corpus of the repository's TOML files (lessons/, lessons/scenes/, lessons/solve/,
tests/bad-input/, tests/fuzz-regressions/) and what earlier runs kept.

  --build DIR    the build directory (default build-sanitize), configured with
                 -DCMAKE_CXX_COMPILER=clang++ -DCOLLIDE_FUZZ=ON (scripts/test-sanitize.sh does)
  --seconds N    seconds per target (default 60)
  --jobs J       targets run at once (default: the number of cores)
  -h, --help     this text

Writes under DIR/fuzz-run/ (inside the gitignored build directory):
  corpus/TARGET/     the growing corpus, kept between runs
  artifacts/TARGET/  crash-*, timeout-*, leak-*, oom-* inputs that failed
  TARGET.log         libFuzzer's output
Exits 1 if any target found a crash, a hang (> 5 s for one input), a leak or undefined
behaviour, printing each failing input (its path, and its bytes in base64 for a log read
elsewhere). Replay one with DIR/fuzz/TARGET_fuzz FILE;
keep it as a regression test in tests/fuzz-regressions/TARGET/ once it is fixed.
USAGE
}

build=build-sanitize
seconds=60
jobs=$(nproc)
targets=()
while [[ $# -gt 0 ]]; do
  case $1 in
    --build) build=$2; shift 2 ;;
    --seconds) seconds=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    scene|solve|lesson|step) targets+=("$1"); shift ;;
    *) echo "fuzz.sh: unknown argument '$1'" >&2; usage >&2; exit 2 ;;
  esac
done
[[ ${#targets[@]} -gt 0 ]] || targets=(scene solve lesson step)
out=$build/fuzz-run

seeds_of() {  # the seed files of a target
  case $1 in
    scene|step) ls lessons/scenes/*.toml lessons/*.toml tests/bad-input/scene/*.toml ;;
    solve) ls lessons/solve/*.toml tests/bad-input/solve/*.toml ;;
    lesson) ls lessons/*.toml tests/bad-input/lesson/*.toml ;;
  esac
  find "tests/fuzz-regressions/$1" -type f ! -name README.md 2>/dev/null || true
}

run_one() {  # run_one TARGET: runs it; the fuzzer's exit code goes to $out/TARGET.code
  local t=$1 code=0
  rm -rf "$out/artifacts/$t"  # only this run's findings
  mkdir -p "$out/corpus/$t" "$out/seeds/$t" "$out/artifacts/$t"
  # shellcheck disable=SC2046
  cp $(seeds_of "$t") "$out/seeds/$t/"
  "$build/fuzz/${t}_fuzz" "$out/corpus/$t" "$out/seeds/$t" -dict=fuzz/toml.dict -max_total_time="$seconds" \
    -timeout=5 -rss_limit_mb=2048 -max_len=8192 -print_final_stats=1 \
    -artifact_prefix="$out/artifacts/$t/" >"$out/$t.log" 2>&1 || code=$?
  echo "$code" >"$out/$t.code"
}

for t in "${targets[@]}"; do
  [[ -x $build/fuzz/${t}_fuzz ]] || {
    echo "fuzz.sh: $build/fuzz/${t}_fuzz is missing: build with -DCMAKE_CXX_COMPILER=clang++ -DCOLLIDE_FUZZ=ON" >&2
    exit 2
  }
done

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_stack_use_after_return=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
symbolizer=/usr/lib/llvm-14/bin/llvm-symbolizer
if [[ -x $symbolizer ]]; then export ASAN_SYMBOLIZER_PATH=${ASAN_SYMBOLIZER_PATH:-$symbolizer}; fi
echo "fuzz.sh: ${targets[*]}: ${seconds} s each, ${jobs} at a time; output in $out"
mkdir -p "$out"
running=0
for t in "${targets[@]}"; do
  if [[ $running -ge $jobs ]]; then wait -n; running=$((running - 1)); fi
  rm -f "$out/$t.code"
  run_one "$t" &
  running=$((running + 1))
done
wait
failed=0
for t in "${targets[@]}"; do
  code=$(cat "$out/$t.code")
  stats=$(grep -E '^stat::number_of_executed_units|^#[0-9]+.*DONE' "$out/$t.log" | tail -1 || true)
  corpus=$(find "$out/corpus/$t" -type f | wc -l)
  if [[ $code -eq 0 ]]; then
    echo "  $t: ok (${stats:-no stats}; corpus $corpus files)"
  else
    failed=1
    echo "  $t: FAILED (exit code $code); log: $out/$t.log"
    grep -E 'ERROR: |runtime error:|SUMMARY:|terminate called|what\(\):' "$out/$t.log" | head -5 | sed 's/^/    /'
    for f in "$out/artifacts/$t"/*; do
      [[ -e $f ]] || continue
      echo "    input: $f"
      # The input itself, so that a finding on a CI machine can be replayed here:
      # base64 -d > tests/fuzz-regressions/TARGET/NAME
      echo "    input (base64, $(wc -c <"$f") bytes):"
      base64 -w 100 "$f" | head -120 | sed 's/^/      /'
    done
  fi
done
exit $failed
