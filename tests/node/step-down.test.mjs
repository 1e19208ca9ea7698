// The sizes a large reduction steps through where a browser's resize samples (web/src/pages/step-down.js).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { halvings } from '../../web/src/pages/step-down.js';

test('node: halvings steps a large reduction down by halves (rounded up) until the last step is 2x or less; none within 2x; a side within 2x stays', () => {
  assert.deepEqual(halvings({ width: 1600, height: 2000 }, { width: 300, height: 375 }),
    [{ width: 800, height: 1000 }, { width: 400, height: 500 }]);
  assert.deepEqual(halvings({ width: 1237, height: 1601 }, { width: 150, height: 194 }),
    [{ width: 619, height: 801 }, { width: 310, height: 401 }, { width: 155, height: 201 }]);
  // A side already within 2x of its target is left as it is (a target of another aspect).
  assert.deepEqual(halvings({ width: 500, height: 2000 }, { width: 400, height: 400 }), [{ width: 500, height: 1000 }, { width: 500, height: 500 }]);
  assert.deepEqual(halvings({ width: 1600, height: 2000 }, { width: 800, height: 1000 }), []);
  assert.deepEqual(halvings({ width: 1000, height: 1000 }, { width: 501, height: 501 }), []);
  assert.deepEqual(halvings({ width: 300, height: 300 }, { width: 600, height: 600 }), []);
  for (const [from, to] of [[[4000, 3000], [90, 60]], [[16384, 200], [7, 1]]]) {
    const steps = halvings({ width: from[0], height: from[1] }, { width: to[0], height: to[1] });
    const last = steps.at(-1);
    assert.ok(last.width <= 2 * to[0] && last.height <= 2 * to[1], `${from} -> ${to}: the last step ${JSON.stringify(last)} is within 2x`);
    const halved = (length, target) => (length > 2 * target ? Math.ceil(length / 2) : length);
    steps.reduce((prev, step) => {
      assert.deepEqual(step, { width: halved(prev.width, to[0]), height: halved(prev.height, to[1]) });
      return step;
    }, { width: from[0], height: from[1] });
  }
});
