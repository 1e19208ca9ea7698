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
