// The package's engine binds only what the package uses; the test build adds the readbacks and
// references tests call. Held here so neither list drifts: the package build lacks every test-only
// name, the test build has each, and no shipped source (web/src, web/demo) calls one.
import test from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { loadEngineForNode } from './load-engine.mjs';

// What CONECURL_TEST_BINDINGS adds in cpp/bindings/: [where, name].
const TEST_ONLY = [
  ['module', 'curlNormalFiniteDifference'], ['module', 'coneBeta'], ['module', 'leafPointToWorld'],
  ['module', 'leafNormalToWorld'], ['module', 'heapBytesInUse'],
  ['Book', 'frame'], ['Book', 'viewProjection'], ['Book', 'gripPixel'], ['Book', 'resetZoom'],
  ['BookRenderer', 'captureLeaf'], ['BookRenderer', 'gridPoints'],
];
const lookup = (engine, [where, name]) => (where === 'module' ? engine[name] : engine[where].prototype[name]);

test('node: the package build of the engine lacks every test-only binding, the test build has each', async () => {
  const shipped = await loadEngineForNode({ build: 'package' });
  const testing = await loadEngineForNode({ build: 'test' });
  for (const entry of TEST_ONLY) {
    assert.equal(typeof lookup(shipped, entry), 'undefined', `package build binds ${entry.join('.')}`);
    assert.equal(typeof lookup(testing, entry), 'function', `test build lacks ${entry.join('.')}`);
  }
  // What the package and its demo do call is in both.
  for (const name of ['curlAt', 'curlAtWith', 'defaultSchedule', 'curlPoint', 'pagesOnScreen']) {
    assert.equal(typeof shipped[name], 'function', name);
  }
  for (const name of ['tick', 'requestTurn']) assert.equal(typeof shipped.FrameLoop.prototype[name], 'function', name);
  for (const name of ['readPixels', 'setPageImage', 'setPageImageRows', 'gridRows']) assert.equal(typeof shipped.BookRenderer.prototype[name], 'function', name);
});

test('node: no shipped source (web/src, web/demo) calls a test-only binding of the engine', () => {
  const root = new URL('../../', import.meta.url).pathname;
  const files = ['web/src', 'web/demo'].flatMap((dir) => fs.readdirSync(path.join(root, dir), { recursive: true })
    .filter((name) => /\.(m?js|html)$/.test(name)).map((name) => path.join(dir, name)));
  assert.ok(files.length > 20, `found ${files.length} files`);
  for (const file of files) {
    const source = fs.readFileSync(path.join(root, file), 'utf8');
    for (const [, name] of TEST_ONLY) {
      assert.doesNotMatch(source, new RegExp(`\\.${name}\\(`), `${file} calls ${name}(), which only the test build binds`);
    }
  }
});
