// Node tests of the page sound's mapping from a leaf's angular speed to the rustle (page-sound.js
// rustleFor): silent at rest, louder and brighter as the leaf goes faster, capped at a fling, lower
// for a hard leaf. The Web Audio graph itself is tested in the browser (tests/browser/sound.spec.js).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { FULL_SPEED, rustleFor } from '../../web/src/book/page-sound.js';

test('node: the rustle is silent at rest, grows louder and brighter with angular speed up to a fling, and ignores bad speeds', () => {
  assert.equal(rustleFor(0, false).gain, 0);
  let last = rustleFor(0, false);
  for (let speed = 0.25; speed <= FULL_SPEED; speed += 0.25) {
    const now = rustleFor(speed, false);
    assert.ok(now.gain > last.gain, `gain at ${speed} rad/s`);
    assert.ok(now.cutoff > last.cutoff, `cutoff at ${speed} rad/s`);
    last = now;
  }
  assert.deepEqual(rustleFor(3 * FULL_SPEED, false), rustleFor(FULL_SPEED, false));  // a fling is as loud as it gets
  // A slow drag (half a radian a second) whispers: under a fiftieth of a fling's gain.
  assert.ok(rustleFor(0.5, false).gain < rustleFor(FULL_SPEED, false).gain / 50);
  for (const bad of [NaN, -1, Infinity, -Infinity]) {
    const { gain, cutoff } = rustleFor(bad, false);
    assert.ok(Number.isFinite(gain) && Number.isFinite(cutoff) && gain >= 0, String(bad));
  }
});

test('node: a hard leaf rustles lower than a soft one at every speed, just as loud', () => {
  for (let speed = 0; speed <= FULL_SPEED; speed += 1) {
    const soft = rustleFor(speed, false);
    const hard = rustleFor(speed, true);
    assert.ok(hard.cutoff < soft.cutoff, `${speed} rad/s`);
    assert.equal(hard.gain, soft.gain);
  }
});
