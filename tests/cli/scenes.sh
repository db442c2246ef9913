#!/usr/bin/env bash
# Every bundled scenario steps (exit 0, output, nothing on stderr) in every output format,
# and the output says what it should: --json one state per output instant (t = 0, output_dt,
# ..., duration: the count from the file's own duration and output_dt, the last at t =
# duration), each a JSON object with the bodies; --events one line per collision, as many in
# text as in JSON. Usage: scenes.sh COLLIDE DIR
set -u
collide=$1
dir=$2
failures=0
work=$(mktemp -d)
err=$work/err
trap 'rm -rf "$work"' EXIT
# Each run once: the checks below read the outputs kept here (a scene's run under the sanitizers
# takes seconds).
kept() { echo "$work/$(basename "$1")${2// /}"; }  # kept FILE FLAGS: where that run's output is
for f in "$dir"/*.toml; do
  for flags in "" "--json" "--events" "--events --json"; do
    # shellcheck disable=SC2086
    "$collide" step $flags "$f" >"$(kept "$f" "$flags")" 2>"$err"
    code=$?
    out=$(<"$(kept "$f" "$flags")")
    # (--events may be empty: a scene without collisions, such as the tumbling box)
    if [[ $code -ne 0 || ( -z $out && $flags != --events* ) || -s $err ]]; then
      echo "FAIL $f $flags: exit $code"; cat "$err"
      failures=$((failures + 1))
    fi
  done
done
for f in "$dir"/*.toml; do
  duration=$(sed -n 's/^duration *= *\([0-9.eE+-]*\).*/\1/p' "$f" | head -1)
  dt=$(sed -n 's/^output_dt *= *\([0-9.eE+-]*\).*/\1/p' "$f" | head -1)
  dt=${dt:-0.01}
  # K = duration / output_dt, rounded when within 1e-9 of an integer, else rounded up; K + 1 states.
  want=$(awk -v d="$duration" -v h="$dt" 'BEGIN { k = d / h; r = int(k + 0.5); if (k - r < 1e-9 && r - k < 1e-9) k = r; else k = int(k) + (k > int(k)); print k + 1 }')
  states=$(<"$(kept "$f" --json)")
  got=$(grep -c . <<<"$states")
  [[ $got -eq $want ]] || { echo "FAIL $f --json: $got states, expected $want (duration $duration, output_dt $dt)"; failures=$((failures + 1)); }
  [[ $(grep -c '^{"t":' <<<"$states") -eq $got ]] || { echo "FAIL $f --json: a line is not a state object"; failures=$((failures + 1)); }
  grep -q '"bodies"' <<<"$(head -1 <<<"$states")" || { echo "FAIL $f --json: no bodies"; failures=$((failures + 1)); }
  last_t=$(tail -1 <<<"$states" | sed 's/^{"t":\([^,]*\),.*/\1/')
  awk -v a="$last_t" -v b="$duration" 'BEGIN { exit !(a - b < 1e-9 && b - a < 1e-9) }' ||
    { echo "FAIL $f --json: the last state is at t = $last_t, not $duration"; failures=$((failures + 1)); }
  events_text=$(grep -c . "$(kept "$f" --events)")
  events_json=$(grep -c '^{' "$(kept "$f" "--events --json")")
  [[ $events_text -eq $events_json ]] ||
    { echo "FAIL $f: $events_text events in text, $events_json in JSON"; failures=$((failures + 1)); }
done
[[ $failures -eq 0 ]] && echo "all scenarios step"
[[ $failures -eq 0 ]]
