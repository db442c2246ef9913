#!/usr/bin/env bash
# The data every bundled lesson writes, byte for byte: builds the site of every lesson (small
# frames: only the data files are compared) and checks the SHA-256 of each lesson's data.csv,
# data.json, events.csv, lesson.md (its answers), worked-example.md and penalty.csv against
# tests/outputs/lessons.sha256.
#
# Usage: lesson_outputs.sh COLLIDE GOLDEN [--update]
#   --update rewrites GOLDEN from this build: do it only for a change meant to change what the
#   lessons print, and say so in the commit.
set -euo pipefail
collide=$1
golden=$2
update=${3:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$collide" material -o "$tmp/site" --size 160x120 --quiet
(cd "$tmp/site" && find . -type f \( -name data.csv -o -name data.json -o -name events.csv \
    -o -name lesson.md -o -name worked-example.md -o -name penalty.csv \) | LC_ALL=C sort |
    xargs sha256sum) > "$tmp/now.sha256"

if [[ $update == --update ]]; then
  cp "$tmp/now.sha256" "$golden"
  echo "lesson_outputs: wrote $(wc -l < "$golden") checksums to $golden"
  exit 0
fi
if ! diff -u "$golden" "$tmp/now.sha256"; then
  echo "lesson_outputs: the files above differ from $golden (lines with -: expected, +: now)." >&2
  echo "If the change is meant, run: $0 $collide $golden --update" >&2
  exit 1
fi
echo "lesson_outputs: $(wc -l < "$golden") files identical"
