#!/usr/bin/env bash
# The Try-it panel in a real browser: `collide material` writes lesson 01's page with the
# WebAssembly module ($COLLIDE_ENGINE_JS), headless Chromium opens it from file:// with
# ?A.mass=3, and the impulse the page shows must equal `collide solve`'s for those inputs
# (catch-up-a3.toml) to 1e-12 relative. Screenshots of the panel before (the lesson's values)
# and after (A.mass = 3) stay in WORK/ to be looked at.
# Usage: browser.sh COLLIDE CHROMIUM WORK
set -euo pipefail
collide=$1
chromium=$2
work=$3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
mkdir -p "$work"
[[ -f ${COLLIDE_ENGINE_JS:-} ]] || { echo "browser.sh: COLLIDE_ENGINE_JS=${COLLIDE_ENGINE_JS:-} is not a file" >&2; exit 1; }

"$collide" material -o "$work/site" --size 640x360 --quiet catch-up
[[ -f $work/site/collide-engine.js && -f $work/site/try-it.js ]] || { echo "browser.sh: the site has no module" >&2; exit 1; }
page="file://$work/site/catch-up/index.html"

# As root (CI's containers) Chromium needs --no-sandbox. The virtual time budget lets the page
# load the module and answer before the DOM is dumped or the picture taken.
browse() {
  "$chromium" --headless --no-sandbox --disable-gpu --hide-scrollbars --virtual-time-budget=15000 \
    --window-size=1100,1400 "$@" 2>"$work/chromium.log"
}
start=$(date +%s.%N)
browse --dump-dom "$page?A.mass=3" >"$work/after.html"
browse --screenshot="$work/before.png" "$page?show=try-it"
browse --screenshot="$work/after.png" "$page?A.mass=3&show=try-it"
end=$(date +%s.%N)

shown=$(grep -o 'class="tryit-impulse" data-value="[^"]*"' "$work/after.html" | sed 's/.*data-value="\([^"]*\)"/\1/' || true)
status=$(grep -o '<p class="tryit-status[^>]*>[^<]*' "$work/after.html" | sed 's/.*>//' || true)
[[ -n $shown ]] || { echo "browser.sh: the page shows no impulse (status: $status)" >&2; exit 1; }
expected=$("$collide" solve "$here/catch-up-a3.toml" --format json | grep -m1 '"impulse"' | sed 's/.*: *\([^,]*\),*/\1/')
echo "browser.sh: the page (?A.mass=3) shows P = $shown N s; collide solve gives $expected N s; $status"
awk -v a="$shown" -v b="$expected" 'BEGIN { d = a - b; if (d < 0) d = -d; m = (a < 0 ? -a : a); exit !(d <= 1e-12 * m) }' || {
  echo "browser.sh: FAIL: they differ" >&2
  exit 1
}
for f in before after; do [[ -s $work/$f.png ]] || { echo "browser.sh: no $f.png" >&2; exit 1; }; done
printf 'browser.sh: equal; screenshots %s/before.png and after.png (Chromium: %.1f s)\n' "$work" "$(awk -v a="$start" -v b="$end" 'BEGIN { print b - a }')"
