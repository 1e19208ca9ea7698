// Node: the documentation keeps up with the code. Every option, every event and every public member of
// the Flipbook class (read at runtime from the modules, not parsed from their source) is named in
// docs/api.md as inline code, every attribute of <cone-flipbook> with its option in
// docs/element-and-frameworks.md, and every relative link in README.md and docs/*.md points at a file that
// exists and, with a #anchor, at a heading there (GitHub's slugs).
import test from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { DEFAULTS, OPTION_NAMES } from '../../web/src/book/options.js';
import { BOOK_EVENTS } from '../../web/src/book/book-events.js';
import { BookController } from '../../web/src/book/book-controller.js';
import { Flipbook } from '../../web/src/book/flipbook.js';
import { StaticBook } from '../../web/src/book/static-book.js';
import { ATTRIBUTES } from '../../web/src/components/element-attributes.js';

const root = fileURLToPath(new URL('../../', import.meta.url));
const read = (file) => fs.readFileSync(path.join(root, file), 'utf8');

/** Markdown without its fenced code blocks (their lines are code, not headings or links). */
function withoutFences(markdown) {
  const kept = [];
  let fence = null;
  for (const line of markdown.split('\n')) {
    const opening = /^\s*(`{3,}|~{3,})/.exec(line);
    if (fence === null && opening) fence = opening[1];
    else if (fence !== null && line.trim().startsWith(fence)) fence = null;
    else if (fence === null) kept.push(line);
  }
  return kept.join('\n');
}

/** The inline code spans of a Markdown text (fenced blocks left out), trimmed. */
function inlineCode(markdown) {
  return [...withoutFences(markdown).matchAll(/(`+)([^`]|[^`][\s\S]*?[^`])\1(?!`)/g)].map((m) => m[2].trim());
}

// A member is named when a code span is the name itself, optionally on an object (`book.page`,
// `Flipbook.create`) and optionally called (`flip(index, { animate })`).
const namesMember = (span, name) => new RegExp(`^(?:[A-Za-z_$][\\w$]*\\.)?${name}(?:\\(.*\\))?$`).test(span);

/** The public members of a class: own names of its prototype and its statics, none starting with '_'. */
function publicMembers(Class, { statics = false } = {}) {
  const names = Object.getOwnPropertyNames(Class.prototype);
  if (statics) names.push(...Object.getOwnPropertyNames(Class).filter((n) => !['length', 'name', 'prototype'].includes(n)));
  return names.filter((n) => n !== 'constructor' && !n.startsWith('_'));
}

test('node: docs/api.md names every option, every option with a default, and every event as inline code', () => {
  const spans = new Set(inlineCode(read('docs/api.md')));
  const options = [...new Set([...OPTION_NAMES, ...Object.keys(DEFAULTS), 'pdf', 'pdfWorkerSrc', 'document'])];
  assert.ok(options.length > 20 && BOOK_EVENTS.length > 10, 'the lists read from the modules look empty');
  const missing = [...options.map((name) => `option ${name}`), ...BOOK_EVENTS.map((name) => `event ${name}`)]
    .filter((entry) => !spans.has(entry.split(' ')[1]));
  assert.deepEqual(missing, [], `not in docs/api.md as \`name\`: ${missing.join(', ')}`);
});

test('node: docs/api.md names every public method and property of Flipbook and StaticBook as inline code', () => {
  const spans = inlineCode(read('docs/api.md'));
  const members = [...new Set([
    ...publicMembers(BookController),
    ...publicMembers(Flipbook, { statics: true }),
    ...publicMembers(StaticBook, { statics: true }),
  ])];
  for (const expected of ['next', 'flip', 'previewTurn', 'destroy', 'create', 'page']) {
    assert.ok(members.includes(expected), `the members read from the classes lack ${expected}`);
  }
  const missing = members.filter((name) => !spans.some((span) => namesMember(span, name)));
  assert.deepEqual(missing, [], `members not in docs/api.md as inline code: ${missing.join(', ')}`);
});

