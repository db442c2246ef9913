// qti.package: the package of `collide worksheet --format qti` (catch-up: 1D; general-2d: 2D
// vectors, figures, an explain question; rotation-directions: choices; general-3d: 3D vectors;
// 3 students) read file by file (jszip, CRC-32 checked; xmldom, every parser message an error)
// and checked against the rules below, stated from IMS QTI 2.1 and IMS Content Packaging 1.1,
// and against key.json, written by the same run:
//
//   the manifest   imscp_v1p1 with a schemaLocation; every file of the zip is a <file> of exactly
//                  one resource and every <file> is in the zip; resource identifiers unique, each
//                  resource's href one of its files, every dependency a resource; an item's type
//                  imsqti_item_xmlv2p1 (its root assessmentItem), a test's imsqti_test_xmlv2p1,
//                  a figure's webcontent; an item that shows a figure depends on its resource
//   an item        imsqti_v2p1 with a schemaLocation; identifier (= its resource's), title,
//                  adaptive, timeDependent; its children in the schema's order; every identifier
//                  an NCName; every interaction's responseIdentifier declared once, with a base
//                  type the interaction takes, and every declaration used; every variable the
//                  rules read declared, every setOutcomeValue an outcome; each modalFeedback's
//                  outcome declared; choices unique, the correct response one of them; only
//                  QTI 2.1's XHTML elements and attributes in the body and feedback, block ones
//                  not inside a <p> (nor text or inline ones directly in itemBody), tables as
//                  XHTML's (tbody, tr, td), textEntryInteraction inline, the others blocks;
//                  <img> files in the zip, parsing as SVG
//   marking        each item's responseProcessing run (an interpreter of the QTI operators it
//                  uses: an unknown one is a failure): a number scores 1 at key.json's value and
//                  within tolerance |value| + 1e-9 of it and 0 beyond (0.999 and 1.001 of it), the
//                  tolerance attribute equal to that; a vector by the length of the difference
//                  (1 at 0.999 of the allowance in any direction, 0 at 1.001, and 0 with every
//                  component at 0.8 of it, which only the length rule refuses); a choice 1 for
//                  its correct response only, with that option's feedback; an explain question
//                  is left to a grader (0) with the model answer in a rubricBlock for the scorer;
//                  the worked example shown once answered
//   key.json       every numeric answer an item (its value exactly, its unit after the field),
//                  every numeric item an answer; each question a test section drawing one of
//                  the students' variants; every item names its student and holds the givens
//
// The same seed gives the same bytes; --format qti alone writes key.json and qti.zip.
// Then the checks are made to fail: each of a list of broken copies of the package (a file left
// out of the manifest, a figure left out of the zip, a tolerance 10 % off, an interaction's
// identifier renamed, a <div> in a <p>, a corrupted byte) must give at least one failure.
// Usage: node check_package.mjs COLLIDE READER_DIR
import { readdirSync, readFileSync } from 'node:fs';
import { join, posix } from 'node:path';

import { descendants, elements, parseXml, readJson, reader, unzip, worksheet } from './common.mjs';

const [collide, readerDir] = process.argv.slice(2);
const { JSZip, DOMParser } = reader(readerDir);

const QTI = 'http://www.imsglobal.org/xsd/imsqti_v2p1';
const CP = 'http://www.imsglobal.org/xsd/imscp_v1p1';
const SVG = 'http://www.w3.org/2000/svg';
const LESSONS = ['catch-up', 'general-2d', 'rotation-directions', 'general-3d'];
const TWO_D = new Set(['general-2d', 'rotation-directions']);
const STUDENTS = 3;

