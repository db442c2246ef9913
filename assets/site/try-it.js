// The Try-it panel of a lesson page (teach/html.h try_it_html; docs/commands/material.md, "The Try-it panel").
// The engine itself answers: collide-engine.js (wasm/) runs the lesson with the panel's values
// and returns the run (states at the page's frame rate, events), the page's collision worked
// out (the same HTML as the page's worked example) and `collide solve --format json`'s numbers
// for it. This script only draws what it gets: a light 1D / 2D picture in the figures' colours
// (render/style.h, given as the page's palette), a plot of the energies, and the numbers; the
// lesson's own [[plot]]s come drawn by the engine (the SVG, alt text and folded table that
// `collide material` writes on the page), and are put in as they are.
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
  var reset = panel.querySelector('.tryit-reset');
  if (reset) reset.addEventListener('click', function () {
    values = {};
    inputs.forEach(function (input) { input.value = input.dataset.lesson; showValue(input); });
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
    var changed = Object.keys(values);
    status.textContent = (changed.length ? 'With ' + changed.map(function (k) { return k + ' = ' + num(values[k]); }).join(', ')
                                          : 'With the lesson\u2019s own values') +
                         ': answered by the engine in ' + (ms < 1 ? 'under 1' : ms.toFixed(0)) + ' ms.';
    prepare();
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
            escapeHtml(JSON.stringify(s.impulse)) + '">P = ' + vec(s.impulse) + ' N\u00b7s</output>' +
            (d > 1 ? ', j = P\u00b7n = <output class="tryit-normal-impulse" data-value="' + s.normal_impulse + '">' +
                     num(s.normal_impulse) + ' N\u00b7s</output>' : '') + '.</p>\n';
    h += '<table><tr><th>body</th><th>v after (m/s)</th>' + (d > 1 ? '<th>\u03c9 after (rad/s)</th>' : '') + '</tr>';
    [['a', w.a], ['b', w.b]].forEach(function (p) {
      h += '<tr><td>' + escapeHtml(p[1]) + '</td><td>' + vec(s[p[0]].v) + '</td>' +
           (d > 1 ? '<td>' + spin(s[p[0]].w) + '</td>' : '') + '</tr>';
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
                                   '<td rowspan="2">' + num(f.t) + '</td><td rowspan="2">' + vec(r.impulse) + '</td>' : '') +
               '<td>' + escapeHtml(p[1]) + '</td><td>' + vec(r[p[0]].v) + '</td>' +
               (d > 1 ? '<td>' + spin(r[p[0]].w) + '</td>' : '') + '</tr>';
        });
      });
      h += '</table>';
    }
    numbers.innerHTML = h;
  }

  // ---- Drawing: world to canvas ----
  var view = null;  // {scale, ox, oy}: canvas x = ox + scale x, y = oy - scale y
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
    var size = Math.min(W, run.dimension === 1 ? 2 * H : H);
    view = {scale: scale, ox: ox, oy: oy, vscale: 0.16 * size / vmax, pscale: 0.14 * size / pmax};
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
  function drawBody(ctx, i, s) {
    var b = run.bodies[i], d = run.dimension;
    ctx.fillStyle = fillOf(i); ctx.strokeStyle = palette.ink; ctx.lineWidth = 2;
    if (d === 1) {
      var w = b.length * view.scale, h = Math.max(28, Math.min(w, 110));
      var c = toCanvas(s.x, 0);
      ctx.fillRect(c[0] - w / 2, c[1] - h, w, h); ctx.strokeRect(c[0] - w / 2, c[1] - h, w, h);
      label(ctx, b.name, [c[0], c[1] - h / 2], palette.ink, 'center');
      return [c[0], c[1] - h - 14];
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
    if (Math.abs(s.w) > 1e-9) {  // the spin: an amber arc, its head in the turning direction
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
    run.bodies.forEach(function (b, i) {
      var s = st.bodies[b.name];
      if (!s && b.kind !== 'half_plane') return;
      var at = drawBody(ctx, i, s);
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
      } else if (b.dataset.act === 'play') {
        playing = !playing;
        if (playing) { clock = frame / fps; last = null; window.requestAnimationFrame(tick); }
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
