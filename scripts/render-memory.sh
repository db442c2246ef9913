#!/usr/bin/env bash
# Peak memory of `collide render` for 100 and for 1 000 frames of the same scene (720p,
# default quality): PNG encoding runs beside rendering through a fixed pool of frame buffers,
# so the two figures should be the same. Prints what the command itself reports.
set -euo pipefail
cd "$(dirname "$0")/.."
collide=${COLLIDE:-build/cli/collide}
scene=lessons/scenes/billiards-2d.toml  # 2 s long
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for frames in 100 1000; do
  fps=$(awk -v n="$frames" 'BEGIN { printf "%.6g", (n - 1) / 2.0 }')  # frames at 0 .. 2 s
  printf '%5d frames: ' "$frames"
  "$collide" render "$scene" -o "$out/$frames" --fps "$fps" | sed 's/.*(\([0-9.]* frames\/s\)).*peak memory \(.*\)/\1, peak memory \2/'
done
