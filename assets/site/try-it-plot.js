// The Try-it panel (try-it.js): plot any quantity against any other. The panel's plot is a
// [[plot]] of the lesson file (docs/formats/lesson-files.md, "Plots") that the reader makes
// with the selects: per sample (every frame: time, a body's position, velocity, spin, angle,
// energy, momentum, angular momentum, a mark's position or velocity, the totals) or per
// collision (its number or time against its time, the interval since the one before, or the
// impulse). It goes to the engine with the lesson's text, so the engine draws it as it draws the
// lesson's own plots (the same SVG, alt text and table as a page's plot-K.svg), from the same
// run, with the panel's inputs; the names and words on offer are the engine's (run.quantities,
// the names a [[plot]] takes). Each of the lesson's own plots opens in it ("Change its axes"),
// and the panel shows the [[plot]] to paste into a lesson file to keep one.
// Loaded before try-it.js, which calls this part with the panel's shared state `lab` (try-it.js).
(window.collideTryItParts = window.collideTryItParts || {}).plot = function (lab) {
  'use strict';
  var box = lab.panel.querySelector('.tryit-free-plot');
  var form = box ? box.querySelector('form') : null;
  var out = box ? box.querySelector('.tryit-free-plot-out') : null;
  var from = box ? box.querySelector('.tryit-free-plot-from') : null;
  var toml = box ? box.querySelector('.tryit-free-plot-toml') : null;
  var escapeHtml = lab.escapeHtml;
  var Y = ['y0', 'y1', 'y2'];  // up to three quantities along y, in one unit
  // The plot asked for: per, x, y and what a lesson's plot carries besides (pair, chain, ...).
  var spec = box ? defaultSpec() : null, title = null, built = false;

  function quantities(per) { return lab.run ? lab.run.quantities[per] : []; }
  function find(per, name) {
    var list = quantities(per);
    for (var k = 0; k < list.length; ++k) if (list[k].name === name) return list[k];
    return null;
  }
  function words(q) { return q.words + (q.unit ? ' (' + q.unit + ')' : ''); }
  function option(q, selected, disabled) {
    return '<option value="' + escapeHtml(q.name) + '"' + (selected ? ' selected' : '') + (disabled ? ' disabled' : '') +
           '>' + escapeHtml(words(q)) + '</option>';
  }
  // The total kinetic energy against time (a name every lesson has: the first answer carries the
  // plot already), until the reader picks another.
  function defaultSpec() { return {per: 'sample', x: 't', y: ['kinetic_energy']}; }

  // The selects show `spec`: x among the per's x quantities, each y among those in the first y's unit.
  function fill() {
    var per = spec.per, list = quantities(per);
    form.elements.per.value = per;
    form.elements.x.innerHTML = list.filter(function (q) { return per === 'sample' || q.x; })
                                    .map(function (q) { return option(q, q.name === spec.x); }).join('');
    var unit = find(per, spec.y[0]).unit;
    Y.forEach(function (name, k) {
      var h = k === 0 ? '' : '<option value=""' + (spec.y[k] ? '' : ' selected') + '>(none)</option>';
      list.forEach(function (q) {
        if (per === 'collision' && !q.y) return;
        h += option(q, q.name === spec.y[k], k > 0 && q.unit !== unit);
      });
      form.elements[name].innerHTML = h;
      // a fit is of one quantity: no second series while a lesson's fit is carried
      form.elements[name].disabled = k > 0 && !!spec.fit;
    });
    var carried = [];
    if (spec.pair) carried.push('the collisions of ' + spec.pair.join(' and '));
    if (spec.chain) carried.push('each of ' + spec.chain.join(', ') + ' striking the next');
    if (spec.instant) carried.push('the collisions of the instant ' + spec.instant.join(' and ') + ' first collide');
    if (spec.fit) carried.push('fitted with a ' + (spec.fit === 'line' ? 'straight line' : 'ratio of each value to the one before'));
    from.textContent = title ? 'Opened from the lesson\u2019s plot \u201c' + title + '\u201d' +
                               (carried.length ? ': ' + carried.join('; ') + '.' : '.') : '';
    from.hidden = !title;
  }
  function read() {
    var per = form.elements.per.value;
    if (per !== spec.per) {  // another kind of plot: its first axes, nothing carried over
      spec = per === 'sample' ? defaultSpec() : {per: 'collision', x: 'collision', y: ['impulse']};
      title = null;
      return;
    }
    spec.x = form.elements.x.value;
    if (spec.fit === 'ratio' && spec.x !== 'collision') delete spec.fit;  // a ratio runs along the collisions' numbers
    var first = find(per, form.elements.y0.value);
    spec.y = [first.name];
    Y.slice(1).forEach(function (name) {
      var q = find(per, form.elements[name].value);
      if (q && q.unit === first.unit && spec.y.indexOf(q.name) < 0) spec.y.push(q.name);
    });
  }

  // The [[plot]] the selects make, as a lesson file writes it (TOML strings: JSON's escapes).
  function plotToml() {
    // (the quantities' words, once the first answer gave them; their names before)
    var s = JSON.stringify, said = function (n) { var q = find(spec.per, n); return q ? q.words : n; };
    var t = spec.y.map(said).join(', ') + ' against ' + said(spec.x);
    var h = '[[plot]]\ntitle = ' + s(t.charAt(0).toUpperCase() + t.slice(1)) + '\nper = ' + s(spec.per) +
            '\nx = ' + s(spec.x) + '\ny = [' + spec.y.map(function (n) { return s(n); }).join(', ') + ']\n';
    ['pair', 'chain', 'instant'].forEach(function (k) {
      if (spec[k]) h += k + ' = [' + spec[k].map(function (n) { return s(n); }).join(', ') + ']\n';
    });
    if (spec.counting && spec.x === 'collision') h += 'counting = ' + s(spec.counting) + '\n';
    if (spec.fit) h += 'fit = ' + s(spec.fit) + '\n';
    if (spec.fit_from) h += 'fit_from = ' + spec.fit_from + '\n';
    return h;
  }

  // What try-it.js adds to the lesson's text for the engine: this plot (after a blank line: a
  // table of its own); nothing on a page without the plot's section.
  function extraText() { return spec ? '\n\n' + plotToml() : ''; }
  // How many of run.plots are this part's (the last): try-it.js shows the others as the lesson's.
  function extra() { return spec ? 1 : 0; }

  function show() {
    if (!spec || !lab.run) return;
    if (!built) { fill(); built = true; }  // the first answer: the quantities on offer are known
    if (lab.run.precomputed) {  // the command's answer at the page's load: without this plot
      lab.setHtml(out, '<p class="note">Drawn by the engine in this page when it has started.</p>');
      return;
    }
    var p = lab.run.plots[lab.run.plots.length - 1];
    var open = out.querySelector('details.plot-data');
    if (lab.setHtml(out, '<figure>' + p.svg + '<figcaption>From the engine in this page: the run with these inputs.' +
                         '</figcaption></figure>' + p.data_html)) {
      var svg = out.querySelector('svg');
      if (svg) svg.setAttribute('aria-label', p.alt);
      if (open && open.open) out.querySelector('details.plot-data').open = true;
    }
    toml.textContent = plotToml();
    // (for the browser test: what is plotted, and the engine's numbers behind it; a property of
    // the panel, not made into text at every answer)
    lab.panel.collideFreePlot = {per: spec.per, x: spec.x, y: spec.y, fit: spec.fit || null, series: p.series};
  }

  // A lesson's own plot, opened here to change its axes.
  function open(k) {
    var p = lab.run.plots[k], s = p.spec;
    spec = JSON.parse(JSON.stringify(s));
    title = p.title;
    fill();
    box.scrollIntoView({block: 'nearest'});
    lab.request();
  }

  if (form) form.addEventListener('change', function () {
    read();
    fill();
    lab.request();
  });
  return {extraText: extraText, extra: extra, show: show, open: open};
};