test('node: docs/element-and-frameworks.md names every attribute of <cone-flipbook> with its option, in the attributes table', () => {
  const doc = read('docs/element-and-frameworks.md');
  const rows = doc.split('\n').filter((line) => line.startsWith('| `'));
  const missing = Object.entries(ATTRIBUTES).filter(([attribute, [option]]) => !rows.some((row) => {
    const [names, options] = row.split('|').slice(1, 3).map((cell) => inlineCode(cell));
    return names.includes(attribute) && (options.includes(option) || (options.length === 0 && option === attribute));
  })).map(([attribute]) => attribute);
  assert.ok(Object.keys(ATTRIBUTES).length > 20, 'the attributes read from the module look empty');
  assert.deepEqual(missing, [], `attributes not in the table with their option: ${missing.join(', ')}`);
});

/** GitHub's anchor of a heading: lowercase, punctuation but '-' and '_' dropped, spaces to '-'. */
export function slug(heading) {
  return heading.trim().toLowerCase().replace(/[^\p{L}\p{N}\s_-]/gu, '').replace(/\s/g, '-');
}

/** The anchors of a Markdown file's headings, with GitHub's -1, -2 ... for repeats. */
function anchors(markdown) {
  const seen = new Map();
  const found = new Set();
  for (const [, text] of withoutFences(markdown).matchAll(/^#{1,6}[ \t]+(.+?)[ \t]*#*[ \t]*$/gm)) {
    const base = slug(text);
    const count = seen.get(base) ?? 0;
    seen.set(base, count + 1);
    found.add(count === 0 ? base : `${base}-${count}`);
  }
  return found;
}

/** Link targets of a Markdown file: [text](target), ![alt](target) and <img src="target">, outside code. */
function linkTargets(markdown) {
  const prose = withoutFences(markdown).replace(/(`+)([^`]|[^`][\s\S]*?[^`])\1(?!`)/g, '');
  const targets = [...prose.matchAll(/!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+"[^"]*")?\s*\)/g)].map((m) => m[1]);
  targets.push(...[...prose.matchAll(/<(?:img|a)\s[^>]*?(?:src|href)="([^"]+)"/g)].map((m) => m[1]));
  return targets;
}

test('node: the slug rule is GitHub\'s', () => {
  assert.equal(slug('The `<cone-flipbook>` element'), 'the-cone-flipbook-element');
  assert.equal(slug('Where the `.wasm` comes from'), 'where-the-wasm-comes-from');
  assert.equal(slug("The package's entries"), 'the-packages-entries');
  assert.equal(slug('Where a press may turn: `turnArea`'), 'where-a-press-may-turn-turnarea');
  assert.equal(slug('snake_case and-dash'), 'snake_case-and-dash');
});

test('node: every relative link in README.md and docs/*.md points at a file that exists, and each #anchor at a heading there', () => {
  const files = ['README.md', ...fs.readdirSync(path.join(root, 'docs')).filter((f) => f.endsWith('.md')).map((f) => `docs/${f}`)];
  const broken = [];
  let checked = 0;
  for (const file of files) {
    for (const target of linkTargets(read(file))) {
      if (/^[a-z][a-z0-9+.-]*:/i.test(target)) continue;  // http:, https:, mailto:
      checked++;
      const [where, anchor] = target.split('#');
      const resolved = where === '' ? path.join(root, file) : path.resolve(path.dirname(path.join(root, file)), decodeURIComponent(where));
      if (!resolved.startsWith(root) || !fs.existsSync(resolved)) {
        broken.push(`${file}: ${target} (no such file)`);
        continue;
      }
      if (anchor !== undefined && resolved.endsWith('.md') && !anchors(fs.readFileSync(resolved, 'utf8')).has(anchor)) {
        broken.push(`${file}: ${target} (no heading with that anchor)`);
      }
    }
  }
  assert.ok(checked > 50, `only ${checked} links found: is the link reader broken?`);
  assert.deepEqual(broken, []);
});
