// Node tests of the layering rules that review alone lets slip: nothing outside web/src reads a
// module's `_private` fields (tests, demo, scripts drive the public API), nor does another module in
// web/src (a subclass reads its base class's through `this`), and every file under web/src holds one
// concern, which shows as a short file (over 350 lines it says why at its top).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { join, relative } from 'node:path';
import { filesUnder, root } from './source-files.mjs';

test('node: no test, demo or script reads a field or method that starts with _ (they use the public API)', () => {
  const files = ['tests', 'web/demo', 'scripts'].flatMap((dir) => filesUnder(join(root, dir), ['.js', '.mjs', '.html', '.ts']));
  assert.ok(files.length > 40, `scanned ${files.length} files`);
  const reads = [];
  for (const file of files) {
    if (file.endsWith('source-rules.test.mjs')) continue;  // this file names the pattern
    readFileSync(file, 'utf8').split('\n').forEach((line, i) => {
      // `._x` as a property access; `window.__flag` (two underscores: the page's own test switches) is not one.
      for (const match of line.matchAll(/\.(_[A-Za-z]\w*)/g)) reads.push(`${relative(root, file)}:${i + 1}: ${match[1]}`);
    });
  }
  assert.deepEqual(reads, []);
});

// A module's `_` members are its own: it reads them on any object (another instance, a lease of its
// budget), and a subclass reads its base class's through `this` (Flipbook's this._build()); no module
// reads another's `_` members on another object (book._build() from flipbook.js).
const stripComments = (source) => source.replace(/\/\*[\s\S]*?\*\//g, '').replace(/(^|[^:'"`])\/\/.*$/gm, '$1');

/** The `_` members a JS source defines: fields it assigns on `this`, and methods, getters and fields of its classes. */
export function privateMembersDefined(source) {
  const code = stripComments(source);
  return new Set([
    ...[...code.matchAll(/\bthis\.(_\w+)\s*(?:=(?!=)|\?\?=|\|\|=|&&=|\+=|-=)/g)].map((m) => m[1]),
    ...[...code.matchAll(/^\s*(?:static\s+)?(?:async\s+)?(?:get\s+|set\s+)?\*?(_\w+)\s*(?:\(|=(?!=))/gm)].map((m) => m[1]),
  ]);
}

/** Every `._name` a JS source reads, as [receiver, name]: receiver 'this' for this._name (or super._name), else 'other'. */
export function privateReads(source) {
  return [...stripComments(source).matchAll(/(\bthis|\bsuper|[\w$\])?]+)\s*\??\.(_[A-Za-z]\w*)/g)]
    .map((m) => [m[1] === 'this' || m[1] === 'super' ? 'this' : 'other', m[2]]);
}

/** Reads in web/src of another module's `_` members: "file: receiver._name". */
export function foreignPrivateReads(sourceRoot) {
  const files = filesUnder(sourceRoot, ['.js']);
  const sources = new Map(files.map((file) => [file, readFileSync(file, 'utf8')]));
  // The modules of a file's base classes (class X extends Y, Y imported from a module of web/src), transitively.
  const baseModules = (file, seen = new Set()) => {
    for (const [, base] of stripComments(sources.get(file)).matchAll(/class\s+\w+\s+extends\s+(\w+)/g)) {
      const from = new RegExp(`import\\s*\\{[^}]*\\b${base}\\b[^}]*\\}\\s*from\\s*['"](\\.{1,2}/[^'"]+)['"]`).exec(sources.get(file))?.[1];
      const module = from && join(file, '..', from);
      if (module && sources.has(module) && !seen.has(module)) {
        seen.add(module);
        baseModules(module, seen);
      }
    }
    return seen;
  };
  const foreign = [];
  for (const file of files) {
    const own = privateMembersDefined(sources.get(file));
    const inherited = new Set([...baseModules(file)].flatMap((base) => [...privateMembersDefined(sources.get(base))]));
    for (const [receiver, name] of privateReads(sources.get(file))) {
      if (own.has(name) || (receiver === 'this' && inherited.has(name))) continue;
      foreign.push(`${relative(sourceRoot, file)}: ${receiver === 'this' ? 'this' : '(another object)'}.${name}`);
    }
  }
  return [...new Set(foreign)];
}

test('node: no module under web/src reads another module\'s _ members, except a subclass its base class\'s through this', () => {
  assert.deepEqual(foreignPrivateReads(join(root, 'web/src')), []);
});

test('node: the _ check sees book._build() from a module that does not define it, and passes this._build() in a subclass', () => {
  assert.deepEqual(privateReads('book._build(); this._events.flush(); // other._x\nsuper._y;'),
    [['other', '_build'], ['this', '_events'], ['this', '_y']]);
  assert.deepEqual([...privateMembersDefined('class A {\n  _open() {}\n  get _size() {}\n  async _load() { this._n = 1; this._m ??= 2; }\n}')].sort(),
    ['_load', '_m', '_n', '_open', '_size']);
});

