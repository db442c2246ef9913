#!/usr/bin/env bash
# Every bundled scenario steps (exit 0, output, nothing on stderr) in every output format.
# Usage: scenes.sh COLLIDE DIR
set -u
collide=$1
dir=$2
failures=0
err=$(mktemp)
trap 'rm -f "$err"' EXIT
for f in "$dir"/*.toml; do
  for flags in "" "--json" "--events" "--events --json"; do
    # shellcheck disable=SC2086
    out=$("$collide" step $flags "$f" 2>"$err")
    code=$?
    # (--events may be empty: a scene without collisions, such as the tumbling box)
    if [[ $code -ne 0 || ( -z $out && $flags != --events* ) || -s $err ]]; then
      echo "FAIL $f $flags: exit $code"; cat "$err"
      failures=$((failures + 1))
    fi
  done
done
[[ $failures -eq 0 ]] && echo "all scenarios step"
[[ $failures -eq 0 ]]
