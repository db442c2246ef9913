#!/usr/bin/env bash
# The Try-it panel in a real browser: `collide material` writes lessons 01 and 06's pages with
# the WebAssembly module ($COLLIDE_ENGINE_JS), headless Chromium opens them from file://:
# - catch-up?A.mass=3: the impulse the page shows must equal `collide solve`'s for those inputs
#   (catch-up-a3.toml) to 1e-12 relative;
# - catch-up?scene.restitution=1: the slider reaches its maximum (a step written as
#   0.10000000000000001 stopped it at 0.9), so the panel has no line about the address;
# - general-2d?A.v.x=2&A.mas=3: one component of a vector set from the address (the impulse
#   equals the first collision of `collide step --events --json` on the lesson with v = [2, 0],
#   to 1e-9 relative: the page samples the run at its frame rate), and the name the lesson has
#   no input for shown on the page.
# - bouncing-ball: the panel shows the lesson's plots as the engine draws them (an SVG each,
#   labelled with the page's alt text), and when its e slider moves (an input event, as a hand
#   moves it) to 0.4 the bounce-interval plot is replaced by the new run's: another SVG, each
#   interval 0.4 times the one before.
# - a run beyond the module's work budget per call (a free box at 1e5 rad/s for 1 s: about
#   2e7 units, which `collide step` runs in seconds) answers with the refusal and its estimate
#   at once instead of freezing the page (issue 34).
# Screenshots of the panels stay in WORK/ to be looked at.
# Usage: browser.sh COLLIDE CHROMIUM WORK
set -euo pipefail
trap 'echo "browser.sh: line $LINENO: a command failed (exit $?)" >&2' ERR
collide=$1
chromium=$2
work=$3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
mkdir -p "$work"
[[ -f ${COLLIDE_ENGINE_JS:-} ]] || { echo "browser.sh: COLLIDE_ENGINE_JS=${COLLIDE_ENGINE_JS:-} is not a file" >&2; exit 1; }

"$collide" material -o "$work/site" --size 640x360 --quiet catch-up general-2d dominoes bouncing-ball
[[ -f $work/site/collide-engine.js && -f $work/site/try-it.js ]] || { echo "browser.sh: the site has no module" >&2; exit 1; }
page="file://$work/site/catch-up/index.html"

# As root (CI's containers) Chromium needs --no-sandbox. The virtual time budget lets the page
# load the module and answer before the DOM is dumped or the picture taken.
# Each run with a profile of its own (a Chromium still ending may hold a profile's lock, and a
# second one on a profile in use hands its page to the first and returns at once).
browse() {
  "$chromium" --headless --no-sandbox --disable-gpu --hide-scrollbars --virtual-time-budget=15000 \
    --user-data-dir="$(mktemp -d "$work/profile.XXXXXX")" --window-size=1100,1400 "$@" 2>"$work/chromium.log"
}
# The page's DOM once the module has answered. The module compiles on a thread of its own, in
# real time, while the virtual time budget runs on: on a loaded machine the budget can end
# first ("Loading the engine…"), so a dump that has not got there yet is taken again (3 times).
browse_dom() {  # browse_dom URL OUT
  local k
  for k in 1 2 3; do
    browse --dump-dom "$1" >"$2"
    grep -q 'Loading the engine' "$2" || return 0
    echo "browser.sh: $1: the module had not answered when the page was dumped (try $k of 3)"
  done
}
start=$(date +%s.%N)
browse_dom "$page?A.mass=3" "$work/after.html"
browse --screenshot="$work/before.png" "$page?show=try-it"
browse --screenshot="$work/after.png" "$page?A.mass=3&show=try-it"

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

# The slider's maximum: e = 1 is set and shown as asked, with no line about the address.
browse_dom "$page?scene.restitution=1" "$work/e1.html"
grep -q 'class="tryit-query-' "$work/e1.html" && {
  echo "browser.sh: FAIL: ?scene.restitution=1: $(grep -o '<li class="tryit-query[^<]*' "$work/e1.html")" >&2
  exit 1
}
grep -q '<output for="tryit-in-5">1</output>' "$work/e1.html" || { echo "browser.sh: FAIL: e = 1 is not shown" >&2; exit 1; }
echo "browser.sh: ?scene.restitution=1 reaches the slider's maximum"

