#!/usr/bin/env bash
# Every bundled example solves (exit 0, output on stdout, nothing on stderr) in every format,
# from a file and from stdin. Usage: examples.sh COLLIDE DIR
set -u
collide=$1
dir=$2
failures=0
for f in "$dir"/*.toml; do
  for format in text markdown json; do
    out=$("$collide" solve --format "$format" "$f" 2>/tmp/collide-examples-err.$$)
    code=$?
    if [[ $code -ne 0 || -z $out || -s /tmp/collide-examples-err.$$ ]]; then
      echo "FAIL $f --format $format: exit $code"; cat /tmp/collide-examples-err.$$
      failures=$((failures + 1))
    fi
  done
  from_stdin=$("$collide" solve - <"$f")
  from_file=$("$collide" solve "$f")
  if [[ "$from_stdin" != "$from_file" ]]; then
    echo "FAIL $f: stdin gives another answer"; failures=$((failures + 1))
  fi
done
rm -f /tmp/collide-examples-err.$$
[[ $failures -eq 0 ]] && echo "all examples solve"
[[ $failures -eq 0 ]]
