// The WebAssembly module equals the native command (issue 22, docs/tests.md): for every
// bundled collision file (lessons/solve/) and every bundled scenario and lesson (lessons/,
// lessons/scenes/), collide-engine.js's solve(text) and run(text) against `collide solve
// --format json` and `collide step --json` / `--events --json`: the same keys in the same order,
// the same strings and booleans, every number within 1e-12 relative (below 1 in SI units,
// within 1e-12 absolute), event times within 1e-12 s. And every malformed file of tests/bad-input/: the
// module throws the command's message without its file name.
//
// Both builds compute alike to the last bit (the engine's own sine and cosine, engine/trig.h;
// Eigen's SIMD code off, engine/CMakeLists.txt), so even the tower's chaotic collapse (lesson
// 21, stepped boxes on boxes) is the same run in both; the count of numbers that differ at all
// is printed (0 expected; the test holds them to the tolerances above).
//
// Usage: node equal.js COLLIDE MODULE SOURCE_DIR
'use strict';
const fs = require('fs');
const path = require('path');
const { spawnSync } = require('child_process');

const [collide, modulePath, source] = process.argv.slice(2);
if (!source) {
  console.error('usage: node equal.js COLLIDE MODULE SOURCE_DIR');
  process.exit(2);
}
const REL = 1e-12, TIME = 1e-12;

function tomlFiles(dir) {
  return fs.readdirSync(path.join(source, dir)).filter(f => f.endsWith('.toml')).sort().map(f => path.join(dir, f));
}

// `collide step` with the module's work budget per call (engine/scene.h kWasmWorkBudget): a
// run is refused by both or by neither, with the same estimate.
const WASM_WORK_BUDGET = '5e6';

function cli(args) {
  if (args[0] === 'step') args = [...args, '--max-work', WASM_WORK_BUDGET];
  const r = spawnSync(collide, args, { encoding: 'utf8', maxBuffer: 1 << 30 });
  return { code: r.status, out: r.stdout, err: r.stderr };
}

// The differences between two parsed JSON values, as "where: what" lines; `count` tallies the
// numbers compared and those not bit-identical.
function differences(a, b, where, out, key, count) {
  if (typeof a === 'number' && typeof b === 'number') {
    const d = Math.abs(a - b), time = key === 't' && where.startsWith('events');
    const ok = time ? d <= TIME : d <= REL * Math.max(Math.abs(a), Math.abs(b), 1);
    if (count) { count.numbers++; if (!Object.is(a, b)) count.unequal++; }
    if (!ok) out.push(`${where}: ${a} (module) vs ${b} (collide), difference ${d}`);
    return;
  }
  if (Array.isArray(a) && Array.isArray(b)) {
    if (a.length !== b.length) { out.push(`${where}: ${a.length} entries (module) vs ${b.length} (collide)`); return; }
    a.forEach((x, i) => differences(x, b[i], `${where}[${i}]`, out, key, count));
    return;
  }
  if (a && b && typeof a === 'object' && typeof b === 'object' && !Array.isArray(a) && !Array.isArray(b)) {
    const ka = Object.keys(a), kb = Object.keys(b);
    if (ka.join(',') !== kb.join(',')) { out.push(`${where}: keys ${ka} (module) vs ${kb} (collide)`); return; }
    ka.forEach(k => differences(a[k], b[k], `${where}.${k}`, out, k, count));
    return;
  }
  if (a !== b) out.push(`${where}: ${JSON.stringify(a)} (module) vs ${JSON.stringify(b)} (collide)`);
}

// The command's message for FILE without "collide: error: FILE" (then ": " or ":").
function fileLess(stderr, file) {
  let m = stderr.trim().replace(/^collide: error: /, '');
  if (m.startsWith(file + ':')) m = m.slice(file.length + 1).replace(/^ /, '');
  return m;
}

function lines(text) { return text.split('\n').filter(l => l.trim() !== '').map(l => JSON.parse(l)); }

