// A lesson's [[plot]]s in the Try-it panel are the page's (issue 33): `collide material` writes
// the lessons with plots (bouncing-ball, dominoes, tower, restitution), and for each page the
// module's lesson(text, {}, fps), with the page's own lesson text (try-it-lesson.js) and frame
// rate (data-fps), must give
//   (a) each plot's SVG byte-equal to the page's plot-K.svg, its alt text the page's <img alt>,
//       and its folded table (data_html) the page's;
//   (d) the answer the command wrote into the page for the lesson's own values (try-it-lesson.js
//       `first`, shown before the module has started) is the module's, to the last bit;
// and with other inputs, numbers that follow from the closed forms, not from copied output:
//   (b) bouncing-ball with e = 0.4 (scene.restitution): bounce k (from 1) comes
//       2 e^(k-1) v0 / g after the one before (v0 = sqrt(2 g H), H = 1 m), so every ratio is
//       e = 0.4: the first 8 intervals and ratios to 1e-9 (later ones are shorter than the
//       times' rounding allows to 1e-9), the pair's e reported as 0.4, and a different SVG;
//   (c) dominoes with the spacing 0.035 m (domino 2.position.x, the others in proportion): the
//       chain's spacing 0.035 m to 1e-12, the slope the least-squares line through the plotted
//       points from domino 9 on (computed here), the wave speed spacing / slope, and a slope
//       other than the lesson's.
// Usage: node plots.js COLLIDE MODULE WORK
'use strict';
const fs = require('fs');
const path = require('path');
const vm = require('vm');
const { spawnSync } = require('child_process');

const [collide, modulePath, work] = process.argv.slice(2);
if (!work) {
  console.error('usage: node plots.js COLLIDE MODULE WORK');
  process.exit(2);
}
fs.rmSync(work, { recursive: true, force: true });
fs.mkdirSync(work, { recursive: true });
const site = path.join(work, 'site');
const lessons = ['bouncing-ball', 'dominoes', 'tower', 'restitution'];
const made = spawnSync(collide, ['material', '-o', site, '--size', '320x180', '--quality', 'low', '--quiet', ...lessons],
                       { encoding: 'utf8' });
if (made.status !== 0) {
  console.error(`plots.js: collide material failed: ${made.stderr}`);
  process.exit(1);
}

let failures = 0;
const fail = what => { failures++; console.log(`FAIL ${what}`); };
const escapeHtml = s => String(s).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');

