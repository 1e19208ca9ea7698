// Node tests of the `resolution` option's adaptation (web/src/surfaces/moving-resolution.js), fed
// frame times by hand: late frames lower the moving frames' scale to the floor, a cut that does not
// make frames sooner is taken back, frames on time raise the scale step by step, a pause between
// turns is not a late frame, and fixed settings never adapt.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { MovingResolution, RESOLUTION_FLOOR } from '../../web/src/surfaces/moving-resolution.js';

/** Feeds frames `interval` ms apart from `start` (all moving unless `moving` is false); returns each answer. */
function feed(resolution, { start = 0, interval, count, ratio = 3, moving = true }) {
  const answers = [];
  for (let i = 0; i < count; i++) answers.push(resolution.nextScale(start + i * interval, moving, ratio));
  return answers;
}

test('node: resolution auto on a screen of ratio 1.5 or less never changes the scale, however late the frames', () => {
  for (const ratio of [1, 1.25, RESOLUTION_FLOOR]) {
    const resolution = new MovingResolution('auto');
    assert.deepEqual(feed(resolution, { interval: 200, count: 20, ratio }), Array(20).fill(null));
    assert.equal(resolution.scale, 1);
  }
});

test('node: resolution auto at ratio 3 lowers the scale after two late frames in a row, to 1.5 device px per CSS px at the lowest, and keeps it when frames come sooner', () => {
  const resolution = new MovingResolution('auto');
  // The first moving frame has no interval; the next is one late frame (not enough); the third lowers.
  assert.deepEqual(feed(resolution, { interval: 100, count: 3 }), [null, null, 0.5]);
  assert.equal(resolution.scale, RESOLUTION_FLOOR / 3);
  // At the lower scale frames come in 40 ms instead of 100: the cut paid, it stays (and 40 ms frames,
  // still late, cut no further: the floor is reached).
  assert.deepEqual(feed(resolution, { start: 240, interval: 40, count: 20 }), Array(20).fill(null));
  assert.equal(resolution.scale, 0.5);
});

test('node: resolution auto takes back a cut after which frames come no sooner (the first frame after it aside), and tries none for 300 frames', () => {
  const resolution = new MovingResolution('auto');
  const answers = feed(resolution, { interval: 100, count: 8 });
  // Cut at the third frame; five frames after it, the four judged as late as before: back to 1.
  assert.deepEqual(answers, [null, null, 0.5, null, null, null, null, 1]);
  const held = feed(resolution, { start: 800, interval: 100, count: 299 });
  assert.deepEqual(held.filter((a) => a !== null), []);
  const after = feed(resolution, { start: 800 + 299 * 100, interval: 100, count: 4 });
  assert.deepEqual(after.filter((a) => a !== null), [0.5]);
  // A cut that pays only a little (frames 95% as long) is taken back too.
  const little = new MovingResolution('auto');
  feed(little, { interval: 100, count: 3 });
  const judged = feed(little, { start: 300, interval: 95, count: 5 });
  assert.deepEqual(judged.filter((a) => a !== null), [1]);
});

test('node: resolution auto lowers a little late frame a little: to the scale whose pixels would have fit, halving at most', () => {
  for (const interval of [21, 25, 40]) {
    const resolution = new MovingResolution('auto');
    assert.equal(feed(resolution, { interval, count: 3, ratio: 6 })[2], Math.sqrt((1000 / 60) / interval));
  }
  const slow = new MovingResolution('auto');
  assert.equal(feed(slow, { interval: 500, count: 3, ratio: 6 })[2], 0.5);
  // Frames on time (up to 1.1 frames of 60 Hz) or a little late but under 1.25 frames lower nothing.
  assert.deepEqual(feed(new MovingResolution('auto'), { interval: 20, count: 50 }), Array(50).fill(null));
});

test('node: resolution auto raises the scale a step (x1.2) after 45 frames on time, up to the screen ratio', () => {
  const resolution = new MovingResolution('auto');
  feed(resolution, { interval: 100, count: 3 });
  assert.equal(resolution.scale, 0.5);
  const onTime = feed(resolution, { start: 1000, interval: 1000 / 60, count: 60 });
  // The first five frames judge the cut (sooner: kept), then 45 on time raise it.
  assert.deepEqual(onTime.filter((a) => a !== null), [0.6]);
  assert.equal(onTime.indexOf(0.6), 49);
  feed(resolution, { start: 2000, interval: 1000 / 60, count: 1000 });
  assert.equal(resolution.scale, 1);
});

test('node: resolution auto does not take the pause between two turns (no moving frame) for a late frame', () => {
  const resolution = new MovingResolution('auto');
  const answers = [];
  for (let turn = 0; turn < 5; turn++) {
    answers.push(...feed(resolution, { start: turn * 2000, interval: 1000 / 60, count: 30 }));
    answers.push(resolution.nextScale(turn * 2000 + 1000, false, 3));  // resting frames between turns
  }
  assert.ok(answers.every((a) => a === null));
  assert.equal(resolution.scale, 1);
});

test("node: resolution 'full' and a number are fixed: the scale is set on the first frame, moving or not, and never adapts", () => {
  const full = new MovingResolution('full');
  assert.deepEqual(feed(full, { interval: 300, count: 10 }), Array(10).fill(null));
  const fixed = new MovingResolution(1.5);
  assert.equal(fixed.nextScale(0, false, 3), 0.5);
  assert.deepEqual(feed(fixed, { start: 10, interval: 300, count: 10 }), Array(10).fill(null));
  assert.equal(fixed.nextScale(5000, true, 2), 0.75);  // the screen's ratio changed (a zoom)
  const above = new MovingResolution(4);
  assert.equal(above.nextScale(0, true, 3), null);  // never sharper than the screen
  assert.equal(above.scale, 1);
});

test('node: changing the setting live takes effect at the next frame: a fixed scale to auto climbs back from there', () => {
  const resolution = new MovingResolution(1.5);
  assert.equal(resolution.nextScale(0, true, 3), 0.5);
  resolution.setting = 'full';
  assert.equal(resolution.nextScale(16, true, 3), 1);
  resolution.setting = 1.5;
  assert.equal(resolution.nextScale(32, true, 3), 0.5);
  resolution.setting = 'auto';
  const answers = feed(resolution, { start: 48, interval: 1000 / 60, count: 46 });
  assert.deepEqual(answers.filter((a) => a !== null), [0.6]);
});