require(path.resolve(modulePath))().then(m => {
  let failures = 0, count = { numbers: 0, unequal: 0 }, checked = { solve: 0, run: 0, states: 0, events: 0, errors: 0, both_refused: 0, both_accepted: 0 };
  const fail = (file, what) => { failures++; console.log(`FAIL ${file}: ${what}`); };

  // Collision files: solve(text) against `collide solve --format json`.
  for (const rel of tomlFiles('lessons/solve')) {
    const file = path.join(source, rel), text = fs.readFileSync(file, 'utf8');
    const c = cli(['solve', file, '--format', 'json']);
    if (c.code !== 0) { fail(rel, `collide solve failed: ${c.err}`); continue; }
    let mine;
    try { mine = JSON.parse(m.solve(text)); } catch (e) { fail(rel, `solve threw: ${e.message}`); continue; }
    const diff = [];
    differences(mine, JSON.parse(c.out), 'solve', diff, '', count);
    diff.slice(0, 5).forEach(d => fail(rel, d));
    checked.solve++;
  }

  // Scenarios and lessons: run(text) against `collide step --json` and `--events --json`.
  for (const rel of [...tomlFiles('lessons'), ...tomlFiles('lessons/scenes')]) {
    const file = path.join(source, rel), text = fs.readFileSync(file, 'utf8');
    const states = cli(['step', file, '--json']), events = cli(['step', file, '--events', '--json']);
    if (states.code !== 0 || events.code !== 0) { fail(rel, `collide step failed: ${states.err}${events.err}`); continue; }
    let mine;
    try { mine = JSON.parse(m.run(text)); } catch (e) { fail(rel, `run threw: ${e.message}`); continue; }
    const diff = [];
    differences(Object.keys(mine), ['states', 'events'], 'run', diff, '');
    differences(mine.states, lines(states.out), 'states', diff, '', count);
    differences(mine.events, lines(events.out), 'events', diff, '', count);
    diff.slice(0, 5).forEach(d => fail(rel, d));
    if (diff.length > 5) fail(rel, `... ${diff.length - 5} more differences`);
    checked.run++;
    checked.states += mine.states.length;
    checked.events += mine.events.length;
  }

  // Malformed files: the module's message is the command's without the file name.
  for (const [dir, command, call] of [['tests/bad-input/solve', ['solve'], t => m.solve(t)],
                                      ['tests/bad-input/scene', ['step'], t => m.run(t)],
                                      ['tests/bad-input/lesson', ['step'], t => m.run(t)]]) {
    for (const rel of tomlFiles(dir)) {
      const file = path.join(source, rel), text = fs.readFileSync(file, 'utf8');
      const c = cli([...command, file, ...(command[0] === 'solve' ? ['--format', 'json'] : ['--json'])]);
      let thrown = null, answer = null;
      try { answer = call(text); } catch (e) { thrown = e.message; }
      if (c.code === 0 && thrown === null) { checked.both_accepted++; continue; }  // refused only by `collide render`
      if (c.code === 0) { fail(rel, `collide accepts it, the module throws: ${thrown}`); continue; }
      if (thrown === null) { fail(rel, `collide refuses it (${c.err.trim()}), the module answers`); continue; }
      const want = fileLess(c.err, file);
      if (thrown !== want) fail(rel, `message\n  module:  ${thrown}\n  collide: ${want}`);
      checked.errors++;
    }
  }
  console.log(`equal.js: ${checked.solve} collision files, ${checked.run} scenarios and lessons ` +
              `(${checked.states} states, ${checked.events} events), ${checked.errors} refusals with the same message ` +
              `(${checked.both_accepted} malformed lessons only \`collide render\` refuses: accepted by both); ` +
              `${count.numbers} numbers compared, ${count.unequal} not bit-identical; ` +
              `${failures ? failures + ' FAILURES' : 'all equal'}`);
  process.exit(failures ? 1 : 0);
}, e => { console.error(`equal.js: the module did not load: ${e}`); process.exit(1); });
