// Plot any quantity, in a real browser (issue 35, items 3 and 5): `collide material` writes the
// bouncing ball's and general-2d's pages with the WebAssembly module; headless Chromium opens
// them from file:// (driven through its DevTools protocol: cdp.js) and the panel's plot is set
// with its selects, by events as a hand gives them (a change event; a key on a focused select).
// - It starts as the total kinetic energy against time: at every sample before the first bounce,
//   1/2 m (g t)^2 (the ball falls from rest: H = 1 m, m = 0.1 kg, g = 9.81), to 1e-9.
// - The ball's velocity y against time: -g t before the first bounce at t0 = sqrt(2 H / g), and
//   after it e v0 - g (t - t0) until the second, for the lesson's e = 0.5 and, the restitution
//   slider moved to 0.35, for that: the plot follows the inputs.
// - A lesson plot opened with "Change its axes" (the bounce intervals, fit = "ratio") carries its
//   pair and fit and says so; its numbers are the lesson plot's own.
// - general-2d: A's and B's angular momentum about the origin add up to the total, which keeps
//   its value through the collision (to 1e-9); the y selects offer only quantities in the first
//   y's unit. The keyboard: ArrowDown on the focused x select changes x.
// Usage: node plot_any.js COLLIDE CHROMIUM WORK   ($COLLIDE_ENGINE_JS: the module)
'use strict';
const fs = require('fs');
const path = require('path');
const {execFileSync} = require('child_process');

const [collide, chromium, work] = process.argv.slice(2);
fs.rmSync(work, {recursive: true, force: true});
fs.mkdirSync(work, {recursive: true});
execFileSync(collide, ['material', '-o', path.join(work, 'site'), '--size', '320x180', '--quiet', 'bouncing-ball', 'general-2d'],
             {stdio: 'inherit'});
const cdp = require('./cdp.js')(collide, chromium, work);
const check = cdp.check;

// The panel's plot: what it plots and the engine's numbers behind it.
const plotted = page => page.eval(`(function (f) {
  return f ? {per: f.per, x: f.x, y: f.y, fit: f.fit,
              series: f.series.map(function (r) { return {name: r.name, x: r.x, y: r.y}; })} : null;
})(document.getElementById('try-it').collideFreePlot)`);
// Sets the select `name` of the plot's form to `value` and sends the change a hand would.
async function choose(page, name, value) {
  const ok = await page.eval(`(function () {
    var s = document.querySelector('.tryit-free-plot form').elements[${JSON.stringify(name)}];
    var o = Array.prototype.find.call(s.options, function (o) { return o.value === ${JSON.stringify(value)}; });
    if (!o || o.disabled) return false;
    s.value = o.value;
    s.dispatchEvent(new Event('change', {bubbles: true}));
    return true; })()`);
  if (!ok) throw new Error(`the select ${name} offers no ${value}`);
}
// The worst difference between the plot's series k and f(t) over the samples with t in [lo, hi).
function worst(p, k, f, lo, hi) {
  let w = 0, n = 0;
  p.series[k].x.forEach((t, i) => { if (t >= lo && t < hi) { w = Math.max(w, Math.abs(p.series[k].y[i] - f(t))); ++n; } });
  return {w, n};
}