# A vector's component from the address, and a name the lesson has no input for.
page2="file://$work/site/general-2d/index.html"
browse_dom "$page2?A.v.x=2&A.mas=3" "$work/general-2d.html"
browse --screenshot="$work/general-2d.png" "$page2?A.v.x=2&A.mas=3&show=try-it"
unknown=$(grep -o '<li class="tryit-query-unknown">[^<]*' "$work/general-2d.html" | sed 's/.*>//' || true)
[[ $unknown == *"this lesson has no input A.mas"* ]] || {
  echo "browser.sh: FAIL: ?A.mas=3 is not shown on the page as a name without an input (got: '$unknown')" >&2
  exit 1
}
shown=$(grep -o 'class="tryit-impulse" data-value="[^"]*"' "$work/general-2d.html" | sed 's/.*data-value="\[\([^,]*\),.*/\1/' || true)
sed 's/^v = \[1.5, 0.0\]$/v = [2.0, 0.0]/' "$here/../../lessons/06-general-2d.toml" >"$work/general-2d-v2.toml"
grep -q '^v = \[2.0, 0.0\]$' "$work/general-2d-v2.toml" || { echo "browser.sh: lesson 06 has no v = [1.5, 0.0]" >&2; exit 1; }
expected=$("$collide" step "$work/general-2d-v2.toml" --events --json | head -1 | sed 's/.*"impulse":\[\([^,]*\),.*/\1/')
echo "browser.sh: the page (?A.v.x=2) shows P_x = $shown N s; collide step gives $expected N s; unknown name: $unknown"
[[ -n $shown ]] || { echo "browser.sh: FAIL: general-2d shows no impulse" >&2; exit 1; }
awk -v a="$shown" -v b="$expected" 'BEGIN { d = a - b; if (d < 0) d = -d; m = (b < 0 ? -b : b); exit !(d <= 1e-9 * m) }' || {
  echo "browser.sh: FAIL: they differ" >&2
  exit 1
}
[[ -s $work/general-2d.png ]] || { echo "browser.sh: no general-2d.png" >&2; exit 1; }

# One truth per page: in dominoes the world resolves the first strike with domino 2's contact
# with the floor, so the panel's impulse is the run's (the first domino 1 / domino 2 event of
# `collide step`), not the two dominoes alone of the worked example below it.
page3="file://$work/site/dominoes/index.html"
browse_dom "$page3" "$work/dominoes.html"
browse --screenshot="$work/dominoes.png" "$page3?show=try-it"
grep -q 'as the run resolved it with the other contacts of that instant' "$work/dominoes.html" || {
  echo "browser.sh: FAIL: dominoes' panel does not say it shows the run's numbers" >&2
  exit 1
}
shown=$(grep -o 'class="tryit-impulse" data-value="[^"]*"' "$work/dominoes.html" | sed 's/.*data-value="\[\([^,]*\),.*/\1/' || true)
# (into a file first: the events are more than a pipe holds, and grep -m1 would leave the
# command writing into a closed pipe)
"$collide" step dominoes --events --json >"$work/dominoes-events.jsonl"
expected=$(grep -m1 '"a":"domino 1","b":"domino 2"' "$work/dominoes-events.jsonl" | sed 's/.*"impulse":\[\([^,]*\),.*/\1/')
echo "browser.sh: dominoes' panel shows P_x = $shown N s; the run (collide step) gives $expected N s"
[[ -n $shown ]] || { echo "browser.sh: FAIL: dominoes shows no impulse" >&2; exit 1; }
awk -v a="$shown" -v b="$expected" 'BEGIN { d = a - b; if (d < 0) d = -d; m = (b < 0 ? -b : b); exit !(d <= 1e-9 * m) }' || {
  echo "browser.sh: FAIL: they differ" >&2
  exit 1
}
# The lesson's plots in the panel, and a slider moved: a copy of bouncing-ball's page with a
# script that waits for the panel's plots, moves the e slider to 0.4, and writes what it saw.
ball="$work/site/bouncing-ball"
cp "$ball/index.html" "$ball/moved.html"
cat >>"$ball/moved.html" <<'HTML'
<pre id="moved">waiting</pre>
<script>
(function () {
  var panel = document.getElementById('try-it'), out = document.getElementById('moved');
  var before = null, tries = 0;
  function plot() { return panel.querySelectorAll('.tryit-lesson-plots section.lesson-plot')[1]; }
  function look() {
    var p = plot(), svg = p && p.querySelector('svg');
    if (++tries > 200) { out.textContent = 'timeout: ' + (before ? 'no new plot' : 'no plot'); return; }
    if (!svg) return setTimeout(look, 50);
    var summary = p.querySelector('details.plot-data p').textContent;
    if (before === null) {
      before = {svg: svg.outerHTML, label: svg.getAttribute('aria-label'), summary: summary,
                count: panel.querySelectorAll('.tryit-lesson-plots svg').length};
      var e = panel.querySelector('input[data-name="scene.restitution"]');
      e.value = '0.4';
      e.dispatchEvent(new Event('input'));
      return setTimeout(look, 50);
    }
    if (svg.outerHTML === before.svg) return setTimeout(look, 50);
    out.textContent = 'plots: ' + before.count + '\nbefore: ' + before.summary + '\nlabel: ' + before.label +
                      '\nafter: ' + summary;
  }
  look();
})();
</script>
HTML
browse_dom "file://$ball/moved.html" "$work/moved.html"
browse --screenshot="$work/bouncing-ball.png" "file://$ball/index.html?show=try-it&scene.restitution=0.4"
moved=$(sed -n '/<pre id="moved">/,/<\/pre>/p' "$work/moved.html" | sed 's/<pre id="moved">//; s/<\/pre>//')
echo "browser.sh: bouncing-ball's panel plots: $moved"
grep -q '^plots: 2$' <<<"$moved" || { echo "browser.sh: FAIL: the panel does not show the lesson's 2 plots" >&2; exit 1; }
grep -q '^label: Time between one bounce and the next: ' <<<"$moved" || {
  echo "browser.sh: FAIL: the panel's plot is not labelled with the page's alt text" >&2
  exit 1
}
grep -q '^before: .*0.5 times the one before' <<<"$moved" || { echo "browser.sh: FAIL: before the move, not e = 0.5" >&2; exit 1; }
grep -q '^after: .*0.4 times the one before.*e = 0.4' <<<"$moved" || {
  echo "browser.sh: FAIL: after the e slider moved to 0.4 the plot did not follow" >&2
  exit 1
}
[[ -s $work/bouncing-ball.png ]] || { echo "browser.sh: no bouncing-ball.png" >&2; exit 1; }