// QTI 2.1's XHTML: the elements, which are blocks, and the attributes each may have.
const XHTML = new Set(['a', 'abbr', 'acronym', 'address', 'b', 'big', 'blockquote', 'br', 'caption', 'cite', 'code',
  'col', 'colgroup', 'dd', 'dfn', 'div', 'dl', 'dt', 'em', 'h1', 'h2', 'h3', 'h4', 'h5', 'h6', 'hr', 'i', 'img', 'kbd',
  'li', 'object', 'ol', 'p', 'pre', 'q', 'samp', 'small', 'span', 'strong', 'sub', 'sup', 'table', 'tbody', 'td',
  'tfoot', 'th', 'thead', 'tr', 'tt', 'ul', 'var']);
const BLOCKS = new Set(['address', 'blockquote', 'div', 'dl', 'h1', 'h2', 'h3', 'h4', 'h5', 'h6', 'hr', 'ol', 'p', 'pre',
  'table', 'ul', 'choiceInteraction', 'extendedTextInteraction', 'rubricBlock']);
const COMMON = ['class', 'id', 'label', 'xml:lang'];
const CELL = ['headers', 'scope', 'abbr', 'axis', 'rowspan', 'colspan', 'align', 'valign'];
const ATTRIBUTES = { a: ['href', 'type'], img: ['src', 'alt', 'longdesc', 'height', 'width'], table: ['summary'],
  td: CELL, th: CELL, col: ['span'], colgroup: ['span'], q: ['cite'], blockquote: ['cite'],
  object: ['data', 'type', 'width', 'height'],
  textEntryInteraction: ['responseIdentifier', 'base', 'stringIdentifier', 'expectedLength', 'patternMask',
    'placeholderText'],
  choiceInteraction: ['responseIdentifier', 'shuffle', 'maxChoices', 'minChoices'],
  simpleChoice: ['identifier', 'fixed', 'templateIdentifier', 'showHide'],
  extendedTextInteraction: ['responseIdentifier', 'base', 'stringIdentifier', 'expectedLength', 'patternMask',
    'placeholderText', 'maxStrings', 'minStrings', 'expectedLines', 'format'],
  rubricBlock: ['view'] };
// Which base types each interaction takes.
const BASE_TYPES = { textEntryInteraction: ['string', 'integer', 'float'], choiceInteraction: ['identifier'],
  extendedTextInteraction: ['string', 'integer', 'float'] };
// assessmentItem's children, in the schema's order.
const ITEM_ORDER = ['responseDeclaration', 'outcomeDeclaration', 'templateDeclaration', 'templateProcessing',
  'stylesheet', 'itemBody', 'responseProcessing', 'modalFeedback'];
const NCNAME = /^[A-Za-z_][A-Za-z0-9_.-]*$/;
const counted = { numbers: 0, vectors: 0, options: 0, essays: 0 };  // what the marking checks ran on

