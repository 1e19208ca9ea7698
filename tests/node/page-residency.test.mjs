// Node tests of the page cache policy (web/src/pages/page-residency.js): which pages
// are wanted in what order, the capacity, and which resident pages go first.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  MAX_TURNS_IN_FLIGHT, PageCache, pagesToRelease, textureCapacity, wantedPages,
} from '../../web/src/pages/page-residency.js';


test('node: textureCapacity holds the load window both ways plus four, and never less than a full screen of leaves', () => {
  assert.equal(textureCapacity(1), 2 + 2 * MAX_TURNS_IN_FLIGHT);
  assert.equal(textureCapacity(4), 14);
  assert.equal(textureCapacity(10), 24);
});

test('node: wantedPages puts pages on screen first, then neighbours outward (next before previous), within capacity', () => {
  const wanted = wantedPages({ onScreen: [5, 6], first: 5, last: 6, loadWindow: 2, pageCount: 100, capacity: 14 });
  assert.deepEqual(wanted, [5, 6, 7, 4, 8, 3]);
  // The start and the end of the book clip the window.
  assert.deepEqual(wantedPages({ onScreen: [0], first: 0, last: 0, loadWindow: 3, pageCount: 100, capacity: 14 }), [0, 1, 2, 3]);
  assert.deepEqual(wantedPages({ onScreen: [99], first: 99, last: 99, loadWindow: 2, pageCount: 100, capacity: 14 }), [99, 98, 97]);
  // A full capacity stops the window; pages on screen are all kept even past it.
  const burst = [9, 10, 11, 12, 13, 14, 15, 16];
  assert.deepEqual(wantedPages({ onScreen: burst, first: 15, last: 16, loadWindow: 4, pageCount: 100, capacity: 10 }), [...burst, 17, 18]);
  assert.deepEqual(wantedPages({ onScreen: burst, first: 15, last: 16, loadWindow: 4, pageCount: 100, capacity: 4 }), burst);
});

test('node: pagesToRelease releases only beyond capacity, never a wanted page, the longest unwanted first', () => {
  const lastWanted = new Map([[1, 5], [2, 1], [3, 9], [4, 3], [5, 10]]);
  assert.deepEqual(pagesToRelease({ resident: [1, 2, 3, 4, 5], wanted: [5], lastWanted, capacity: 5 }), []);
  assert.deepEqual(pagesToRelease({ resident: [1, 2, 3, 4, 5], wanted: [5], lastWanted, capacity: 3 }), [2, 4]);
  assert.deepEqual(pagesToRelease({ resident: [1, 2, 3, 4, 5], wanted: [2, 4, 5], lastWanted, capacity: 3 }), [1, 3]);
  // Nothing unwanted to release: the wanted pages stay even over capacity.
  assert.deepEqual(pagesToRelease({ resident: [1, 2], wanted: [1, 2], lastWanted, capacity: 1 }), []);
});

test('node: wantedPages stops at the ends of the book and at capacity, so a huge loadWindow does not hang the book', { timeout: 10_000 }, () => {
  // loadWindow 1e12 is a valid option; a loop over every distance would run for hours (the timeout
  // catches a hang, it does not measure speed).
  const wanted = wantedPages({ onScreen: [5], first: 5, last: 5, loadWindow: 1e12, pageCount: 12, capacity: textureCapacity(1e12) });
  assert.deepEqual(wanted, [5, 6, 4, 7, 3, 8, 2, 9, 1, 10, 0, 11]);
  assert.deepEqual(wantedPages({ onScreen: [500], first: 500, last: 500, loadWindow: 1e12, pageCount: 1e6, capacity: 5 }), [500, 501, 499, 502, 498]);
});

test('node: PageCache walking through a 1000-page book wants the open pages and their neighbours, and never keeps more than its capacity, least recently wanted going first', () => {
  const cache = new PageCache(4);
  assert.equal(cache.capacity, textureCapacity(4));
  let resident = [];
  let most = 0;
  for (let first = 1; first + 1 < 1000; first += 2) {
    const wanted = cache.want({ onScreen: [first, first + 1], first, last: first + 1, loadWindow: 4, pageCount: 1000 });
    assert.deepEqual(wanted.slice(0, 2), [first, first + 1], 'the open pages come first');
    assert.ok(wanted.every((page) => page >= 0 && page < 1000));
    resident = [...new Set([...resident, ...wanted])];
    const released = cache.release(resident);
    assert.ok(released.every((page) => !cache.wanted.has(page)), 'a wanted page is never let go');
    resident = resident.filter((page) => !released.includes(page));
    most = Math.max(most, resident.length);
    if (first > 40) assert.ok(resident.every((page) => Math.abs(page - first) <= 12), `far pages were let go (at ${first}: ${resident})`);
  }
  assert.ok(most <= cache.capacity, `at most ${cache.capacity} resident, saw ${most}`);
});

test('node: PageCache counts loads in flight and pages settled for progress, and whenIdle resolves when the last load ends', async () => {
  const cache = new PageCache(1, 5);
  assert.equal(cache.stateOf(3), 'idle');
  cache.startLoad(0);
  cache.startLoad(1);
  let idle = false;
  const waiting = cache.whenIdle().then(() => { idle = true; });
  cache.setState(0, 'loaded');
  assert.deepEqual(cache.endLoad(), { loaded: 1, total: 5, pending: 1 });
  cache.setState(1, 'failed');
  assert.deepEqual(cache.endLoad(), { loaded: 2, total: 5, pending: 0 });
  await waiting;
  assert.equal(idle, true);
  cache.setState(0, 'idle');  // let go: no longer counted as loaded
  cache.startLoad(2);
  cache.setState(2, 'loaded');
  assert.deepEqual(cache.endLoad(), { loaded: 2, total: 5, pending: 0 });
});

test('node: FirstView admits only the pages on screen until released, those a turn brings on screen before the release too, then every page', async () => {
  const { FirstView } = await import('../../web/src/pages/early-loads.js');
  const first = new FirstView();
  assert.equal(first.admits(7), true, 'before the first update nothing is held back');
  first.update([3, 4]);
  assert.deepEqual([2, 3, 4, 5].map((page) => first.admits(page)), [false, true, true, false]);
  first.update([3, 4, 5, 6]);  // a leaf turning in the frames before the release shows 5 and 6
  assert.deepEqual([4, 5, 6, 7].map((page) => first.admits(page)), [true, true, true, false]);
  let released = false;
  first.whenReleased.then(() => { released = true; });
  first.release();
  await first.whenReleased;
  assert.equal(released, true);
  first.update([9]);
  assert.deepEqual([1, 7, 9].map((page) => first.admits(page)), [true, true, true]);
});
