// The published reader's first spread within issue 38's JavaScript budget, as built (dist/reader/): a
// count of gzip bytes, recomputed here from the chunks bundle.json says load first, never its own sum.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { FIRST_SPREAD_TARGETS } from '../../scripts/bench/first-spread-targets.mjs';

const root = new URL('../../', import.meta.url).pathname;
const BUDGET = FIRST_SPREAD_TARGETS.scriptBytes;  // gzip -9 bytes of JavaScript before the first spread

test('node: the published reader loads at most 45 KB gzip of JavaScript, in at most 3 files, before its first spread; the package glue is closure-compiled (needs dist/ built)', () => {
  const bundle = JSON.parse(fs.readFileSync(path.join(root, 'dist/reader/bundle.json'), 'utf8'));
  const first = [bundle.entry, ...bundle.preload];
  const sizes = first.map((file) => zlib.gzipSync(fs.readFileSync(path.join(root, 'dist/reader', file)), { level: 9 }).length);
  const total = sizes.reduce((sum, size) => sum + size, 0);
  assert.equal(total, bundle.firstSpreadGzip, 'bundle.json\'s firstSpreadGzip is the sum of its first files');
  assert.ok(first.length <= 3, `the first spread loads ${first.length} JavaScript files: ${first.join(', ')}`);
  assert.ok(total <= BUDGET, `the first spread's JavaScript is ${(total / 1024).toFixed(1)} KB gzip (${first.map((file, i) => `${file} ${sizes[i]}`).join(', ')}), over ${BUDGET / 1024} KB`);
  // Closure renames Embind's internals (about 2 KB of the budget); the test build keeps them.
  const glue = (build) => fs.readFileSync(path.join(root, build, 'conecurl-engine.mjs'), 'utf8');
  assert.doesNotMatch(glue('dist'), /\bcraftInvokerFunction\b/, 'the package build\'s glue was built without closure: see scripts/build-wasm.sh');
  assert.match(glue('dist/test'), /\bcraftInvokerFunction\b/);
});
