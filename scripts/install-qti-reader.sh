#!/usr/bin/env bash
# Installs the QTI software the tests run on `collide worksheet --format qti` (tests/qti/): the
# npm registry's @citolab/qti-convert (a QTI 2 to 3 reader), @citolab/qti-components (a QTI
# player, run in Chromium) and the XML and zip readers of the checks, exactly as
# tests/qti/package-lock.json pins them, into BUILD_DIR/qti-reader/node_modules: tools of the
# tests only, nothing of them is built into collide or installed with it. Needs the
# network the first time (npm's cache after that); the tests themselves run offline. Runs on
# Debian 12's Node 18 and npm 9 (scripts/install-deps.sh installs them). scripts/build.sh calls
# it; again with an unchanged lock file it does nothing.
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
(cd "$dir" && npm ci --no-audit --no-fund --prefer-offline --loglevel=error)
