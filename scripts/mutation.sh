#!/usr/bin/env bash
# Mistakes compiled into student-facing code, one at a time: each must make a test fail.
# See docs/tests.md, "Mutation check".
set -euo pipefail
cd "$(dirname "$0")/.."

usage() {
  cat <<'USAGE'
Usage: scripts/mutation.sh [--work DIR] [--jobs J] [--only SUBSTRING] [--list]

Applies each mistake of scripts/mutations.txt (a sign of an arrow, the sense of a spin, a
number or symbol of a worked example, a table column, before and after swapped, a label's
unit, a body's rotation in 3D, ...) to a copy of the committed sources, rebuilds what
changed and runs the tests the entry names. A mistake is caught when a test fails. Prints
one line per mistake and the score; exits 1 unless every mistake is caught.

  --work DIR      where the copy and its build live (default build-mutation; kept between
                  runs, so later runs only rebuild what each mistake changes)
  --jobs J        build jobs (default: the number of cores)
  --only TEXT     only the mistakes whose name contains TEXT
  --list          list the mistakes and exit
  -h, --help      this text

Each entry of scripts/mutations.txt: `name:`, `file:`, `tests:` (a ctest -R pattern),
`old:` (text that occurs exactly once in the file) and `new:`; `\n` in old and new is a
line break. Blank lines separate entries; lines starting with # are comments.
USAGE
}

work=build-mutation
jobs=$(nproc)
only=""
list=0
while [[ $# -gt 0 ]]; do
  case $1 in
    --work) work=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --only) only=$2; shift 2 ;;
    --list) list=1; shift ;;
    -h|--help) usage; exit 0 ;;
    *) echo "mutation.sh: unknown argument '$1'" >&2; usage >&2; exit 2 ;;
  esac
done

# Read the entries into parallel arrays.
names=() files=() tests=() olds=() news=()
flush() {
  if [[ -n ${name:-} ]]; then
    if [[ -z ${file:-} || -z ${test:-} || -z ${old:-} || -z ${new+x} ]]; then
      echo "mutation.sh: scripts/mutations.txt: entry '$name' lacks file, tests, old or new" >&2
      exit 2
    fi
    names+=("$name") files+=("$file") tests+=("$test") olds+=("$old") news+=("$new")
  fi
  name="" file="" test="" old="" new=""
  unset new
}
name="" file="" test="" old=""
unset new
while IFS= read -r line || [[ -n $line ]]; do
  case $line in
    '#'*) ;;
    '') flush ;;
    name:*) name=${line#name: } ;;
    file:*) file=${line#file: } ;;
    tests:*) test=${line#tests: } ;;
    old:*) old=${line#old: } ;;
    new:*) new=${line#new: } ;;
    *) echo "mutation.sh: scripts/mutations.txt: cannot read: $line" >&2; exit 2 ;;
  esac
done <scripts/mutations.txt
flush

if [[ $list -eq 1 ]]; then
  for i in "${!names[@]}"; do printf '%2d. %s  (%s)\n' $((i + 1)) "${names[$i]}" "${files[$i]}"; done
  exit 0
fi

# The copy: the committed sources (HEAD), built once; each mistake is undone after its run.
src=$work/src
build=$work/build
mkdir -p "$src"
rm -rf "$work/head"
mkdir -p "$work/head"
git archive HEAD | tar -x -C "$work/head"
# Copy only what differs, so that the build after the first is incremental.
(cd "$work/head" && find . -type f) | while IFS= read -r p; do
  if ! cmp -s "$work/head/$p" "$src/$p"; then
    mkdir -p "$(dirname "$src/$p")"
    cp "$work/head/$p" "$src/$p"
  fi
done
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
echo "mutation.sh: building the unchanged copy in $build"
cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCOLLIDE_BUILD_BENCH=OFF "${launcher[@]}" >"$work/configure.log"
cmake --build "$build" -j "$jobs" >"$work/build.log" 2>&1 || {
  echo "mutation.sh: the unchanged copy does not build; see $work/build.log" >&2
  exit 2
}

caught=0 total=0 missed=()
for i in "${!names[@]}"; do
  [[ -z $only || ${names[$i]} == *"$only"* ]] || continue
  total=$((total + 1))
  f=$src/${files[$i]}
  cp "$f" "$work/original"
  old=${olds[$i]//\\n/$'\n'}
  new=${news[$i]//\\n/$'\n'}
  count=$(OLD="$old" perl -0ne 'BEGIN { $n = 0 } $n += () = /\Q$ENV{OLD}\E/g; END { print $n }' "$f")
  if [[ $count -ne 1 ]]; then
    printf '  %-60s  NOT APPLIED (the text occurs %s times)\n' "${names[$i]}" "$count"
    missed+=("${names[$i]} (not applied)")
    continue
  fi
  OLD="$old" NEW="$new" perl -0pi -e 's/\Q$ENV{OLD}\E/$ENV{NEW}/' "$f"
  result="survived"
  if ! cmake --build "$build" -j "$jobs" >"$work/mutant.log" 2>&1; then
    result="does not build"
  elif ! ctest --test-dir "$build" -R "${tests[$i]}" -j "$jobs" >"$work/mutant-tests.log" 2>&1; then
    result="caught"
  elif ! grep -q "tests passed\|No tests were found" "$work/mutant-tests.log" ||
       grep -q "No tests were found" "$work/mutant-tests.log"; then
    result="no tests matched '${tests[$i]}'"
  fi
  # Undo it, keeping the file's time stamp moving forward so that the next build sees it.
  cp "$work/original" "$f"
  touch "$f"
  if [[ $result == caught ]]; then
    caught=$((caught + 1))
    printf '  %-60s  caught\n' "${names[$i]}"
  else
    printf '  %-60s  %s\n' "${names[$i]}" "${result^^}"
    missed+=("${names[$i]} ($result)")
  fi
done
echo "mutation.sh: $caught of $total mistakes caught by a failing test"
for m in "${missed[@]}"; do echo "  missed: $m"; done
[[ $caught -eq $total ]]
