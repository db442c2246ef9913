#!/usr/bin/env bash
# The tree's C++ in the style .clang-format states (clang-format 14, Debian 12's).
# Usage: scripts/format.sh          rewrites every tracked .cpp and .h in place
#        scripts/format.sh --check  changes nothing; lists the files that differ and exits 1
#                                   (the test style.format runs this)
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null || { echo "format: clang-format is not installed (scripts/install-deps.sh)" >&2; exit 2; }
mapfile -t files < <(git ls-files '*.cpp' '*.h' 2>/dev/null || find . -path ./build -prune -o \( -name '*.cpp' -o -name '*.h' \) -print)
case ${1:-} in
  "") clang-format -i "${files[@]}"; echo "format: ${#files[@]} files formatted" ;;
  --check)
    bad=()
    for f in "${files[@]}"; do
      clang-format --dry-run --Werror "$f" >/dev/null 2>&1 || bad+=("$f")
    done
    if [[ ${#bad[@]} -gt 0 ]]; then
      printf 'format: not in the style of .clang-format: %s\n' "${bad[@]}" >&2
      echo "format: run scripts/format.sh to fix them (or clang-format -i FILE)" >&2
      exit 1
    fi
    echo "format: ${#files[@]} files in the style of .clang-format" ;;
  *) echo "usage: $0 [--check]" >&2; exit 2 ;;
esac
