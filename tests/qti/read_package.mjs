// qti.convert: a real QTI reader from the npm registry reads the package of
// `collide worksheet --format qti`: @citolab/qti-convert, which reads a QTI 2.x package (its
// manifest, items and tests, with Saxon-JS's XML parser and an XSLT of the QTI 2 to 3 upgrade)
// and writes it as QTI 3.0. Any warning or error it gives fails the test; then its QTI 3.0
// package is checked to hold every item, interaction, response rule, feedback and figure of ours
// (nothing it did not understand dropped).
// Usage: node read_package.mjs COLLIDE READER_DIR      (offline: READER_DIR holds node_modules)
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

import { descendants, parseXml, reader, unzip, worksheet } from './common.mjs';

const [collide, readerDir] = process.argv.slice(2);
const { dir, JSZip, DOMParser } = reader(readerDir);
const failures = [];
const check = (ok, what) => { if (!ok) failures.push(what); };

// Whatever the reader says on the console as a warning or an error is a failure.
const said = [];
for (const level of ['warn', 'error']) {
  const original = console[level];
  console[level] = (...args) => { said.push(`${level}: ${args.join(' ')}`); original(...args); };
}
process.on('warning', w => said.push(`process warning: ${w.message}`));
const log = console.log;
console.log = () => {};  // its progress lines ("Converting manifest file...")

const { convertPackageFile } = await import(
  pathToFileURL(join(dir, 'node_modules/@citolab/qti-convert/dist/qti-converter-node/index.js')).href);

const LESSONS = ['catch-up', 'general-2d', 'rotation-directions'];  // 1D; 2D with figures, vectors, explain; choices
const ws = worksheet(collide, LESSONS, 3, 3);
try {
  const input = join(ws.out, 'qti.zip'), output = join(ws.tmp, 'qti3.zip');
  await convertPackageFile(input, output);
  const ours = await unzip(JSZip, readFileSync(input));
  const theirs = await unzip(JSZip, readFileSync(output));
  check(said.length === 0, `the reader's messages:\n  ${said.join('\n  ')}`);

  const QTI3 = 'http://www.imsglobal.org/xsd/imsqtiasi_v3p0';
  // QTI 2.1's elements and the QTI 3.0 names the upgrade gives them.
  const renamed = {
    responseDeclaration: 'qti-response-declaration', outcomeDeclaration: 'qti-outcome-declaration',
    textEntryInteraction: 'qti-text-entry-interaction', choiceInteraction: 'qti-choice-interaction',
    simpleChoice: 'qti-simple-choice', extendedTextInteraction: 'qti-extended-text-interaction',
    rubricBlock: 'qti-rubric-block', modalFeedback: 'qti-modal-feedback', equal: 'qti-equal', lte: 'qti-lte',
    sum: 'qti-sum', product: 'qti-product', subtract: 'qti-subtract', match: 'qti-match',
    responseIf: 'qti-response-if', responseElse: 'qti-response-else', and: 'qti-and', not: 'qti-not',
    isNull: 'qti-is-null', assessmentItemRef: 'qti-assessment-item-ref',
    assessmentSection: 'qti-assessment-section', selection: 'qti-selection'
  };
  let items = 0, tests = 0, figures = 0;
  for (const [name, bytes] of ours) {
    check(theirs.has(name), `${name}: left out of the converted package`);
    if (!theirs.has(name)) continue;
    if (name.endsWith('.svg')) {
      figures++;
      check(theirs.get(name).equals(bytes), `${name}: the figure changed`);
      continue;
    }
    const a = parseXml(DOMParser, bytes.toString('utf8'), name).documentElement;
    const b = parseXml(DOMParser, theirs.get(name).toString('utf8'), `${name} (QTI 3.0)`).documentElement;
    if (a.localName === 'assessmentItem' || a.localName === 'assessmentTest') {
      const item = a.localName === 'assessmentItem';
      item ? items++ : tests++;
      check(b.localName === (item ? 'qti-assessment-item' : 'qti-assessment-test') && b.namespaceURI === QTI3,
            `${name}: read as ${b.namespaceURI} ${b.localName}`);
      check(b.getAttribute('title') === a.getAttribute('title'), `${name}: title`);
      for (const [from, to] of Object.entries(renamed)) {
        const n = descendants(a, from).length, m = descendants(b, to).length;
        check(n === m, `${name}: ${n} ${from}, ${m} ${to} after reading`);
      }
      // (The upgrade adds rules that reset the outcomes first: as many of ours, or more.)
      const sets = descendants(a, 'setOutcomeValue').length, sets3 = descendants(b, 'qti-set-outcome-value').length;
      check(sets3 >= sets, `${name}: ${sets} setOutcomeValue, ${sets3} after reading`);
      for (const eq of descendants(a, 'equal')) {
        const match = descendants(b, 'qti-equal').find(e => e.getAttribute('tolerance') === eq.getAttribute('tolerance'));
        check(match && match.getAttribute('tolerance-mode') === 'absolute', `${name}: the tolerance is not kept`);
      }
      const imgs = descendants(a, 'img').map(i => i.getAttribute('src'));
      const imgs3 = descendants(b, 'img').map(i => i.getAttribute('src'));
      check(JSON.stringify(imgs) === JSON.stringify(imgs3), `${name}: images ${imgs} became ${imgs3}`);
    } else {
      check(name === 'imsmanifest.xml', `${name}: neither an item, a test nor the manifest`);
      const types = r => descendants(r, 'resource').map(x => x.getAttribute('type')).sort();
      const want = types(a).map(t => t.replace('xmlv2p1', 'xmlv3p0'));
      check(JSON.stringify(types(b)) === JSON.stringify(want), `the manifest's resources: ${types(b)}`);
    }
  }
  // Every file was compared above; the package has an item per question and student, a test per
  // lesson and a figure per student of the two 2D lessons.
  check(items >= 3 * LESSONS.length && items % 3 === 0 && tests === LESSONS.length && figures === 2 * 3,
        `read ${items} items, ${tests} tests, ${figures} figures`);
} catch (e) {
  failures.push(`the reader failed: ${e.stack || e}`);
} finally {
  ws.cleanup();
}
console.log = log;
for (const f of failures) console.log(`FAIL: ${f}`);
console.log(`${failures.length ? 0 : 1} passed, ${failures.length ? 1 : 0} failed (${failures.length} problems)`);
process.exit(failures.length ? 1 : 0);
