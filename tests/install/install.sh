#!/usr/bin/env bash
# `cmake --install` into a fresh prefix, then what a user does with the installed tree, from a
# directory outside the source and build trees (docs/install.md):
#   - the files are where GNUInstallDirs puts them (command, lessons, man page, completion,
#     headers, libraries, CMake package);
#   - the installed collide reads the installed lessons, found from its own executable (a lesson
#     removed from the install is gone from its list; COLLIDE_LESSONS still overrides);
#   - the man page has every subcommand; bash completion completes subcommands, options, an
#     option's values and lesson ids;
#   - examples/cpp-consumer configures with find_package(Collide) against the prefix, builds and
#     runs (an engine collision checked against its closed form; a frame drawn by collide::render).
# Usage: install.sh BUILD_DIR SOURCE_DIR WORK_DIR MAN(ON|OFF) [CMAKE ARGS FOR THE CONSUMER...]
# WORK_DIR is emptied first; it is this test's own (ctest runs tests in parallel).
set -uo pipefail
build=$1 source=$2 work=$3 man=$4
shift 4
consumer_args=("$@")
prefix=$work/prefix
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

rm -rf "$work"
mkdir -p "$work/elsewhere"
if ! cmake --install "$build" --prefix "$prefix" >"$work/install.log" 2>&1; then
  cat "$work/install.log"
  echo "FAIL cmake --install"
  exit 1
fi

# ---- The files ----
libdir=$(cd "$prefix" && dirname "$(find . -name libcollide_engine.a | head -n 1)")
for f in bin/collide share/collide/lessons/01-catch-up.toml share/collide/lessons/solve/rod-on-ground.toml \
         share/collide/lessons/scenes/cradle-1d.toml share/bash-completion/completions/collide \
         share/doc/collide/README.md share/doc/collide/docs/commands/solve.md \
         include/collide/engine/respond.h include/collide/render/renderer.h \
         "$libdir/libcollide_engine.a" "$libdir/libcollide_render.a" "$libdir/cmake/Collide/CollideConfig.cmake"; do
  [[ -f $prefix/$f ]] || fail "not installed: $f"
done
[[ $man == ON && ! -f $prefix/share/man/man1/collide.1.gz ]] && fail "not installed: share/man/man1/collide.1.gz"
# Nothing of the build tree is needed: no source path in the installed CMake files.
grep -rlF -- "$source" "$prefix/$libdir/cmake" && fail "the installed CMake package names the source tree"

# ---- The installed command, from elsewhere ----
cd "$work/elsewhere"
unset COLLIDE_LESSONS
collide=$prefix/bin/collide
# Bare `collide` shows what it can do: the same help as --help, every subcommand.
diff <("$collide") <("$collide" --help) >/dev/null || fail "bare collide does not print the whole --help"
"$collide" lessons >lessons.txt 2>&1 || fail "installed collide lessons: $(cat lessons.txt)"
"$build/cli/collide" lessons >expected.txt 2>&1
diff -u expected.txt lessons.txt || fail "the installed collide lists other lessons than the build tree's"
"$collide" solve "$prefix/share/collide/lessons/solve/carts-1d.toml" --format json >solve.json 2>&1 ||
  fail "installed collide solve: $(cat solve.json)"
grep -q '"impulse"' solve.json || fail "collide solve --format json printed no impulse"
"$collide" step catch-up --events >events.txt 2>&1 || fail "installed collide step catch-up: $(cat events.txt)"
"$collide" render catch-up -o render --size 160x120 --quiet >render.log 2>&1 || fail "installed collide render: $(cat render.log)"
[[ -f render/figure.png ]] || fail "installed collide render wrote no figure.png"
# It reads the installed lessons: one removed there is gone from its list (the build tree still
# has it), and COLLIDE_LESSONS brings the source tree's back.
dominoes=$(ls "$prefix"/share/collide/lessons/*dominoes.toml)
rm "$dominoes"
"$collide" lessons | grep -q dominoes && fail "the installed collide does not read the installed lessons"
COLLIDE_LESSONS=$source/lessons "$collide" lessons | grep -q dominoes || fail "COLLIDE_LESSONS does not override"
"$collide" render dominoes -o x --quiet 2>render.err && fail "rendered a lesson that is not installed"
grep -q "did you mean\|no such file" render.err || fail "unexpected message: $(cat render.err)"

# ---- Man page ----
if [[ $man == ON ]]; then
  page=$(gzip -dc "$prefix/share/man/man1/collide.1.gz")
  for sub in $("$collide" --help | sed -n '/^Subcommands:/,$ s/^  \([a-z][a-z-]*\) .*/\1/p'); do
    grep -qF ".SS \"collide $sub\"" <<<"$page" || fail "the man page has no section for collide $sub"
  done
  grep -qF 'COLLIDE_LESSONS' <<<"$page" || fail "the man page does not mention COLLIDE_LESSONS"
fi

# ---- Bash completion ----
complete_line() {  # complete_line WORD...: what completing the last word offers
  PATH=$prefix/bin:$PATH bash -c '
    source "$1"; shift
    COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1))
    _collide
    printf "%s\n" "${COMPREPLY[@]}"' _ "$prefix/share/bash-completion/completions/collide" "$@"
}
expect_completion() {  # expect_completion "WANTED WORDS" WORD...
  local wanted=$1 got
  shift
  got=$(complete_line "$@" | LC_ALL=C sort | tr '\n' ' ')
  for w in $wanted; do
    grep -qw -- "$w" <<<"$got" || fail "completing '$*' does not offer $w (offers: $got)"
  done
}
expect_completion "render" collide ren
expect_completion "solve step render lessons material worksheet gui compare --help --version" collide ""
expect_completion "--quality --quiet" collide render --qu
expect_completion "low medium high" collide render --quality ""
expect_completion "markdown" collide solve --format m
expect_completion "catch-up" collide render cat
expect_completion "--json --events --interactive --no-interactive" collide step --
[[ $(complete_line collide render --quality "" | wc -l) -eq 3 ]] || fail "--quality offers more than its three values"

# ---- A C++ program on find_package(Collide) ----
if ! cmake -S "$source/examples/cpp-consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$prefix" \
     -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS=-Wall -Wextra -Wpedantic -Werror" "${consumer_args[@]}" \
     >"$work/consumer.log" 2>&1; then
  cat "$work/consumer.log"
  fail "examples/cpp-consumer does not configure"
elif ! grep -q "^Collide_DIR:PATH=$prefix/" "$work/consumer/CMakeCache.txt"; then
  fail "examples/cpp-consumer found another Collide: $(grep ^Collide_DIR "$work/consumer/CMakeCache.txt")"
elif ! cmake --build "$work/consumer" -j 2 >>"$work/consumer.log" 2>&1; then
  cat "$work/consumer.log"
  fail "examples/cpp-consumer does not build"
else
  "$work/consumer/rod-on-ground" || fail "rod-on-ground"
  "$work/consumer/drop-frame" "$work/frame.png" || fail "drop-frame"
  [[ $(head -c 8 "$work/frame.png" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]] ||
    fail "drop-frame wrote no PNG"
fi

if [[ $failures -gt 0 ]]; then
  echo "install: $failures failure(s)"
  exit 1
fi
rm -rf "$work"
echo "install: the installed tree works"
