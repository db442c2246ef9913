// The Try-it panel (try-it.js): the 3D view, drawn with three.js (three.min.js beside the pages,
// from Debian's libjs-three: `collide material` copies it; no network). The run's bodies to scale
// (run.bodies: a box's half extents, a sphere's radius, a half space's normal and offset) at each
// frame's centre and orientation, in the figures' colours with their edges outlined; the ground;
// the velocities (blue arrows), the spins (amber: omega as an arrow along the axis, a curl round
// it in the turning sense, right hand), each collision's impulse on b (red) at the contact point
// and its normal (teal); over it a 2D canvas (the panel's `scene`) with the names, the legend,
// the time and the drag handles' knobs. A camera that orbits (drag, wheel, pinch, keys); buttons
// to the next collision and to the frames before, the instant of and after the page's collision.
// The drag handles (handles3d) are try-it-drag.js's, given here as knobs with the inputs' values
// where the pointer is: a velocity or spin arrow's head, a body's centre along a track.
// Loaded before try-it.js, which calls it with the panel's shared state `lab` and the flat
// picture (try-it-picture.js), whose plot, labels, arrows' 2D drawing and colours it keeps.
(window.collideTryItParts = window.collideTryItParts || {}).view3d = function (lab, flat) {
  'use strict';
  var panel = lab.panel, overlay = lab.scene, palette = lab.palette, num = lab.num, vec = lab.vec;
  var canvas = panel.querySelector('canvas.tryit-scene3d'), stage = overlay.parentNode;
  var self = Object.create(flat);  // the plot and the rest as the flat picture; the scene here
  var THREE = null, gl = null, view = null, refit = true, orbit = null;
  var FOV = 30;  // degrees, vertical: as the figures' camera (render/camera.h kFovY)
  var mode = null, caption = null;  // a jump's: 'before' | 'at' | 'after' | 'next', and its words

  // ---- Nothing drawn without three.js or WebGL: said where the picture would be ----
  function unavailable(why) {
    var p = document.createElement('p');
    p.className = 'tryit-3d-missing';
    p.setAttribute('role', 'alert');
    p.textContent = why + ' The numbers, the worked example and the plot below are the engine\u2019s all the same.';
    stage.parentNode.insertBefore(p, stage);
    stage.hidden = true;
    panel.dataset.view3d = 'missing';
  }
  // three.js is read after the page has shown its first answer (850 KB of script that the
  // numbers need not wait for): try-it.js loads three.min.js and calls start when it has
  // loaded, or missing when it has not. Until then the picture is blank.
  self.missing = function () {
    unavailable('The 3D view needs three.js: the file three.min.js beside the lesson pages did not load. ' +
                'The command collide material copies it there from Debian\u2019s libjs-three (apt-get install libjs-three, ' +
                'then build the site again).');
  };
  self.start = function () {  // whether there is a 3D view to draw
    THREE = window.THREE;
    if (!THREE) { self.missing(); return false; }
    try {
      gl = {renderer: new THREE.WebGLRenderer({canvas: canvas, antialias: true, preserveDrawingBuffer: true})};
      gl.renderer.setPixelRatio(1);
      gl.renderer.setSize(canvas.width, canvas.height, false);
      gl.renderer.setClearColor(new THREE.Color(palette.background), 1);
    } catch (e) {
      gl = null;
      unavailable('This browser gives the page no WebGL, which the 3D view needs (' + e.message + ').');
      return false;
    }
    controls();
    jumps();
    return true;
  };
  // three.js renamed its geometries (BoxBufferGeometry in r111, BoxGeometry later): either.
  function geometry(name) { return THREE[name + 'BufferGeometry'] || THREE[name + 'Geometry']; }
  function V(a) { return new THREE.Vector3(a[0], a[1], a[2]); }
  function Q(q) { return new THREE.Quaternion(q[1], q[2], q[3], q[0]); }  // the run's (w, x, y, z)
  function colour(c) { return new THREE.Color(c); }

  // ---- The scene: a mesh a body, arrows made as needed ----
  function bodyMesh(b, i) {
    // The outlines as the figures' 3D ones: the fill's darker hue (render/style.h Palette darks).
    var fill = flat.fillOf(i), k = palette.fills.indexOf(fill), group = new THREE.Group(), geo;
    var ink = colour(k >= 0 && palette.darks ? palette.darks[k] : palette.ink);
    var face = new THREE.MeshLambertMaterial({color: colour(fill), polygonOffset: true, polygonOffsetFactor: 1,
                                              polygonOffsetUnits: 1, side: THREE.DoubleSide});
    var line = new THREE.LineBasicMaterial({color: ink});
    if (b.kind === 'box') {
      geo = new (geometry('Box'))(2 * b.half[0], 2 * b.half[1], 2 * b.half[2]);
      group.add(new THREE.Mesh(geo, face), new THREE.LineSegments(new THREE.EdgesGeometry(geo), line));
      group.children[0].castShadow = true;
    } else if (b.kind === 'sphere') {
      group.add(new THREE.Mesh(new (geometry('Sphere'))(b.radius, 32, 20), face));
      group.children[0].castShadow = true;
      [[0, 1], [1, 2], [2, 0]].forEach(function (ax) {  // three great circles: the ball's turning shows
        var pts = [];
        for (var k = 0; k <= 64; ++k) {
          var p = [0, 0, 0], a = 2 * Math.PI * k / 64;
          p[ax[0]] = 1.003 * b.radius * Math.cos(a); p[ax[1]] = 1.003 * b.radius * Math.sin(a);
          pts.push(V(p));
        }
        group.add(new THREE.Line(new THREE.BufferGeometry().setFromPoints(pts), line));
      });
    } else if (b.kind === 'half_space') {  // sized and placed by prepare (the run's extent)
      face.color = colour(palette.static_fill);
      face.polygonOffsetFactor = 2; face.polygonOffsetUnits = 2;
      group.add(new THREE.Mesh(new (geometry('Plane'))(1, 1), face));
      group.add(new THREE.GridHelper(1, 20, colour(palette.muted), colour('#b4b4b0')));
      group.children[0].receiveShadow = true;
      group.children[1].rotation.x = Math.PI / 2;  // the grid's plane (xz) as the mesh's (xy)
      group.children[1].position.z = 1e-3;
    }
    return group;
  }
  var materials = {};
  function material(c) {  // an arrow's: over the bodies, as in 2D
    return materials[c] = materials[c] || new THREE.MeshBasicMaterial({color: colour(c), depthTest: false});
  }
  function makeArrow(c) {
    var m = material(c), g = new THREE.Group();
    g.add(new THREE.Mesh(new (geometry('Cylinder'))(1, 1, 1, 12), m), new THREE.Mesh(new (geometry('Cone'))(1, 1, 16), m));
    g.renderOrder = g.children[0].renderOrder = g.children[1].renderOrder = 10;  // over the bodies, as in 2D
    gl.scene.add(g);
    return g;
  }
  var Y = null;
  // An arrow from `from` along `d` (world vectors): a shaft and a cone, `thick` the shaft's radius.
  function setArrow(g, from, d, thick) {
    var len = d.length();
    g.visible = len > 1e-9;
    if (!g.visible) return;
    // (a short arrow thinner too: a small impulse is a small arrow, not a disc)
    var head = Math.min(0.4 * len, 7 * thick), dir = d.clone().divideScalar(len);
    var shaft = Math.min(thick, 0.2 * head), cone = Math.min(2.6 * thick, 0.45 * head);
    g.position.copy(from);
    g.quaternion.setFromUnitVectors(Y, dir);
    g.children[0].scale.set(shaft, len - head, shaft); g.children[0].position.set(0, (len - head) / 2, 0);
    g.children[1].scale.set(cone, head, cone); g.children[1].position.set(0, len - head / 2, 0);
  }
  // The spin's curl: three quarters of a ring round the axis and a cone at its end, turning as
  // omega turns the body (counterclockwise seen from the arrow's head).
  function makeCurl() {
    var m = material(palette.spin), g = new THREE.Group();
    var ring = new THREE.Mesh(new (geometry('Torus'))(1, 0.12, 6, 32, 1.5 * Math.PI), m);
    ring.rotation.x = -Math.PI / 2;  // in the xz plane, from +x towards -z: positive about +y
    var tip = new THREE.Mesh(new (geometry('Cone'))(0.3, 0.6, 12), m);
    tip.position.set(0.15, 0, 1); tip.rotation.z = -Math.PI / 2;  // at the ring's end, along +x
    g.add(ring, tip);
    g.traverse(function (o) { o.renderOrder = 10; });
    gl.scene.add(g);
    return g;
  }
  function build() {
    var s = gl.scene = new THREE.Scene();
    Y = new THREE.Vector3(0, 1, 0);
    // Shaded faces 80 to 100 % of the fill (the figures' palette keeps its colours apart so).
    s.add(new THREE.AmbientLight(0xffffff, 0.8));
    gl.light = new THREE.DirectionalLight(0xffffff, 0.22);
    s.add(gl.light, gl.light.target);
    // On a ground, the bodies' shadows (the light from above): how high a body is shows.
    gl.ground = lab.run.bodies.some(function (b) { return b.kind === 'half_space'; });
    if (gl.ground) {
      gl.renderer.shadowMap.enabled = true;
      gl.light.castShadow = true;
      gl.light.shadow.mapSize.set(1024, 1024);
    }
    gl.camera = new THREE.PerspectiveCamera(FOV, canvas.width / canvas.height, 0.01, 1000);
    gl.meshes = lab.run.bodies.map(function (b, i) { var g = bodyMesh(b, i); s.add(g); return g; });
    gl.velocity = lab.run.bodies.map(function () { return makeArrow(palette.velocity); });
    gl.spin = lab.run.bodies.map(function () { return {arrow: makeArrow(palette.spin), curl: makeCurl()}; });
    gl.events = [];
  }

  // ---- Scales, the ground's size and the camera, fitted to the run ----
  // The points of body `b` in state `s` whose box holds it: a box's corners, a sphere's centre +- r.
  function extremes(b, s) {
    var out = [], c = V(s.x), q = Q(s.orientation);
    for (var k = 0; k < 8; ++k) {
      if (b.kind === 'box') out.push(new THREE.Vector3(k & 1 ? b.half[0] : -b.half[0], k & 2 ? b.half[1] : -b.half[1], k & 4 ? b.half[2] : -b.half[2]).applyQuaternion(q).add(c));
      else out.push(new THREE.Vector3(k & 1 ? b.radius : -b.radius, k & 2 ? b.radius : -b.radius, k & 4 ? b.radius : -b.radius).add(c));
    }
    return out;
  }
  self.prepare = function () {
    if (!gl) { lab.view = {}; return; }
    if (!gl.scene) build();
    var lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity], vmax = 1e-12, wmax = 1e-12, pmax = 1e-12;
    lab.run.states.forEach(function (st) {
      lab.run.bodies.forEach(function (b) {
        var s = st.bodies[b.name];
        if (!s || b.kind === 'half_space') return;
        extremes(b, s).forEach(function (p) {
          for (var c = 0; c < 3; ++c) { lo[c] = Math.min(lo[c], p.getComponent(c)); hi[c] = Math.max(hi[c], p.getComponent(c)); }
        });
        vmax = Math.max(vmax, Math.hypot.apply(null, s.v)); wmax = Math.max(wmax, Math.hypot.apply(null, s.w));
      });
    });
    lab.run.events.forEach(function (e) { pmax = Math.max(pmax, Math.hypot.apply(null, e.impulse)); });
    var centre = V(lo).add(V(hi)).multiplyScalar(0.5), size = Math.max(V(hi).sub(V(lo)).length(), 0.1);
    // Arrows: the fastest speed 0.25 of the scene's size, the fastest spin and the largest
    // impulse 0.2; kept from one answer to the next while they stay short enough (one scale to
    // compare before and after), fitted afresh by "The lesson's values".
    var next = {size: size, centre: centre, vscale: 0.25 * size / vmax, wscale: 0.2 * size / wmax, pscale: 0.2 * size / pmax};
    if (view && !refit) {
      if (view.vscale * vmax <= 0.5 * size) next.vscale = view.vscale;
      if (view.wscale * wmax <= 0.4 * size) next.wscale = view.wscale;
      next.size = view.size; next.centre = view.centre;
    }
    next.thick = 0.0045 * next.size;
    view = lab.view = next;
    panel.dataset.view = JSON.stringify({vscale: view.vscale, wscale: view.wscale, pscale: view.pscale, size: view.size});
    lab.run.bodies.forEach(function (b, i) {  // the ground: 4 sizes across, under the scene's centre
      if (b.kind !== 'half_space') return;
      var n = V(b.normal), g = gl.meshes[i], L = 4 * view.size;
      g.position.copy(view.centre).addScaledVector(n, b.offset - n.dot(view.centre));
      g.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), n);
      g.scale.set(L, L, L);
    });
    if (!orbit || refit) {
      var v = lab.run.view || {}, fit = 0.5 * size / Math.sin(FOV * Math.PI / 360);
      // (the figures' default: turned 32 degrees right of the front, raised 24; render/camera.cpp)
      orbit = {az: (v.azimuth !== null && v.azimuth !== undefined ? v.azimuth : 32) * Math.PI / 180,
               el: (v.elevation !== null && v.elevation !== undefined ? v.elevation : 24) * Math.PI / 180,
               dist: v.distance || fit, target: v.target ? V(v.target) : centre.clone()};
      // As the figures' camera: the run's box projected fills 80 % of the picture, re-aimed at
      // its middle (render/camera.cpp Camera::frame), unless the [view] sets both.
      for (var k = 0; k < 4 && !(v.target && v.distance); ++k) {
        aim();
        var x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
        for (var c = 0; c < 8; ++c) {
          var p = project(new THREE.Vector3(c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], c & 4 ? hi[2] : lo[2]));
          x0 = Math.min(x0, p[0]); x1 = Math.max(x1, p[0]); y0 = Math.min(y0, p[1]); y1 = Math.max(y1, p[1]);
        }
        var half = orbit.dist * Math.tan(FOV * Math.PI / 360), cam = gl.camera.matrixWorld;
        if (!v.target) {
          orbit.target.addScaledVector(new THREE.Vector3().setFromMatrixColumn(cam, 0), ((x0 + x1) / canvas.width - 1) * half * canvas.width / canvas.height)
                      .addScaledVector(new THREE.Vector3().setFromMatrixColumn(cam, 1), (1 - (y0 + y1) / canvas.height) * half);
        }
        if (!v.distance) orbit.dist *= Math.max(0.3, Math.min(3, Math.max((x1 - x0) / canvas.width, (y1 - y0) / canvas.height) / 0.8));
      }
      orbit.home = {az: orbit.az, el: orbit.el, dist: orbit.dist, target: orbit.target.clone()};
    }
    refit = false;
    aim();
    if (mode && mode !== 'next') jump(mode);  // the new run's frame before / at / after its collision
  };
  self.refit = function () { refit = true; };
  function aim() {
    var c = gl.camera, o = orbit;
    o.el = Math.max(-1.5, Math.min(1.5, o.el));
    c.position.set(Math.sin(o.az) * Math.cos(o.el), Math.sin(o.el), Math.cos(o.az) * Math.cos(o.el)).multiplyScalar(o.dist).add(o.target);
    c.near = o.dist / 100; c.far = o.dist * 100 + 10 * view.size;
    c.lookAt(o.target);
    c.updateProjectionMatrix(); c.updateMatrixWorld();
    // The light from above the camera and to its left: the three faces of a box in view differ.
    var right = new THREE.Vector3().setFromMatrixColumn(c.matrixWorld, 0);
    gl.light.position.copy(c.position).addScaledVector(right, -0.5 * o.dist).add(new THREE.Vector3(0, o.dist, 0));
    gl.light.target.position.copy(o.target);
    if (gl.ground) {  // the shadows' box: the scene from the light
      var sh = gl.light.shadow.camera, r = 1.5 * view.size;
      sh.left = sh.bottom = -r; sh.right = sh.top = r; sh.near = 0.01; sh.far = gl.light.position.distanceTo(o.target) + 2 * r;
      sh.updateProjectionMatrix();
    }
  }
  function project(p) {  // world -> the canvases' pixels
    var q = p.clone().project(gl.camera);
    return [(q.x + 1) / 2 * canvas.width, (1 - q.y) / 2 * canvas.height];
  }
  function rayAt(px) {  // the canvases' pixels -> the ray from the camera through them
    var r = new THREE.Raycaster();
    r.setFromCamera(new THREE.Vector2(2 * px[0] / canvas.width - 1, 1 - 2 * px[1] / canvas.height), gl.camera);
    return r.ray;
  }

  // ---- One picture: the frame `st`, or at the page's collision the two bodies where they touch ----
  self.drawScene = function (st) {
    if (!gl || !gl.scene) return;
    var instant = mode === 'at' && lab.run.worked && lab.run.worked.at && !lab.playing ? lab.run.worked : null;
    var t = instant ? instant.t : st.t, ctx = overlay.getContext('2d'), W = overlay.width, H = overlay.height;
    var stateOf = function (name) { return instant && instant.at[name] ? instant.at[name] : st.bodies[name]; };
    var legend = [], tags = [];
    lab.run.bodies.forEach(function (b, i) {
      var s = stateOf(b.name), g = gl.meshes[i], sp = gl.spin[i];
      gl.velocity[i].visible = sp.arrow.visible = sp.curl.visible = false;
      if (!s || b.kind === 'half_space') return;
      g.position.copy(V(s.x)); g.quaternion.copy(Q(s.orientation));
      tags.push({text: b.name, at: project(V(s.x))});
      if (b.static) return;
      setArrow(gl.velocity[i], V(s.x), V(s.v).multiplyScalar(view.vscale), view.thick);
      var w = V(s.w).multiplyScalar(view.wscale), len = w.length();
      setArrow(sp.arrow, V(s.x), w, 0.8 * view.thick);
      sp.curl.visible = len > 1e-9;
      if (sp.curl.visible) {
        sp.curl.position.copy(V(s.x)).addScaledVector(w, 0.55);
        sp.curl.quaternion.setFromUnitVectors(Y, w.clone().divideScalar(len));
        var r = b.kind === 'box' ? Math.max.apply(null, b.half) : b.radius;  // the curl a little inside the body's size
        sp.curl.scale.setScalar(Math.max(3 * view.thick, Math.min(0.7 * r, 0.05 * view.size)));
      }
      legend.push({i: i, text: b.name + ':  v = ' + vec(s.v) + ' m/s,  \u03c9 = ' + vec(s.w) + ' rad/s'});
    });
    // The collisions: each pair's latest of the last 0.15 s (at the page's collision: that
    // instant's), the impulse on b (red) at the contact point; the latest instant's with their
    // normals (teal), named under the picture. (A tower's resting contacts would bury it else.)
    var recent = {}, shown = [];
    lab.run.events.forEach(function (e) {
      if (instant ? Math.abs(e.t - t) > 1e-12 : e.t > t + 1e-12 || e.t < t - 0.15) return;
      // the page's pair in the page's roles (the engine may have found it the other way round)
      var w = lab.run.worked, neg = function (v) { return v.map(function (x) { return -x; }); };
      if (w && e.a === w.b && e.b === w.a) e = {t: e.t, a: w.a, b: w.b, point: e.point, normal: neg(e.normal), impulse: neg(e.impulse)};
      recent[e.a + '\u0000' + e.b] = e;
    });
    Object.keys(recent).forEach(function (k) { shown.push(recent[k]); });
    shown.sort(function (x, y) { return x.t - y.t; });
    var latest = shown.length ? shown[shown.length - 1].t : null;
    // (named: the page's collision first at its instant, then the largest impulses)
    var pairOf = function (e) { return !!instant && e.a === instant.a && e.b === instant.b; };
    var named = shown.filter(function (e) { return e.t === latest; }).sort(function (x, y) {
      return (pairOf(y) - pairOf(x)) || (Math.hypot.apply(null, y.impulse) - Math.hypot.apply(null, x.impulse));
    });
    while (gl.events.length < shown.length) {  // the normal over the impulse (frictionless: along it)
      var pair = {p: makeArrow(palette.impulse), n: makeArrow(palette.normal)};
      pair.n.traverse(function (o) { o.renderOrder = 11; });
      gl.events.push(pair);
    }
    gl.events.forEach(function (g, k) {
      var e = shown[k];
      g.p.visible = g.n.visible = !!e;
      if (!e) return;
      g.n.visible = e.t === latest;
      if (g.n.visible) setArrow(g.n, V(e.point), V(e.normal).multiplyScalar(0.12 * view.size), 0.6 * view.thick);
      setArrow(g.p, V(e.point), V(e.impulse).multiplyScalar(view.pscale), 1.2 * view.thick);
    });
    gl.renderer.render(gl.scene, gl.camera);
    panel.dataset.view3d = 'drawn';
    panel.dataset.view3dT = t;

    ctx.clearRect(0, 0, W, H);
    tags.forEach(function (g) { flat.label(ctx, g.text, [g.at[0] + 8, g.at[1] + 14], palette.ink); });
    // Under the picture, from the bottom: the caption (what a jump shows, else how to turn the
    // view), then the latest instant's impulses, three at most; the first's arrow says on whom.
    var rows = wrap(ctx, caption || 'Drag the picture to turn it, wheel or pinch to zoom (keys: Tab to it, arrows turn, + and \u2212 zoom, Home)', W - 130).reverse().map(function (l) {
      return {text: l, colour: caption ? palette.ink : palette.muted};
    });
    if (named.length > 3) rows.push({text: '+ ' + (named.length - 3) + ' other contacts at this instant', colour: palette.impulse});
    named.slice(0, 3).reverse().forEach(function (e) {
      rows.push({text: 'P = ' + vec(e.impulse) + ' N\u00b7s on ' + e.b + ' (' + e.a + ' and ' + e.b + ', t = ' + num(e.t) + ' s)',
                 colour: palette.impulse});
    });
    if (named.length) {
      var tip = project(V(named[0].point).addScaledVector(V(named[0].impulse), view.pscale));
      flat.label(ctx, 'P on ' + named[0].b, [tip[0] + 8, tip[1] - 10], palette.impulse);
    }
    rows.forEach(function (r, k) { flat.label(ctx, r.text, [12, H - 16 - 21 * k], r.colour); });
    // The legend's rows: at the page's collision its two, else the latest collision's (drawLegend).
    var last = instant ? {a: instant.a, b: instant.b} : null;
    if (!instant) lab.run.events.forEach(function (e) { if (e.t <= t + 1e-12) last = e; });
    flat.drawLegend(ctx, legend, last);
    flat.label(ctx, 't = ' + (instant ? num(t) : t.toFixed(3)) + ' s', [W - 12, 19], palette.muted, 'right');
    axes(ctx, [W - 50, H - 50]);
    if (!instant && lab.handles.atStart()) {
      lab.handles.list().forEach(function (h) { if (h.track) drawTrack(ctx, h); });
      lab.handles.draw(ctx);
    }
  };
  // `text` in lines of at most `width` pixels (the labels' font).
  function wrap(ctx, text, width) {
    flat.useFont(ctx);
    var lines = [''];
    text.split(' ').forEach(function (word) {
      var line = lines[lines.length - 1], next = line ? line + ' ' + word : word;
      if (line && ctx.measureText(next).width > width) lines.push(word);
      else lines[lines.length - 1] = next;
    });
    return lines;
  }
  // The world's axes as the camera sees them, at `o` (the overlay's pixels): x, y, z.
  function axes(ctx, o) {
    var inv = gl.camera.matrixWorldInverse;
    ['x', 'y', 'z'].forEach(function (name, c) {
      var d = new THREE.Vector3(); d.setComponent(c, 1); d.transformDirection(inv);
      var tip = [o[0] + 32 * d.x, o[1] - 32 * d.y];
      flat.arrow(ctx, o, tip, palette.muted, 2);
      flat.label(ctx, name, [o[0] + 44 * d.x, o[1] - 44 * d.y], palette.muted, 'center');
    });
  }
  function drawTrack(ctx, h) {  // a position's range through the body's centre, with its ends' values
    var a = h.track[0], e = h.track[1];
    ctx.save();
    ctx.strokeStyle = palette.ink; ctx.lineWidth = 2.5; ctx.globalAlpha = 0.55;
    ctx.beginPath(); ctx.moveTo(a[0], a[1]); ctx.lineTo(e[0], e[1]); ctx.stroke();
    ctx.restore();
    flat.label(ctx, num(h.inputs[0].lo), [a[0], a[1] - 16], palette.muted, 'center');
    flat.label(ctx, num(h.inputs[0].hi) + (h.inputs[0].unit ? ' ' + h.inputs[0].unit : ''), [e[0], e[1] - 16], palette.muted, 'center');
  }

  // ---- The drag handles (try-it-drag.js drags, snaps and takes the keys) ----
  // A velocity (v), spin (w) or position input of a body: its knob where the arrow's head is (the
  // body's centre for a position). Dragged, the knob follows the pointer along the input's axis
  // (one component: the point of that line nearest the pointer's ray), or in the plane facing
  // the camera through it (more components).
  var FIELDS = [['v', 'velocity', 'velocity', 'the blue knob at the head of {}\u2019s velocity arrow'],
                ['w', 'spin', 'spin', 'the amber knob at the head of {}\u2019s spin arrow'],
                ['position', 'position', 'ink', 'the dark knob at {}\u2019s centre, along its track']];
  self.handles3d = function () {
    var out = [];
    if (!gl || !gl.scene || !lab.run.vary) return out;
    var st = lab.run.states[0];
    lab.run.bodies.forEach(function (b) {
      var s = st.bodies[b.name];
      if (!s || b.static) return;
      FIELDS.forEach(function (f) {
        var inputs = lab.run.vary.filter(function (v) { return v.body === b.name && v.field === f[0] && v.component >= 0; });
        if (!inputs.length) return;
        var tail = f[0] === 'position' ? new THREE.Vector3() : V(s.x);
        var scale = f[0] === 'v' ? view.vscale : f[0] === 'w' ? view.wscale : 1;
        var value = f[0] === 'v' ? s.v : f[0] === 'w' ? s.w : s.x;
        var at = function (val) { return tail.clone().addScaledVector(V(val), scale); };
        var h = {kind: f[1], body: b.name, inputs: inputs, knobOnly: true, colour: palette[f[2]],
                 words: f[3].replace('{}', b.name), knob: project(at(value))};
        h.valuesAt = function (px) {
          var ray = rayAt(px), head = at(value), p;
          if (inputs.length === 1) {  // the axis's line through the head: its point nearest the ray
            var u = new THREE.Vector3(), c = inputs[0].component;
            u.setComponent(c, 1);
            var w0 = ray.origin.clone().sub(head), bb = ray.direction.dot(u), dd = ray.direction.dot(w0), e = u.dot(w0);
            var den = 1 - bb * bb;
            p = head.clone().addScaledVector(u, den > 1e-6 ? (e - bb * dd) / den : 0);
          } else {  // the plane facing the camera through the head
            var n = gl.camera.getWorldDirection(new THREE.Vector3());
            p = new THREE.Vector3();
            if (!ray.intersectPlane(new THREE.Plane().setFromNormalAndCoplanarPoint(n, head), p)) p = head;
          }
          return inputs.map(function (v) { return (p.getComponent(v.component) - tail.getComponent(v.component)) / scale; });
        };
        if (inputs.length === 1) {  // the knob's place at each of the grid's values (the browser test's)
          var v0 = inputs[0], n = Math.round((v0.hi - v0.lo) / v0.step), where = function (x) {
            var val = value.slice(); val[v0.component] = x; return project(at(val));
          };
          h.grid = [];
          for (var k = 0; k <= n; ++k) h.grid.push(where(k === n ? v0.hi : v0.lo + k * v0.step));
          if (f[0] === 'position') h.track = [where(v0.lo), where(v0.hi)];
        }
        out.push(h);
      });
    });
    return out;
  };

  // ---- The camera: drag to orbit, wheel or pinch to zoom, keys on the focused picture ----
  function moved() {
    aim();
    lab.handles.make();  // the knobs where the arrows now are on the canvas
    lab.draw();
  }
  var pointers = {}, span = null;
  function canvasPoint(e) {
    var r = overlay.getBoundingClientRect();
    return [(e.clientX - r.left) * overlay.width / r.width, (e.clientY - r.top) * overlay.height / r.height];
  }
  function spanOf() {
    var p = Object.keys(pointers).map(function (k) { return pointers[k]; });
    return p.length === 2 ? Math.hypot(p[0][0] - p[1][0], p[0][1] - p[1][1]) : null;
  }
  function controls() {
    overlay.tabIndex = 0;
    overlay.setAttribute('aria-label', 'The run in 3D. Arrow keys turn the camera, + and \u2212 zoom, Home: the first view.');
    // After try-it-drag.js's own listeners on the canvas: a drag it took (a knob) is not an orbit.
    stage.addEventListener('pointerdown', function (e) {
      if (e.defaultPrevented || e.target !== overlay || (e.pointerType === 'mouse' && e.button !== 0) || !orbit) return;
      pointers[e.pointerId] = canvasPoint(e);
      span = spanOf();
      overlay.setPointerCapture(e.pointerId);
      stage.classList.add('orbiting');
    });
    stage.addEventListener('pointermove', function (e) {
      var was = pointers[e.pointerId];
      if (!was || lab.handles.dragging()) return;
      var p = canvasPoint(e);
      pointers[e.pointerId] = p;
      var now = spanOf();
      if (now !== null && span) { orbit.dist *= span / Math.max(now, 1); span = now; }
      else if (now === null) { orbit.az -= (p[0] - was[0]) * 0.008; orbit.el += (p[1] - was[1]) * 0.008; }
      moved();
    });
    var up = function (e) {
      delete pointers[e.pointerId];
      span = spanOf();
      if (!Object.keys(pointers).length) stage.classList.remove('orbiting');
    };
    stage.addEventListener('pointerup', up);
    stage.addEventListener('pointercancel', up);
    overlay.addEventListener('wheel', function (e) {
      if (!orbit) return;
      e.preventDefault();
      orbit.dist *= Math.exp(Math.max(-1, Math.min(1, e.deltaY * 0.002)));
      moved();
    }, {passive: false});
    overlay.addEventListener('keydown', function (e) {
      if (!orbit || e.altKey || e.ctrlKey || e.metaKey) return;
      var turn = 5 * Math.PI / 180;
      switch (e.key) {
        case 'ArrowLeft': orbit.az += turn; break;
        case 'ArrowRight': orbit.az -= turn; break;
        case 'ArrowUp': orbit.el += turn; break;
        case 'ArrowDown': orbit.el -= turn; break;
        case '+': case '=': orbit.dist /= 1.15; break;
        case '-': case '\u2212': orbit.dist *= 1.15; break;
        case 'Home':
          orbit.az = orbit.home.az; orbit.el = orbit.home.el; orbit.dist = orbit.home.dist; orbit.target = orbit.home.target.clone();
          break;
        default: return;
      }
      e.preventDefault();
      moved();
    });
  }

  // ---- Jumps: to the next collision, and before / at / after the page's collision ----
  function frameWhere(test, fromEnd) {
    var st = lab.run.states;
    if (fromEnd) { for (var k = st.length - 1; k >= 0; --k) if (test(st[k].t)) return k; return 0; }
    for (var j = 0; j < st.length; ++j) if (test(st[j].t)) return j;
    return st.length - 1;
  }
  function jump(what) {
    var run = lab.run, w = run.worked;
    mode = what;
    if (what === 'next') {
      mode = null;
      var now = run.states[lab.frame].t, e = null;
      run.events.forEach(function (x) { if (!e && x.t > now + 1e-12) e = x; });
      if (!e) { caption = 'No collision after t = ' + num(now) + ' s: \u25c0\u25c0 t = 0 starts again.'; lab.draw(); return; }
      lab.goTo(frameWhere(function (t) { return t >= e.t - 1e-12; }));
      var more = run.events.filter(function (x) { return x.t > now + 1e-12 && x.t <= run.states[lab.frame].t + 1e-12; }).length - 1;
      caption = 'The next collision: ' + e.a + ' and ' + e.b + ' at t = ' + num(e.t) + ' s' +
                (more > 0 ? ' (and ' + more + ' more up to this frame)' : '') + '; the arrows at the contact: P on ' + e.b + ' (red), n (teal).';
      lab.draw();
      return;
    }
    if (!w) { mode = null; caption = 'No collision in this run.'; lab.draw(); return; }
    var pair = w.a + ' and ' + w.b + ' (at t = ' + num(w.t) + ' s)';
    var before = frameWhere(function (t) { return t < w.t - 1e-12; }, true);
    var others = run.bodies.filter(function (b) { return !b.static && b.name !== w.a && b.name !== w.b; }).length;
    if (what === 'before') caption = 'Just before the collision of ' + pair + ': the frame at t = ' + num(run.states[before].t) + ' s.';
    else if (what === 'after') caption = 'Just after the collision of ' + pair + '.';
    else caption = 'The instant ' + w.a + ' and ' + w.b + ' touch: velocities just before, the impulse on ' + w.b + ' (red), the normal (teal)' +
                   (others ? '; the other bodies as at t = ' + num(run.states[before].t) + ' s.' : '.');
    lab.goTo(what === 'after' ? frameWhere(function (t) { return t > w.t + 1e-12; }) : before);
  }
  function jumps() {
    var bar = document.createElement('div');
    bar.className = 'player tryit-jumps';
    bar.setAttribute('role', 'group');
    bar.setAttribute('aria-label', 'Collisions');
    bar.innerHTML = '<button type="button" data-jump="next">next collision \u25b6|</button>' +
                    '<span>the page\u2019s collision:</span><button type="button" data-jump="before">before</button>' +
                    '<button type="button" data-jump="at">at the instant</button><button type="button" data-jump="after">after</button>';
    var player = panel.querySelector('.tryit-player');
    player.parentNode.insertBefore(bar, player.nextSibling);
    bar.querySelectorAll('button').forEach(function (b) {
      b.addEventListener('click', function () { if (lab.run) jump(b.dataset.jump); });
    });
    // The player's own buttons (play, step, t = 0) leave the jump's picture and words.
    player.addEventListener('click', function () { mode = null; caption = null; }, true);
  }
  return self;
};
