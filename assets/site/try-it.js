// The Try-it panel of a lesson page (teach/html.h try_it_html; docs/commands/material.md, "The Try-it panel").
// The engine itself answers: collide-engine.js (wasm/) runs the lesson with the panel's values
// and returns the run (states at the page's frame rate, events), the page's collision worked
// out (the same HTML as the page's worked example) and `collide solve --format json`'s numbers
// for it. The scripts only draw what they get. This one holds the inputs (sliders, the address),
// the answers, the numbers, the lesson's own [[plot]]s (drawn by the engine: the SVG, alt text and
// folded table that `collide material` writes on the page, put in as they are) and playback; its
// parts, loaded before it, draw the picture (try-it-picture.js; in 3D try-it-3d.js, with three.js,
// which this script loads after the first answer)
// and its drag handles (try-it-drag.js), and make the plot of any quantity (try-it-plot.js). They
// share one object, `lab`: the panel's elements, its number format, the
// current run, frame and values (read through getters: this script alone changes them).
// No network: the module is a file beside the pages, loaded by a <script> tag (file:// works).
(function () {
  'use strict';
  var panel = document.getElementById('try-it');
  if (!panel) return;
  var status = panel.querySelector('.tryit-status');
  var parts = window.collideTryItParts || {};
  var d3 = panel.dataset.dimension === '3';
  if (!window.collideTryIt || !parts.picture || !parts.handles || !parts.plot || (d3 && !parts.view3d)) {
    status.textContent = 'The lesson (try-it-lesson.js) or the panel\u2019s scripts (try-it-picture.js, try-it-drag.js, ' +
                         'try-it-plot.js' + (d3 ? ', try-it-3d.js' : '') + ') did not load: the panel needs them beside ' +
                         'the pages.';
    return;
  }
  // The folder of this script, where the engine and three.js are (loaded once the page's first
  // answer is shown, below).
  var here = document.currentScript.src.replace(/try-it\.js(\?.*)?$/, '');
  var text = window.collideTryIt.lesson;  // the lesson's file, as `collide` reads it
  var palette = window.collideTryIt.palette;
  var fps = parseFloat(panel.dataset.fps) || 30;
  var scene = panel.querySelector('canvas.tryit-scene');
  var plot = panel.querySelector('canvas.tryit-plot');
  var numbers = panel.querySelector('.tryit-numbers');
  var worked = panel.querySelector('.tryit-worked');
  var lessonPlots = panel.querySelector('.tryit-lesson-plots');
  var timeText = panel.querySelector('.tryit-player .time');
  var inputs = Array.prototype.slice.call(panel.querySelectorAll('input[type=range]'));
  var values = {};  // the inputs changed from the lesson's own values, by name ("A.mass")
  var engine = null, run = null, frame = 0, playing = false, rate = 1, clock = 0, last = null, pending = false;
  var answers = 0;  // how many answers the engine gave (panel.dataset.answers: the browser test waits on it)
  var times = {};  // where the next answer's time goes (show: panel.collideTimes)
  var inFrame = false;  // (an answer given in an animation frame's callback: show)

  // ---- Numbers as the site writes them: 4 significant figures, a true minus sign ----
  function num(x) {
    if (Math.abs(x) < 1e-12) return '0';
    var s = String(Number(x.toPrecision(4)));
    if (/e/.test(s)) s = x.toPrecision(4);
    return s.replace('-', '\u2212');
  }
  function vec(v) { return Array.isArray(v) ? '(' + v.map(num).join(', ') + ')' : num(v); }
  function spin(w) { return Array.isArray(w) ? vec(w) : num(w); }
  function escapeHtml(s) {
    return String(s).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');
  }

  // ---- Putting an answer's HTML in: only where it changed, a folded table when it is opened ----
  // (Each answer brings the worked example, the numbers and the plots' SVG and tables anew; the
  // browser's style and layout of them took longer than the engine. A part whose HTML is the
  // same is left as it is, and a folded table, hundreds of cells no one sees until it is
  // unfolded, goes in when the reader unfolds it.) Returns whether the element changed.
  var FOLD = '<details class="plot-data">';
  function setHtml(el, html) {
    if (el.collideHtml === html) return false;
    el.collideHtml = html;
    var bodies = [], out = '', at = 0;
    for (;;) {
      var start = html.indexOf(FOLD, at);
      var head = start < 0 ? -1 : html.indexOf('<table', start);  // (its summary and words stay)
      var end = head < 0 ? -1 : html.indexOf('</details>', head);
      if (end < 0) break;
      out += html.slice(at, head);
      bodies.push(html.slice(head, end));
      at = end;
    }
    el.innerHTML = out + html.slice(at);
    if (bodies.length) {
      el.querySelectorAll('details.plot-data').forEach(function (d, k) {
        var body = bodies[k];
        function unfold() {
          if (!d.open || body === null) return;
          d.insertAdjacentHTML('beforeend', body);
          body = null;
          d.removeEventListener('toggle', unfold);
        }
        d.addEventListener('toggle', unfold);
      });
    }
    return true;
  }

  // ---- The inputs: the lesson's values, a query string's (?A.mass=3), the sliders' ----
  function valueOf(input) {
    var name = input.dataset.name;
    return name in values ? values[name] : parseFloat(input.dataset.lesson);
  }
  function showValue(input) {
    var out = input.parentNode.querySelector('output');
    if (out) out.textContent = num(valueOf(input));
  }
  var query = new URLSearchParams(window.location.search);
  // ?show=try-it: the panel alone on the page (the browser test's screenshots: a headless
  // screenshot shows the top of a page, wherever it is scrolled to).
  if (query.get('show') === 'try-it') {
    document.body.classList.add('tryit-only');
    for (var up = panel.parentNode; up && up !== document.body; up = up.parentNode) up.classList.add('tryit-path');
  }
  // The address's inputs (?A.mass=3, ?ball.v.x=5): each sets its slider; what cannot be done
  // as asked is said in a line on the page (.tryit-query), never ignored without a word.
  var queryLines = panel.querySelector('.tryit-query');
  var byName = {};
  inputs.forEach(function (input) { byName[input.dataset.name] = input; });
  function queryLine(cls, textValue) {
    if (!queryLines) return;
    var li = document.createElement('li');
    li.className = cls;
    li.textContent = textValue;
    queryLines.appendChild(li);
    queryLines.hidden = false;
  }
  var names = inputs.map(function (input) { return input.dataset.name; });
  query.forEach(function (q, name) {
    if (name === 'show') return;
    var input = byName[name];
    if (!input) {
      queryLine('tryit-query-unknown', 'The page\u2019s address sets ' + name + ' = ' + q + ', but this lesson has no input ' +
                name + (names.length ? ' (its inputs: ' + names.join(', ') + ').' : ' (it has no inputs to change).'));
      return;
    }
    var x = Number(q), lo = parseFloat(input.min), hi = parseFloat(input.max), step = parseFloat(input.step);
    if (q.trim() === '' || !isFinite(x)) {
      queryLine('tryit-query-bad', 'The page\u2019s address sets ' + name + ' = \u201c' + q +
                '\u201d, which is not a number: the lesson\u2019s ' + name + ' = ' + num(parseFloat(input.dataset.lesson)) + ' is used.');
      return;
    }
    // A hair of slack for a value typed as the slider shows it.
    var slack = 1e-9 * Math.max(1, Math.abs(lo), Math.abs(hi));
    if (x < lo - slack || x > hi + slack) {
      queryLine('tryit-query-bad', 'The page\u2019s address sets ' + name + ' = ' + num(x) + ', outside the input\u2019s range ' +
                num(lo) + ' to ' + num(hi) + ' (the lesson\u2019s point holds only there): the lesson\u2019s ' + name +
                ' = ' + num(parseFloat(input.dataset.lesson)) + ' is used.');
      return;
    }
    values[name] = x;
    input.value = q;
    // The browser puts the slider on its nearest step: said when that is not the value asked.
    var shown = parseFloat(input.value);
    if (Math.abs(shown - x) > slack)
      queryLine('tryit-query-between', 'The page\u2019s address sets ' + name + ' = ' + num(x) +
                ', between the slider\u2019s steps of ' + num(step) + ' (it shows ' + num(shown) + '): the run uses ' +
                num(x) + ' exactly.');
  });
  panel.dataset.queryLines = queryLines ? queryLines.children.length : 0;
  inputs.forEach(function (input) {
    showValue(input);
    input.addEventListener('input', function () {
      values[input.dataset.name] = parseFloat(input.value);
      showValue(input);
      request();
    });
  });
  // The address follows the inputs (?A.v.x=2.25: a link to this run), the lesson's own values
  // left out, once they rest for 50 ms (history.replaceState took as long as the engine's answer
  // when called at every move of a slider). A browser that refuses to change a file:// address
  // keeps the one it has.
  var addressTimer = null;
  function followAddress() {
    if (addressTimer !== null) window.clearTimeout(addressTimer);
    addressTimer = window.setTimeout(function () { addressTimer = null; setAddress(); }, 50);
  }
  function setAddress() {
    try {
      var q = new URLSearchParams(window.location.search);
      inputs.forEach(function (input) {
        var name = input.dataset.name;
        q.delete(name);
        if (name in values && values[name] !== parseFloat(input.dataset.lesson)) q.set(name, String(values[name]));
      });
      var s = q.toString();
      window.history.replaceState(null, '', window.location.pathname + (s ? '?' + s : '') + window.location.hash);
    } catch (e) { /* the address stays as it was */ }
  }
  var reset = panel.querySelector('.tryit-reset');
  if (reset) reset.addEventListener('click', function () {
    values = {};
    inputs.forEach(function (input) { input.value = input.dataset.lesson; showValue(input); });
    picture.refit();
    request();
  });

  // The engine's run of the lesson with the panel's values and plot (its JSON text).
  function ask() { return engine.lesson(text + freePlot.extraText(), values, fps); }

  // The browser compiles the module's code first plainly, and again optimised once it has run
  // for a while (V8's tiers): in Chromium general-2d's answers took 19 ms until the 7th and 6 ms
  // from the 8th on. So once the page has answered, the engine answers a few more times in the
  // background (the same lesson and values, the answers unused): at most 10 runs or 400 ms of
  // them, one per task, none while the reader's own answer waits.
  function warmUp(runs, spent) {
    if (runs >= 10 || spent >= 400) { panel.dataset.warmRuns = runs; return; }
    window.setTimeout(function () {
      if (pending) { warmUp(runs, spent); return; }
      var t0 = performance.now();
      try { ask(); } catch (e) { return; }  // answer() says why
      warmUp(runs + 1, spent + performance.now() - t0);
    }, 20);
  }

  // One answer per frame however fast a slider moves.
  function request() {
    if (pending) return;
    pending = true;
    window.requestAnimationFrame(function () { pending = false; inFrame = true; answer(); inFrame = false; });
  }

  function answer() {
    if (!engine) return;  // the module has not started: it answers when it has (below)
    var t0 = performance.now(), next, reply;
    try {
      reply = ask();
      times.engine = performance.now() - t0;
      next = JSON.parse(reply);
    } catch (e) {
      status.textContent = 'The engine refuses these values: ' + e.message;
      panel.dataset.error = e.message;
      return;
    }
    var ms = performance.now() - t0;
    delete panel.dataset.error;
    panel.dataset.answerMs = ms.toFixed(1);
    panel.dataset.answers = ++answers;
    var changed = Object.keys(values);
    status.textContent = (changed.length ? 'With ' + changed.map(function (k) { return k + ' = ' + num(values[k]); }).join(', ')
                                          : 'With the lesson\u2019s own values') +
                         ': answered by the engine in ' + (ms < 1 ? 'under 1' : ms.toFixed(0)) + ' ms.';
    show(next, t0);
  }

  // Shows a run: the engine's answer, or at the page's load the command's (window.collideTryIt.first).
  function show(next, t0) {
    var t = performance.now();
    function took(stage) { var now = performance.now(); times[stage] = now - t; t = now; }
    times.parse = t - t0 - (times.engine || 0);
    run = next;
    followAddress();
    // While a handle is dragged the picture keeps its scale, so that what is dragged stays under
    // the pointer; it is fitted to the new run when the drag ends.
    if (!handles.dragging() || !lab.view) picture.prepare();
    handles.make();
    frame = Math.min(frame, run.states.length - 1);
    took('prepare');
    showNumbers();
    took('numbers');
    setHtml(worked, run.worked ? run.worked.html : '<p>No collision in this run.</p>');
    took('worked');
    showPlots();
    took('plots');
    freePlot.show();
    took('free');
    draw();
    took('picture');
    // (for scripts/browser-speed.js: the whole answer shown, and when the page first showed one,
    // in ms from the page's navigation; panel.collideTimes: the last answer's stages, ms)
    panel.dataset.shownMs = (performance.now() - t0).toFixed(1);
    panel.collideTimes = times;
    // ... and painted: after the browser's style, layout and paint of what changed. An answer
    // to a move is given in an animation frame's callback, and that frame is painted when the
    // callbacks are done: a task queued now runs after it. Otherwise the next frame is the one.
    var painted = times;
    function paintedNow() { painted.painted = performance.now() - t0; panel.dataset.paintedMs = painted.painted.toFixed(1); }
    if (inFrame) window.setTimeout(paintedNow, 0);
    else window.requestAnimationFrame(function () { window.setTimeout(paintedNow, 0); });
    times = {};
    if (!panel.dataset.firstShownAt) panel.dataset.firstShownAt = performance.now().toFixed(1);
  }

  // ---- The lesson's [[plot]]s of this run: the engine's SVG, alt text and folded table ----
  function showPlots() {
    if (!lessonPlots) return;
    var open = {};  // a table the reader unfolded stays unfolded when the inputs move
    lessonPlots.querySelectorAll('details.plot-data').forEach(function (d, k) { if (d.open) open[k] = true; });
    // (the last: the panel's plot; the command's answer at the page's load has none)
    var h = '', own = run.plots.slice(0, run.plots.length - (run.precomputed ? 0 : freePlot.extra()));
    own.forEach(function (p) {
      h += '<section class="lesson-plot" data-file="' + escapeHtml(p.file) + '"><h3>' + escapeHtml(p.title) + '</h3>' +
           '<figure>' + p.svg + '<figcaption>From the engine in this page: the run with these inputs. ' +
           '<button type="button" class="tryit-open-plot">Change its axes</button></figcaption></figure>' +
           p.data_html + '</section>';
    });
    if (!setHtml(lessonPlots, h)) return;
    lessonPlots.querySelectorAll('section.lesson-plot').forEach(function (section, k) {
      var svg = section.querySelector('svg');
      if (svg) svg.setAttribute('aria-label', run.plots[k].alt);  // what it shows, as the page's alt text
      var d = section.querySelector('details.plot-data');
      if (d && open[k]) d.open = true;
      section.querySelector('.tryit-open-plot').addEventListener('click', function () { freePlot.open(k); });
    });
  }

  // ---- The numbers of the page's collision ----
  function showNumbers() {
    var w = run.worked;
    if (!w) {
      setHtml(numbers, '<p>No collision in this run: change the inputs.</p>');
      return;
    }
    // The run's numbers: where other contacts act at the same instant (a tower, a row of
    // dominoes) the world's outcome (w.run), not the two bodies alone (w.solve) that the
    // worked example below calculates as a simplified case.
    var s = w.run || w.solve, d = s.dimension;
    var h = '<p>The collision of ' + escapeHtml(w.a) + ' (a) and ' + escapeHtml(w.b) + ' (b) at t = ' + num(w.t) +
            ' s' + (w.run ? ', as the run resolved it with the other contacts of that instant' : '') +
            '. Impulse on ' + escapeHtml(w.b) + ': <output class="tryit-impulse" data-value="' +
            escapeHtml(JSON.stringify(s.impulse)) + '" data-a="' + escapeHtml(w.a) + '" data-b="' + escapeHtml(w.b) +
            '" data-t="' + w.t + '">P = ' + vec(s.impulse) + ' N\u00b7s</output>' +
            (d > 1 ? ', j = P\u00b7n = <output class="tryit-normal-impulse" data-value="' + s.normal_impulse + '">' +
                     num(s.normal_impulse) + ' N\u00b7s</output>' : '') + '.</p>\n';
    h += '<table><tr><th>body</th><th>v after (m/s)</th>' + (d > 1 ? '<th>\u03c9 after (rad/s)</th>' : '') + '</tr>';
    [['a', w.a], ['b', w.b]].forEach(function (p) {
      h += '<tr><td>' + escapeHtml(p[1]) + '</td><td class="tryit-v-after" data-value="' +
           escapeHtml(JSON.stringify(s[p[0]].v)) + '">' + vec(s[p[0]].v) + '</td>' +
           (d > 1 ? '<td class="tryit-w-after" data-value="' + escapeHtml(JSON.stringify(s[p[0]].w)) + '">' +
                    spin(s[p[0]].w) + '</td>' : '') + '</tr>';
    });
    h += '</table><table><tr><th>totals</th><th>before</th><th>after</th></tr>' +
         '<tr><td>momentum (kg m/s)</td><td>' + vec(s.momentum.before) + '</td><td>' + vec(s.momentum.after) + '</td></tr>';
    if (s.angular_momentum)
      h += '<tr><td>angular momentum about the origin (kg m\u00b2/s)</td><td>' + spin(s.angular_momentum.before) +
           '</td><td>' + spin(s.angular_momentum.after) + '</td></tr>';
    h += '<tr><td>kinetic energy (J)</td><td class="tryit-ke-before">' + num(s.kinetic_energy.before) +
         '</td><td class="tryit-ke-after">' + num(s.kinetic_energy.after) + '</td></tr></table>';
    // A lesson of several figures (two bats, three rows, two pucks): each of their collisions,
    // since an input may change another than the first.
    var figs = run.figures || [];
    if (figs.length > 1) {
      h += '<table class="tryit-figures"><caption>Every collision the lesson\u2019s figures show, with these inputs</caption>' +
           '<tr><th>collision</th><th>t (s)</th><th>impulse on b (N\u00b7s)</th><th>body</th><th>v after (m/s)</th>' +
           (d > 1 ? '<th>\u03c9 after (rad/s)</th>' : '') + '</tr>';
      figs.forEach(function (f) {
        var r = f.run || f.solve;  // the run's outcome, as above
        [['a', f.a], ['b', f.b]].forEach(function (p, k) {
          h += '<tr>' + (k === 0 ? '<td rowspan="2">' + escapeHtml(f.a) + ' (a) and ' + escapeHtml(f.b) + ' (b)</td>' +
                                   '<td rowspan="2">' + num(f.t) + '</td><td rowspan="2" class="tryit-figure-impulse" data-value="' +
                                   escapeHtml(JSON.stringify(r.impulse)) + '" data-a="' + escapeHtml(f.a) + '" data-b="' +
                                   escapeHtml(f.b) + '" data-t="' + f.t + '">' + vec(r.impulse) + '</td>' : '') +
               '<td>' + escapeHtml(p[1]) + '</td><td class="tryit-v-after" data-value="' + escapeHtml(JSON.stringify(r[p[0]].v)) +
               '">' + vec(r[p[0]].v) + '</td>' + (d > 1 ? '<td>' + spin(r[p[0]].w) + '</td>' : '') + '</tr>';
        });
      });
      h += '</table>';
    }
    setHtml(numbers, h);
  }

  // ---- What the parts share: the panel, its number format, the state (read-only to them) ----
  var lab = {panel: panel, scene: scene, plot: plot, palette: palette, byName: byName, num: num, vec: vec,
             escapeHtml: escapeHtml, setHtml: setHtml,
             valueOf: valueOf, showValue: showValue, request: request, draw: draw, view: null, named: null};
  Object.defineProperty(lab, 'run', {get: function () { return run; }});
  Object.defineProperty(lab, 'frame', {get: function () { return frame; }});
  Object.defineProperty(lab, 'playing', {get: function () { return playing; }});
  Object.defineProperty(lab, 'values', {get: function () { return values; }});
  // (goTo: a frame, paused: the 3D view's buttons)
  lab.goTo = function (k) { playing = false; frame = Math.max(0, Math.min(k, run.states.length - 1)); draw(); };
  var picture = lab.picture = parts.picture(lab);
  if (d3) picture = lab.picture = parts.view3d(lab, picture);  // the 3D view, with the flat one's plot
  var handles = lab.handles = parts.handles(lab);
  var freePlot = parts.plot(lab);

  function draw() {
    if (!run) return;
    var st = run.states[frame];
    timeText.textContent = 't = ' + st.t.toFixed(3) + ' s  (frame ' + frame + ' of ' + (run.states.length - 1) + ')';
    if (scene) picture.drawScene(st);
    if (plot) picture.drawPlot(st.t);
    handles.place();
  }

  // ---- Playback: play / pause, one frame forward, 0.25x and 1x (simulated time) ----
  function tick(now) {
    if (!playing) return;
    if (last !== null) clock += (now - last) / 1000 * rate;
    last = now;
    var k = Math.floor(clock * fps + 1e-9);
    if (k >= run.states.length) { clock = 0; k = 0; }  // loops, as the page's video
    if (k !== frame) { frame = k; draw(); }
    window.requestAnimationFrame(tick);
  }
  panel.querySelectorAll('.tryit-player button').forEach(function (b) {
    b.addEventListener('click', function () {
      if (!run) return;
      if (b.dataset.rate) {
        rate = parseFloat(b.dataset.rate);
        panel.querySelectorAll('.tryit-player [data-rate]').forEach(function (o) { o.setAttribute('aria-pressed', o === b); });
      } else if (b.dataset.act === 'start') {  // back to t = 0, paused: where the handles are
        playing = false;
        frame = 0;
        draw();
      } else if (b.dataset.act === 'play') {
        playing = !playing;
        if (playing) { clock = frame / fps; last = null; window.requestAnimationFrame(tick); }
        else draw();  // paused: at the start, the handles come back
      } else {
        playing = false;
        frame = (frame + 1) % run.states.length;
        draw();
      }
    });
  });

  // The lesson's own values, as the page opens: the answer the command wrote into the page's data
  // (present/try_it_answer.h, the module's function run by `collide material`), shown at once;
  // the engine in the page answers again when it has started, and every change after.
  var first = window.collideTryIt.first;
  if (first && Object.keys(values).length === 0) {
    first.precomputed = true;
    status.textContent = 'With the lesson\u2019s own values: the answer collide material wrote into this page ' +
                         '(the same engine, run by the command). The engine in this page is starting\u2026';
    show(first, performance.now());
  }

  if (window.location.hash === '#try-it') panel.scrollIntoView();
  // In 3D, three.js (beside the pages, as the engine) once the first answer is shown; the 3D
  // view draws the run it has when it has loaded.
  // (a script beside this one, by a script element: file:// works)
  function loadBeside(file, loaded, failed) {
    var script = document.createElement('script');
    script.src = here + file;
    script.onerror = failed;
    script.onload = loaded;
    document.body.appendChild(script);
  }
  if (d3) loadBeside('three.min.js', function () {
    if (!picture.start() || !run) return;
    picture.prepare();
    handles.make();
    draw();
  }, function () { picture.missing(); });
  function engineMissing() {
    status.textContent = 'The engine (collide-engine.js) did not load: the panel needs it beside the pages.';
  }
  loadBeside('collide-engine.js', function () {
    if (typeof CollideEngine !== 'function') { engineMissing(); return; }
    CollideEngine().then(function (m) {
      engine = m;
      panel.dataset.engineAt = performance.now().toFixed(1);
      answer();
      warmUp(0, 0);
    }, function (e) {
      status.textContent = 'The engine did not start: ' + e;
    });
  }, engineMissing);
})();
