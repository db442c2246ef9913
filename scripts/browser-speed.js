// The Try-it panel's speed in headless Chromium (issue 35, item 4; docs/wasm.md "Speed"): every
// bundled lesson's page of a site built with the WebAssembly module, opened from file:// in a
// fresh tab, driven through the DevTools protocol (tests/wasm/cdp.js). Per lesson:
//   engine  when the module had started (ms from the page's navigation)
//   first   when the panel showed its first answer (ms from navigation: the page load's answer)
//   load    when the page's load event ended (ms from navigation: its images, video and scripts
//           read), for comparison with first
//   answer  the median of 9 answers after a slider moves (each [[vary]] input one step in turn,
//           set as a hand sets it: the slider's value and its input event): the engine's call
//   shown   the same answers' median including the panel's drawing (numbers, worked example,
//           plots, picture): the script's work
//   painted the same answers' median until the browser has painted them (its style, layout
//           and paint of what changed: the next frame): what the reader waits for
//   native  the median of 3 runs of the command on the same lesson file (`collide step FILE
//           --events --json`: the run alone, process start included), for scale
// The slider moves begin once the page has warmed the engine up (try-it.js warmUp: a few
// answers in the background after the start, at most 400 ms of them), as a reader's first move
// comes a second or so after the page appears. Then a line per lesson with the medians of the
// answer's stages (panel.collideTimes), where the time goes.
// Goals (issue 35): first under 100 ms; each answer under 16 ms (1D, 2D) and 50 ms (3D).
// A benchmark, not a test: it prints figures and exits 0 whatever they are.
// Usage: node scripts/browser-speed.js COLLIDE CHROMIUM SITE   (SITE: `collide material -o SITE`)
'use strict';
const fs = require('fs');
const os = require('os');
const path = require('path');
const {execFileSync} = require('child_process');

const [collide, chromium, site] = process.argv.slice(2);
if (!site || !fs.existsSync(path.join(site, 'collide-engine.js'))) {
  console.error('browser-speed: usage: node scripts/browser-speed.js COLLIDE CHROMIUM SITE (a site with collide-engine.js)');
  process.exit(2);
}
const root = path.join(__dirname, '..');
const work = fs.mkdtempSync(path.join(os.tmpdir(), 'browser-speed.'));
const cdp = require(path.join(root, 'tests', 'wasm', 'cdp.js'))(collide, chromium, work);
const median = xs => { const s = xs.slice().sort((a, b) => a - b); return s[Math.floor(s.length / 2)]; };
const fixed = x => (x === undefined || isNaN(x) ? '-' : x.toFixed(1));

