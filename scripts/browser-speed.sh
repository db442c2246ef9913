#!/usr/bin/env bash
# The Try-it panel's speed in headless Chromium, beside the native command (scripts/browser-speed.js
# says what each column is; docs/wasm.md gives the last figures). Builds the site of every lesson
# with the WebAssembly module into a temporary folder first (about a minute), unless SITE is given.
# A benchmark, not a test: it prints figures.
# Usage: scripts/browser-speed.sh [SITE]   (after scripts/build.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
collide=build/cli/collide
[[ -x $collide ]] || { echo "browser-speed: $collide is missing: run scripts/build.sh first" >&2; exit 2; }
chromium=$(command -v chromium || command -v chromium-browser || true)
[[ -n $chromium ]] || { echo "browser-speed: needs chromium (scripts/install-deps.sh installs it)" >&2; exit 2; }
site=${1:-}
if [[ -z $site ]]; then
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
  site=$tmp/site
  echo "browser-speed: building the site ($collide material -o $site)"
  "$collide" material -o "$site" --size 320x180 --quiet
fi
node scripts/browser-speed.js "$collide" "$chromium" "$site"
