#!/usr/bin/env bash
# Installs the QTI software the tests run on `collide worksheet --format qti` (tests/qti/): the
# npm registry's @citolab/qti-convert (a QTI 2 to 3 reader), @citolab/qti-components (a QTI
# player, run in Chromium) and the XML and zip readers of the checks, exactly as
# tests/qti/package-lock.json pins them, into BUILD_DIR/qti-reader/node_modules: tools of the
# tests only, nothing of them is built into collide or installed with it. Needs the
# network the first time (npm's cache after that); the tests themselves run offline. Runs on
# Debian 12's Node 18 and npm 9 (scripts/install-deps.sh installs them). scripts/build.sh calls
# it; again with an unchanged lock file it does nothing. When npm fails (no network, a proxy it
# does not trust), it says so, exits 1, and leaves the reason in BUILD_DIR/qti-reader/
# not-installed.txt: the qti tests then report themselves skipped with that reason.
# Usage: scripts/install-qti-reader.sh [BUILD_DIR]     (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-build}/qti-reader
if ! command -v npm >/dev/null; then
  echo "install-qti-reader: npm is not installed (scripts/install-deps.sh installs it): the qti tests will fail" >&2
  exit 1
fi
if [[ -d $dir/node_modules ]] && cmp -s tests/qti/package-lock.json "$dir/package-lock.json" &&
   cmp -s tests/qti/package.json "$dir/package.json"; then
  exit 0
fi
mkdir -p "$dir"
cp tests/qti/package.json tests/qti/package-lock.json "$dir/"
echo "install-qti-reader: npm ci in $dir"
rm -f "$dir/not-installed.txt"
if ! (cd "$dir" && npm ci --no-audit --no-fund --prefer-offline --loglevel=error) 2>"$dir/npm.log"; then
  cat "$dir/npm.log" >&2
  # The qti tests say they were skipped, and why (tests/qti/common.mjs), instead of failing on a
  # machine that cannot reach the npm registry (no network, or a proxy npm does not trust).
  { echo "npm ci failed in $dir:"; grep -m 3 'npm ERR!' "$dir/npm.log" || head -n 3 "$dir/npm.log"; } >"$dir/not-installed.txt"
  exit 1
fi
