// Node tests of the wasm build's book bindings: a book turns and lands through the module, and bad
// options are refused with a TypeError that names them.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { loadEngineForNode } from './load-engine.mjs';

let engine;
before(async () => { engine = await loadEngineForNode(); });

test('node: a book turns forward and back through the bindings and lands', () => {
  const book = engine.Book.create({ pageCount: 6, hardPages: [0] });
  try {
    assert.equal(book.leafCount(), 3);
    assert.equal(book.startTurn('forward'), true);
    const flying = book.frame().filter((leaf) => !leaf.resting);
    assert.equal(flying.length, 1);
    assert.equal(flying[0].hard, true);
    assert.equal(book.advance(0.5), true);
    assert.equal(book.advance(0.6), false);
    assert.equal(book.position(), 1);
    assert.deepEqual(book.frame().map((l) => [l.frontPage, l.backPage, l.resting]), [[0, 1, true], [2, 3, true]]);
    assert.equal(book.startTurn('backward'), true);
    assert.equal(book.frame().find((l) => !l.resting).mirrored, true);
  } finally {
    book.delete();
  }
});

test('node: pagesOnScreen (wasm) shows a resting left page\'s back, a resting right page\'s front, both sides of a turning leaf, no blanks', () => {
  const book = engine.Book.create({ pageCount: 9 });
  try {
    book.jumpTo(2);
    assert.deepEqual(engine.pagesOnScreen(book), [3, 4]);
    assert.equal(book.startTurn('forward'), true);  // leaf 2 (pages 4, 5) lifts off page 6
    assert.deepEqual(engine.pagesOnScreen(book).toSorted((a, b) => a - b), [3, 4, 5, 6]);
    book.jumpTo(0);
    assert.deepEqual(engine.pagesOnScreen(book), [0]);
    book.jumpTo(book.lastPosition());  // the last leaf lies turned over, showing only its blank back
    assert.deepEqual(engine.pagesOnScreen(book), []);
    book.jumpTo(book.lastPosition() - 1);
    assert.deepEqual(engine.pagesOnScreen(book), [7, 8]);
  } finally {
    book.delete();
  }
});

test('node: bad book options throw a TypeError naming the option', () => {
  const cases = [
    [{}, /pageCount/],
    [{ pageCount: -1 }, /pageCount/],
    [{ pageCount: 2.5 }, /pageCount/],
    [{ pageCount: 4, display: 'triple' }, /display/],
    [{ pageCount: 4, binding: 'bottom' }, /binding/],
    [{ pageCount: 4, pageWidth: 0 }, /pageWidth/],
    [{ pageCount: 4, pageHeight: NaN }, /pageHeight/],
    [{ pageCount: 4, turnSeconds: -1 }, /turnSeconds/],
    [{ pageCount: 4, hardPages: 'covers' }, /hardPages/],
    [{ pageCount: 4, hardPages: [7] }, /hardPages\[0\]/],
  ];
  for (const [options, message] of cases) {
    assert.throws(() => engine.Book.create(options), (error) => error instanceof TypeError && message.test(error.message),
      JSON.stringify(options));
  }
  const book = engine.Book.create({ pageCount: 2 });
  assert.throws(() => book.startTurn('sideways'), TypeError);
  book.delete();
});

test('node: leafPointToWorld places a resting page on its side of the spine for every binding', () => {
  const book = engine.Book.create({ pageCount: 4 });
  book.jumpTo(1);
  const [left, right] = book.frame();
  const at = (draw, binding) => engine.leafPointToWorld(draw, binding, 1, 0.7, 0.5);
  assert.ok(at(right, 'left').x > 0.6 && at(left, 'left').x < -0.6);
  assert.ok(at(right, 'right').x < -0.6 && at(left, 'right').x > 0.6);
  assert.ok(at(right, 'top').y < -0.6 && at(left, 'top').y > 0.6);
  book.delete();
});

test('node: numbers crossing into the engine are checked: NaN, strings, fractions and out-of-range indices throw a RangeError naming the argument', () => {
  const book = engine.Book.create({ pageCount: 10 });
  const refused = [
    ['position', () => book.jumpTo(NaN)],
    ['position', () => book.jumpTo('3')],
    ['position', () => book.jumpTo(2.5)],
    ['position', () => book.jumpTo(book.lastPosition() + 1)],
    ['position', () => book.jumpTo(-1)],
    ['page', () => book.positionOfPage(10)],
    ['page', () => book.positionOfPage(undefined)],
    ['seconds', () => book.advance(NaN)],
    ['seconds', () => book.advance(-0.1)],
    ['progress', () => book.setLatestTurnProgress(Infinity)],
    ['progress', () => book.setLatestTurnProgress(1.5)],
    ['pointer position', () => book.gripAt(NaN, 0, 100, 100)],
    ['canvas size', () => book.gripAt(1, 1, 0, 100)],
  ];
  for (const [name, call] of refused) {
    assert.throws(call, (error) => error instanceof RangeError && error.message.startsWith(`conecurl: ${name}`),
      `expected a RangeError naming '${name}'`);
  }
  assert.throws(() => book.startTurn(5), (error) => error instanceof TypeError && /direction/.test(error.message));
  assert.throws(() => book.startHeldTurn(null), (error) => error instanceof TypeError && /grip/.test(error.message));
  assert.throws(() => book.dragHeldTurn({ x: 0, y: 0 }, 1, 1, 100, 100), /no held turn/);
  // The book was left as it was by every refused call, and still works.
  assert.equal(book.position(), 0);
  book.jumpTo(3);
  assert.equal(book.position(), 3);
  assert.equal(book.startTurn('forward'), true);
  book.delete();
});

