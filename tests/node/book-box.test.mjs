// Node: the box a book fills is written once (components/book-box.js): <cone-flipbook>'s :host and
// the React and Vue components' container take it from there, so the three cannot drift apart.
import test from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync, statSync } from 'node:fs';
import { join, relative } from 'node:path';
import { fileURLToPath } from 'node:url';
import { BOX_CSS, BOX_STYLE } from '../../web/src/components/book-box.js';

const src = fileURLToPath(new URL('../../web/src/', import.meta.url));
const filesUnder = (dir) => readdirSync(dir).flatMap((name) => {
  const path = join(dir, name);
  return statSync(path).isDirectory() ? filesUnder(path) : name.endsWith('.js') ? [path] : [];
});

test('node: the book box\'s style is written once, in components/book-box.js, and element.js, react.js and vue.js use it', () => {
  assert.equal(BOX_CSS, 'display: block; position: relative; width: 100%; aspect-ratio: 16 / 10;');
  assert.deepEqual(Object.keys(BOX_STYLE), ['display', 'position', 'width', 'aspectRatio']);
  // Its one tell-tale, the default aspect ratio, appears nowhere else.
  const elsewhere = filesUnder(src).filter((file) => !file.endsWith('book-box.js') && /aspect-?ratio\s*[:=]?\s*['"`]?\s*16/i.test(readFileSync(file, 'utf8')));
  assert.deepEqual(elsewhere.map((file) => relative(src, file)), []);
  for (const entry of ['element.js', 'react.js', 'vue.js']) {
    const source = readFileSync(join(src, entry), 'utf8');
    assert.match(source, /^import \{[^}]*\bBOX_(CSS|STYLE)\b[^}]*\} from '\.\/components\/book-box\.js';$/m, `${entry} imports book-box.js`);
    assert.match(source, /\bBOX_(CSS|STYLE)\b(?!\s*=)/, `${entry} uses it`);
  }
});
