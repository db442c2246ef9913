// The 3D lessons drawn live (issue 35, items 1, 2 and 5): `collide material` writes the 3D
// lessons' pages with the WebAssembly module and three.js (three.min.js beside them); headless
// Chromium (WebGL by SwiftShader: --use-angle=swiftshader --enable-unsafe-swiftshader) opens
// them from file:// and is driven through its DevTools protocol (cdp.js). Checked:
// - every 3D lesson: the 3D canvas is drawn and not blank (its pixels have many colours, among
//   them the first moving body's fill, lit: each channel the fill's times one factor), and the
//   panel has a drag handle (a velocity, spin or position knob) and says what it drags;
// - general-3d: a slider moved (an input event, as a hand moves it) changes the picture's pixels,
//   and the numbers equal `collide step --events --json`'s for the new values; a key on A's
//   velocity knob sets A.v.x one step up, the numbers follow; the buttons before / at / after
//   the page's collision and "next collision" show the frames around its instant and the
//   instant itself (t = the worked example's t); the keys turn the camera (pixels change, the
//   knob moves with the arrow's head);
// - tower: the ball's velocity knob dragged with the mouse to between two grid values sets
//   ball.v.x to the nearer one, the numbers follow; a key one step down;
// - without three.min.js (removed from a copy of the site, and a site built with
//   COLLIDE_THREE_JS pointing nowhere): the command says so on stderr, the panel says so where
//   the picture would be (no blank canvas) and still shows the engine's numbers.
// Screenshots of the panels stay in WORK/*.png (general-3d, tower, conservation, errata; stick, 2D).
// Usage: node view3d.js COLLIDE CHROMIUM WORK   ($COLLIDE_ENGINE_JS: the module)
'use strict';
const fs = require('fs');
const path = require('path');
const {execFileSync, spawnSync} = require('child_process');