test('node: every file under web/src has at most 350 lines, or says at its top why it has more', () => {
  const files = filesUnder(join(root, 'web/src'), ['.js']);
  assert.ok(files.length > 20, `scanned ${files.length} files`);
  const long = files.filter((file) => {
    const lines = readFileSync(file, 'utf8').split('\n');
    return lines.length > 350 && !lines.slice(0, 8).some((line) => /Over 350 lines because/.test(line));
  }).map((file) => `${relative(root, file)} (${readFileSync(file, 'utf8').split('\n').length} lines)`);
  assert.deepEqual(long, []);
});

// The layers of web/src, lowest first (docs/architecture.md): a module imports from its own folder or
// from a layer below it, never from one above. The entry points at the top of web/src may import any.
const LAYERS = ['engine', 'pages', 'surfaces', 'input', 'layers', 'viewer', 'document', 'read-aloud', 'book', 'components', '.'];

/** The modules a JS source imports (static and dynamic), comments left out: JSDoc may name any type. */
function importsOf(source) {
  const code = source.replace(/\/\*[\s\S]*?\*\//g, '').replace(/(^|[^:'"`])\/\/.*$/gm, '$1');
  return [...code.matchAll(/(?:^\s*import\s[^'"]*?from\s*|^\s*export\s[^'"]*?from\s*|\bimport\s*\(\s*)['"](\.{1,2}\/[^'"]+)['"]/gm)].map((m) => m[1]);
}

/** Every import in web/src/**.js that goes up the layers: "file -> import (layer -> layer)". */
function upwardImports(sourceRoot) {
  const upward = [];
  for (const file of filesUnder(sourceRoot, ['.js'])) {
    const from = relative(sourceRoot, file).split('/');
    const fromLayer = from.length > 1 ? from[0] : '.';
    for (const target of importsOf(readFileSync(file, 'utf8'))) {
      const to = relative(sourceRoot, join(file, '..', target)).split('/');
      if (to[0] === '..') continue;  // outside web/src: the built engine in dist/
      const toLayer = to.length > 1 ? to[0] : '.';
      if (!LAYERS.includes(fromLayer) || !LAYERS.includes(toLayer)) {
        upward.push(`${from.join('/')} -> ${target}: a folder outside the layers (${fromLayer}, ${toLayer})`);
      } else if (LAYERS.indexOf(toLayer) > LAYERS.indexOf(fromLayer)) {
        upward.push(`${from.join('/')} -> ${target} (${fromLayer} imports ${toLayer}, a layer above it)`);
      }
    }
  }
  return upward;
}

test('node: web/src is folders by layer and no module imports from a layer above its own', () => {
  const sourceRoot = join(root, 'web/src');
  const folders = readdirSync(sourceRoot).filter((name) => statSync(join(sourceRoot, name)).isDirectory());
  assert.deepEqual(folders.sort(), LAYERS.filter((layer) => layer !== '.').sort());
  assert.deepEqual(upwardImports(sourceRoot), []);
});

test('node: the layer check sees an upward import, static or dynamic, and passes one in a comment', () => {
  assert.deepEqual(importsOf("import { a } from '../book/options.js';\nconst m = await import('./x.js');\nexport { b } from './y.js';"),
    ['../book/options.js', './x.js', './y.js']);
  assert.deepEqual(importsOf("/** @param {import('../book/flipbook.js').Flipbook} b */\n// import('../up.js')\nconst url = 'http://x/y';"), []);
});

test('node: only engine/direction.js names the reading directions: every other module asks it what depends on one', () => {
  const sourceRoot = join(root, 'web/src');
  const naming = [];
  for (const file of filesUnder(sourceRoot, ['.js'])) {
    if (relative(sourceRoot, file) === 'engine/direction.js') continue;
    const code = readFileSync(file, 'utf8').replace(/\/\*[\s\S]*?\*\//g, '').replace(/(^|[^:'"`])\/\/.*$/gm, '$1');
    code.split('\n').forEach((line, i) => {
      if (/['"`](ltr|rtl|vertical)['"`]/.test(line) && !/\?\?\s*'ltr'|direction = 'ltr'|direction: 'ltr'/.test(line)) {
        naming.push(`${relative(sourceRoot, file)}:${i + 1}: ${line.trim()}`);
      }
    });
  }
  assert.deepEqual(naming, []);
});

test('node: docs/architecture.md names every module of web/src', () => {
  const architecture = readFileSync(join(root, 'docs/architecture.md'), 'utf8');
  const files = filesUnder(join(root, 'web/src'), ['.js']).map((file) => relative(join(root, 'web/src'), file));
  assert.ok(files.length > 40, `found ${files.length} modules`);
  assert.deepEqual(files.filter((file) => !architecture.includes(`\`${file.split('/').pop()}\``)), []);
});
