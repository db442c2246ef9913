// The Try-it panel (try-it.js): the picture. A light 1D / 2D drawing of the run's states in the
// figures' colours (render/style.h, given as the page's palette), fitted to the run, with the
// velocities, spins and each collision's impulse and normal, and the plot of the energies.
// Loaded before try-it.js, which calls this part with the panel's shared state `lab` (try-it.js).
(window.collideTryItParts = window.collideTryItParts || {}).picture = function (lab) {
  'use strict';
  var panel = lab.panel, scene = lab.scene, plot = lab.plot, palette = lab.palette, num = lab.num, vec = lab.vec;
  // ---- Drawing: world to canvas ----
  var view = null;  // {scale, ox, oy}: canvas x = ox + scale x, y = oy - scale y
  var refit = true;  // the next run fits the picture afresh (prepare)
  function bodyState(k, name) { return lab.run.states[k].bodies[name]; }
  function extentOf(b) {  // the body's size from its centre (m)
    if (lab.run.dimension === 1) return b.length / 2;
    if (b.kind === 'disc') return b.radius;
    if (b.kind === 'polygon') return Math.max.apply(null, b.vertices.map(function (p) { return Math.hypot(p[0], p[1]); }));
    return 0;
  }
  function prepare() {
    if (!scene) return;
    var lo = [Infinity, Infinity], hi = [-Infinity, -Infinity];
    lab.run.states.forEach(function (st) {
      lab.run.bodies.forEach(function (b) {
        var s = st.bodies[b.name];
        if (!s || b.kind === 'half_plane') return;
        var r = extentOf(b), x = lab.run.dimension === 1 ? [s.x, 0] : s.x;
        lo[0] = Math.min(lo[0], x[0] - r); hi[0] = Math.max(hi[0], x[0] + r);
        lo[1] = Math.min(lo[1], x[1] - r); hi[1] = Math.max(hi[1], x[1] + r);
      });
    });
    // A static body without a state (1D walls have one; 2D half planes do not): its line in view.
    lab.run.bodies.forEach(function (b) {
      if (b.kind !== 'half_plane') return;
      var c = [(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2];
      var dist = b.normal[0] * c[0] + b.normal[1] * c[1] - b.offset;
      var p = [c[0] - dist * b.normal[0], c[1] - dist * b.normal[1]];
      lo[0] = Math.min(lo[0], p[0]); hi[0] = Math.max(hi[0], p[0]);
      lo[1] = Math.min(lo[1], p[1]); hi[1] = Math.max(hi[1], p[1]);
    });
    // Above the scene: the legend, at most three rows (drawScene).
    var moving = lab.run.bodies.filter(function (b) { return !b.static; }).length;
    var W = scene.width, H = scene.height, top = moving > 2 ? 84 : 70, margin = 40;
    var w = Math.max(hi[0] - lo[0], 1e-3), h = Math.max(hi[1] - lo[1], 1e-3);
    var scale = lab.run.dimension === 1 ? (W - 2 * margin) / w : Math.min((W - 2 * margin) / w, (H - top - margin) / h);
    var ox = W / 2 - scale * (lo[0] + hi[0]) / 2;
    var oy = lab.run.dimension === 1 ? H * 0.72 : top + (H - top - margin) / 2 + scale * (lo[1] + hi[1]) / 2;
    // Arrows: the fastest speed of the run is 0.16 of the picture, the largest impulse 0.14.
    var vmax = 1e-12, pmax = 1e-12;
    lab.run.states.forEach(function (st) {
      Object.keys(st.bodies).forEach(function (n) { vmax = Math.max(vmax, norm(st.bodies[n].v)); });
    });
    lab.run.events.forEach(function (e) { pmax = Math.max(pmax, norm(e.impulse)); });
    var size = Math.min(W, lab.run.dimension === 1 ? 2 * H : H), vscale = 0.16 * size / vmax;
    // Once fitted, the picture keeps its scales while the new run fits in it and its arrows stay
    // short enough: a body dragged stays where it was let go, and an arrow made longer is longer
    // (one scale before and after, to compare). "The lesson's values" fits it afresh.
    if (view && !refit) {
      var fits = true;
      [lo, hi].forEach(function (p) {
        var c = [view.ox + view.scale * p[0], view.oy - view.scale * p[1]];
        if (c[0] < 4 || c[0] > W - 4 || (lab.run.dimension > 1 && (c[1] < top - 30 || c[1] > H - 4))) fits = false;
      });
      if (fits) { scale = view.scale; ox = view.ox; oy = view.oy; }
      if (view.vscale * vmax <= 0.3 * size) vscale = view.vscale;
    }
    refit = false;
    view = {scale: scale, ox: ox, oy: oy, vscale: vscale, pscale: 0.14 * size / pmax};
    // (on the panel: canvas pixels per metre and per m/s, for the browser test's drags)
    lab.view = view;
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
  // (the font set once per canvas: setting it again, even to the same, took more than drawing)
  function useFont(ctx) {
    var key = ctx.canvas.width + 'x' + ctx.canvas.height;  // a canvas resized forgets its font
    if (ctx.collideFont !== key) { ctx.font = '15px "DejaVu Sans", Arial, sans-serif'; ctx.collideFont = key; }
  }
  // A label with a white halo that keeps it legible over lines: the text filled white at eight
  // offsets 2 px round it, then in its colour (Chromium's strokeText, the usual halo, took 1.4 ms a
  // label on the page's canvas, a hundred times fillText: most of a slider move's drawing).
  var HALO = [[2, 0], [-2, 0], [0, 2], [0, -2], [1.4, 1.4], [-1.4, 1.4], [1.4, -1.4], [-1.4, -1.4]];
  function label(ctx, textValue, at, colour, align) {
    useFont(ctx);
    ctx.textAlign = align || 'left'; ctx.textBaseline = 'middle';
    ctx.fillStyle = 'rgba(255,255,255,0.6)';
    for (var k = 0; k < HALO.length; ++k) ctx.fillText(textValue, at[0] + HALO[k][0], at[1] + HALO[k][1]);
    ctx.fillStyle = colour; ctx.fillText(textValue, at[0], at[1]);
  }
  // Colour by the order among moving bodies, as the figures (render/diagram_draw.cpp).
  function fillOf(i) {
    var b = lab.run.bodies[i];
    if (b.static) return palette.static_fill;
    var order = 0;
    for (var j = 0; j < i; ++j) order += lab.run.bodies[j].static ? 0 : 1;
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
    var b = lab.run.bodies[i], d = lab.run.dimension;
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

  function drawScene(st) {
    var ctx = scene.getContext('2d'), d = lab.run.dimension, W = scene.width, H = scene.height;
    ctx.fillStyle = palette.background; ctx.fillRect(0, 0, W, H);
    if (d === 1) {  // the x axis the blocks stand on, with its positive direction
      ctx.strokeStyle = palette.ink; ctx.lineWidth = 2;
      ctx.beginPath(); ctx.moveTo(10, view.oy); ctx.lineTo(W - 20, view.oy); ctx.stroke();
      arrow(ctx, [W - 40, view.oy], [W - 10, view.oy], palette.ink, 2);
      label(ctx, 'x', [W - 18, view.oy + 16], palette.ink, 'center');
    }
    var legend = [], last = null;
    lab.run.events.forEach(function (e) { if (e.t <= st.t + 1e-12) last = e; });
    var moving = lab.run.bodies.filter(function (b) { return !b.static; });
    named = null;
    if (moving.length > 3) {
      named = {};
      named[moving[0].name] = named[moving[moving.length - 1].name] = true;
      if (last) named[last.a] = named[last.b] = true;
      else named[moving[1].name] = true;  // the legend's first two
    }
    lab.named = named;
    var dials = {};  // bodies whose spin the start's dial shows (instead of the arc)
    if (lab.handles.atStart()) lab.handles.list().forEach(function (h) { if (h.kind === 'spin') dials[h.body] = true; });
    lab.run.bodies.forEach(function (b, i) {
      var s = st.bodies[b.name];
      if (!s && b.kind !== 'half_plane') return;
      var at = drawBody(ctx, i, s, dials[b.name]);
      if (!at || b.static) return;
      var v = d === 1 ? [s.v, 0] : s.v;  // the velocity: a blue arrow from the centre (1D: above the block)
      arrow(ctx, at, [at[0] + v[0] * view.vscale, at[1] - v[1] * view.vscale], palette.velocity, 3);
      legend.push({i: i, text: b.name + ':  v = ' + vec(s.v) + ' m/s' + (d > 1 ? ',  \u03c9 = ' + num(s.w) + ' rad/s' : '')});
    });
    // Each collision of the last 0.15 s: the impulse on b (red) at the contact point, the normal (teal).
    lab.run.events.forEach(function (e) {
      if (e.t > st.t + 1e-12 || e.t < st.t - 0.15) return;
      var p = d === 1 ? toCanvas(e.point, 0) : toCanvas(e.point[0], e.point[1]);
      if (d === 1) p[1] -= 150;  // above the blocks and their velocity arrows
      var P = d === 1 ? [e.impulse, 0] : e.impulse, n = d === 1 ? [e.normal, 0] : e.normal;
      if (d > 1) arrow(ctx, p, [p[0] + n[0] * 60, p[1] - n[1] * 60], palette.normal, 2.5);  // 1D: n is +x
      arrow(ctx, p, [p[0] + P[0] * view.pscale, p[1] - P[1] * view.pscale], palette.impulse, 3.5);
      label(ctx, 'P = ' + vec(e.impulse) + ' N\u00b7s on ' + e.b, [p[0] + 10, p[1] - 20], palette.impulse);
    });
    drawLegend(ctx, legend, last);
    label(ctx, 't = ' + st.t.toFixed(3) + ' s', [W - 12, 19], palette.muted, 'right');
    if (lab.handles.atStart()) lab.handles.draw(ctx);
  }

  // The legend above the scene (`legend`: {i, text} a moving body; `last`: the latest collision
  // so far), three rows at most (a row of dominoes would cover them): with more moving bodies,
  // the two of the latest collision (else the first two) and a row that says how many are left out.
  function drawLegend(ctx, legend, last) {
    var rows = legend, others = 0;
    if (legend.length > 3) {
      rows = legend.filter(function (l) {
        var n = lab.run.bodies[l.i].name;
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
  }

  // The energies against time, as the page's plot (kinetic; with gravity potential and total),
  // faint red lines at the collisions, the current time in grey.
  function drawPlot(t) {
    var ctx = plot.getContext('2d'), W = plot.width, H = plot.height, l = 70, r = 20, top = 30, bottom = 30;
    ctx.fillStyle = '#ffffff'; ctx.fillRect(0, 0, W, H);
    var g = lab.run.gravity.some(function (x) { return x !== 0; });
    var series = [{name: 'kinetic', colour: '#1d4ed8', f: function (s) { return s.kinetic_energy; }}];
    if (g) {
      series.push({name: 'potential', colour: '#0f766e', f: function (s) { return s.potential_energy; }});
      series.push({name: 'total', colour: '#1c1c1e', f: function (s) { return s.kinetic_energy + s.potential_energy; }});
    }
    var lo = Infinity, hi = -Infinity;
    series.forEach(function (sr) { lab.run.states.forEach(function (s) { var y = sr.f(s); lo = Math.min(lo, y); hi = Math.max(hi, y); }); });
    lo = Math.min(lo, 0);  // from zero, so that a loss looks as large as it is
    if (hi - lo < 1e-9) hi = lo + 1;
    var X = function (x) { return l + (W - l - r) * x / lab.run.duration; };
    var Y = function (y) { return H - bottom - (H - top - bottom) * (y - lo) / (hi - lo); };
    ctx.strokeStyle = 'rgba(206,32,41,0.35)'; ctx.lineWidth = 1;
    lab.run.events.forEach(function (e) { ctx.beginPath(); ctx.moveTo(X(e.t), top); ctx.lineTo(X(e.t), H - bottom); ctx.stroke(); });
    ctx.strokeStyle = palette.grid; ctx.strokeRect(l, top, W - l - r, H - top - bottom);
    series.forEach(function (sr, k) {
      ctx.strokeStyle = sr.colour; ctx.lineWidth = 2; ctx.beginPath();
      lab.run.states.forEach(function (s, i) { if (i === 0) ctx.moveTo(X(s.t), Y(sr.f(s))); else ctx.lineTo(X(s.t), Y(sr.f(s))); });
      ctx.stroke();
      label(ctx, sr.name, [l + 10 + k * 110, 14], sr.colour);
    });
    label(ctx, 'Energy (J)', [W - r, 14], palette.ink, 'right');
    label(ctx, num(hi), [l - 6, top], palette.muted, 'right');
    label(ctx, num(lo), [l - 6, H - bottom], palette.muted, 'right');
    label(ctx, '0', [l, H - bottom + 14], palette.muted, 'center');
    label(ctx, num(lab.run.duration) + ' s', [W - r, H - bottom + 14], palette.muted, 'right');
    ctx.strokeStyle = palette.muted; ctx.lineWidth = 1.5;
    ctx.beginPath(); ctx.moveTo(X(t), top); ctx.lineTo(X(t), H - bottom); ctx.stroke();
  }

  return {
    prepare: prepare,
    refit: function () { refit = true; },
    drawScene: drawScene,
    drawPlot: drawPlot,
    toCanvas: toCanvas,
    blockBox: blockBox,
    extentOf: extentOf,
    label: label,
    useFont: useFont,
    arrow: arrow,
    fillOf: fillOf,
    drawLegend: drawLegend
  };
};
