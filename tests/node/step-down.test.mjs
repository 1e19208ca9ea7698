// The sizes a reduction steps through where a browser's resize takes one sample a pixel (web/src/pages/step-down.js).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { reductionSteps } from '../../web/src/pages/step-down.js';

const size = (width, height) => ({ width, height });

test('node: reductionSteps halves each side (rounded up) while over 2x its target, then enlarges a side left over 1.25x to twice its target, so every pass is a halving; none within 1.25x', () => {
  assert.deepEqual(reductionSteps(size(1600, 2000), size(370, 463)), [size(800, 1000), size(400, 500)]);  // 400/370: direct
  assert.deepEqual(reductionSteps(size(1600, 2000), size(300, 375)), [size(800, 1000), size(400, 500), size(600, 750)]);  // 400/300: 1.33x
  // The published manual's page: 1236 x 1600 for a 675 x 874 texture (1.83x), enlarged to 1350 x 1748 and halved.
  assert.deepEqual(reductionSteps(size(1236, 1600), size(675, 874)), [size(1350, 1748)]);
  assert.deepEqual(reductionSteps(size(1237, 1601), size(150, 194)), [size(619, 801), size(310, 401), size(155, 201)]);
  // A side already within 1.25x of its target is left as it is (a target of another aspect).
  assert.deepEqual(reductionSteps(size(500, 2000), size(450, 400)), [size(500, 1000), size(500, 500)]);
  assert.deepEqual(reductionSteps(size(1000, 1000), size(801, 801)), []);
  assert.deepEqual(reductionSteps(size(1600, 2000), size(800, 1000)), []);  // exactly 2x: one halving
  assert.deepEqual(reductionSteps(size(300, 300), size(600, 600)), []);
  for (const [from, to] of [[[4000, 3000], [90, 60]], [[16384, 200], [7, 1]], [[999, 777], [500, 300]]]) {
    const steps = reductionSteps(size(...from), size(...to));
    const last = steps.at(-1);
    const ratios = [last.width / to[0], last.height / to[1]];
    assert.ok(ratios.every((r) => r <= 1.25 || r === 2), `${from} -> ${to}: the last pass is direct or a halving (${ratios})`);
    const halved = (length, target) => (length > 2 * target ? Math.ceil(length / 2) : length);
    steps.slice(0, -1).reduce((prev, step) => {
      assert.deepEqual(step, size(halved(prev.width, to[0]), halved(prev.height, to[1])));
      return step;
    }, size(...from));
  }
});