test('node: Book.create takes schedule \'paper\' or \'smooth\' and refuses others by name; curlAtWith honours a smooth schedule (same key poses, other poses between them)', () => {
  const smoothBook = engine.Book.create({ pageCount: 4, schedule: 'smooth' });
  smoothBook.delete();
  engine.Book.create({ pageCount: 4, schedule: 'paper' }).delete();
  assert.throws(() => engine.Book.create({ pageCount: 4, schedule: 'wavy' }), /schedule must be 'paper' or 'smooth'/);
  const paper = engine.defaultSchedule();
  assert.equal(paper.smooth, false);
  const smooth = { ...paper, smooth: true };
  for (const t of [0, 0.15, 0.4, 1]) {
    assert.ok(Math.abs(engine.curlAtWith(t, smooth, 1).theta - engine.curlAtWith(t, paper, 1).theta) < 1e-12, `theta at ${t}`);
    assert.ok(Math.abs(engine.curlAtWith(t, smooth, 1).apexY - engine.curlAtWith(t, paper, 1).apexY) < 1e-12, `apexY at ${t}`);
  }
  const mid = engine.curlAtWith(0.08, smooth, 1);
  assert.ok(Math.abs(mid.theta - engine.curlAtWith(0.08, paper, 1).theta) > 1e-3, 'the smooth schedule is another curve between the keys');
  assert.ok(mid.theta <= paper.thetaRest && mid.theta >= paper.thetaPhase1);
});

test('node: Book.setPages (wasm) changes the page count and hard pages of a live book, keeps the first visible page, refuses bad values', () => {
  const book = engine.Book.create({ pageCount: 6, hardPages: [0] });
  try {
    book.jumpTo(2);  // pages 3 and 4
    book.setPages(10, [4]);
    assert.equal(book.pageCount(), 10);
    assert.equal(book.firstVisiblePage(), 3);
    assert.equal(book.lastPosition(), 5);
    assert.deepEqual(book.frame().map((l) => [l.leaf, l.hard]), [[1, false], [2, true]]);
    book.setPages(2, []);
    assert.equal(book.firstVisiblePage(), 1);
    assert.throws(() => book.setPages(-1, []), { name: 'TypeError', message: /pageCount/ });
    assert.throws(() => book.setPages(3, [3]), { name: 'TypeError', message: /hardPages\[0\]/ });
    assert.throws(() => book.setPages(3, 'cover'), { name: 'TypeError', message: /hardPages must be an array/ });
  } finally {
    book.delete();
  }
});

test('node: Book.edgeMarkPlaces (wasm) places each mark on the block its leaf lies in, outside the open pages, and refuses bad marks by name', () => {
  const book = engine.Book.create({ pageCount: 100 });
  try {
    book.jumpTo(20);
    const marks = [{ page: 4, kind: 'tab' }, { page: 90, kind: 'tab' }, { page: 60, kind: 'tick' }, { page: 500, kind: 'tab' }];
    const places = book.edgeMarkPlaces(marks, 1200, 800);
    const [left, right] = book.openPagePlaces(1200, 800);
    // Ticks first; a page past the book shows nowhere.
    assert.deepEqual(places.map((p) => [p.mark, p.page, p.kind, p.turned]), [[2, 60, 'tick', false], [0, 4, 'tab', true], [1, 90, 'tab', false]]);
    for (const place of places) {
      if (place.turned) assert.ok(place.x + place.width <= left.x + 1e-6);
      else assert.ok(place.x >= right.x + right.width - 1e-6);
    }
    assert.throws(() => book.edgeMarkPlaces([{ page: 1, kind: 'dot' }], 1200, 800),
      { name: 'TypeError', message: "conecurl: edge marks[0].kind must be 'tab' or 'tick'" });
    assert.throws(() => book.edgeMarkPlaces([{ page: -1, kind: 'tab' }], 1200, 800),
      { name: 'TypeError', message: 'conecurl: edge marks[0].page must be a page index (a whole number from 0)' });
    assert.throws(() => book.edgeMarkPlaces('tabs', 1200, 800), { name: 'TypeError' });
  } finally {
    book.delete();
  }
});