// The page's lesson text (as the panel reads it) and frame rate.
function page(id) {
  const dir = path.join(site, id);
  const sandbox = { window: {} };
  vm.runInNewContext(fs.readFileSync(path.join(dir, 'try-it-lesson.js'), 'utf8'), sandbox);
  const html = fs.readFileSync(path.join(dir, 'index.html'), 'utf8');
  const fps = Number((html.match(/id="try-it"[^>]*data-fps="([^"]*)"/) || [])[1]);
  return { dir, html, text: sandbox.window.collideTryIt.lesson, fps, first: sandbox.window.collideTryIt.first };
}

require(path.resolve(modulePath))().then(m => {
  const answers = {};
  let plots = 0;
  // (a) the default inputs: the page's plots, to the byte.
  for (const id of lessons) {
    const p = page(id);
    if (!(p.fps > 0) || typeof p.text !== 'string') { fail(`${id}: the page has no lesson text or frame rate`); continue; }
    const a = JSON.parse(m.lesson(p.text, {}, p.fps));
    answers[id] = a;
    // (d) the answer the command wrote into the page (shown before the module has started) is
    // the module's, to the last bit.
    if (JSON.stringify(p.first) !== JSON.stringify(a))
      fail(`${id}: the page's first answer (the command's) differs from the module's`);
    else console.log(`ok   ${id}: the page's first answer (the command's) is the module's, to the last bit`);
    const files = fs.readdirSync(p.dir).filter(f => /^plot-\d+\.svg$/.test(f)).sort();
    if (!Array.isArray(a.plots) || a.plots.length !== files.length || files.length === 0) {
      fail(`${id}: the module gives ${a.plots && a.plots.length} plots, the page has ${files.length}`);
      continue;
    }
    if (!p.html.includes('class="tryit-lesson-plots"')) fail(`${id}: the panel has no place for the plots`);
    a.plots.forEach((q, k) => {
      const file = `plot-${k + 1}.svg`, svg = fs.readFileSync(path.join(p.dir, file), 'utf8');
      if (q.file !== file) fail(`${id}: plot ${k + 1} is called ${q.file}`);
      if (q.svg !== svg) fail(`${id}/${file}: the module's SVG differs from the page's (${q.svg.length} vs ${svg.length} bytes)`);
      if (!p.html.includes(`<img src="${file}" alt="${escapeHtml(q.alt)}">`)) fail(`${id}/${file}: the alt text is not the page's`);
      if (!p.html.includes(q.data_html)) fail(`${id}/${file}: the folded table is not the page's`);
      plots++;
    });
  }

  // (b) bouncing-ball with e = 0.4: the intervals 2 e^(k-1) v0 / g, their ratios e.
  const g = 9.81, H = 1.0, e = 0.4, v0 = Math.sqrt(2 * g * H);
  const ball = page('bouncing-ball');
  const b = JSON.parse(m.lesson(ball.text, { 'scene.restitution': e }, ball.fps));
  const iv = b.plots.find(q => q.ratio);
  if (!iv) fail('bouncing-ball: no plot with ratios');
  else {
    const s = iv.series[0];
    if (iv.ratio.restitution !== e) fail(`bouncing-ball e = 0.4: the plot says e = ${iv.ratio.restitution}`);
    if (s.y.length < 9) fail(`bouncing-ball e = 0.4: only ${s.y.length} intervals`);
    for (let k = 0; k < 8 && k < s.y.length; ++k) {
      const want = 2 * Math.pow(e, s.number[k] - 1) * v0 / g;
      if (!(Math.abs(s.y[k] - want) <= 1e-9)) fail(`bouncing-ball e = 0.4: interval ${s.number[k]} is ${s.y[k]} s, not ${want}`);
      if (k > 0 && !(Math.abs(iv.ratio.ratios[k - 1] - e) <= 1e-9))
        fail(`bouncing-ball e = 0.4: ratio ${k} is ${iv.ratio.ratios[k - 1]}, not ${e}`);
    }
    if (!iv.summary.includes('0.4 times the one before')) fail(`bouncing-ball e = 0.4: the summary says ${iv.summary}`);
    const before = answers['bouncing-ball'].plots.find(q => q.ratio);
    if (before && before.svg === iv.svg) fail('bouncing-ball e = 0.4: the SVG did not change');
    console.log(`plots.js: bouncing-ball, e = 0.4: intervals ${s.y.slice(0, 3).map(x => x.toFixed(6)).join(', ')} s ...; ` +
                `ratios ${iv.ratio.ratios.slice(0, 3).join(', ')} ...`);
  }

  // (c) dominoes 0.035 m apart: the spacing, the least-squares slope, the wave speed.
  const dom = page('dominoes'), spacing = 0.035;
  const d = JSON.parse(m.lesson(dom.text, { 'domino 2.position.x': spacing }, dom.fps));
  const fit = d.plots.find(q => q.line), fit0 = answers.dominoes.plots.find(q => q.line);
  if (!fit || !fit0) fail('dominoes: no plot with a fitted line');
  else {
    const s = fit.series[0];
    let n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    s.x.forEach((x, k) => {
      if (s.number[k] < 9) return;  // the lesson's fit_from = 9
      n++; sx += x; sy += s.y[k]; sxx += x * x; sxy += x * s.y[k];
    });
    const slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    if (n !== fit.line.points) fail(`dominoes: the line has ${fit.line.points} points, the plot ${n} from domino 9 on`);
    if (!(Math.abs(fit.line.slope - slope) <= 1e-9 * Math.abs(slope))) fail(`dominoes: slope ${fit.line.slope}, least squares ${slope}`);
    if (!(Math.abs(fit.line.spacing - spacing) <= 1e-12)) fail(`dominoes: spacing ${fit.line.spacing} m, not ${spacing}`);
    if (!(Math.abs(fit.line.speed - spacing / slope) <= 1e-9 * fit.line.speed)) fail(`dominoes: speed ${fit.line.speed}, not ${spacing / slope}`);
    if (!(Math.abs(fit.line.slope - fit0.line.slope) > 1e-6)) fail(`dominoes: the slope did not change (${fit.line.slope})`);
    if (fit.svg === fit0.svg) fail('dominoes: the SVG did not change');
    console.log(`plots.js: dominoes, spacing 0.03 -> 0.035 m: slope ${fit0.line.slope} -> ${fit.line.slope} s per domino, ` +
                `wave speed ${fit0.line.speed} -> ${fit.line.speed} m/s`);
  }
  console.log(`plots.js: ${plots} plots of ${lessons.length} lessons equal to the page's; ${failures ? failures + ' FAILURES' : 'all as expected'}`);
  process.exit(failures ? 1 : 0);
}, e => { console.error(`plots.js: the module did not load: ${e}`); process.exit(1); });
