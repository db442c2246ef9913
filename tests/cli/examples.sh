#!/usr/bin/env bash
# Every bundled example solves (exit 0, output on stdout, nothing on stderr) in every format,
# from a file and from stdin, and each format holds what it promises: the text and Markdown
# reports open with the file's title and walk from "1. Given" through the final velocities
# to the checks; the JSON record has the documented keys. (The numbers themselves are
# checked against closed forms in tests/teach/.) Usage: examples.sh COLLIDE DIR
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
  title=$(sed -n 's/^title = "\(.*\)"$/\1/p' "$f" | head -1)
  text=$("$collide" solve --format text "$f" 2>/dev/null)
  markdown=$("$collide" solve --format markdown "$f" 2>/dev/null)
  json=$("$collide" solve --format json "$f" 2>/dev/null)
  expect() {  # expect WHAT HAYSTACK NEEDLE
    grep -qF -- "$3" <<<"$2" || { echo "FAIL $f: $1 lacks '$3'"; failures=$((failures + 1)); }
  }
  if [[ -n $title ]]; then
    [[ $(head -1 <<<"$text") == "$title" ]] || { echo "FAIL $f: text does not open with its title"; failures=$((failures + 1)); }
    [[ $(head -1 <<<"$markdown") == "# $title" ]] || { echo "FAIL $f: markdown does not open with # title"; failures=$((failures + 1)); }
  fi
  for step in "1. Given" "Final velocities" "Checks"; do expect text "$text" "$step"; done
  for step in "## 1. Given" "Final velocities" "## " '$$'; do expect markdown "$markdown" "$step"; done
  for key in '"dimension"' '"model"' '"restitution"' '"normal"' '"impulse"' '"normal_impulse"' '"a"' '"b"' \
             '"relative_normal_velocity"' '"kinetic_energy"' '"momentum"'; do
    expect json "$json" "$key"
  done
  [[ ${json:0:1} == "{" && ${json: -1} == "}" ]] || { echo "FAIL $f: json is not one object"; failures=$((failures + 1)); }
  from_stdin=$("$collide" solve - <"$f")
  from_file=$("$collide" solve "$f")
  if [[ "$from_stdin" != "$from_file" ]]; then
    echo "FAIL $f: stdin gives another answer"; failures=$((failures + 1))
  fi
done
rm -f /tmp/collide-examples-err.$$
[[ $failures -eq 0 ]] && echo "all examples solve"
[[ $failures -eq 0 ]]