async function main() {
  await cdp.send('Target.setDiscoverTargets', {discover: false});
  const site = 'file://' + path.join(work, 'site');
  const g = 9.81, H = 1.0, m = 0.1, t0 = Math.sqrt(2 * H / g), v0 = g * t0;

  // ---- bouncing-ball ----
  {
    const page = await cdp.openPage(site + '/bouncing-ball/index.html?show=try-it');
    let n = await cdp.answered(page, 0);
    let p = await plotted(page);
    check(p && p.x === 't' && p.y.join() === 'kinetic_energy', 'bouncing-ball: the plot starts as the kinetic energy against t');
    let r = worst(p, 0, t => 0.5 * m * (g * t) ** 2, 0, t0 - 1e-6);
    check(r.n > 10 && r.w < 1e-9, `bouncing-ball: kinetic energy before the bounce is 1/2 m (g t)^2 (${r.n} samples, worst ${r.w})`);

    await choose(page, 'y0', 'ball.v.y');
    n = await cdp.answered(page, n);
    p = await plotted(page);
    check(p.y.join() === 'ball.v.y', 'bouncing-ball: y set to ball.v.y');
    const t1 = e => t0 + 2 * e * v0 / g;  // the second bounce
    for (const e of [0.5, 0.35]) {  // the lesson's e, then one of its slider's steps (0.3 to 0.6)
      if (e !== 0.5) {
        await page.eval(`(function () { var i = document.querySelector('#try-it input[data-name="scene.restitution"]');
          i.value = '${e}'; i.dispatchEvent(new Event('input')); })()`);
        n = await cdp.answered(page, n);
        p = await plotted(page);
      }
      const before = worst(p, 0, t => -g * t, 0, t0 - 1e-6);
      const after = worst(p, 0, t => e * v0 - g * (t - t0), t0 + 1e-6, t1(e) - 1e-6);
      check(before.n > 10 && before.w < 1e-9 && after.n > 5 && after.w < 1e-9,
            `bouncing-ball, e = ${e}: v_y is -g t, then e v0 - g (t - t0) (${before.n} + ${after.n} samples, worst ${Math.max(before.w, after.w)})`);
    }
    const toml = await page.eval(`document.querySelector('.tryit-free-plot-toml').textContent`);
    check(/^\[\[plot\]\]\ntitle = "Ball: velocity of centre, y against time t"\nper = "sample"\nx = "t"\ny = \["ball\.v\.y"\]\n$/.test(toml),
          'bouncing-ball: the plot as lines of a lesson file: ' + JSON.stringify(toml));

    // The second lesson plot (the intervals between bounces, fit = "ratio"), opened here.
    const own = await page.eval(`document.querySelectorAll('.tryit-lesson-plots .tryit-open-plot').length`);
    check(own === 2, 'bouncing-ball: each of its 2 plots has a "Change its axes" button');
    await page.eval(`document.querySelectorAll('.tryit-lesson-plots .tryit-open-plot')[1].click()`);
    n = await cdp.answered(page, n);
    p = await plotted(page);
    const from = await page.eval(`document.querySelector('.tryit-free-plot-from').textContent`);
    check(p.per === 'collision' && p.y.join() === 'interval' && p.fit === 'ratio',
          'bouncing-ball: the intervals plot opened with its per, y and fit: ' + JSON.stringify([p.per, p.x, p.y, p.fit]));
    check(/Opened from the lesson’s plot “Time between one bounce and the next”: the collisions of ball and floor; fitted with a ratio/.test(from),
          'bouncing-ball: it says what it carries: ' + from);
    // (the table's rows go in when it is unfolded, as a reader unfolds it)
    await page.eval(`document.querySelectorAll('.tryit-lesson-plots section')[1].querySelector('details.plot-data').open = true`);
    await cdp.sleep(100);
    const lessonSeries = await page.eval(`(function () {
      var rows = document.querySelectorAll('.tryit-lesson-plots section')[1].querySelectorAll('details.plot-data tr');
      return rows.length; })()`);
    check(p.series[0].x.length > 20 && lessonSeries > 20, `bouncing-ball: ${p.series[0].x.length} intervals plotted, the lesson plot's table has ${lessonSeries} rows`);
    // e = 0.35 now: each interval is e times the one before (to 1e-6 while they are long)
    const iv = p.series[0].y, ratios = iv.slice(1, 6).map((y, k) => y / iv[k]);
    check(ratios.every(x => Math.abs(x - 0.35) < 1e-6), 'bouncing-ball: the intervals shrink by e = 0.35: ' + ratios.map(x => x.toFixed(9)).join(', '));
    await page.close();
  }

  // ---- general-2d: angular momentum shares, units, the keyboard ----
  {
    const page = await cdp.openPage(site + '/general-2d/index.html?show=try-it');
    let n = await cdp.answered(page, 0);
    await choose(page, 'y0', 'A.angular_momentum');
    n = await cdp.answered(page, n);
    await choose(page, 'y1', 'B.angular_momentum');
    n = await cdp.answered(page, n);
    await choose(page, 'y2', 'angular_momentum');
    n = await cdp.answered(page, n);
    const p = await plotted(page);
    check(p.y.join() === 'A.angular_momentum,B.angular_momentum,angular_momentum', 'general-2d: three series: ' + p.y.join(', '));
    const [a, b, total] = p.series.map(s => s.y);
    const sums = a.every((x, i) => Math.abs(x + b[i] - total[i]) < 1e-9);
    const kept = total.every(x => Math.abs(x - total[0]) < 1e-9);
    const moved = Math.abs(a[a.length - 1] - a[0]) > 1e-2;
    check(sums && kept && moved, `general-2d: A's and B's shares add to the total, kept through the collision, ` +
                                 `A's changed by ${(a[a.length - 1] - a[0]).toFixed(4)} kg m^2/s`);
    const offered = await page.eval(`Array.prototype.filter.call(document.querySelector('.tryit-free-plot form').elements.y1.options,
      function (o) { return !o.disabled && o.value; }).map(function (o) { return o.value; })`);
    check(offered.length > 2 && offered.every(v => /angular_momentum$/.test(v)),
          'general-2d: the second y offers only kg m^2/s quantities: ' + offered.join(', '));
    // The keyboard: ArrowDown on the focused x select picks the next quantity.
    await page.eval(`document.querySelector('.tryit-free-plot form').elements.x.focus()`);
    const base = {key: 'ArrowDown', code: 'ArrowDown', windowsVirtualKeyCode: 40};
    await page('Input.dispatchKeyEvent', Object.assign({type: 'rawKeyDown'}, base));
    await page('Input.dispatchKeyEvent', Object.assign({type: 'keyUp'}, base));
    n = await cdp.answered(page, n);
    const q = await plotted(page);
    check(q.x !== 't', 'general-2d: ArrowDown on the x select set x to ' + q.x);
    await page.close();
  }
}

cdp.finish(main, 'plot_any.js');