// Runs an item's responseProcessing with `responses` (identifier -> value, null for none):
// the outcomes after it. Throws for an operator it does not know.
function respond(item, responses) {
  const declared = new Map();
  for (const d of elements(item).filter(e => e.localName === 'responseDeclaration' || e.localName === 'outcomeDeclaration'))
    declared.set(d.getAttribute('identifier'), d);
  const parse = (baseType, text) => baseType === 'float' || baseType === 'integer' ? Number(text) : text;
  const outcomes = new Map();
  for (const d of elements(item).filter(e => e.localName === 'outcomeDeclaration')) {
    const v = descendants(d, 'defaultValue').flatMap(x => descendants(x, 'value'));
    outcomes.set(d.getAttribute('identifier'), v.length ? parse(d.getAttribute('baseType'), v[0].textContent) : null);
  }
  const value = id => responses.has(id) ? responses.get(id) : outcomes.has(id) ? outcomes.get(id) : undefined;
  const numeric = x => x === null ? null : Number(x);
  const evaluate = e => {
    const args = elements(e).map(evaluate);
    const anyNull = args.some(a => a === null);
    switch (e.localName) {
      case 'baseValue': return parse(e.getAttribute('baseType'), e.textContent);
      case 'variable': {
        const v = value(e.getAttribute('identifier'));
        if (v === undefined) throw new Error(`variable ${e.getAttribute('identifier')} is not declared`);
        return v;
      }
      case 'correct': {
        const d = declared.get(e.getAttribute('identifier'));
        const v = d && descendants(d, 'correctResponse').flatMap(x => descendants(x, 'value'));
        if (!v || v.length !== 1) throw new Error(`correct ${e.getAttribute('identifier')}: no correct response`);
        return parse(d.getAttribute('baseType'), v[0].textContent);
      }
      case 'equal': {
        if (anyNull) return null;
        const [a, b] = args.map(numeric);
        const mode = e.getAttribute('toleranceMode') || 'exact';
        if (mode === 'exact') return a === b;
        const t = (e.getAttribute('tolerance') || '').trim().split(/\s+/).map(Number);
        const [t0, t1] = [t[0], t.length > 1 ? t[1] : t[0]];
        const lo = mode === 'absolute' ? b - t0 : b * (1 - t0 / 100), hi = mode === 'absolute' ? b + t1 : b * (1 + t1 / 100);
        const lower = e.getAttribute('includeLowerBound') !== 'false', upper = e.getAttribute('includeUpperBound') !== 'false';
        return (lower ? a >= lo : a > lo) && (upper ? a <= hi : a < hi);
      }
      case 'match': return anyNull ? null : args[0] === args[1];
      case 'lte': return anyNull ? null : numeric(args[0]) <= numeric(args[1]);
      case 'lt': return anyNull ? null : numeric(args[0]) < numeric(args[1]);
      case 'gte': return anyNull ? null : numeric(args[0]) >= numeric(args[1]);
      case 'gt': return anyNull ? null : numeric(args[0]) > numeric(args[1]);
      case 'sum': return anyNull ? null : args.reduce((s, x) => s + numeric(x), 0);
      case 'product': return anyNull ? null : args.reduce((s, x) => s * numeric(x), 1);
      case 'subtract': return anyNull ? null : numeric(args[0]) - numeric(args[1]);
      case 'isNull': return args[0] === null;
      case 'not': return args[0] === null ? null : !args[0];
      case 'and': return anyNull ? null : args.every(Boolean);
      case 'or': return anyNull ? null : args.some(Boolean);
      default: throw new Error(`the checks do not know the operator ${e.localName}`);
    }
  };
  const run = rule => {
    switch (rule.localName) {
      case 'setOutcomeValue': {
        const id = rule.getAttribute('identifier');
        if (!outcomes.has(id)) throw new Error(`setOutcomeValue ${id}: not an outcome`);
        outcomes.set(id, evaluate(elements(rule)[0]));
        return;
      }
      case 'responseCondition':
        for (const branch of elements(rule)) {
          const [test, ...rules] = branch.localName === 'responseElse' ? [null, ...elements(branch)] : elements(branch);
          if (branch.localName !== 'responseElse' && evaluate(test) !== true) continue;
          rules.forEach(run);
          return;
        }
        return;
      default: throw new Error(`the checks do not know the rule ${rule.localName}`);
    }
  };
  const processing = elements(item).find(e => e.localName === 'responseProcessing');
  if (processing) elements(processing).forEach(run);
  return outcomes;
}

