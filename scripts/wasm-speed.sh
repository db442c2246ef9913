#!/usr/bin/env bash
# The WebAssembly module's size and speed (docs/wasm.md): the size of
# collide-engine.js (goal: under 2 MB), and for every bundled lesson what a fresh page does:
# start the module, answer once with the lesson's values (the panel at load), then the time the
# panel waits after a slider moves: lesson(text, values, fps) at the page's 30 frames/s, each
# [[vary]] input moved one step in turn (a lesson without [[vary]]: its own values again), 9
# times (goal: the median under 50 ms for every 1D and 2D lesson, and for the 3D ones, which
# the page draws with three.js besides); then, after 20 more, 9 again ("warm": V8 has optimised the hot code by then,
# which a page reaches after some moves). Each lesson in a new Node process, as each page loads its own module (in one
# process V8 would reuse the code it has optimised). A benchmark, not a test: it prints figures.
# Usage: scripts/wasm-speed.sh [MODULE]   (default build/wasm/collide-engine.js)
set -euo pipefail
cd "$(dirname "$0")/.."
module=${1:-build/wasm/collide-engine.js}
[[ -f $module ]] || { echo "wasm-speed: $module is missing: scripts/build.sh (with emscripten) or scripts/build-wasm.sh" >&2; exit 2; }
echo "wasm-speed: $module, $(wc -c <"$module") bytes; node $(node --version); $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "  lesson                       dim   start   load  median    max   warm  (ms; 9 answers after a slider moves)"
worst=0
for file in lessons/*.toml; do
  line=$(node - "$(realpath "$module")" "$file" <<'JS'
const fs = require('fs'), path = require('path');
const [modulePath, file] = process.argv.slice(2);
const t0 = performance.now();
require(modulePath)().then(m => {
  const start = performance.now() - t0;
  const text = fs.readFileSync(file, 'utf8');
  const t1 = performance.now();
  const first = JSON.parse(m.lesson(text, {}, 30));
  const load = performance.now() - t1;
  const moves = first.vary.length ? first.vary.map(v => ({ [v.name]: v.value + (v.value + v.step <= v.hi ? v.step : -v.step) })) : [{}];
  const answer = k => m.lesson(text, moves[k % moves.length], 30);  // after the k-th slider move
  const nine = () => {  // the times of 9 answers, in ms, sorted
    const t = [];
    for (let k = 0; k < 9; ++k) {
      const s = performance.now();
      answer(k);
      t.push(performance.now() - s);
    }
    return t.sort((a, b) => a - b);
  };
  const times = nine();
  for (let k = 0; k < 20; ++k) answer(k);
  const warm = nine();
  console.log([path.basename(file, '.toml'), first.dimension, start, load, times[4], times[8], warm[4]].map((x, i) => i >= 2 ? x.toFixed(1) : x).join(' '));
});
JS
)
  read -r name dim start load median max warm <<<"$line"
  printf '  %-28s %sD %7s %6s %7s %6s %6s\n' "$name" "$dim" "$start" "$load" "$median" "$max" "$warm"
  if [[ $dim -lt 3 ]]; then worst=$(awk -v a="$worst" -v b="$median" 'BEGIN { print (b > a ? b : a) }'); fi
done
echo "  slowest 1D/2D lesson (median after a slider moves): $worst ms (goal: under 50 ms)"
