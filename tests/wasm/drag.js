// Drag to set, in a real browser (issue 35, items 1 and 5): `collide material` writes lesson
// pages with the WebAssembly module; headless Chromium opens them from file:// and is driven
// through its DevTools protocol (cdp.js: real pointer, touch and key events). After each drag or key:
// - the input's slider and the panel's value are the grid value nearest where the pointer was
//   let go (lo + k step, the input's step; within its range, the end said in words when passed);
// - the panel's numbers (the impulse and the velocities after, full precision in data-value)
//   equal what the command gives for the new values: `collide solve --format json` on the
//   collision (catch-up), else the same pair's event of `collide step --events --json` on the
//   lesson file with the new values written in (the same collision at the same t), to 1e-9.
// Every 1D and 2D lesson has at least one handle (3D lessons: view3d.js). Lessons: catch-up
// (1D: A's velocity arrow dragged with the mouse, then past its range's end;
// B's arrow by a key), general-2d (A's arrow by touch; B moved by the mouse and by keys),
// centre-of-percussion (ball 2 dragged along bat 2: the hit point), contact-point-velocity (the
// spin dial by keys, Shift: ten steps), restitution (a mass knob: the lesson whose bodies'
// inputs are masses only). Screenshots of the panels before and after stay in WORK/*.png.
// Usage: node drag.js COLLIDE CHROMIUM WORK   ($COLLIDE_ENGINE_JS: the module)
'use strict';
const fs = require('fs');
const path = require('path');
const {execFileSync} = require('child_process');

const [collide, chromium, work] = process.argv.slice(2);
const here = __dirname;
const lessons = path.join(here, '..', '..', 'lessons');
fs.rmSync(work, {recursive: true, force: true});
fs.mkdirSync(work, {recursive: true});
const {check, close, send, openPage, answered, look, mouseDrag, touchDrag, shot, key, lessonWith, sameAsStep, onGrid,
       finish} = require('./cdp.js')(collide, chromium, work, ['--disable-gpu']);
// Every bundled 1D and 2D lesson (the 3D ones: view3d.js).
const flat = fs.readdirSync(lessons).filter(f => f.endsWith('.toml')).map(f => fs.readFileSync(path.join(lessons, f), 'utf8'))
               .filter(t => !/^dimension = 3$/m.test(t)).map(t => t.match(/^id = "([^"]*)"/m)[1]);
execFileSync(collide, ['material', '-o', path.join(work, 'site'), '--size', '320x180', '--quiet'].concat(flat), {stdio: 'inherit'});

