// qti.player: a QTI player from the npm registry marks our items. @citolab/qti-components (a
// QTI 3.0 player, web components) runs in headless Chromium on the items of
// `collide worksheet --format qti` as @citolab/qti-convert reads them into QTI 3.0 (general-2d:
// 2D vectors; rotation-directions: choices; general-3d: 3D vectors; 3 students): each item
// loads, the responses are set and the player's own response processing scores them:
//   a vector  1 at key.json's value and at 0.999 of the allowance tolerance |value| + 1e-9 from
//             it in any direction, 0 at 1.001 of it, 0 with every component 0.8 of it off (the
//             length of the difference, the rule of collide grade), 0 with a component empty
//   a choice  1 for the right option only, that option's feedback (FEEDBACK), and the worked
//             example once answered (SOLUTION)
// Any error the player logs fails the test. Numbers are not played: qti-components 7.27 does not
// implement <equal toleranceMode="absolute"> (it says "toleranceMode is not supported yet");
// qti.package runs the numbers' rules (check_package.mjs).
// Usage: node play_items.mjs COLLIDE READER_DIR CHROMIUM      (KEEP=1: keep the page to look at)
import { execFileSync } from 'node:child_process';
import { copyFileSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

import { descendants, elements, parseXml, readJson, reader, unzip, worksheet } from './common.mjs';

const [collide, readerDir, chromium] = process.argv.slice(2);
const { dir, JSZip, DOMParser } = reader(readerDir);
const failures = [];
const check = (ok, what) => { if (!ok) failures.push(what); };

const log = console.log;
console.log = () => {};  // qti-convert's progress lines
const { convertPackageFile } = await import(
  pathToFileURL(join(dir, 'node_modules/@citolab/qti-convert/dist/qti-converter-node/index.js')).href);

const LESSONS = ['general-2d', 'rotation-directions', 'general-3d'];
const ws = worksheet(collide, LESSONS, 3, 5);
try {
  await convertPackageFile(join(ws.out, 'qti.zip'), join(ws.tmp, 'qti3.zip'));
  const ours = await unzip(JSZip, readFileSync(join(ws.out, 'qti.zip')));
  const theirs = await unzip(JSZip, readFileSync(join(ws.tmp, 'qti3.zip')));
  const keys = new Map(LESSONS.map(l => [l, readJson(join(ws.out, l, 'key.json'))]));

  // The cases: an item (QTI 3.0) and the responses to give it, each with the SCORE it must get.
  const cases = [];
  for (const [name, bytes] of ours) {
    if (!/\/q\d+-s\d+\.xml$/.test(name)) continue;
    const item = parseXml(DOMParser, bytes.toString('utf8'), name).documentElement;
    const body = elements(item).find(e => e.localName === 'itemBody');
    const fields = descendants(body, 'textEntryInteraction').map(f => f.getAttribute('responseIdentifier'));
    const choice = descendants(body, 'choiceInteraction')[0];
    const trials = [];
    if (fields.length >= 2) {
      const [, lesson, q, s] = name.match(/^(.*)\/q(\d+)-s(\d+)\.xml$/);
      const student = keys.get(lesson).students.find(x => x.student === Number(s));
      const answer = student.answers.find(a => a.question === Number(q));
      const want = answer.value, A = answer.tolerance * Math.hypot(...want) + 1e-9;
      const units = want.length === 2 ? [[1, 0], [0, -1], [Math.cos(2), Math.sin(2)]] : [[1, 0, 0], [0, 0, -1], [0.48, -0.6, 0.64]];
      const give = (values, score, what) => trials.push({ what, score, responses: fields.map((f, c) => [f, values[c]]) });
      give(want, 1, "key.json's value");
      for (const u of units)
        for (const [f, score] of [[0.999, 1], [1.001, 0]]) give(want.map((w, c) => w + f * A * u[c]), score, `${f} A along ${u}`);
      give(want.map(w => w + 0.8 * A), 0, '0.8 A in every component');
      give(want.map((w, c) => (c ? undefined : w)), 0, 'a component left empty');
    } else if (choice) {
      const id = choice.getAttribute('responseIdentifier');
      const d = elements(item).find(e => e.localName === 'responseDeclaration' && e.getAttribute('identifier') === id);
      const right = descendants(d, 'value')[0].textContent;
      for (const option of descendants(choice, 'simpleChoice').map(c => c.getAttribute('identifier')))
        trials.push({ what: option, score: option === right ? 1 : 0, feedback: option, responses: [[id, option]] });
    } else {
      continue;
    }
    cases.push({ name, xml: theirs.get(name).toString('utf8'), trials });
  }
  const vectors = [...keys.values()].flatMap(k => k.students.flatMap(st => st.answers)).filter(a => Array.isArray(a.value));
  const played = cases.filter(c => c.trials.some(t => t.responses.length > 1)).length;
  check(played === vectors.length && vectors.length > 0 && cases.length > played,
        `${played} vectors of key.json's ${vectors.length} to play, ${cases.length - played} choices`);

  // The page: each item loaded into the player in turn, its responses given, SCORE read.
  copyFileSync(join(dir, 'node_modules/@citolab/qti-components/cdn/index.js'), join(ws.tmp, 'qti-components.js'));
  writeFileSync(join(ws.tmp, 'cases.js'), `export default ${JSON.stringify(cases)};\n`);
  writeFileSync(join(ws.tmp, 'play.html'), `<!doctype html><meta charset="utf-8"><body><div id="item"></div>
<pre id="out">not run (qti-components.js or cases.js did not load)</pre>
<script type="module">
import { qtiTransformItem } from './qti-components.js';
import cases from './cases.js';
const out = document.getElementById('out');
const errors = [];
for (const level of ['error', 'warn']) {
  const original = console[level];
  console[level] = (...args) => { errors.push(level + ': ' + args.join(' ')); original(...args); };
}
window.addEventListener('error', e => errors.push('error: ' + e.message));
try {
  const results = [];
  for (const c of cases) {
    const host = document.getElementById('item');
    host.replaceChildren(qtiTransformItem().parse(c.xml).htmlDoc());
    await new Promise(r => setTimeout(r, 50));
    const item = host.querySelector('qti-assessment-item');
    for (const t of c.trials) {
      item.resetResponses();
      for (const [id, v] of t.responses) if (v !== undefined && v !== null) item.updateResponseVariable(id, String(v));
      item.processResponse();
      const get = id => { const o = item.getOutcome(id); return o ? o.value : null; };
      results.push({ name: c.name, what: t.what, want: t.score, score: get('SCORE'), feedback: get('FEEDBACK'),
                     wantFeedback: t.feedback || null, solution: get('SOLUTION') });
    }
  }
  out.textContent = 'RESULT ' + btoa(JSON.stringify({ results, errors }));
} catch (e) {
  out.textContent = 'FAILED ' + btoa(String(e.stack || e));
}
</script>`);
  const dom = execFileSync('timeout', ['120', chromium, '--headless', '--no-sandbox', '--disable-gpu',
    '--allow-file-access-from-files', '--virtual-time-budget=60000', `--user-data-dir=${join(ws.tmp, 'profile')}`,
    '--dump-dom', pathToFileURL(join(ws.tmp, 'play.html')).href], { stdio: ['ignore', 'pipe', 'ignore'] }).toString();
  const m = dom.match(/(RESULT|FAILED) ([A-Za-z0-9+/=]+)/);
  if (!m) throw new Error(`the page gave no result:\n${dom.slice(-2000)}`);
  if (m[1] === 'FAILED') throw new Error(`the page failed: ${Buffer.from(m[2], 'base64')}`);
  const { results, errors } = JSON.parse(Buffer.from(m[2], 'base64').toString('utf8'));
  check(errors.length === 0, `the player's messages:\n  ${errors.join('\n  ')}`);
  for (const r of results) {
    check(Number(r.score) === r.want, `${r.name}, ${r.what}: the player scores ${r.score}, want ${r.want}`);
    if (r.wantFeedback) check(r.feedback === r.wantFeedback, `${r.name}, ${r.what}: FEEDBACK ${r.feedback}`);
    check(r.solution === 'WORKED', `${r.name}, ${r.what}: SOLUTION ${r.solution}`);
  }
  check(results.length > 0, 'nothing played');
  console.log = log;
  console.log(`played ${results.length} responses to ${cases.length} items`);
} catch (e) {
  failures.push(e.stack || String(e));
} finally {
  if (process.env.KEEP) console.log(`kept ${ws.tmp} (play.html, cases.js)`);
  else ws.cleanup();
}
console.log = log;
for (const f of failures) console.log(`FAIL: ${f}`);
console.log(`${failures.length ? 0 : 1} passed, ${failures.length ? 1 : 0} failed (${failures.length} problems)`);
process.exit(failures.length ? 1 : 0);
