// What the qti tests share: the reader's packages (installed by scripts/install-qti-reader.sh
// into BUILD/qti-reader), a package written by `collide worksheet --format qti`, its files read
// with jszip (CRC-32 checked) and its XML parsed with xmldom, every parser message an error.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

export function reader(dir) {
  if (!existsSync(join(dir, 'node_modules', '@citolab', 'qti-convert'))) {
    // Set-up tried and npm could not install it: skipped (ctest's SKIP_RETURN_CODE 77), saying why.
    const why = join(dir, 'not-installed.txt');
    if (existsSync(why)) {
      console.error('SKIPPED: the QTI reader could not be installed at set-up (scripts/install-qti-reader.sh needs ' +
                    'the npm registry once):\n' + readFileSync(why, 'utf8'));
      process.exit(77);
    }
    console.error(`the QTI reader is not installed in ${dir}: run scripts/install-qti-reader.sh BUILD_DIR ` +
                  '(scripts/build.sh does; it needs npm and, the first time, the npm registry)');
    process.exit(1);
  }
  const require = createRequire(join(dir, 'package.json'));
  return { dir, JSZip: require('jszip'), DOMParser: require('@xmldom/xmldom').DOMParser };
}

// `collide worksheet LESSONS -o TMP/ws --format qti,...`: the directory, removed by cleanup().
export function worksheet(collide, lessons, students, seed, format = 'qti') {
  const tmp = mkdtempSync(join(tmpdir(), 'collide-qti-'));
  const out = join(tmp, 'ws');
  execFileSync(collide, ['worksheet', ...lessons, '-o', out, '--students', String(students), '--seed', String(seed),
                         '--format', format], { env: { ...process.env, PATH: '/nonexistent' }, stdio: 'pipe' });
  return { tmp, out, cleanup: () => rmSync(tmp, { recursive: true, force: true }) };
}

// The archive's files in order, name -> Buffer; throws for a bad CRC or a broken archive.
export async function unzip(JSZip, bytes) {
  const zip = await JSZip.loadAsync(bytes, { checkCRC32: true });
  const files = new Map();
  for (const name of Object.keys(zip.files)) {
    const entry = zip.files[name];
    if (!entry.dir) files.set(name, await entry.async('nodebuffer'));
  }
  return files;
}

// The document, or throws with every message the parser gave (warnings too).
export function parseXml(DOMParser, text, name) {
  const messages = [];
  const parser = new DOMParser({ onError: (level, message) => messages.push(`${name}: ${level}: ${message}`) });
  let doc;
  try {
    doc = parser.parseFromString(text, 'text/xml');
  } catch (e) {
    messages.push(`${name}: ${e.message}`);
  }
  if (messages.length) throw new Error(messages.join('\n'));
  return doc;
}

export function elements(node) {
  return Array.from(node.childNodes).filter(n => n.nodeType === 1);
}

export function descendants(node, localName) {
  const out = [];
  const walk = n => {
    for (const c of elements(n)) {
      if (!localName || c.localName === localName) out.push(c);
      walk(c);
    }
  };
  walk(node);
  return out;
}

export function readJson(path) { return JSON.parse(readFileSync(path, 'utf8')); }