async function main() {
  await send('Target.setDiscoverTargets', {discover: false});
  const site = 'file://' + path.join(work, 'site');

  // ---- Every 1D and 2D lesson: at least one handle, and the line saying what it drags ----
  for (const id of flat) {
    const page = await openPage(site + '/' + id + '/index.html?show=try-it');
    await answered(page, 0);
    const s = await look(page);
    const ids = Object.keys(s.handles);
    check(ids.length > 0 && /^Drag on the picture/.test(s.help), `${id}: handles ${ids.join(', ')}`);
    await page.close();
  }

  // ---- catch-up (1D): A's velocity arrow by the mouse, to between two steps and past the end ----
  {
    const page = await openPage(site + '/catch-up/index.html?show=try-it');
    let n = await answered(page, 0);
    let s = await look(page);
    check(/Drag on the picture/.test(s.help) && /velocity arrow: A\.v\b/.test(s.help), 'catch-up: the panel says what can be dragged: ' + s.help);
    check(!!s.handles['velocity:A'] && !!s.handles['velocity:B'], 'catch-up: a knob at each velocity arrow head');
    // A.v: 1.5 m/s, range [1.25, 3], step 0.25. To 2.3 (between 2.25 and 2.5): 2.25 expected.
    const dx = (2.3 - 1.5) * s.view.vscale * s.canvas, from = s.handles['velocity:A'];
    await shot(page, 'catch-up-before');
    await mouseDrag(page, from, [from[0] + dx, from[1] + 30]);  // (up or down: 1D, only x counts)
    n = await answered(page, n);
    s = await look(page);
    await shot(page, 'catch-up-after');
    check(s.inputs['A.v'].value === '2.25' && s.inputs['A.v'].shown === '2.25',
          `catch-up: the drag to 2.3 m/s set A.v to the step 2.25 (slider ${s.inputs['A.v'].value}, shown ${s.inputs['A.v'].shown})`);
    check(s.address.includes('A.v=2.25'), 'catch-up: the address follows: ' + s.address);
    check(/^A\.v = 2\.25 m\/s$/.test(s.said), 'catch-up: said: ' + s.said);
    const toml = fs.readFileSync(path.join(here, 'catch-up-a3.toml'), 'utf8')
                   .replace('mass = 3.0\nposition = -0.175\nv = 1.5', 'mass = 2.0\nposition = -0.175\nv = 2.25');
    fs.writeFileSync(path.join(work, 'catch-up-v225.toml'), toml);
    const solved = JSON.parse(execFileSync(collide, ['solve', path.join(work, 'catch-up-v225.toml'), '--format', 'json']).toString());
    // closed form: j = (1 + e)(va - vb) / (1/ma + 1/mb) = 1.5 * 1.95 / 1.5 = 1.95 N s
    check(close(solved.impulse, 1.95, 1e-12), 'catch-up: collide solve gives j = 1.95 N s for A.v = 2.25 (closed form)');
    check(close(s.worked.impulse, solved.impulse) && close(s.worked.v[0], solved.a.v) && close(s.worked.v[1], solved.b.v),
          `catch-up: the panel's P = ${s.worked.impulse}, v after ${JSON.stringify(s.worked.v)} are collide solve's ` +
          `(${solved.impulse}, ${solved.a.v}, ${solved.b.v})`);
    // Past the end: held at 3 m/s, and said so.
    const again = s.handles['velocity:A'];
    await mouseDrag(page, again, [again[0] + 3 * s.view.vscale * s.canvas, again[1]]);
    n = await answered(page, n);
    s = await look(page);
    check(s.inputs['A.v'].value === '3', 'catch-up: dragged past the range, A.v stops at its end, 3 (' + s.inputs['A.v'].value + ')');
    check(/the end of its range \(1\.25 to 3 m\/s\): it goes no further/.test(s.said), 'catch-up: said: ' + s.said);
    // B's arrow by the keyboard: Right, one step of 0.1 from 0.3.
    await key(page, 'velocity:B', 'ArrowRight');
    n = await answered(page, n);
    s = await look(page);
    check(s.inputs['B.v'].value === '0.4' && s.inputs['B.v'].shown === '0.4' && /^B\.v = 0\.4 m\/s$/.test(s.said), `catch-up: Right on B's knob: B.v = ${s.inputs['B.v'].value}; said: ${s.said}`);
    sameAsStep(s, lessonWith('01-catch-up.toml', [['A', 'v', -1, 3], ['B', 'v', -1, 0.4]]), 'catch-up (A.v = 3, B.v = 0.4)');
    await page.close();
  }

  // ---- general-2d: A's arrow by touch (v.x only: v.y stays 0), B moved by the mouse and keys ----
  {
    const page = await openPage(site + '/general-2d/index.html?show=try-it');
    let n = await answered(page, 0);
    let s = await look(page);
    // A.v.x: 1.5, [1, 2.5] step 0.25: to 1.85 -> 1.75. The finger also moves down: v.y is no input.
    const from = s.handles['velocity:A'];
    await shot(page, 'general-2d-before');
    await touchDrag(page, from, [from[0] + (1.85 - 1.5) * s.view.vscale * s.canvas, from[1] + 40]);
    n = await answered(page, n);
    s = await look(page);
    check(s.inputs['A.v.x'].value === '1.75', 'general-2d: a touch drag of A\'s arrow head set A.v.x = ' + s.inputs['A.v.x'].value);
    // B.position.y: 0.25, [0.15, 0.3] step 0.05: B dragged down by 0.06 m -> 0.2 (from its centre's handle).
    const b = s.handles['position:B'];
    await mouseDrag(page, b, [b[0] + 25, b[1] + 0.06 * s.view.scale * s.canvas]);
    n = await answered(page, n);
    s = await look(page);
    await shot(page, 'general-2d-after');
    check(s.inputs['B.position.y'].value === '0.2' && onGrid(0.2, 0.15, 0.05),
          'general-2d: B dragged 0.06 m down: B.position.y = ' + s.inputs['B.position.y'].value + ' (x is no input: it stays)');
    sameAsStep(s, lessonWith('06-general-2d.toml', [['A', 'v', 0, 1.75], ['B', 'position', 1, 0.2]]), 'general-2d (A.v.x = 1.75, B.position.y = 0.2)');
    // Keys: Up moves B up a step (0.25); Down with Shift ten steps: held at 0.15, said.
    await key(page, 'position:B', 'ArrowUp');
    n = await answered(page, n);
    s = await look(page);
    check(s.inputs['B.position.y'].value === '0.25', 'general-2d: Up on B: B.position.y = ' + s.inputs['B.position.y'].value);
    await key(page, 'position:B', 'ArrowDown', true);
    n = await answered(page, n);
    s = await look(page);
    check(s.inputs['B.position.y'].value === '0.15' && /it goes no further/.test(s.said),
          'general-2d: Shift+Down on B: held at 0.15; said: ' + s.said);
    sameAsStep(s, lessonWith('06-general-2d.toml', [['A', 'v', 0, 1.75], ['B', 'position', 1, 0.15]]), 'general-2d (B.position.y = 0.15)');
    await page.close();
  }

  // ---- centre-of-percussion: ball 2's hit point along bat 2 ----
  {
    const page = await openPage(site + '/centre-of-percussion/index.html?show=try-it');
    let n = await answered(page, 0);
    let s = await look(page);
    // ball 2.position.x: 1.05, [0.9, 1.08] step 0.01: dragged 0.083 m toward the bat's centre -> 0.97.
    const from = s.handles['position:ball 2'];
    check(!!from && /ball 2 itself \(in a dashed outline\) moves it: ball 2\.position\.x/.test(s.help), 'centre-of-percussion: ball 2 can be dragged: ' + s.help);
    await shot(page, 'centre-of-percussion-before');
    await mouseDrag(page, from, [from[0] - 0.083 * s.view.scale * s.canvas, from[1] - 10]);
    n = await answered(page, n);
    s = await look(page);
    await shot(page, 'centre-of-percussion-after');
    check(s.inputs['ball 2.position.x'].value === '0.97', 'centre-of-percussion: ball 2.position.x = ' + s.inputs['ball 2.position.x'].value);
    check(s.figures.length === 2, 'centre-of-percussion: the panel shows both bats\' collisions');
    sameAsStep(s, lessonWith('19-centre-of-percussion.toml', [['ball 2', 'position', 0, 0.97]]), 'centre-of-percussion (ball 2 at x = 0.97)');
    await page.close();
  }

  // ---- contact-point-velocity: the spin dial by keys ----
  {
    const page = await openPage(site + '/contact-point-velocity/index.html?show=try-it');
    let n = await answered(page, 0);
    let s = await look(page);
    const w0 = Number(s.inputs['A.w'].value);  // [-6, -4] step 0.5
    check(!!s.handles['spin:A'], 'contact-point-velocity: a spin dial on A');
    await shot(page, 'contact-point-velocity-before');
    await key(page, 'spin:A', 'ArrowUp');
    n = await answered(page, n);
    s = await look(page);
    check(close(Number(s.inputs['A.w'].value), w0 + 0.5, 1e-12), `contact-point-velocity: Up on the dial: A.w ${w0} -> ${s.inputs['A.w'].value}`);
    await key(page, 'spin:A', 'ArrowDown', true);
    n = await answered(page, n);
    s = await look(page);
    await shot(page, 'contact-point-velocity-after');
    check(s.inputs['A.w'].value === '-6' && /lower|no further/.test(s.said), 'contact-point-velocity: Shift+Down: A.w = -6; said: ' + s.said);
    sameAsStep(s, lessonWith('04-contact-point-velocity.toml', [['A', 'w', -1, -6]]), 'contact-point-velocity (A.w = -6)');
    await page.close();
  }

  // ---- restitution: the mass knob (its bodies' inputs are masses only) ----
  {
    const page = await openPage(site + '/restitution/index.html?show=try-it');
    let n = await answered(page, 0);
    let s = await look(page);
    const from = s.handles['mass:A (e=0.1)'];
    check(!!from, 'restitution: a mass knob on A (e=0.1)');
    // A (e=0.1).mass: 0.5, [0.25, 1] step 0.05 over the knob's 100 px upright track: +0.21 kg -> 0.7.
    await mouseDrag(page, from, [from[0] + 5, from[1] - 0.21 * 100 / 0.75 * s.canvas]);
    n = await answered(page, n);
    s = await look(page);
    await shot(page, 'restitution-after');
    check(s.inputs['A (e=0.1).mass'].value === '0.7', 'restitution: the mass knob set A (e=0.1).mass = ' + s.inputs['A (e=0.1).mass'].value);
    sameAsStep(s, lessonWith('05-restitution.toml', [['A (e=0.1)', 'mass', -1, 0.7], ['A (e=0.5)', 'mass', -1, 0.7], ['A (e=1)', 'mass', -1, 0.7]]),
               'restitution (the A balls 0.7 kg)');
    await page.close();
  }
}

finish(main, 'drag.js');