// Every failure the package gives; `files`: name -> Buffer, `keys`: lesson -> key.json.
function checkPackage(files, keys) {
  const failures = [];
  const check = (ok, what) => { if (!ok) failures.push(what); return ok; };
  const docs = new Map();
  for (const [name, bytes] of files)
    if (/\.(xml|svg)$/.test(name)) {
      try {
        docs.set(name, parseXml(DOMParser, bytes.toString('utf8'), name).documentElement);
      } catch (e) {
        failures.push(e.message);
      }
    }
  const manifest = docs.get('imsmanifest.xml');
  if (!check(manifest, 'no imsmanifest.xml')) return failures;

  // The manifest.
  check(manifest.namespaceURI === CP && manifest.localName === 'manifest', 'the manifest is not imscp_v1p1');
  check(/imscp_v1p1\s+\S+\.xsd/.test(manifest.getAttribute('xsi:schemaLocation')), 'the manifest: schemaLocation');
  check(descendants(manifest, 'organizations').length === 1, 'the manifest: <organizations/>');
  const resources = new Map(), owner = new Map();
  for (const r of descendants(manifest, 'resource')) {
    const id = r.getAttribute('identifier');
    check(NCNAME.test(id) && !resources.has(id), `resource ${id}: an identifier once`);
    resources.set(id, r);
    const own = descendants(r, 'file').map(f => f.getAttribute('href'));
    check(own.includes(r.getAttribute('href')), `resource ${id}: its href is not one of its files`);
    for (const f of own) {
      check(!owner.has(f), `${f}: a file of two resources`);
      owner.set(f, r);
      check(files.has(f), `${f}: in the manifest, not in the zip`);
    }
  }
  for (const name of files.keys())
    check(name === 'imsmanifest.xml' || owner.has(name), `${name}: in the zip, not in the manifest`);
  for (const r of resources.values())
    for (const d of descendants(r, 'dependency'))
      check(resources.has(d.getAttribute('identifierref')), `${r.getAttribute('identifier')}: depends on nothing`);
  const dependencies = r => descendants(r, 'dependency').map(d => resources.get(d.getAttribute('identifierref')));

  // Each item and test.
  const items = new Map();  // identifier -> {name, root}
  for (const [name, root] of docs) {
    const r = owner.get(name);
    if (name.endsWith('.svg')) {
      check(root.namespaceURI === SVG && root.localName === 'svg', `${name}: not SVG`);
      check(!r || r.getAttribute('type') === 'webcontent', `${name}: not webcontent`);
      continue;
    }
    if (name === 'imsmanifest.xml') continue;
    const type = { assessmentItem: 'imsqti_item_xmlv2p1', assessmentTest: 'imsqti_test_xmlv2p1' }[root.localName];
    check(root.namespaceURI === QTI && type, `${name}: neither an item nor a test of QTI 2.1`);
    check(!r || r.getAttribute('type') === type, `${name}: resource type ${r && r.getAttribute('type')}`);
    check(new RegExp(`${QTI}\\s+\\S+imsqti_v2p1\\.xsd`).test(root.getAttribute('xsi:schemaLocation')),
          `${name}: schemaLocation`);
    for (const e of [root, ...descendants(root)])
      for (const a of ['identifier', 'responseIdentifier', 'outcomeIdentifier'])
        if (e.hasAttribute(a)) check(NCNAME.test(e.getAttribute(a)), `${name}: ${a} "${e.getAttribute(a)}"`);
    if (root.localName === 'assessmentItem') {
      items.set(root.getAttribute('identifier'), { name, root });
      check(r && r.getAttribute('identifier') === root.getAttribute('identifier'), `${name}: resource identifier`);
      checkItem(name, root, r, files, docs, dependencies, check);
    }
  }

  // key.json: every numeric answer an item with its value and unit, and every numeric item an answer.
  const numeric = new Set();
  for (const [id, { root }] of items)
    if (descendants(root, 'textEntryInteraction').length) numeric.add(id);
  for (const lesson of LESSONS) {
    const key = keys.get(lesson);
    check(key.students.length === STUDENTS, `${lesson}: ${key.students.length} students in key.json`);
    for (const s of key.students)
      for (const a of s.answers) {
        const id = `collide-${lesson}-q${a.question}-s${s.student}`;
        numeric.delete(id);
        if (!check(items.has(id), `${id}: no item for key.json's answer`)) continue;
        const { name, root } = items.get(id);
        checkAnswer(name, root, a, s.student, check);
      }
    const test = docs.get(`${lesson}/test.xml`);
    if (!check(test, `${lesson}: no test`)) continue;
    const sections = descendants(test, 'assessmentSection');
    const lessonItems = [...items.keys()].filter(i => i.startsWith(`collide-${lesson}-q`));
    check(sections.length * STUDENTS === lessonItems.length, `${lesson}: ${sections.length} sections, ${lessonItems.length} items`);
    for (const section of sections) {
      const selection = descendants(section, 'selection');
      check(selection.length === 1 && selection[0].getAttribute('select') === '1', `${lesson}: a section draws one item`);
      const refs = descendants(section, 'assessmentItemRef');
      check(refs.length === STUDENTS, `${lesson}: ${refs.length} variants in a section`);
      for (const ref of refs) {
        const target = posix.join(posix.dirname(`${lesson}/test.xml`), ref.getAttribute('href'));
        const item = items.get(ref.getAttribute('identifier'));
        check(item && item.name === target, `${lesson}: the test's ${ref.getAttribute('href')} is not its item`);
      }
    }
  }
  check(numeric.size === 0, `numeric items without an answer in key.json: ${[...numeric]}`);
  return failures;
}

