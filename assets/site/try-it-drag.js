// The Try-it panel (try-it.js): drag to set.
// Each handle sets one or two of the lesson's [[vary]] inputs (run.vary: name, lo, hi, step,
// body, field, component): a body whose position is an input (a dashed outline; along a
// track where one coordinate is), the head of a velocity arrow (a blue knob: the components
// that are inputs, the others stay), a spin dial (an amber knob on a circle: the arc from the
// top is w, counterclockwise positive), a turn handle (the body's angle), and only where a
// lesson has none of these, a body's mass knob on a short upright track beside it. A drag or a key sets
// each input to the nearest value of its grid, lo + k step (as the slider and the worksheets:
// scenario/lesson.h LessonVary::value), never beyond lo or hi (and says so), through the
// slider: its value, the number beside it, the address, and one answer a frame.
// In 3D the view (try-it-3d.js, lab.picture there) makes the handles (handles3d): knobs only,
// each with the words that say what it sets and valuesAt(p), the inputs' values where the
// pointer is; this part drags them, snaps, says and takes the keys as for the others.
// Loaded before try-it.js, which calls this part with the panel's shared state `lab` (try-it.js).
(window.collideTryItParts = window.collideTryItParts || {}).handles = function (lab) {
  'use strict';
  var panel = lab.panel, scene = lab.scene, palette = lab.palette, num = lab.num, byName = lab.byName;
  var valueOf = lab.valueOf, showValue = lab.showValue, request = lab.request, draw = lab.draw;
  var picture = lab.picture, prepare = picture.prepare, toCanvas = picture.toCanvas, blockBox = picture.blockBox;
  var extentOf = picture.extentOf, label = picture.label;
  var layer = panel.querySelector('.tryit-handles');
  var help = panel.querySelector('.tryit-drag-help');
  var said = panel.querySelector('.tryit-drag-said');
  var handles = [];  // of the latest answer's first frame (makeHandles)
  var drag = null;   // the drag under way: {h, id, p0, start, a0, a}
  var focusedId = null, hoverId = null;
  var KNOB = 9;  // a knob's radius on the canvas (px)

  function atStart() { return !!lab.run && lab.frame === 0 && !lab.playing && handles.length > 0; }
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
    lab.values[v.name] = s.value;  // (before showValue, which shows it)
    if (input) { input.value = String(s.value); showValue(input); }
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
    if (!scene || !lab.run || !lab.run.vary) return;
    if (lab.run.dimension > 2) {
      handles = picture.handles3d ? picture.handles3d() : [];
      handles.forEach(function (h) { h.id = h.kind + ':' + h.body; });
      return;
    }
    var d = lab.run.dimension, st = lab.run.states[0], of = {};
    lab.run.vary.forEach(function (v) {
      if (v.body !== 'scene' && st.bodies[v.body]) (of[v.body] = of[v.body] || []).push(v);
    });
    var kinematic = 0;
    lab.run.bodies.forEach(function (b) {
      var list = of[b.name], s = st.bodies[b.name];
      if (!list || b.kind === 'half_plane') return;
      var pick = function (field) { return list.filter(function (v) { return v.field === field; }); };
      var box = d === 1 ? blockBox(b, s) : null;
      var centre = d === 1 ? box.centre : toCanvas(s.x[0], s.x[1]);
      var r = d === 1 ? (box.x1 - box.x0) / 2 : extentOf(b) * lab.view.scale;
      var pos = pick('position'), vel = pick('v'), w = pick('w'), ang = pick('angle');
      if (pos.length) handles.push({kind: 'position', body: b.name, inputs: pos, knob: centre, centre: centre, r: r,
                                    box: box, s: s, b: b, per: lab.view.scale});
      if (vel.length) {
        var at = d === 1 ? box.at : centre, v = d === 1 ? [s.v, 0] : s.v;
        handles.push({kind: 'velocity', body: b.name, inputs: vel, at: at, per: lab.view.vscale,
                      knob: [at[0] + v[0] * lab.view.vscale, at[1] - v[1] * lab.view.vscale]});
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
      var moving = lab.run.bodies.filter(function (b) { return !b.static && st.bodies[b.name]; });
      var middle = moving.reduce(function (m, b) { return m + centreOf(b)[0]; }, 0) / Math.max(1, moving.length);
      lab.run.bodies.forEach(function (b) {
        var list = (of[b.name] || []).filter(function (v) { return v.field === 'mass'; });
        if (!list.length || b.kind === 'half_plane') return;
        var v = list[0], centre = centreOf(b), r = d === 1 ? (blockBox(b, st.bodies[b.name]).x1 - centre[0]) : extentOf(b) * lab.view.scale;
        var ctx = scene.getContext('2d');
        lab.picture.useFont(ctx);  // the name's label, right of the centre (drawBody)
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
    if (h.words) return h.words + ': ' + names + more;
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
    var others = lab.run.vary.filter(function (v) { return !draggable[v.name]; }).map(function (v) { return v.name; });
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
      if (h.knobOnly) {  // 3D: the view draws the rest
        knob(ctx, h.knob, h.colour, hot);
      } else if (h.kind === 'position') {
        // the outline a little outside the body, dashed
        ctx.strokeStyle = palette.ink; ctx.lineWidth = hot ? 3 : 2; ctx.setLineDash([7, 5]);
        ctx.beginPath();
        if (h.box) ctx.rect(h.box.x0 - 6, h.box.y0 - 6, h.box.x1 - h.box.x0 + 12, h.box.y1 - h.box.y0 + 12);
        else if (h.b.kind === 'polygon') {
          h.b.vertices.forEach(function (v, k) {
            var a = h.s.angle, len = Math.hypot(v[0], v[1]) * lab.view.scale, f = len > 0 ? (len + 7) / len : 1;
            var x = (Math.cos(a) * v[0] - Math.sin(a) * v[1]) * lab.view.scale * f;
            var y = (Math.sin(a) * v[0] + Math.cos(a) * v[1]) * lab.view.scale * f;
            if (k === 0) ctx.moveTo(h.centre[0] + x, h.centre[1] - y); else ctx.lineTo(h.centre[0] + x, h.centre[1] - y);
          });
          ctx.closePath();
        } else ctx.arc(h.centre[0], h.centre[1], h.r + 7, 0, 2 * Math.PI);
        ctx.stroke();
        ctx.setLineDash([]);
        // the track of each coordinate that is an input: its range through the body's centre,
        // with the ends' values
        h.inputs.forEach(function (v) {
          var c = lab.run.dimension === 1 || v.component === 0 ? 0 : 1, here = current(v), u = unitOf(v);
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
        if (lab.named && !lab.named[h.body]) label(ctx, h.body, [h.centre[0] + h.r + 10, h.centre[1] - h.r - 6], palette.ink);
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
      if (h.grid) el.dataset.grid = JSON.stringify(h.grid);  // 3D: the knob's place at each grid value (canvas px)
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
      var q = [(p[0] - h.centre[0]) / lab.view.scale, -(p[1] - h.centre[1]) / lab.view.scale];
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
      if (h.kind === 'position' && !h.knobOnly) return;
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
    if (h.valuesAt) {  // 3D: where the knob is let go, in the inputs' values
      var x = h.valuesAt([p[0] - drag.grab[0], p[1] - drag.grab[1]]);
      h.inputs.forEach(function (v, k) { results.push(setInput(v, x[k])); });
    } else if (h.kind === 'spin' || h.kind === 'angle') {
      var a = turnOf(h, [p[0] - drag.grab[0], p[1] - drag.grab[1]]);
      while (a - drag.a > Math.PI) a -= 2 * Math.PI;  // continuous round the circle
      while (a - drag.a < -Math.PI) a += 2 * Math.PI;
      drag.a = a;
      results.push(setInput(h.inputs[0], drag.start[0] + (a - drag.a0) / h.per));
    } else {
      h.inputs.forEach(function (v, k) {
        var delta = h.kind !== 'mass' && (lab.run.dimension === 1 || v.component === 0) ? p[0] - drag.p0[0] : -(p[1] - drag.p0[1]);
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
      if (lab.run) { prepare(); makeHandles(); draw(); }  // the picture fitted to the new run
    };
    scene.addEventListener('pointerup', end);
    scene.addEventListener('pointercancel', end);
    scene.addEventListener('pointerleave', function () { if (!drag && hoverId) { hoverId = null; draw(); } });
  }

  return {
    atStart: atStart,
    list: function () { return handles; },
    dragging: function () { return !!drag; },
    make: makeHandles,
    draw: drawHandles,
    place: placeHandles
  };
};
