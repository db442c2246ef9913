#!/usr/bin/env bash
# Times `collide material` (the whole site of every lesson) for this build and for an earlier
# revision, side by side in one run: the two alternate, ROUNDS times each, and the figures
# (wall and CPU seconds, each run and the medians) are printed. For a change that must not make
# the site slower (e.g. the run-record refactor: REV = 7d87315, the commit before it).
# Usage: scripts/material-speed.sh [REV] [ROUNDS] [SIZE]   (defaults: 7d87315, 3, 720p)
# Needs build/cli/collide (scripts/build.sh); checks REV out into build-speed-REV/src (a git
# worktree, kept for the next run: `git worktree remove` it when done) and builds its
# `collide` in build-speed-REV/build.
set -euo pipefail
cd "$(dirname "$0")/.."
rev=${1:-7d87315}
rounds=${2:-3}
size=${3:-720p}
new=build/cli/collide
[[ -x $new ]] || { echo "material-speed: build first (scripts/build.sh)" >&2; exit 1; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
src=$PWD/build-speed-$rev/src
old_build=$PWD/build-speed-$rev/build
[[ -d $src ]] || git worktree add --detach "$src" "$rev" >/dev/null
echo "material-speed: building $rev in $old_build ..."
cmake -S "$src" -B "$old_build" -DCOLLIDE_BUILD_TESTS=OFF -DCOLLIDE_BUILD_BENCH=OFF >/dev/null
cmake --build "$old_build" --target collide -j "$(nproc)" >/dev/null
old=$old_build/cli/collide
if [[ $rounds -lt 1 ]]; then echo "material-speed: built $old (0 rounds: nothing timed)"; exit 0; fi

TIMEFORMAT='%R %U %S'
declare -A wall cpu
run() {  # run NAME BINARY LESSONS-DIR
  local t
  rm -rf "$out/site"
  t=$( { time COLLIDE_LESSONS=$3 "$2" material -o "$out/site" --size "$size" --quiet >/dev/null 2>&1; } 2>&1 )
  read -r r u s <<<"$t"
  wall[$1]+="$r "
  cpu[$1]+="$(awk -v u="$u" -v s="$s" 'BEGIN {print u + s}') "
  printf '  %-4s wall %6.2f s  cpu %6.2f s\n' "$1" "$r" "$(awk -v u="$u" -v s="$s" 'BEGIN {print u + s}')"
}
echo "material-speed: collide material --size $size, every bundled lesson, $rounds rounds"
for ((k = 1; k <= rounds; ++k)); do
  run old "$old" "$src/lessons"
  run new "$new" "$PWD/lessons"
done
median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
for name in old new; do
  printf '%s (%s): median wall %s s, median cpu %s s\n' "$name" \
    "$([[ $name == old ]] && echo "$rev" || git rev-parse --short HEAD)" \
    "$(median <<<"${wall[$name]}")" "$(median <<<"${cpu[$name]}")"
done
