// The Try-it panel of a lesson page (teach/html.h try_it_html; docs/commands/material.md, "The Try-it panel").
// The engine itself answers: collide-engine.js (wasm/) runs the lesson with the panel's values
// and returns the run (states at the page's frame rate, events), the page's collision worked
// out (the same HTML as the page's worked example) and `collide solve --format json`'s numbers
// for it. This script only draws what it gets: a light 1D / 2D picture in the figures' colours
// (render/style.h, given as the page's palette), a plot of the energies, and the numbers; the
// lesson's own [[plot]]s come drawn by the engine (the SVG, alt text and folded table that
// `collide material` writes on the page), and are put in as they are. At the paused start of
// the run (t = 0) the picture's handles set inputs too: a drag (mouse, pen or touch: Pointer
// Events) or the keyboard on a body whose position is an input, a velocity arrow's head, a
// spin dial, a turn handle, and in a lesson with none of these a body's mass knob; each value
// snaps to its input's step and stays in its range, and goes the sliders' way to the engine.
// No network: the module is a file beside the pages, loaded by a <script> tag (file:// works).
(function () {
  'use strict';
  var panel = document.getElementById('try-it');
  if (!panel) return;
  var status = panel.querySelector('.tryit-status');
  if (typeof CollideEngine !== 'function' || !window.collideTryIt) {
    status.textContent = 'The engine (collide-engine.js) or the lesson (try-it-lesson.js) did not load: ' +
                         'the panel needs them beside the pages.';
    return;
  }
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
  if (query.get('show') === 'try-it') document.body.classList.add('tryit-only');
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
  // left out. A browser that refuses to change a file:// address keeps the one it has.
  function followAddress() {
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
    refit = true;
    request();
  });

  // One answer per frame however fast a slider moves.
  function request() {
    if (pending) return;
    pending = true;
    window.requestAnimationFrame(function () { pending = false; answer(); });
  }

  function answer() {
    var t0 = performance.now(), next;
    try {
      next = JSON.parse(engine.lesson(text, values, fps));
    } catch (e) {
      status.textContent = 'The engine refuses these values: ' + e.message;
      panel.dataset.error = e.message;
      return;
    }
    var ms = performance.now() - t0;
    delete panel.dataset.error;
    run = next;
    panel.dataset.answerMs = ms.toFixed(1);
    panel.dataset.answers = ++answers;
    followAddress();
    var changed = Object.keys(values);
    status.textContent = (changed.length ? 'With ' + changed.map(function (k) { return k + ' = ' + num(values[k]); }).join(', ')
                                          : 'With the lesson\u2019s own values') +
                         ': answered by the engine in ' + (ms < 1 ? 'under 1' : ms.toFixed(0)) + ' ms.';
    // While a handle is dragged the picture keeps its scale, so that what is dragged stays under
    // the pointer; it is fitted to the new run when the drag ends.
    if (!drag || !view) prepare();
    makeHandles();
    frame = Math.min(frame, run.states.length - 1);
    showNumbers();
    worked.innerHTML = run.worked ? run.worked.html : '<p>No collision in this run.</p>';
    showPlots();
    draw();
  }

  // ---- The lesson's [[plot]]s of this run: the engine's SVG, alt text and folded table ----
  function showPlots() {
    if (!lessonPlots) return;
    var open = {};  // a table the reader unfolded stays unfolded when the inputs move
    lessonPlots.querySelectorAll('details.plot-data').forEach(function (d, k) { if (d.open) open[k] = true; });
    var h = '';
    (run.plots || []).forEach(function (p) {
      h += '<section class="lesson-plot" data-file="' + escapeHtml(p.file) + '"><h3>' + escapeHtml(p.title) + '</h3>' +
           '<figure>' + p.svg + '<figcaption>From the engine in this page: the run with these inputs.</figcaption>' +
           '</figure>' + p.data_html + '</section>';
    });
    lessonPlots.innerHTML = h;
    lessonPlots.querySelectorAll('section.lesson-plot').forEach(function (section, k) {
      var svg = section.querySelector('svg');
      if (svg) svg.setAttribute('aria-label', run.plots[k].alt);  // what it shows, as the page's alt text
      var d = section.querySelector('details.plot-data');
      if (d && open[k]) d.open = true;
    });
  }

  // ---- The numbers of the page's collision ----
  function showNumbers() {
    var w = run.worked;
    if (!w) {
      numbers.innerHTML = '<p>No collision in this run: change the inputs.</p>';
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
    numbers.innerHTML = h;
  }

  // ---- Drawing: world to canvas ----
  var view = null;  // {scale, ox, oy}: canvas x = ox + scale x, y = oy - scale y
  var refit = true;  // the next run fits the picture afresh (prepare)
  function bodyState(k, name) { return run.states[k].bodies[name]; }
  function extentOf(b) {  // the body's size from its centre (m)
    if (run.dimension === 1) return b.length / 2;
    if (b.kind === 'disc') return b.radius;
    if (b.kind === 'polygon') return Math.max.apply(null, b.vertices.map(function (p) { return Math.hypot(p[0], p[1]); }));
    return 0;
  }
  function prepare() {
    if (!scene) return;
    var lo = [Infinity, Infinity], hi = [-Infinity, -Infinity];
    run.states.forEach(function (st) {
      run.bodies.forEach(function (b) {
        var s = st.bodies[b.name];
        if (!s || b.kind === 'half_plane') return;
        var r = extentOf(b), x = run.dimension === 1 ? [s.x, 0] : s.x;
        lo[0] = Math.min(lo[0], x[0] - r); hi[0] = Math.max(hi[0], x[0] + r);
        lo[1] = Math.min(lo[1], x[1] - r); hi[1] = Math.max(hi[1], x[1] + r);
      });
    });
    // A static body without a state (1D walls have one; 2D half planes do not): its line in view.
    run.bodies.forEach(function (b) {
      if (b.kind !== 'half_plane') return;
      var c = [(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2];
      var dist = b.normal[0] * c[0] + b.normal[1] * c[1] - b.offset;
      var p = [c[0] - dist * b.normal[0], c[1] - dist * b.normal[1]];
      lo[0] = Math.min(lo[0], p[0]); hi[0] = Math.max(hi[0], p[0]);
      lo[1] = Math.min(lo[1], p[1]); hi[1] = Math.max(hi[1], p[1]);
    });
    // Above the scene: the legend, at most three rows (drawScene).
    var moving = run.bodies.filter(function (b) { return !b.static; }).length;
    var W = scene.width, H = scene.height, top = moving > 2 ? 84 : 70, margin = 40;
    var w = Math.max(hi[0] - lo[0], 1e-3), h = Math.max(hi[1] - lo[1], 1e-3);
    var scale = run.dimension === 1 ? (W - 2 * margin) / w : Math.min((W - 2 * margin) / w, (H - top - margin) / h);
    var ox = W / 2 - scale * (lo[0] + hi[0]) / 2;
    var oy = run.dimension === 1 ? H * 0.72 : top + (H - top - margin) / 2 + scale * (lo[1] + hi[1]) / 2;
    // Arrows: the fastest speed of the run is 0.16 of the picture, the largest impulse 0.14.
    var vmax = 1e-12, pmax = 1e-12;
    run.states.forEach(function (st) {
      Object.keys(st.bodies).forEach(function (n) { vmax = Math.max(vmax, norm(st.bodies[n].v)); });
    });
    run.events.forEach(function (e) { pmax = Math.max(pmax, norm(e.impulse)); });
    var size = Math.min(W, run.dimension === 1 ? 2 * H : H), vscale = 0.16 * size / vmax;
    // Once fitted, the picture keeps its scales while the new run fits in it and its arrows stay
    // short enough: a body dragged stays where it was let go, and an arrow made longer is longer
    // (one scale before and after, to compare). "The lesson's values" fits it afresh.
    if (view && !refit) {
      var fits = true;
      [lo, hi].forEach(function (p) {
        var c = [view.ox + view.scale * p[0], view.oy - view.scale * p[1]];
        if (c[0] < 4 || c[0] > W - 4 || (run.dimension > 1 && (c[1] < top - 30 || c[1] > H - 4))) fits = false;
      });
      if (fits) { scale = view.scale; ox = view.ox; oy = view.oy; }
      if (view.vscale * vmax <= 0.3 * size) vscale = view.vscale;
    }
    refit = false;
    view = {scale: scale, ox: ox, oy: oy, vscale: vscale, pscale: 0.14 * size / pmax};
    // (on the panel: canvas pixels per metre and per m/s, for the browser test's drags)
    panel.dataset.view = JSON.stringify({scale: scale, vscale: view.vscale});
  }
  function norm(v) { return Array.isArray(v) ? Math.hypot.apply(null, v) : Math.abs(v); }
  function toCanvas(x, y) { return [view.ox + view.scale * x, view.oy - view.scale * y]; }

  function arrow(ctx, from, to, colour, width) {
    var dx = to[0] - from[0], dy = to[1] - from[1], len = Math.hypot(dx, dy);
    if (len < 2) return;
    var ux = dx / len, uy = dy / len, head = Math.min(14, len * 0.6), half = head * 0.45;
    ctx.strokeStyle = colour; ctx.fillStyle = colour; ctx.lineWidth = width;
    ctx.beginPath(); ctx.moveTo(from[0], from[1]); ctx.lineTo(to[0] - ux * head * 0.8, to[1] - uy * head * 0.8); ctx.stroke();
    ctx.beginPath(); ctx.moveTo(to[0], to[1]);
    ctx.lineTo(to[0] - ux * head - uy * half, to[1] - uy * head + ux * half);
    ctx.lineTo(to[0] - ux * head + uy * half, to[1] - uy * head - ux * half);
    ctx.closePath(); ctx.fill();
  }
  function label(ctx, textValue, at, colour, align) {
    ctx.font = '15px "DejaVu Sans", Arial, sans-serif';
    ctx.textAlign = align || 'left'; ctx.textBaseline = 'middle';
    ctx.lineWidth = 4; ctx.strokeStyle = 'rgba(255,255,255,0.85)'; ctx.strokeText(textValue, at[0], at[1]);
    ctx.fillStyle = colour; ctx.fillText(textValue, at[0], at[1]);
  }
  // Colour by the order among moving bodies, as the figures (render/diagram_draw.cpp).
  function fillOf(i) {
    var b = run.bodies[i];
    if (b.static) return palette.static_fill;
    var order = 0;
    for (var j = 0; j < i; ++j) order += run.bodies[j].static ? 0 : 1;
    return palette.fills[order % palette.fills.length];
  }

  // The bodies named in the scene: all of them, or in a row of many (dominoes, whose names
  // would run into each other) the first, the last and the latest collision's two (drawScene).
  var named = null;
  // A 1D block on the canvas: its box and where its velocity arrow starts (above it).
  function blockBox(b, s) {
    var w = b.length * view.scale, h = Math.max(28, Math.min(w, 110)), c = toCanvas(s.x, 0);
    return {x0: c[0] - w / 2, x1: c[0] + w / 2, y0: c[1] - h, y1: c[1], centre: [c[0], c[1] - h / 2], at: [c[0], c[1] - h - 14]};
  }
  function drawBody(ctx, i, s, noSpin) {
    var b = run.bodies[i], d = run.dimension;
    ctx.fillStyle = fillOf(i); ctx.strokeStyle = palette.ink; ctx.lineWidth = 2;
    if (d === 1) {
      var box = blockBox(b, s);
      ctx.fillRect(box.x0, box.y0, box.x1 - box.x0, box.y1 - box.y0);
      ctx.strokeRect(box.x0, box.y0, box.x1 - box.x0, box.y1 - box.y0);
      label(ctx, b.name, box.centre, palette.ink, 'center');
      return box.at;
    }
    if (b.kind === 'half_plane') {
      var n = b.normal, t = [-n[1], n[0]], p0 = [n[0] * b.offset, n[1] * b.offset], far = 1e3;
      var a = toCanvas(p0[0] - t[0] * far, p0[1] - t[1] * far), e = toCanvas(p0[0] + t[0] * far, p0[1] + t[1] * far);
      var down = [-n[0] * 14, n[1] * 14];
      ctx.fillStyle = palette.static_fill;
      ctx.beginPath(); ctx.moveTo(a[0], a[1]); ctx.lineTo(e[0], e[1]); ctx.lineTo(e[0] + down[0], e[1] + down[1]);
      ctx.lineTo(a[0] + down[0], a[1] + down[1]); ctx.closePath(); ctx.fill();
      ctx.beginPath(); ctx.moveTo(a[0], a[1]); ctx.lineTo(e[0], e[1]); ctx.stroke();
      return null;
    }
    var centre = toCanvas(s.x[0], s.x[1]), angle = s.angle || 0;
    ctx.beginPath();
    if (b.kind === 'disc') {
      ctx.arc(centre[0], centre[1], b.radius * view.scale, 0, 2 * Math.PI);
    } else {
      b.vertices.forEach(function (v, k) {
        var x = s.x[0] + Math.cos(angle) * v[0] - Math.sin(angle) * v[1];
        var y = s.x[1] + Math.sin(angle) * v[0] + Math.cos(angle) * v[1];
        var p = toCanvas(x, y);
        if (k === 0) ctx.moveTo(p[0], p[1]); else ctx.lineTo(p[0], p[1]);
      });
      ctx.closePath();
    }
    ctx.fill(); ctx.stroke();
    if (b.kind === 'disc') {  // a radius line shows the disc turning
      var r = b.radius * view.scale;
      ctx.lineWidth = 1.5;
      ctx.beginPath(); ctx.moveTo(centre[0], centre[1]);
      ctx.lineTo(centre[0] + r * Math.cos(angle), centre[1] - r * Math.sin(angle)); ctx.stroke();
    }
    ctx.fillStyle = palette.ink;
    ctx.beginPath(); ctx.arc(centre[0], centre[1], 4, 0, 2 * Math.PI); ctx.fill();
    if (!named || named[b.name]) label(ctx, b.name, [centre[0] + 8, centre[1] + 14], palette.ink);
    if (Math.abs(s.w) > 1e-9 && !noSpin) {  // the spin: an amber arc, its head in the turning direction
      var rr = Math.max(16, extentOf(b) * view.scale * 0.55), ccw = s.w > 0;
      ctx.strokeStyle = palette.spin; ctx.fillStyle = palette.spin; ctx.lineWidth = 2.5;
      ctx.beginPath(); ctx.arc(centre[0], centre[1], rr, -0.3, -1.9, true); ctx.stroke();
      var endA = ccw ? -1.9 : -0.3, tip = [centre[0] + rr * Math.cos(endA), centre[1] + rr * Math.sin(endA)];
      var dir = ccw ? [-Math.sin(endA), Math.cos(endA)] : [Math.sin(endA), -Math.cos(endA)];
      dir = [-dir[0], -dir[1]];
      arrow(ctx, [tip[0] - dir[0] * 10, tip[1] - dir[1] * 10], tip, palette.spin, 2.5);
    }
    return centre;
  }

  function draw() {
    if (!run) return;
    var st = run.states[frame];
    timeText.textContent = 't = ' + st.t.toFixed(3) + ' s  (frame ' + frame + ' of ' + (run.states.length - 1) + ')';
    if (scene) drawScene(st);
    if (plot) drawPlot(st.t);
    placeHandles();
  }

  function drawScene(st) {
    var ctx = scene.getContext('2d'), d = run.dimension, W = scene.width, H = scene.height;
    ctx.fillStyle = palette.background; ctx.fillRect(0, 0, W, H);
    if (d === 1) {  // the x axis the blocks stand on, with its positive direction
      ctx.strokeStyle = palette.ink; ctx.lineWidth = 2;
      ctx.beginPath(); ctx.moveTo(10, view.oy); ctx.lineTo(W - 20, view.oy); ctx.stroke();
      arrow(ctx, [W - 40, view.oy], [W - 10, view.oy], palette.ink, 2);
      label(ctx, 'x', [W - 18, view.oy + 16], palette.ink, 'center');
    }
    var legend = [], last = null;
    run.events.forEach(function (e) { if (e.t <= st.t + 1e-12) last = e; });
    var moving = run.bodies.filter(function (b) { return !b.static; });
    named = null;
    if (moving.length > 3) {
      named = {};
      named[moving[0].name] = named[moving[moving.length - 1].name] = true;
      if (last) named[last.a] = named[last.b] = true;
      else named[moving[1].name] = true;  // the legend's first two
    }
    var dials = {};  // bodies whose spin the start's dial shows (instead of the arc)
    if (atStart()) handles.forEach(function (h) { if (h.kind === 'spin') dials[h.body] = true; });
    run.bodies.forEach(function (b, i) {
      var s = st.bodies[b.name];
      if (!s && b.kind !== 'half_plane') return;
      var at = drawBody(ctx, i, s, dials[b.name]);
      if (!at || b.static) return;
      var v = d === 1 ? [s.v, 0] : s.v;  // the velocity: a blue arrow from the centre (1D: above the block)
      arrow(ctx, at, [at[0] + v[0] * view.vscale, at[1] - v[1] * view.vscale], palette.velocity, 3);
      legend.push({i: i, text: b.name + ':  v = ' + vec(s.v) + ' m/s' + (d > 1 ? ',  \u03c9 = ' + num(s.w) + ' rad/s' : '')});
    });
    // Each collision of the last 0.15 s: the impulse on b (red) at the contact point, the normal (teal).
    run.events.forEach(function (e) {
      if (e.t > st.t + 1e-12 || e.t < st.t - 0.15) return;
      var p = d === 1 ? toCanvas(e.point, 0) : toCanvas(e.point[0], e.point[1]);
      if (d === 1) p[1] -= 150;  // above the blocks and their velocity arrows
      var P = d === 1 ? [e.impulse, 0] : e.impulse, n = d === 1 ? [e.normal, 0] : e.normal;
      if (d > 1) arrow(ctx, p, [p[0] + n[0] * 60, p[1] - n[1] * 60], palette.normal, 2.5);  // 1D: n is +x
      arrow(ctx, p, [p[0] + P[0] * view.pscale, p[1] - P[1] * view.pscale], palette.impulse, 3.5);
      label(ctx, 'P = ' + vec(e.impulse) + ' N\u00b7s on ' + e.b, [p[0] + 10, p[1] - 20], palette.impulse);
    });
    // The legend above the scene, three rows at most (a row of dominoes would cover them): with
    // more moving bodies, the two of the latest collision so far (else the first two) and a
    // row that says how many are left out.
    var rows = legend, others = 0;
    if (legend.length > 3) {
      rows = legend.filter(function (l) {
        var n = run.bodies[l.i].name;
        return last ? n === last.a || n === last.b : false;
      });
      if (rows.length === 0) rows = legend.slice(0, 2);
      others = legend.length - rows.length;
    }
    rows.forEach(function (l, k) {
      ctx.fillStyle = fillOf(l.i); ctx.fillRect(12, 12 + k * 22, 14, 14);
      ctx.strokeStyle = palette.ink; ctx.lineWidth = 1; ctx.strokeRect(12, 12 + k * 22, 14, 14);
      label(ctx, l.text, [32, 19 + k * 22], palette.ink);
    });
    if (others > 0)
      label(ctx, '+ ' + others + ' other moving bodies (listed: ' + (last ? 'the latest collision\u2019s two)' : 'the first two)'),
            [32, 19 + rows.length * 22], palette.muted);
    label(ctx, 't = ' + st.t.toFixed(3) + ' s', [W - 12, 19], palette.muted, 'right');
    if (atStart()) drawHandles(ctx);
  }

  // The energies against time, as the page's plot (kinetic; with gravity potential and total),
  // faint red lines at the collisions, the current time in grey.
  function drawPlot(t) {
    var ctx = plot.getContext('2d'), W = plot.width, H = plot.height, l = 70, r = 20, top = 30, bottom = 30;
    ctx.fillStyle = '#ffffff'; ctx.fillRect(0, 0, W, H);
    var g = run.gravity.some(function (x) { return x !== 0; });
    var series = [{name: 'kinetic', colour: '#1d4ed8', f: function (s) { return s.kinetic_energy; }}];
    if (g) {
      series.push({name: 'potential', colour: '#0f766e', f: function (s) { return s.potential_energy; }});
      series.push({name: 'total', colour: '#1c1c1e', f: function (s) { return s.kinetic_energy + s.potential_energy; }});
    }
    var lo = Infinity, hi = -Infinity;
    series.forEach(function (sr) { run.states.forEach(function (s) { var y = sr.f(s); lo = Math.min(lo, y); hi = Math.max(hi, y); }); });
    lo = Math.min(lo, 0);  // from zero, so that a loss looks as large as it is
    if (hi - lo < 1e-9) hi = lo + 1;
    var X = function (x) { return l + (W - l - r) * x / run.duration; };
    var Y = function (y) { return H - bottom - (H - top - bottom) * (y - lo) / (hi - lo); };
    ctx.strokeStyle = 'rgba(206,32,41,0.35)'; ctx.lineWidth = 1;
    run.events.forEach(function (e) { ctx.beginPath(); ctx.moveTo(X(e.t), top); ctx.lineTo(X(e.t), H - bottom); ctx.stroke(); });
    ctx.strokeStyle = palette.grid; ctx.strokeRect(l, top, W - l - r, H - top - bottom);
    series.forEach(function (sr, k) {
      ctx.strokeStyle = sr.colour; ctx.lineWidth = 2; ctx.beginPath();
      run.states.forEach(function (s, i) { if (i === 0) ctx.moveTo(X(s.t), Y(sr.f(s))); else ctx.lineTo(X(s.t), Y(sr.f(s))); });
      ctx.stroke();
      label(ctx, sr.name, [l + 10 + k * 110, 14], sr.colour);
    });
    label(ctx, 'Energy (J)', [W - r, 14], palette.ink, 'right');
    label(ctx, num(hi), [l - 6, top], palette.muted, 'right');
    label(ctx, num(lo), [l - 6, H - bottom], palette.muted, 'right');
    label(ctx, '0', [l, H - bottom + 14], palette.muted, 'center');
    label(ctx, num(run.duration) + ' s', [W - r, H - bottom + 14], palette.muted, 'right');
    ctx.strokeStyle = palette.muted; ctx.lineWidth = 1.5;
    ctx.beginPath(); ctx.moveTo(X(t), top); ctx.lineTo(X(t), H - bottom); ctx.stroke();
  }

  // ---- Drag to set: the picture's handles at the paused start (t = 0) ----
  // Each handle sets one or two of the lesson's [[vary]] inputs (run.vary: name, lo, hi, step,
  // body, field, component): a body whose position is an input (a dashed outline; along a
  // track where one coordinate is), the head of a velocity arrow (a blue knob: the components
  // that are inputs, the others stay), a spin dial (an amber knob on a circle: the arc from the
  // top is w, counterclockwise positive), a turn handle (the body's angle), and only where a
  // lesson has none of these, a body's mass knob on a short upright track beside it. A drag or a key sets
  // each input to the nearest value of its grid, lo + k step (as the slider and the worksheets:
  // scenario/lesson.h LessonVary::value), never beyond lo or hi (and says so), through the
  // slider: its value, the number beside it, the address, and one answer a frame.
  var layer = panel.querySelector('.tryit-handles');
  var help = panel.querySelector('.tryit-drag-help');
  var said = panel.querySelector('.tryit-drag-said');
  var handles = [];  // of the latest answer's first frame (makeHandles)
  var drag = null;   // the drag under way: {h, id, p0, start, a0, a}
  var focusedId = null, hoverId = null;
  var KNOB = 9;  // a knob's radius on the canvas (px)

  function atStart() { return !!run && frame === 0 && !playing && handles.length > 0; }
  function current(v) { return byName[v.name] ? valueOf(byName[v.name]) : v.value; }
  // The grid's k-th value, as LessonVary::value gives it (rounded to 1e-9; the last is hi).
  function gridCount(v) { return Math.round((v.hi - v.lo) / v.step); }
  function gridValue(v, k) {
    return k >= gridCount(v) ? v.hi : Math.round((v.lo + k * v.step) * 1e9) / 1e9;
  }
  // The grid value nearest x, and whether x lay beyond an end (by more than half a step).
  function snapped(v, x) {
    var n = gridCount(v), k = Math.round((x - v.lo) / v.step), beyond = null;
    if (k < 0 || (k === 0 && x < v.lo)) { beyond = x < v.lo - v.step / 2 ? 'low' : null; k = 0; }
    if (k > n || (k === n && x > v.hi)) { beyond = x > v.hi + v.step / 2 ? 'high' : null; k = n; }
    return {value: gridValue(v, k), k: k, n: n, beyond: beyond};
  }
  function unitOf(v) { return v.unit; }  // the slider label's unit (teach/html.h vary_unit)
  function say(v, s) {
    var u = unitOf(v), text = v.name + ' = ' + num(s.value) + (u ? ' ' + u : '');
    if (s.k === 0 || s.k === s.n)
      text += s.beyond ? ' \u2014 the end of its range (' + num(v.lo) + ' to ' + num(v.hi) + (u ? ' ' + u : '') +
                         '): it goes no further'
                       : ' (the ' + (s.k === 0 ? 'lower' : 'upper') + ' end of its range)';
    return text;
  }
  // Sets the input `v` to the grid value nearest x, as its slider does; returns what to say.
  function setInput(v, x) {
    var s = snapped(v, x), input = byName[v.name];
    if (input) { input.value = String(s.value); showValue(input); }
    values[v.name] = s.value;
    return {text: say(v, s), end: !!s.beyond};
  }
  function announce(results) {
    if (!said) return;
    said.textContent = results.map(function (r) { return r.text; }).join('; ');
    said.classList.toggle('at-end', results.some(function (r) { return r.end; }));
  }

  // The handles of the first frame (t = 0) with the current view.
  function makeHandles() {
    handles = [];
    if (!scene || !run || !run.vary || run.dimension > 2) return;
    var d = run.dimension, st = run.states[0], of = {};
    run.vary.forEach(function (v) {
      if (v.body !== 'scene' && st.bodies[v.body]) (of[v.body] = of[v.body] || []).push(v);
    });
    var kinematic = 0;
    run.bodies.forEach(function (b) {
      var list = of[b.name], s = st.bodies[b.name];
      if (!list || b.kind === 'half_plane') return;
      var pick = function (field) { return list.filter(function (v) { return v.field === field; }); };
      var box = d === 1 ? blockBox(b, s) : null;
      var centre = d === 1 ? box.centre : toCanvas(s.x[0], s.x[1]);
      var r = d === 1 ? (box.x1 - box.x0) / 2 : extentOf(b) * view.scale;
      var pos = pick('position'), vel = pick('v'), w = pick('w'), ang = pick('angle');
      if (pos.length) handles.push({kind: 'position', body: b.name, inputs: pos, knob: centre, centre: centre, r: r,
                                    box: box, s: s, b: b, per: view.scale});
      if (vel.length) {
        var at = d === 1 ? box.at : centre, v = d === 1 ? [s.v, 0] : s.v;
        handles.push({kind: 'velocity', body: b.name, inputs: vel, at: at, per: view.vscale,
                      knob: [at[0] + v[0] * view.vscale, at[1] - v[1] * view.vscale]});
      }
      if (w.length && d === 2) {
        var big = Math.max(Math.abs(w[0].lo), Math.abs(w[0].hi), 1e-12), R = Math.min(Math.max(r + 18, 30), 110);
        var per = 5 / big;  // radians of the dial's arc per rad/s: the largest |w| is 5 rad (286 degrees)
        var th = Math.PI / 2 + s.w * per;
        handles.push({kind: 'spin', body: b.name, inputs: w, centre: centre, R: R, per: per,
                      knob: [centre[0] + R * Math.cos(th), centre[1] - R * Math.sin(th)]});
      }
      if (ang.length && d === 2) {
        var Ra = Math.min(Math.max(r + 40, 50), 140);
        handles.push({kind: 'angle', body: b.name, inputs: ang, centre: centre, R: Ra, per: 1,
                      knob: [centre[0] + Ra * Math.cos(s.angle), centre[1] - Ra * Math.sin(s.angle)]});
      }
      kinematic += pos.length + vel.length + w.length + ang.length;
    });
    if (kinematic === 0) {  // a lesson whose bodies' inputs are masses only: a mass knob each, on
      // a short upright track beside the body, on its side away from the others (up: heavier)
      var centreOf = function (b) {
        var s = st.bodies[b.name];
        return d === 1 ? blockBox(b, s).centre : toCanvas(s.x[0], s.x[1]);
      };
      var moving = run.bodies.filter(function (b) { return !b.static && st.bodies[b.name]; });
      var middle = moving.reduce(function (m, b) { return m + centreOf(b)[0]; }, 0) / Math.max(1, moving.length);
      run.bodies.forEach(function (b) {
        var list = (of[b.name] || []).filter(function (v) { return v.field === 'mass'; });
        if (!list.length || b.kind === 'half_plane') return;
        var v = list[0], centre = centreOf(b), r = d === 1 ? (blockBox(b, st.bodies[b.name]).x1 - centre[0]) : extentOf(b) * view.scale;
        var ctx = scene.getContext('2d');
        ctx.font = '15px "DejaVu Sans", Arial, sans-serif';  // the name's label, right of the centre (drawBody)
        var right = Math.max(r + 26, 8 + ctx.measureText(b.name).width + 18);
        var len = 100, x = centre[0] + (centre[0] < middle ? -(r + 26) : right), y0 = centre[1] + len / 2;
        var f = (current(v) - v.lo) / (v.hi - v.lo);
        handles.push({kind: 'mass', body: b.name, inputs: list, x: x, y0: y0, len: len, per: len / (v.hi - v.lo),
                      knob: [x, y0 - f * len]});
      });
    }
    handles.forEach(function (h) { h.id = h.kind + ':' + h.body; });
  }

  function handleWords(h) {
    var names = h.inputs.map(function (v) { return v.name; }).join(' and ');
    var also = [];
    h.inputs.forEach(function (v) { (v.in_proportion || []).forEach(function (o) { if (also.indexOf(o) < 0) also.push(o); }); });
    var more = also.length ? ' (' + (also.length > 3 ? also.length + ' other bodies' : also.join(', ')) + ' in proportion)' : '';
    switch (h.kind) {
      case 'position': return h.body + ' itself (in a dashed outline) moves it: ' + names + more;
      case 'velocity': return 'the blue knob at the head of ' + h.body + '\u2019s velocity arrow: ' + names + more;
      case 'spin': return 'the amber knob on ' + h.body + '\u2019s spin dial, round the circle: ' + names + more;
      case 'angle': return 'the dark knob at the end of ' + h.body + '\u2019s turn handle: ' + names + more;
      default: return 'the dark knob on the short upright track (m) beside ' + h.body + ', up for heavier: ' + names + more;
    }
  }
  function showHelp() {
    if (!help) return;
    if (!handles.length) { help.hidden = true; return; }
    help.hidden = false;
    var draggable = {};
    handles.forEach(function (h) { h.inputs.forEach(function (v) { draggable[v.name] = true; }); });
    var others = run.vary.filter(function (v) { return !draggable[v.name]; }).map(function (v) { return v.name; });
    help.textContent = (atStart() ? 'Drag on the picture (paused at t = 0): '
                                  : 'Back at t = 0 (\u25c0\u25c0 t = 0), paused, drag on the picture: ') +
                       handles.map(handleWords).join('; ') + '. Each value snaps to its slider\u2019s step. ' +
                       'Keyboard: Tab to a handle, arrow keys for one step, Shift+arrow for ten.' +
                       (others.length ? ' The sliders set the rest (' + others.join(', ') + ').' : '');
  }

  // The handles on the canvas, in the colours of what they set.
  function knob(ctx, at, fill, focused) {
    ctx.beginPath(); ctx.arc(at[0], at[1], KNOB + (focused ? 3 : 0), 0, 2 * Math.PI);
    ctx.fillStyle = fill; ctx.fill();
    ctx.lineWidth = 2.5; ctx.strokeStyle = '#ffffff'; ctx.stroke();
    ctx.beginPath(); ctx.arc(at[0], at[1], KNOB + 2.5 + (focused ? 3 : 0), 0, 2 * Math.PI);
    ctx.lineWidth = focused ? 2.5 : 1.2; ctx.strokeStyle = palette.ink; ctx.stroke();
  }
  function drawHandles(ctx) {
    handles.forEach(function (h) {
      var hot = h.id === focusedId || h.id === hoverId || (drag && drag.h.id === h.id);
      ctx.save();
      if (h.kind === 'position') {
        // the outline a little outside the body, dashed
        ctx.strokeStyle = palette.ink; ctx.lineWidth = hot ? 3 : 2; ctx.setLineDash([7, 5]);
        ctx.beginPath();
        if (h.box) ctx.rect(h.box.x0 - 6, h.box.y0 - 6, h.box.x1 - h.box.x0 + 12, h.box.y1 - h.box.y0 + 12);
        else if (h.b.kind === 'polygon') {
          h.b.vertices.forEach(function (v, k) {
            var a = h.s.angle, len = Math.hypot(v[0], v[1]) * view.scale, f = len > 0 ? (len + 7) / len : 1;
            var x = (Math.cos(a) * v[0] - Math.sin(a) * v[1]) * view.scale * f;
            var y = (Math.sin(a) * v[0] + Math.cos(a) * v[1]) * view.scale * f;
            if (k === 0) ctx.moveTo(h.centre[0] + x, h.centre[1] - y); else ctx.lineTo(h.centre[0] + x, h.centre[1] - y);
          });
          ctx.closePath();
        } else ctx.arc(h.centre[0], h.centre[1], h.r + 7, 0, 2 * Math.PI);
        ctx.stroke();
        ctx.setLineDash([]);
        // the track of each coordinate that is an input: its range through the body's centre,
        // with the ends' values
        h.inputs.forEach(function (v) {
          var c = run.dimension === 1 || v.component === 0 ? 0 : 1, here = current(v), u = unitOf(v);
          var at = function (x) {
            return c === 0 ? [h.centre[0] + (x - here) * h.per, h.centre[1]] : [h.centre[0], h.centre[1] - (x - here) * h.per];
          };
          var a = at(v.lo), e = at(v.hi), tick = c === 0 ? [0, 7] : [7, 0];
          ctx.strokeStyle = palette.ink; ctx.lineWidth = 2.5; ctx.globalAlpha = 0.55;
          ctx.beginPath(); ctx.moveTo(a[0], a[1]); ctx.lineTo(e[0], e[1]);
          [a, e].forEach(function (p) { ctx.moveTo(p[0] - tick[0], p[1] - tick[1]); ctx.lineTo(p[0] + tick[0], p[1] + tick[1]); });
          ctx.stroke(); ctx.globalAlpha = 1;
          if (Math.hypot(e[0] - a[0], e[1] - a[1]) < 90) {  // short: one label beside it, "lo to hi"
            var mid = [(a[0] + e[0]) / 2, (a[1] + e[1]) / 2];
            label(ctx, num(v.lo) + ' to ' + num(v.hi) + (u ? ' ' + u : ''),
                  c === 0 ? [mid[0], mid[1] + h.r + 20] : [e[0] + 10, e[1] - 2], palette.muted, c === 0 ? 'center' : 'left');
          } else {
            [[a, v.lo], [e, v.hi]].forEach(function (q, k) {
              var off = c === 0 ? [0, 20] : [12, k === 0 ? 14 : -14];
              label(ctx, num(q[1]) + (k === 1 && u ? ' ' + u : ''), [q[0][0] + off[0], q[0][1] + off[1]], palette.muted,
                    c === 0 ? 'center' : 'left');
            });
          }
        });
        if (named && !named[h.body]) label(ctx, h.body, [h.centre[0] + h.r + 10, h.centre[1] - h.r - 6], palette.ink);
      } else if (h.kind === 'velocity') {
        knob(ctx, h.knob, palette.velocity, hot);
      } else if (h.kind === 'spin' || h.kind === 'angle') {
        ctx.setLineDash([4, 5]); ctx.lineWidth = 1.5;
        ctx.strokeStyle = h.kind === 'spin' ? palette.spin : palette.muted;
        ctx.beginPath();
        if (h.kind === 'spin') ctx.arc(h.centre[0], h.centre[1], h.R, 0, 2 * Math.PI);
        else { ctx.moveTo(h.centre[0], h.centre[1]); ctx.lineTo(h.knob[0], h.knob[1]); }
        ctx.stroke();
        ctx.setLineDash([]);
        if (h.kind === 'spin') {  // the arc from the top to the knob: w (counterclockwise positive)
          var w = current(h.inputs[0]), sweep = w * h.per;
          ctx.strokeStyle = palette.spin; ctx.lineWidth = 4;
          ctx.beginPath(); ctx.arc(h.centre[0], h.centre[1], h.R, -Math.PI / 2, -Math.PI / 2 - sweep, sweep > 0); ctx.stroke();
          label(ctx, '\u03c9', [h.centre[0], h.centre[1] - h.R - 12], palette.spin, 'center');
        }
        knob(ctx, h.knob, h.kind === 'spin' ? palette.spin : palette.ink, hot);
      } else {  // mass: a short upright track (its range, up: heavier), the knob at the value
        ctx.strokeStyle = palette.muted; ctx.lineWidth = 3;
        ctx.beginPath(); ctx.moveTo(h.x, h.y0); ctx.lineTo(h.x, h.y0 - h.len);
        ctx.moveTo(h.x - 6, h.y0); ctx.lineTo(h.x + 6, h.y0); ctx.moveTo(h.x - 6, h.y0 - h.len); ctx.lineTo(h.x + 6, h.y0 - h.len);
        ctx.stroke();
        label(ctx, 'm', [h.x, h.y0 - h.len - 12], palette.ink, 'center');
        knob(ctx, h.knob, palette.ink, hot);
      }
      ctx.restore();
    });
  }

  // A focusable element over each handle: Tab reaches it, the arrow keys set its inputs.
  var elements = {};
  function placeHandles() {
    if (!layer) return;
    var show = atStart(), keep = {};
    if (show) handles.forEach(function (h) {
      keep[h.id] = true;
      var el = elements[h.id];
      if (!el) {
        el = elements[h.id] = document.createElement('div');
        el.className = 'tryit-handle';
        el.tabIndex = 0;
        el.setAttribute('role', 'slider');
        el.dataset.handle = h.id;
        el.addEventListener('keydown', function (e) { keyStep(el.dataset.handle, e); });
        el.addEventListener('focus', function () { focusedId = el.dataset.handle; draw(); });
        el.addEventListener('blur', function () { if (focusedId === el.dataset.handle) { focusedId = null; draw(); } });
        layer.appendChild(el);
      }
      el.style.left = (100 * h.knob[0] / scene.width) + '%';
      el.style.top = (100 * h.knob[1] / scene.height) + '%';
      var words = h.inputs.map(function (v) { var u = unitOf(v); return v.name + ' = ' + num(current(v)) + (u ? ' ' + u : ''); });
      el.setAttribute('aria-label', handleWords(h));
      el.setAttribute('aria-valuetext', words.join(', '));
      el.setAttribute('aria-valuemin', h.inputs[0].lo);
      el.setAttribute('aria-valuemax', h.inputs[0].hi);
      el.setAttribute('aria-valuenow', current(h.inputs[0]));
    });
    Object.keys(elements).forEach(function (id) {
      if (keep[id]) return;
      if (document.activeElement === elements[id]) return;  // kept while it has the focus
      layer.removeChild(elements[id]);
      delete elements[id];
    });
    showHelp();
  }
  function handleById(id) { for (var k = 0; k < handles.length; ++k) if (handles[k].id === id) return handles[k]; return null; }

  // Keys: one step (Shift: ten); left / right set an x component or a single input, up / down a
  // y component or a single input; Home / End a single input's ends.
  function keyStep(id, e) {
    var h = handleById(id);
    if (!h || !atStart()) return;
    var dx = {ArrowRight: 1, ArrowLeft: -1}[e.key] || 0, dy = {ArrowUp: 1, ArrowDown: -1}[e.key] || 0;
    var ends = {Home: 'lo', End: 'hi'}[e.key];
    if (!dx && !dy && !ends) return;
    e.preventDefault();
    var n = e.shiftKey ? 10 : 1, results = [];
    h.inputs.forEach(function (v) {
      if (ends) { if (h.inputs.length === 1) results.push(setInput(v, v[ends])); return; }
      var sign = h.inputs.length === 1 ? dx || dy : v.component === 1 ? dy : dx;
      if (!sign) return;
      var k = snapped(v, current(v)).k + sign * n;  // from the grid value nearest the current one
      results.push(setInput(v, v.lo + k * v.step));
    });
    if (!results.length) return;
    announce(results);
    request();
  }

  // The pointer: a knob within reach, else a body whose position is an input.
  function canvasPoint(e) {
    var r = scene.getBoundingClientRect();
    return [(e.clientX - r.left) * scene.width / r.width, (e.clientY - r.top) * scene.height / r.height];
  }
  function inside(h, p) {
    if (h.box) return p[0] >= h.box.x0 - 6 && p[0] <= h.box.x1 + 6 && p[1] >= h.box.y0 - 6 && p[1] <= h.box.y1 + 6;
    var b = h.b, s = h.s;
    if (b.kind === 'polygon') {  // the body's outline, turned by its angle
      var q = [(p[0] - h.centre[0]) / view.scale, -(p[1] - h.centre[1]) / view.scale];
      var c = Math.cos(-s.angle), sn = Math.sin(-s.angle), x = c * q[0] - sn * q[1], y = sn * q[0] + c * q[1];
      var vs = b.vertices, inPoly = false;
      for (var i = 0, j = vs.length - 1; i < vs.length; j = i++)
        if ((vs[i][1] > y) !== (vs[j][1] > y) &&
            x < (vs[j][0] - vs[i][0]) * (y - vs[i][1]) / (vs[j][1] - vs[i][1]) + vs[i][0]) inPoly = !inPoly;
      return inPoly || Math.hypot(p[0] - h.centre[0], p[1] - h.centre[1]) <= 14;
    }
    return Math.hypot(p[0] - h.centre[0], p[1] - h.centre[1]) <= Math.max(h.r + 7, 14);
  }
  function hit(p, touch) {
    var reach = touch ? 24 : 15, best = null, bestD = Infinity;
    handles.forEach(function (h) {
      if (h.kind === 'position') return;
      var dd = Math.hypot(p[0] - h.knob[0], p[1] - h.knob[1]);
      if (dd <= reach && dd < bestD) { best = h; bestD = dd; }
    });
    if (best) return best;
    for (var k = handles.length - 1; k >= 0; --k)  // the body drawn last is on top
      if (handles[k].kind === 'position' && inside(handles[k], p)) return handles[k];
    return null;
  }
  function turnOf(h, p) { return Math.atan2(-(p[1] - h.centre[1]), p[0] - h.centre[0]); }
  function dragTo(p) {
    var h = drag.h, results = [];
    if (h.kind === 'spin' || h.kind === 'angle') {
      var a = turnOf(h, [p[0] - drag.grab[0], p[1] - drag.grab[1]]);
      while (a - drag.a > Math.PI) a -= 2 * Math.PI;  // continuous round the circle
      while (a - drag.a < -Math.PI) a += 2 * Math.PI;
      drag.a = a;
      results.push(setInput(h.inputs[0], drag.start[0] + (a - drag.a0) / h.per));
    } else {
      h.inputs.forEach(function (v, k) {
        var delta = h.kind !== 'mass' && (run.dimension === 1 || v.component === 0) ? p[0] - drag.p0[0] : -(p[1] - drag.p0[1]);
        results.push(setInput(v, drag.start[k] + delta / h.per));
      });
    }
    announce(results);
    request();
  }
  if (scene) {
    scene.addEventListener('pointerdown', function (e) {
      if (!atStart() || drag || (e.pointerType === 'mouse' && e.button !== 0)) return;
      var p = canvasPoint(e), h = hit(p, e.pointerType === 'touch');
      if (!h) return;
      e.preventDefault();
      scene.setPointerCapture(e.pointerId);
      drag = {h: h, id: e.pointerId, p0: p, start: h.inputs.map(current), grab: [p[0] - h.knob[0], p[1] - h.knob[1]]};
      if (h.centre) drag.a = drag.a0 = turnOf(h, h.knob);
      scene.style.cursor = 'grabbing';
      draw();
    });
    scene.addEventListener('pointermove', function (e) {
      if (drag) { if (e.pointerId === drag.id) dragTo(canvasPoint(e)); return; }
      var h = atStart() ? hit(canvasPoint(e), e.pointerType === 'touch') : null, id = h ? h.id : null;
      scene.style.cursor = h ? 'grab' : '';
      if (id !== hoverId) { hoverId = id; draw(); }
    });
    var end = function (e) {
      if (!drag || e.pointerId !== drag.id) return;
      drag = null;
      scene.style.cursor = 'grab';
      if (run) { prepare(); makeHandles(); draw(); }  // the picture fitted to the new run
    };
    scene.addEventListener('pointerup', end);
    scene.addEventListener('pointercancel', end);
    scene.addEventListener('pointerleave', function () { if (!drag && hoverId) { hoverId = null; draw(); } });
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

  CollideEngine().then(function (m) {
    engine = m;
    answer();
    if (window.location.hash === '#try-it') panel.scrollIntoView();
  }, function (e) {
    status.textContent = 'The engine did not start: ' + e;
  });
})();