async function main() {
  const files = fs.readdirSync(path.join(root, 'lessons')).filter(f => f.endsWith('.toml')).sort();
  const module = fs.statSync(path.join(site, 'collide-engine.js')).size;
  console.log(`browser-speed: ${site}, collide-engine.js ${(module / 1e6).toFixed(2)} MB; ` +
              `${execFileSync(chromium, ['--version']).toString().trim()}; ${os.cpus()[0].model}, ${os.cpus().length} cores, ` +
              `load ${os.loadavg().map(x => x.toFixed(2)).join(' ')}`);
  console.log('  lesson                     dim  engine   first    load  answer   shown painted  native  (ms; medians of 9 slider moves, native of 3)');
  const rows = [];
  for (const f of files) {
    const text = fs.readFileSync(path.join(root, 'lessons', f), 'utf8');
    const id = text.match(/^id = "([^"]*)"/m)[1], dim = Number((text.match(/^dimension = (\d)/m) || [0, 1])[1]);
    const page = await cdp.openPage('file://' + path.resolve(site, id, 'index.html') + '?show=try-it');
    let n = await cdp.answered(page, 0);
    for (let k = 0; k < 100 && !(await page.eval(`document.getElementById('try-it').dataset.warmRuns`)); ++k) await cdp.sleep(50);
    for (let k = 0; k < 100 && (await page.eval('document.readyState')) !== 'complete'; ++k) await cdp.sleep(50);
    const first = await page.eval(`(function () { var d = document.getElementById('try-it').dataset;
      var nav = performance.getEntriesByType('navigation')[0];
      return {engine: Number(d.engineAt), first: Number(d.firstShownAt), load: nav ? nav.loadEventEnd : NaN}; })()`);
    const inputs = await page.eval(`Array.prototype.map.call(document.querySelectorAll('#try-it input[type=range]'),
      function (i) { return i.dataset.name; })`);
    const answer = [], shown = [], painted = [], stages = {};
    for (let k = 0; k < 9 && inputs.length; ++k) {
      const name = inputs[k % inputs.length];
      await page.eval(`(function () {
        var i = Array.prototype.find.call(document.querySelectorAll('#try-it input[type=range]'),
                                          function (x) { return x.dataset.name === ${JSON.stringify(name)}; });
        if (Number(i.value) + Number(i.step) <= Number(i.max) + 1e-12) i.stepUp(); else i.stepDown();
        i.dispatchEvent(new Event('input'));
      })()`);
      n = await cdp.answered(page, n);  // (it waits 100 ms more: the paint is in)
      const d = await page.eval(`(function () { var p = document.getElementById('try-it'), d = p.dataset;
        return {answer: Number(d.answerMs), shown: Number(d.shownMs), times: p.collideTimes, error: d.error || null}; })()`);
      if (d.error) throw new Error(id + ': ' + d.error);
      answer.push(d.answer);
      shown.push(d.shown);
      painted.push(d.times.painted);
      for (const k of Object.keys(d.times)) (stages[k] = stages[k] || []).push(d.times[k]);
    }
    await page.close();
    const native = [];
    for (let k = 0; k < 3; ++k) {
      const t0 = process.hrtime.bigint();
      execFileSync(collide, ['step', path.join(root, 'lessons', f), '--events', '--json'], {stdio: ['ignore', 'ignore', 'ignore']});
      native.push(Number(process.hrtime.bigint() - t0) / 1e6);
    }
    const row = {id, dim, engine: first.engine, first: first.first, load: first.load, answer: median(answer), shown: median(shown),
                 painted: median(painted), native: median(native)};
    rows.push(row);
    console.log(`  ${id.padEnd(26)} ${dim}D ${fixed(row.engine).padStart(7)} ${fixed(row.first).padStart(7)} ${fixed(row.load).padStart(7)} ` +
                `${fixed(row.answer).padStart(7)} ${fixed(row.shown).padStart(7)} ${fixed(row.painted).padStart(7)} ` +
                `${fixed(row.native).padStart(7)}`);
    console.log('      stages: ' + Object.keys(stages).map(k => k + ' ' + fixed(median(stages[k]))).join(', '));
  }
  const goal = r => (r.dim === 3 ? 50 : 16);
  const slow = rows.filter(r => r.painted > goal(r)).map(r => `${r.id} ${fixed(r.painted)}`);
  const late = rows.filter(r => r.first > 100).map(r => `${r.id} ${fixed(r.first)}`);
  const afterLoad = rows.filter(r => !(r.first < r.load)).map(r => `${r.id} ${fixed(r.first)} (load ${fixed(r.load)})`);
  console.log(`  medians over the lessons: first ${fixed(median(rows.map(r => r.first)))} ms, painted ` +
              `${fixed(median(rows.filter(r => r.dim < 3).map(r => r.painted)))} ms (1D, 2D), ` +
              `${fixed(median(rows.filter(r => r.dim === 3).map(r => r.painted)))} ms (3D)`);
  console.log(`  first answer over 100 ms after the navigation: ${late.length ? late.join(', ') : 'none'}`);
  console.log(`  first answer not before the page's load event: ${afterLoad.length ? afterLoad.join(', ') : 'none'}`);
  console.log(`  answers painted over the goal (16 ms 1D/2D, 50 ms 3D): ${slow.length ? slow.join(', ') : 'none'}`);
}

main().then(() => { cdp.stop(); fs.rmSync(work, {recursive: true, force: true}); }, e => {
  cdp.stop();
  console.error('browser-speed: ' + e.stack);
  process.exit(1);
});