function checkItem(name, root, resource, files, docs, dependencies, check) {
  for (const a of ['identifier', 'title', 'adaptive', 'timeDependent']) check(root.hasAttribute(a), `${name}: no ${a}`);
  const order = elements(root).map(e => ITEM_ORDER.indexOf(e.localName));
  check(order.every((k, i) => k >= 0 && (i === 0 || k >= order[i - 1])), `${name}: children out of the schema's order`);
  for (const one of ['itemBody', 'responseProcessing'])
    check(elements(root).filter(e => e.localName === one).length === 1, `${name}: one ${one}`);
  const body = elements(root).find(e => e.localName === 'itemBody');
  if (!body) return;
  const declarations = new Map();
  for (const d of elements(root).filter(e => /^(response|outcome)Declaration$/.test(e.localName))) {
    const id = d.getAttribute('identifier');
    check(!declarations.has(id) && d.hasAttribute('cardinality'), `${name}: ${id} declared twice or without cardinality`);
    declarations.set(id, d);
  }
  const used = new Set();
  const interactions = Object.keys(BASE_TYPES).flatMap(k => descendants(body, k));
  for (const i of interactions) {
    const id = i.getAttribute('responseIdentifier'), d = declarations.get(id);
    check(d && d.localName === 'responseDeclaration', `${name}: ${i.localName} answers ${id}, not declared`);
    check(!used.has(id), `${name}: ${id} answered twice`);
    used.add(id);
    if (d) check(BASE_TYPES[i.localName].includes(d.getAttribute('baseType')), `${name}: ${i.localName} as ${d.getAttribute('baseType')}`);
  }
  for (const [id, d] of declarations)
    if (d.localName === 'responseDeclaration') check(used.has(id), `${name}: ${id} declared, answered by nothing`);
  const processing = elements(root).find(e => e.localName === 'responseProcessing');
  for (const v of processing ? descendants(processing, 'variable').concat(descendants(processing, 'correct')) : [])
    check(declarations.has(v.getAttribute('identifier')), `${name}: the rules read ${v.getAttribute('identifier')}, not declared`);
  const feedback = elements(root).filter(e => e.localName === 'modalFeedback');
  for (const f of feedback) {
    const d = declarations.get(f.getAttribute('outcomeIdentifier'));
    check(d && d.localName === 'outcomeDeclaration' && f.hasAttribute('identifier') && f.hasAttribute('showHide'),
          `${name}: modalFeedback on ${f.getAttribute('outcomeIdentifier')}`);
  }
  for (const c of descendants(body, 'choiceInteraction')) {
    const ids = descendants(c, 'simpleChoice').map(s => s.getAttribute('identifier'));
    check(new Set(ids).size === ids.length && ids.length >= 2, `${name}: choices ${ids}`);
    const d = declarations.get(c.getAttribute('responseIdentifier'));
    const right = d ? descendants(d, 'value').map(v => v.textContent) : [];
    check(right.length === 1 && ids.includes(right[0]), `${name}: the correct response ${right} is no choice`);
  }
  // The XHTML of the body, the feedback and the rubric.
  const walk = (e, inP) => {
    for (const c of Array.from(e.childNodes)) {
      if (c.nodeType === 3 && e === body) check(!c.data.trim(), `${name}: text directly in itemBody`);
      if (c.nodeType !== 1) continue;
      const n = c.localName;
      check(c.namespaceURI === QTI, `${name}: <${n}> in ${c.namespaceURI}`);
      check(XHTML.has(n) || n in ATTRIBUTES && !XHTML.has(n) || n === 'prompt', `${name}: <${n}> is not QTI 2.1's`);
      const allowed = COMMON.concat(ATTRIBUTES[n] || []);
      for (const a of Array.from(c.attributes)) check(allowed.includes(a.name), `${name}: <${n} ${a.name}>`);
      if (e === body) check(BLOCKS.has(n), `${name}: <${n}> directly in itemBody`);
      if (inP) check(!BLOCKS.has(n), `${name}: <${n}> inside <p>`);
      if (n === 'textEntryInteraction') check(e !== body, `${name}: textEntryInteraction outside a block`);
      const kids = elements(c).map(k => k.localName);
      const only = { table: ['caption', 'col', 'colgroup', 'thead', 'tfoot', 'tbody'], tbody: ['tr'], thead: ['tr'],
        tfoot: ['tr'], tr: ['td', 'th'], ul: ['li'], ol: ['li'], choiceInteraction: ['prompt', 'simpleChoice'] }[n];
      if (only) check(kids.every(k => only.includes(k)), `${name}: <${n}> holds ${kids}`);
      if (n === 'table') check(kids.includes('tbody'), `${name}: a table without tbody`);
      if (n === 'img') {
        check(c.hasAttribute('alt'), `${name}: <img> without alt`);
        const file = posix.join(posix.dirname(name), c.getAttribute('src'));
        check(files.has(file), `${name}: <img> of ${file}, not in the zip`);
        check(resource && dependencies(resource).some(d => d && descendants(d, 'file').some(f => f.getAttribute('href') === file)),
              `${name}: the resource does not depend on ${file}`);
        check(docs.has(file) && docs.get(file).localName === 'svg', `${name}: ${file} is not an SVG`);
      }
      walk(c, inP || n === 'p' || /^h[1-6]$/.test(n) || n === 'textEntryInteraction');
    }
  };
  for (const part of [body, ...feedback]) walk(part, false);

  // Marking: what the rules give.
  const responses = ids => new Map(ids);
  try {
    const outcomes = respond(root, responses([...used].map(id => [id, null])));
    check(outcomes.get('SCORE') === 0, `${name}: no answer scores ${outcomes.get('SCORE')}`);
    const kind = descendants(body, 'choiceInteraction').length ? 'choice' :
      descendants(body, 'extendedTextInteraction').length ? 'explain' : 'numeric';
    if (kind === 'choice') {
      const c = descendants(body, 'choiceInteraction')[0];
      const right = descendants(declarations.get(c.getAttribute('responseIdentifier')), 'value')[0].textContent;
      for (const s of descendants(c, 'simpleChoice')) {
        counted.options++;
        const id = s.getAttribute('identifier');
        const o = respond(root, responses([[c.getAttribute('responseIdentifier'), id]]));
        check(o.get('SCORE') === (id === right ? 1 : 0), `${name}: option ${id} scores ${o.get('SCORE')}`);
        check(feedback.some(f => f.getAttribute('outcomeIdentifier') === 'FEEDBACK' && o.get('FEEDBACK') === id &&
                                 f.getAttribute('identifier') === id && f.getAttribute('showHide') === 'show' &&
                                 f.textContent.trim()), `${name}: option ${id} has no feedback`);
      }
    }
    if (kind === 'explain') {
      counted.essays++;
      const o = respond(root, responses([['RESPONSE', 'an answer']]));
      check(o.get('SCORE') === 0, `${name}: an essay is scored by the rules`);
      const rubric = descendants(body, 'rubricBlock');
      check(rubric.length === 1 && rubric[0].getAttribute('view') === 'scorer' && rubric[0].textContent.trim().length > 20,
            `${name}: the model answer for the scorer`);
    }
    const worked = feedback.find(f => f.getAttribute('outcomeIdentifier') === 'SOLUTION');
    check(worked && /worked out/.test(worked.textContent) && outcomes.get('SOLUTION') === worked.getAttribute('identifier'),
          `${name}: the worked example once answered`);
  } catch (e) {
    check(false, `${name}: ${e.message}`);
  }
  check(body.textContent.includes('your own numbers') && descendants(body, 'table').some(t => t.getAttribute('class') === 'givens'),
        `${name}: the student's givens`);
  check(descendants(body, 'img').length === (TWO_D.has(name.split('/')[0]) ? 1 : 0), `${name}: the figure`);
}

