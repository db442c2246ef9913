#!/usr/bin/env bash
# Runs `collide solve` on every file of a bad-input folder. Each must: exit with code 2, print
# nothing on stdout, print exactly one line on stderr that names the file and contains the
# expected fragment (the file's first line "# expect: ...", or its entry in expectations.txt).
# Usage: bad_input.sh COLLIDE DIR
set -u
collide=$1
dir=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
count=0

check() {  # check FILE EXPECTED [collide args...]
  local file=$1 expect=$2
  shift 2
  count=$((count + 1))
  "$collide" "$@" >"$tmp/out" 2>"$tmp/err"
  local code=$? problem=""
  [[ $code -eq 2 ]] || problem+=" exit code $code (expected 2);"
  [[ -s $tmp/out ]] && problem+=" wrote to stdout;"
  [[ $(wc -l <"$tmp/err") -eq 1 ]] || problem+=" stderr is not exactly one line;"
  grep -qF -- "$file" "$tmp/err" || problem+=" message does not name the file;"
  grep -qF -- "$expect" "$tmp/err" || problem+=" message lacks '$expect';"
  if [[ -n $problem ]]; then
    failures=$((failures + 1))
    echo "FAIL $file:$problem"
    sed 's/^/     stderr: /' "$tmp/err" | head -5
  fi
}

for f in "$dir"/*.toml; do
  name=$(basename "$f")
  expect=$(sed -n '1s/^# expect: //p' "$f")
  [[ -n $expect ]] || expect=$(awk -F'\t' -v n="$name" '$1 == n {print $2}' "$dir/expectations.txt")
  [[ -n $expect ]] || { echo "FAIL $f: no expectation"; failures=$((failures + 1)); continue; }
  check "$f" "$expect" solve "$f"
  check "$f" "$expect" solve --format json "$f"
done

# Generated cases that are not worth committing.
head -c $((10 * 1024 * 1024)) /dev/zero | tr '\0' '#' >"$tmp/ten-megabytes.toml"
check "$tmp/ten-megabytes.toml" "too large" solve "$tmp/ten-megabytes.toml"
check "$tmp/missing.toml" "cannot open" solve "$tmp/missing.toml"
check "<stdin>" "missing key 'dimension'" solve - <<<'restitution = 1.0'

echo "$count cases, $failures failed"
[[ $failures -eq 0 ]]