const [collide, chromium, work] = process.argv.slice(2);
fs.rmSync(work, {recursive: true, force: true});
fs.mkdirSync(work, {recursive: true});
const {check, close, send, sleep, openPage, answered, look, mouseDrag, shot, key, lessonWith, sameAsStep, finish} =
  require('./cdp.js')(collide, chromium, work, ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist']);
const lessons3d = ['general-3d', 'conservation', 'errata', 'tower'];
const site = path.join(work, 'site');
execFileSync(collide, ['material', '-o', site, '--size', '320x180', '--quiet'].concat(lessons3d, ['stick']), {stdio: 'inherit'});

// What the 3D canvas shows: distinct colours (to 3 bits a channel), the pixels of the fill `fill`
// lit (each channel the fill's times one factor, to 10 levels; a bright face may clip at 255),
// and the pixels that differ from the snapshot `since` (window.__snaps[since]); kept as `as`.
function pixels(page, fill, as, since) {
  return page.eval(`(function () {
    var c = document.querySelector('canvas.tryit-scene3d'), t = document.createElement('canvas');
    t.width = c.width; t.height = c.height;
    var x = t.getContext('2d'); x.drawImage(c, 0, 0);
    var d = x.getImageData(0, 0, t.width, t.height).data, seen = {}, colours = 0, lit = 0, differ = 0;
    var f = ${JSON.stringify(fill)}, low = f.indexOf(Math.min.apply(null, f)), before = (window.__snaps || {})[${JSON.stringify(since || '')}];
    for (var i = 0; i < d.length; i += 4) {
      var q = (d[i] >> 5) * 64 + (d[i + 1] >> 5) * 8 + (d[i + 2] >> 5);
      if (!seen[q]) { seen[q] = true; ++colours; }
      var k = d[i + low] / f[low], ok = k > 0.3 && k < 1.15;
      for (var j = 0; j < 3 && ok; ++j) ok = Math.abs(d[i + j] - Math.min(255, k * f[j])) <= 10;
      if (ok) ++lit;
      if (before && (before[i] !== d[i] || before[i + 1] !== d[i + 1] || before[i + 2] !== d[i + 2])) ++differ;
    }
    (window.__snaps = window.__snaps || {})[${JSON.stringify(as)}] = d;
    var p = document.getElementById('try-it');
    return {colours: colours, lit: lit, differ: differ, drawn: p.dataset.view3d, t: Number(p.dataset.view3dT)};
  })()`);
}
function rgb(css) { return [1, 3, 5].map(k => parseInt(css.slice(k, k + 2), 16)); }
async function setSlider(page, name, value) {
  await page.eval(`(function () { var i = document.querySelector('#try-it input[data-name="${name}"]');
    i.value = '${value}'; i.dispatchEvent(new Event('input', {bubbles: true})); })()`);
}
async function click(page, selector) { await page.eval(`document.querySelector('${selector}').click()`); }

async function main() {
  await send('Target.setDiscoverTargets', {discover: false});
  const url = id => 'file://' + path.join(site, id, 'index.html') + '?show=try-it';
  check(fs.existsSync(path.join(site, 'three.min.js')) && fs.existsSync(path.join(site, 'try-it-3d.js')),
        'the site has three.min.js and try-it-3d.js beside the pages');

  // ---- Every 3D lesson: drawn, not blank, a handle ----
  for (const id of lessons3d) {
    const page = await openPage(url(id));
    await answered(page, 0);
    await sleep(300);
    const fill = rgb(await page.eval('window.collideTryIt.palette.fills[0]'));
    const px = await pixels(page, fill, 'start');
    const s = await look(page);
    check(px.drawn === 'drawn' && px.colours >= 12 && px.lit >= 400,
          `${id}: the 3D canvas is drawn (${px.drawn}): ${px.colours} colours, ${px.lit} pixels of the first body's fill, lit`);
    check(Object.keys(s.handles).length > 0 && /^Drag on the picture/.test(s.help), `${id}: handles ${Object.keys(s.handles).join(', ')}; ${s.help}`);
    await shot(page, id);
    await page.close();
  }

  // ---- general-3d: a slider, a key on A's velocity knob, the jumps, the camera ----
  {
    const page = await openPage(url('general-3d'));
    let n = await answered(page, 0);
    const fill = rgb(await page.eval('window.collideTryIt.palette.fills[0]'));
    await pixels(page, fill, 'start');
    await setSlider(page, 'A.v.x', '2');  // [1, 2.5] step 0.25, from 1.5
    n = await answered(page, n);
    await sleep(200);
    let px = await pixels(page, fill, 'v2', 'start');
    let s = await look(page);
    check(px.differ > 200, `general-3d: A.v.x 1.5 -> 2 by its slider: ${px.differ} pixels of the 3D canvas changed`);
    sameAsStep(s, lessonWith('07-general-3d.toml', [['A', 'v', 0, 2]]), 'general-3d (slider: A.v.x = 2)');
    await key(page, 'velocity:A', 'ArrowRight');
    n = await answered(page, n);
    s = await look(page);
    check(s.inputs['A.v.x'].value === '2.25' && s.inputs['A.v.x'].shown === '2.25' && /^A\.v\.x = 2\.25 m\/s$/.test(s.said),
          `general-3d: Right on A's velocity knob: A.v.x = ${s.inputs['A.v.x'].value} (shown ${s.inputs['A.v.x'].shown}); said: ${s.said}`);
    check(s.address.includes('A.v.x=2.25'), 'general-3d: the address follows: ' + s.address);
    sameAsStep(s, lessonWith('07-general-3d.toml', [['A', 'v', 0, 2.25]]), 'general-3d (key: A.v.x = 2.25)');
    const t = s.worked.t;
    await click(page, '.tryit-jumps [data-jump="at"]');
    px = await pixels(page, fill, 'at');
    check(close(px.t, t, 1e-12), `general-3d: "at the instant" shows t = ${px.t}, the worked example's ${t}`);
    await shot(page, 'general-3d-at');
    await click(page, '.tryit-jumps [data-jump="before"]');
    px = await pixels(page, fill, 'before', 'at');
    const fps = await page.eval('Number(document.getElementById("try-it").dataset.fps)');
    check(px.t < t && px.t > t - 1 / fps - 1e-9 && px.differ > 50, `general-3d: "before" shows the frame t = ${px.t} (${px.differ} pixels differ from the instant)`);
    await click(page, '.tryit-jumps [data-jump="after"]');
    px = await pixels(page, fill, 'after');
    check(px.t > t && px.t < t + 1 / fps + 1e-9, `general-3d: "after" shows the frame t = ${px.t}`);
    await click(page, '.tryit-player [data-act="start"]');
    await click(page, '.tryit-jumps [data-jump="next"]');
    px = await pixels(page, fill, 'next');
    const first = await page.eval('document.querySelector("#try-it .tryit-impulse") && Number(document.querySelector("#try-it .tryit-impulse").dataset.t)');
    check(px.t >= first && px.t < first + 1 / fps + 1e-9, `general-3d: "next collision" from t = 0 shows t = ${px.t}, the first frame from the collision at ${first}`);
    // The camera: Left on the picture turns it; the knob moves with the arrow's head.
    await click(page, '.tryit-player [data-act="start"]');
    const knob0 = (await look(page)).handles['velocity:A'];
    await pixels(page, fill, 'camera0');
    await page.eval(`document.querySelector('#try-it canvas.tryit-scene').focus()`);
    for (let k = 0; k < 3; ++k) {  // 15 degrees
      await page('Input.dispatchKeyEvent', {type: 'rawKeyDown', key: 'ArrowLeft', code: 'ArrowLeft', windowsVirtualKeyCode: 37});
      await page('Input.dispatchKeyEvent', {type: 'keyUp', key: 'ArrowLeft', code: 'ArrowLeft', windowsVirtualKeyCode: 37});
    }
    await sleep(200);
    px = await pixels(page, fill, 'camera1', 'camera0');
    const knob1 = (await look(page)).handles['velocity:A'];
    check(px.differ > 500 && Math.hypot(knob1[0] - knob0[0], knob1[1] - knob0[1]) > 3,
          `general-3d: Left on the picture turns the camera (${px.differ} pixels changed; the knob ${knob0.map(Math.round)} -> ${knob1.map(Math.round)})`);
    await page.close();
  }

  // ---- tower: the ball's velocity knob by the mouse, then a key ----
  {
    const page = await openPage(url('tower'));
    let n = await answered(page, 0);
    const fill = rgb(await page.eval('window.collideTryIt.palette.fills[0]'));
    await pixels(page, fill, 'start');
    let s = await look(page);
    // ball.v.x: 4, [3.8, 4.1] step 0.05. The knob's place at each grid value (canvas px): to 0.3
    // of the way from 4.05 towards 4.1, it snaps to 4.05.
    const grid = await page.eval(`JSON.parse(document.querySelector('.tryit-handle[data-handle="velocity:ball"]').dataset.grid)`);
    const at = (k, f) => [0, 1].map(c => (grid[k][c] + f * (grid[k + 1][c] - grid[k][c])) * s.canvas);
    const rect = await page.eval(`(function () { var b = document.querySelector('#try-it canvas.tryit-scene').getBoundingClientRect(); return [b.left, b.top]; })()`);
    const from = at(4, 0).map((x, c) => x + rect[c]), to = at(5, 0.3).map((x, c) => x + rect[c]);
    const el = s.handles['velocity:ball'];  // the focusable element over the knob
    check(Math.hypot(from[0] - el[0], from[1] - el[1]) < 1.5,
          `tower: the ball's knob (${el.map(Math.round)}) stands at its grid place for 4 m/s (${from.map(Math.round)})`);
    await mouseDrag(page, from, to);
    n = await answered(page, n);
    await sleep(200);
    s = await look(page);
    const px = await pixels(page, fill, 'dragged', 'start');
    await shot(page, 'tower-dragged');
    check(s.inputs['ball.v.x'].value === '4.05' && /^ball\.v\.x = 4\.05 m\/s$/.test(s.said),
          `tower: the ball's velocity knob dragged to between 4.05 and 4.1 m/s set ball.v.x = ${s.inputs['ball.v.x'].value}; said: ${s.said}`);
    check(px.differ > 50, `tower: the picture changed (${px.differ} pixels)`);
    sameAsStep(s, lessonWith('21-tower.toml', [['ball', 'v', 0, 4.05]]), 'tower (ball.v.x = 4.05)');
    await key(page, 'velocity:ball', 'ArrowLeft');
    n = await answered(page, n);
    s = await look(page);
    check(s.inputs['ball.v.x'].value === '4', `tower: Left on the ball's knob: ball.v.x = ${s.inputs['ball.v.x'].value}`);
    await page.close();
  }
  {  // stick (2D), to look at beside the 3D ones
    const page = await openPage(url('stick'));
    await answered(page, 0);
    await shot(page, 'stick');
    await page.close();
  }

  // ---- Without three.min.js ----
  const copy = path.join(work, 'site-copy');
  fs.cpSync(site, copy, {recursive: true});
  fs.rmSync(path.join(copy, 'three.min.js'));
  const none = path.join(work, 'site-none');
  const r = spawnSync(collide, ['material', '-o', none, '--size', '320x180', '--quiet', 'general-3d'],
                      {env: Object.assign({}, process.env, {COLLIDE_THREE_JS: path.join(work, 'nowhere', 'three.min.js')})});
  check(r.status === 0 && /three\.js is not at .*nowhere\/three\.min\.js.*libjs-three/.test(r.stderr.toString()),
        'collide material without three.js says so on stderr: ' + r.stderr.toString().trim());
  check(!fs.existsSync(path.join(none, 'three.min.js')), 'that site has no three.min.js');
  for (const dir of [copy, none]) {
    const page = await openPage('file://' + path.join(dir, 'general-3d', 'index.html') + '?show=try-it');
    await answered(page, 0);
    const said = await page.eval(`(function () { var p = document.getElementById('try-it'), m = p.querySelector('.tryit-3d-missing');
      return {text: m ? m.textContent : '', stage: p.querySelector('.tryit-stage').hidden, impulse: !!p.querySelector('.tryit-impulse'),
              state: p.dataset.view3d}; })()`);
    check(/needs three\.js/.test(said.text) && said.stage && said.impulse && said.state === 'missing',
          `${path.basename(dir)}: without three.min.js the panel says so (${said.text.slice(0, 60)}...), hides the picture, shows the numbers`);
    await shot(page, path.basename(dir) + '-general-3d');
    await page.close();
  }
}

finish(main, 'view3d.js');
