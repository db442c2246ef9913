#!/usr/bin/env bash
# Interrupts while a child program runs (issue 34): SIGINT or SIGTERM to `collide render`,
# `collide material` while "ffmpeg" encodes and to `collide worksheet` while "weasyprint"
# prints. Each time: exit code 130 within seconds, the child ended with the command, the
# target directory untouched (material, worksheet: absent) and no DIR.tmp-PID left.
# The children are stand-ins on PATH that record their pid and sleep (the real ones are
# optional and fast); one "ffmpeg" sends the signal itself and exits 0, the interrupt
# arriving while the command waits for it.
set -euo pipefail
collide=$1
lessons=$2
out=$(mktemp -d)
children=()
cleanup() {
  for p in "${children[@]}"; do kill -9 "$p" 2>/dev/null || true; done
  rm -rf "$out"
}
trap cleanup EXIT
mkdir "$out/bin"
for prog in ffmpeg weasyprint; do
  cat >"$out/bin/$prog" <<SCRIPT
#!/bin/sh
echo \$\$ > "$out/$prog.pid"
exec sleep 60
SCRIPT
  chmod +x "$out/bin/$prog"
done
mkdir "$out/self"
cat >"$out/self/ffmpeg" <<'SCRIPT'
#!/bin/sh
kill -s TERM "$PPID"
exit 0
SCRIPT
chmod +x "$out/self/ffmpeg"

fail() { echo "$1"; cat "$out/err" 2>/dev/null; exit 1; }

# run NAME SIGNAL CHILD DIR COMMAND...: starts the command, waits for CHILD to start, signals.
run() {
  local name=$1 sig=$2 child=$3 dir=$4
  shift 4
  rm -f "$out/$child.pid"
  PATH="$out/bin:/usr/bin:/bin" "$@" 2>"$out/err" >/dev/null &
  local pid=$!
  for _ in $(seq 1 1200); do
    [[ -s $out/$child.pid ]] && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.05
  done
  [[ -s $out/$child.pid ]] || fail "$name: $child never started"
  local cpid
  cpid=$(cat "$out/$child.pid")
  children+=("$cpid")
  local t0=$SECONDS
  kill -s "$sig" "$pid"
  set +e
  wait "$pid"
  local code=$?
  set -e
  [[ $code -eq 130 ]] || fail "$name SIG$sig: exit code $code, expected 130"
  ((SECONDS - t0 <= 5)) || fail "$name SIG$sig: took $((SECONDS - t0)) s to stop"
  grep -q "interrupted" "$out/err" || fail "$name SIG$sig: no message"
  ! kill -0 "$cpid" 2>/dev/null || fail "$name SIG$sig: $child (pid $cpid) still runs"
  if find "$out" -maxdepth 3 -name '*.tmp-*' | grep -q .; then fail "$name SIG$sig: temporary files left"; fi
  echo "$name SIG$sig: exit 130, $child ended"
}

small=(--size 320x180 --fps 5)
for sig in INT TERM; do
  run render "$sig" ffmpeg "$out/r" "$collide" render "$lessons/scenes/billiards-2d.toml" -o "$out/r" \
    --format mp4 --quiet "${small[@]}"
  [[ ! -e $out/r/animation.mp4 ]] || fail "render: a video was left"
  rm -rf "$out/r"
  run material "$sig" ffmpeg "$out/m" "$collide" material catch-up -o "$out/m" --quiet "${small[@]}"
  [[ ! -e $out/m ]] || fail "material: $out/m was written"
  run worksheet "$sig" weasyprint "$out/w" "$collide" worksheet catch-up -o "$out/w" --students 2
  [[ ! -e $out/w ]] || fail "worksheet: $out/w was written"
done

# The interrupt while the command waits for a child that then exits 0: not lost.
set +e
PATH="$out/self:/usr/bin:/bin" "$collide" material catch-up -o "$out/m" --quiet "${small[@]}" 2>"$out/err" >/dev/null
code=$?
set -e
[[ $code -eq 130 ]] || fail "material, signal from ffmpeg: exit code $code, expected 130"
[[ ! -e $out/m ]] || fail "material, signal from ffmpeg: $out/m was written"
if find "$out" -maxdepth 3 -name '*.tmp-*' | grep -q .; then fail "material: temporary files left"; fi
echo "material, signal during ffmpeg: exit 130, nothing written"
