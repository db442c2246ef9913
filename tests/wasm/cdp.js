// What the Try-it panel's browser tests share (drag.js, view3d.js): headless Chromium driven
// through its DevTools protocol over a pipe (--remote-debugging-pipe: no port, no network, and
// Node 20 needs no WebSocket for it), pages opened from file://, real pointer, touch and key
// events (Input.dispatch*: the page's handlers cannot tell them from a hand's), what the panel
// shows (look), and the command's answers for the same values (`collide step --events --json`
// on the lesson file with the new values written in) to compare the panel's numbers with.
// Usage: const t = require('./cdp.js')(COLLIDE, CHROMIUM, WORK, [more Chromium flags]);
//        ... t.finish(main, 'drag.js')   (or t.stop(): scripts/browser-speed.js, which checks nothing)
'use strict';
const fs = require('fs');
const path = require('path');
const {spawn, execFileSync} = require('child_process');

module.exports = function start(collide, chromium, work, flags = []) {
  const lessons = path.join(__dirname, '..', '..', 'lessons');
  let failures = 0;
  function check(ok, what) {
    console.log((ok ? 'ok   ' : 'FAIL ') + what);
    if (!ok) failures++;
  }
  function close(a, b, tol = 1e-9) {
    if (Array.isArray(a) || Array.isArray(b)) {
      return Array.isArray(a) && Array.isArray(b) && a.length === b.length && a.every((x, k) => close(x, b[k], tol));
    }
    return Math.abs(a - b) <= tol * Math.max(1, Math.abs(a), Math.abs(b));
  }

  // ---- The DevTools protocol over a pipe: fd 3 to Chromium, fd 4 from it, messages end in \0 ----
  const browser = spawn(chromium, ['--headless', '--no-sandbox', '--hide-scrollbars', '--remote-debugging-pipe',
                                   '--user-data-dir=' + fs.mkdtempSync(path.join(work, 'profile.'))].concat(flags, ['about:blank']),
                        {stdio: ['ignore', 'ignore', fs.openSync(path.join(work, 'chromium.log'), 'w'), 'pipe', 'pipe']});
  const toBrowser = browser.stdio[3], fromBrowser = browser.stdio[4];
  let nextId = 1, buffer = '';
  const waiting = new Map();
  fromBrowser.on('data', chunk => {
    buffer += chunk.toString('utf8');
    let end;
    while ((end = buffer.indexOf('\0')) >= 0) {
      const message = JSON.parse(buffer.slice(0, end));
      buffer = buffer.slice(end + 1);
      if (message.id && waiting.has(message.id)) {
        const {resolve, reject, method} = waiting.get(message.id);
        waiting.delete(message.id);
        if (message.error) reject(new Error(method + ': ' + message.error.message));
        else resolve(message.result);
      }
    }
  });
  function send(method, params = {}, sessionId) {
    const id = nextId++;
    toBrowser.write(JSON.stringify(sessionId ? {id, method, params, sessionId} : {id, method, params}) + '\0');
    return new Promise((resolve, reject) => waiting.set(id, {resolve, reject, method}));
  }
  const sleep = ms => new Promise(r => setTimeout(r, ms));

  async function openPage(url) {
    const {targetId} = await send('Target.createTarget', {url: 'about:blank'});
    const {sessionId} = await send('Target.attachToTarget', {targetId, flatten: true});
    const page = (method, params) => send(method, params, sessionId);
    await page('Emulation.setDeviceMetricsOverride', {width: 1100, height: 1400, deviceScaleFactor: 1, mobile: false});
    await page('Page.navigate', {url});
    page.eval = async expression => {
      const r = await page('Runtime.evaluate', {expression, returnByValue: true, awaitPromise: true});
      if (r.exceptionDetails) throw new Error(expression + ': ' + JSON.stringify(r.exceptionDetails));
      return r.result.value;
    };
    page.close = () => send('Target.closeTarget', {targetId});
    return page;
  }
  // Waits until the engine has given more than `after` answers; returns the count.
  async function answered(page, after) {
    for (let k = 0; k < 600; ++k) {
      const n = await page.eval(`(function () { var p = document.getElementById('try-it');
        return p && p.dataset.answers ? Number(p.dataset.answers) : 0; })()`).catch(() => 0);
      if (n > after) {
        await sleep(100);  // answers still queued by the last moves
        return page.eval(`Number(document.getElementById('try-it').dataset.answers)`);
      }
      await sleep(50);
    }
    throw new Error('the engine did not answer');
  }
  // What the page shows: the inputs, the view, the collision's numbers, the handles (CSS pixels).
  function look(page) {
    return page.eval(`(function () {
      var p = document.getElementById('try-it'), o = p.querySelector('.tryit-impulse'), r = {inputs: {}, handles: {}};
      p.querySelectorAll('input[type=range]').forEach(function (i) {
        r.inputs[i.dataset.name] = {value: i.value, shown: i.parentNode.querySelector('output').textContent};
      });
      r.view = JSON.parse(p.dataset.view);
      r.canvas = p.querySelector('canvas.tryit-scene').getBoundingClientRect().width / p.querySelector('canvas.tryit-scene').width;
      r.said = p.querySelector('.tryit-drag-said').textContent;
      r.help = p.querySelector('.tryit-drag-help').textContent;
      r.address = window.location.search;
      if (o) r.worked = {a: o.dataset.a, b: o.dataset.b, t: Number(o.dataset.t), impulse: JSON.parse(o.dataset.value),
                         v: Array.prototype.map.call(p.querySelectorAll('.tryit-numbers table:first-of-type .tryit-v-after'),
                                                     function (c) { return JSON.parse(c.dataset.value); })};
      r.figures = Array.prototype.map.call(p.querySelectorAll('.tryit-figure-impulse'), function (c) {
        return {a: c.dataset.a, b: c.dataset.b, t: Number(c.dataset.t), impulse: JSON.parse(c.dataset.value)};
      });
      p.querySelectorAll('.tryit-handle').forEach(function (h) {
        var b = h.getBoundingClientRect();
        r.handles[h.dataset.handle] = [b.left + b.width / 2, b.top + b.height / 2];
      });
      return r;
    })()`);
  }
  async function mouseDrag(page, from, to) {
    const steps = 12;
    await page('Input.dispatchMouseEvent', {type: 'mouseMoved', x: from[0], y: from[1]});
    await page('Input.dispatchMouseEvent', {type: 'mousePressed', x: from[0], y: from[1], button: 'left', buttons: 1, clickCount: 1});
    for (let k = 1; k <= steps; ++k) {
      const x = from[0] + (to[0] - from[0]) * k / steps, y = from[1] + (to[1] - from[1]) * k / steps;
      await page('Input.dispatchMouseEvent', {type: 'mouseMoved', x, y, button: 'left', buttons: 1});
      await sleep(20);
    }
    await page('Input.dispatchMouseEvent', {type: 'mouseReleased', x: to[0], y: to[1], button: 'left', buttons: 0, clickCount: 1});
  }
  async function touchDrag(page, from, to) {
    const steps = 12;
    await page('Input.dispatchTouchEvent', {type: 'touchStart', touchPoints: [{x: from[0], y: from[1]}]});
    for (let k = 1; k <= steps; ++k) {
      const x = from[0] + (to[0] - from[0]) * k / steps, y = from[1] + (to[1] - from[1]) * k / steps;
      await page('Input.dispatchTouchEvent', {type: 'touchMove', touchPoints: [{x, y}]});
      await sleep(20);
    }
    await page('Input.dispatchTouchEvent', {type: 'touchEnd', touchPoints: []});
  }
  // A screenshot of the panel's top (its inputs, the picture, the lines under it) in WORK/NAME.png.
  async function shot(page, name) {
    const r = await page.eval(`(function () { var b = document.querySelector('.tryit-player').getBoundingClientRect();
      return b.bottom + window.scrollY + 10; })()`);
    const {data} = await page('Page.captureScreenshot', {format: 'png', clip: {x: 0, y: 0, width: 1100, height: r, scale: 1}});
    fs.writeFileSync(path.join(work, name + '.png'), Buffer.from(data, 'base64'));
  }
  const KEYS = {ArrowUp: 38, ArrowDown: 40, ArrowLeft: 37, ArrowRight: 39};
  async function key(page, handle, name, shift) {
    await page.eval(`document.querySelector('.tryit-handle[data-handle="${handle}"]').focus()`);
    const base = {key: name, code: name, windowsVirtualKeyCode: KEYS[name], modifiers: shift ? 8 : 0};
    await page('Input.dispatchKeyEvent', Object.assign({type: 'rawKeyDown'}, base));
    await page('Input.dispatchKeyEvent', Object.assign({type: 'keyUp'}, base));
  }

  // ---- The command's answers for the new values ----
  // The lesson's file with `field` (component `comp`, -1 for a number) of body `body` set to x.
  function lessonWith(file, changes) {
    let text = fs.readFileSync(path.join(lessons, file), 'utf8');
    for (const [body, field, comp, x] of changes) {
      const lines = text.split('\n');
      let inBody = false, done = false;
      for (let k = 0; k < lines.length && !done; ++k) {
        if (/^\[/.test(lines[k])) inBody = false;
        if (lines[k] === `name = "${body}"` && /^\[\[body\]\]/.test(lines[k - 1] || '')) inBody = true;
        const m = inBody && lines[k].match(new RegExp(`^${field} = (.*)$`));
        if (!m) continue;
        if (comp < 0) lines[k] = `${field} = ${x}`;
        else {
          const v = JSON.parse(m[1]);
          v[comp] = x;
          lines[k] = `${field} = [${v.join(', ')}]`;
        }
        done = true;
      }
      if (!done) throw new Error(`${file}: no ${field} in body ${body}`);
      text = lines.join('\n');
    }
    const out = path.join(work, file.replace('.toml', '') + '-' + (nextId++) + '.toml');
    fs.writeFileSync(out, text);
    return out;
  }
  function stepEvents(file) {
    return execFileSync(collide, ['step', file, '--events', '--json'], {maxBuffer: 1 << 28}).toString().trim().split('\n').map(JSON.parse);
  }
  // The panel's collision (and each figure's) against the same pair's event of the run. The
  // engine may have found the pair the other way round (tower: box 4 hits the ball): then its
  // impulse, on the other body, is the panel's with the sign changed.
  function sameAsStep(shown, file, what) {
    const events = stepEvents(file);
    const pick = c => events.find(e => ((e.a === c.a && e.b === c.b) || (e.a === c.b && e.b === c.a)) && Math.abs(e.t - c.t) < 1e-9);
    const onB = (c, e) => e.a === c.a ? e.impulse : Array.isArray(e.impulse) ? e.impulse.map(x => -x) : -e.impulse;
    const w = shown.worked, e = pick(w);
    check(!!e && close(w.impulse, onB(w, e)) && close(w.v[0], e.after[w.a].v) && close(w.v[1], e.after[w.b].v),
          `${what}: the panel's impulse ${JSON.stringify(w.impulse)} and velocities after ` +
          `${JSON.stringify(w.v)} are collide step's (${e ? JSON.stringify(onB(w, e)) : 'no such event'})`);
    for (const f of shown.figures) {
      const g = pick(f);
      check(!!g && close(f.impulse, onB(f, g)),
            `${what}: the figures' ${f.a} / ${f.b} impulse ${JSON.stringify(f.impulse)} is collide step's (${g ? JSON.stringify(onB(f, g)) : 'none'})`);
    }
  }
  function onGrid(value, lo, step) { return Math.abs((value - lo) / step - Math.round((value - lo) / step)) < 1e-6; }

  // Runs the test's main(), ends Chromium, prints the count and exits 0 or 1.
  function finish(main, name) {
    main().then(() => {
      browser.kill();
      console.log(failures ? `${name}: ${failures} FAILED` : `${name}: all passed`);
      process.exit(failures ? 1 : 0);
    }, e => {
      browser.kill();
      console.error(`${name}: ` + e.stack);
      process.exit(1);
    });
  }
  return {check, close, send, sleep, openPage, answered, look, mouseDrag, touchDrag, shot, key, lessonWith, stepEvents,
          sameAsStep, onGrid, finish, stop: () => browser.kill()};
};