# A run beyond the module's budget: an Error with the estimate, within seconds, not a frozen page.
cp "$COLLIDE_ENGINE_JS" "$work/collide-engine.js"
cat >"$work/refused.html" <<'HTML'
<!doctype html><meta charset="utf-8"><title>refused</title><p id="out">waiting</p>
<script src="collide-engine.js"></script>
<script>
const spin = `[scene]
dimension = 3
duration = 1
output_dt = 0.1

[[body]]
name = "box"
shape = "box"
size = [1, 2, 3]
mass = 1
w = [1e5, 1, 0]
`;
CollideEngine().then(m => {
  const t0 = performance.now();
  let said;
  try { m.run(spin); said = 'answered'; } catch (e) { said = 'refused: ' + e.message; }
  document.getElementById('out').textContent = said + ' [' + (performance.now() - t0).toFixed(0) + ' ms]';
});
</script>
HTML
t0=$(date +%s)
timeout 120 "$chromium" --headless --no-sandbox --disable-gpu --virtual-time-budget=15000 \
  --user-data-dir="$(mktemp -d "$work/profile.XXXXXX")" --dump-dom "file://$work/refused.html" >"$work/refused.dom" 2>"$work/chromium.log" || true
said=$(grep -o '<p id="out">[^<]*' "$work/refused.dom" | sed 's/.*>//' || true)
echo "browser.sh: a run beyond the module's budget: $said ($(($(date +%s) - t0)) s with Chromium's start)"
[[ $said == "refused: the scene would take about 2"*"e+07 units of work"*"more than its budget of 5e+06"* ]] || {
  echo "browser.sh: FAIL: the page did not answer with the refusal" >&2
  exit 1
}
ms=$(sed 's/.*\[\([0-9]*\) ms\]/\1/' <<<"$said")
((ms < 1000)) || { echo "browser.sh: FAIL: the refusal took $ms ms" >&2; exit 1; }
"$collide" step - --events >/dev/null <<'TOML' || { echo "browser.sh: FAIL: collide step refuses the spin" >&2; exit 1; }
[scene]
dimension = 3
duration = 1
output_dt = 0.1

[[body]]
name = "box"
shape = "box"
size = [1, 2, 3]
mass = 1
w = [1e5, 1, 0]
TOML
end=$(date +%s.%N)
printf 'browser.sh: equal; screenshots %s/before.png, after.png and general-2d.png (Chromium: %.1f s)\n' "$work" "$(awk -v a="$start" -v b="$end" 'BEGIN { print b - a }')"
