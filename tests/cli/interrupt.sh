#!/usr/bin/env bash
# SIGINT and SIGTERM during `collide render`: exit code 130, and every file left behind is
# complete (each frame a whole PNG, no temporary names).
set -euo pipefail
collide=$1
scene=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for sig in INT TERM; do
  dir="$out/$sig"
  # Many small frames: the render runs for a few seconds.
  "$collide" render "$scene" -o "$dir" --fps 2000 --size 320x180 --quiet 2>"$out/err" &
  pid=$!
  # Wait until frames appear, then interrupt.
  for _ in $(seq 1 200); do
    [[ -n $(ls "$dir/frames" 2>/dev/null | head -1) ]] && break
    sleep 0.05
  done
  kill -s "$sig" "$pid"
  set +e
  wait "$pid"
  code=$?
  set -e
  if [[ $code -ne 130 ]]; then echo "SIG$sig: exit code $code, expected 130"; cat "$out/err"; exit 1; fi
  grep -q "interrupted" "$out/err" || { echo "SIG$sig: no message"; cat "$out/err"; exit 1; }
  if find "$dir" -name '*.tmp-*' | grep -q .; then echo "SIG$sig: temporary files left"; exit 1; fi
  n=0
  for f in "$dir"/frames/frame_*.png; do
    # A complete PNG ends with the IEND chunk.
    tail -c 8 "$f" | od -An -c | grep -q 'I   E   N   D' || { echo "SIG$sig: $f is incomplete"; exit 1; }
    n=$((n + 1))
  done
  [[ $n -gt 0 ]] || { echo "SIG$sig: no frame written"; exit 1; }
  echo "SIG$sig: stopped with $n complete frames"
done