// A numeric question of key.json against its item.
function checkAnswer(name, root, a, student, check) {
  const body = elements(root).find(e => e.localName === 'itemBody');
  check(body.textContent.includes(`Student ${student}`), `${name}: does not name student ${student}`);
  const fields = descendants(body, 'textEntryInteraction');
  const want = Array.isArray(a.value) ? a.value : [a.value];
  if (!check(fields.length === want.length, `${name}: ${fields.length} fields for ${want}`)) return;
  const ids = fields.map(f => f.getAttribute('responseIdentifier'));
  const declared = ids.map(id => elements(root).find(e => e.localName === 'responseDeclaration' &&
                                                         e.getAttribute('identifier') === id));
  declared.forEach((d, c) => check(d && d.getAttribute('baseType') === 'float' &&
                                   Number(descendants(d, 'value')[0].textContent) === want[c],
                                   `${name}: correct response != key.json's ${want[c]}`));
  // The unit right after the (last) field: "... N s".
  const p = fields[fields.length - 1].parentNode;
  if (a.unit) check(p.textContent.trim().endsWith(` ${a.unit}`), `${name}: "${p.textContent}" does not end in ${a.unit}`);
  const size = Math.hypot(...want);
  const allowance = a.tolerance * size + 1e-9;
  const score = values => respond(root, new Map(ids.map((id, c) => [id, values[c]]))).get('SCORE');
  try {
    check(score(want) === 1, `${name}: the key's value scores ${score(want)}`);
    counted[want.length === 1 ? 'numbers' : 'vectors']++;
    if (want.length === 1) {
      const eq = descendants(root, 'equal');
      check(eq.length === 1 && eq[0].getAttribute('toleranceMode') === 'absolute' &&
            Math.abs(Number(eq[0].getAttribute('tolerance')) - allowance) <= 1e-12 * allowance,
            `${name}: tolerance ${eq[0] && eq[0].getAttribute('tolerance')} != ${allowance}`);
      for (const [f, s] of [[0.999, 1], [-0.999, 1], [1.001, 0], [-1.001, 0]])
        check(score([want[0] + f * allowance]) === s, `${name}: ${f} of the allowance scores ${score([want[0] + f * allowance])}`);
    } else {
      const directions = want.length === 2 ? [[1, 0], [0, -1], [Math.cos(2), Math.sin(2)]] :
        [[1, 0, 0], [0, 0, -1], [0.48, -0.6, 0.64]];
      for (const u of directions)
        for (const [f, s] of [[0.999, 1], [1.001, 0]]) {
          const got = want.map((w, c) => w + f * allowance * u[c]);
          check(score(got) === s, `${name}: ${f} of the allowance along ${u} scores ${score(got)}`);
        }
      const each = want.map(w => w + 0.8 * allowance);  // each component within, the length not
      check(score(each) === 0, `${name}: 0.8 of the allowance in every component scores ${score(each)}`);
      check(score(want.map((w, c) => c ? null : w)) === 0, `${name}: a component left empty scores`);
    }
  } catch (e) {
    check(false, `${name}: ${e.message}`);
  }
}

// Broken copies of the package, each of which the checks must find.
function replaceIn(files, pick, from, to) {
  const copy = new Map(files);
  const name = [...copy.keys()].find(pick);
  const text = copy.get(name).toString('utf8');
  if (!text.match(from)) throw new Error(`no ${from} in ${name} to break`);
  copy.set(name, Buffer.from(text.replace(from, to)));
  return copy;
}
const BROKEN = {
  'a file left out of the manifest': f => replaceIn(f, n => n === 'imsmanifest.xml', /<file href="general-2d\/q2-s1.xml"\/>\n/, ''),
  'a figure left out of the zip': f => { const c = new Map(f); c.delete([...c.keys()].find(n => n.endsWith('.svg'))); return c; },
  'a tolerance 10 % off': f => replaceIn(f, n => n === 'catch-up/q1-s2.xml', /tolerance="([^"]+)"/,
                                         (m, t) => `tolerance="${Number(t) * 1.1}"`),
  "an interaction's identifier renamed": f => replaceIn(f, n => n === 'general-2d/q1-s1.xml',
                                                        'responseIdentifier="RESPONSE_Y"', 'responseIdentifier="RESPONSE_V"'),
  'a <div> in a <p>': f => replaceIn(f, n => n === 'rotation-directions/q1-s1.xml', '</b>: your own', '</b><div>x</div>: your own'),
  'a value 1 % off': f => replaceIn(f, n => n === 'general-3d/q1-s1.xml', /<value>([^<]+)<\/value>/,
                                    (m, v) => `<value>${Number(v) * 1.01}</value>`),
};

const failures = [];
const ws = worksheet(collide, LESSONS, STUDENTS, 11, 'qti,moodle');
try {
  const bytes = readFileSync(join(ws.out, 'qti.zip'));
  const keys = new Map(LESSONS.map(l => [l, readJson(join(ws.out, l, 'key.json'))]));
  const files = await unzip(JSZip, bytes);
  failures.push(...checkPackage(files, keys));
  console.log(`checked ${files.size} files; marked ${counted.numbers} numbers and ${counted.vectors} vectors of ` +
              `key.json, ${counted.options} options, ${counted.essays} essays`);
  if (!(counted.numbers && counted.vectors && counted.options && counted.essays))
    failures.push('a kind of question was not checked');
  for (const [what, brake] of Object.entries(BROKEN)) {
    const found = checkPackage(brake(files), keys);
    if (found.length === 0) failures.push(`the checks miss ${what}`);
    else console.log(`broken on purpose, ${what}: ${found[0]}${found.length > 1 ? ` (+${found.length - 1})` : ''}`);
  }
  // The same seed, the same bytes; qti alone writes key.json (for collide grade) and qti.zip.
  const again = worksheet(collide, LESSONS, STUDENTS, 11, 'qti');
  try {
    if (!readFileSync(join(again.out, 'qti.zip')).equals(bytes)) failures.push('the same seed gave other bytes');
    const written = readdirSync(again.out).sort().join(' ');
    if (written !== 'catch-up general-2d general-3d index.html qti.zip rotation-directions') failures.push(`qti alone wrote ${written}`);
    const one = readdirSync(join(again.out, 'catch-up')).join(' ');
    if (one !== 'key.json') failures.push(`qti alone wrote catch-up/${one}`);
  } finally {
    again.cleanup();
  }
  const corrupt = Buffer.from(bytes);
  const at = corrupt.indexOf('Student 1');
  corrupt[at] = 's'.charCodeAt(0);
  try {
    await unzip(JSZip, corrupt);
    failures.push('a corrupted byte is not found (CRC-32)');
  } catch (e) {
    console.log(`broken on purpose, a corrupted byte: ${e.message}`);
  }
} catch (e) {
  failures.push(e.stack || String(e));
} finally {
  ws.cleanup();
}
for (const f of failures) console.log(`FAIL: ${f}`);
console.log(`${failures.length ? 0 : 1} passed, ${failures.length ? 1 : 0} failed (${failures.length} problems)`);
process.exit(failures.length ? 1 : 0);
