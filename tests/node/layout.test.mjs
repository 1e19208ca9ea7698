// Node tests of web/src/engine/layout.js, the engine's layout in plain JS for the 2D fallback: its positions,
// page places and zoom equal the wasm engine's, and the generated constants equal the C++ header's.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import * as layout from '../../web/src/engine/layout.js';
import * as generated from '../../dist/engine-constants.js';
import { loadEngineForNode } from './load-engine.mjs';

const BINDING = { ltr: 'left', rtl: 'right', vertical: 'top' };
const SIZES = [{ width: 800, height: 600 }, { width: 300, height: 700 }];
// The default page, and one whose width and height differ from it and from each other.
const PAGES = [{}, { pageWidth: 1.4, pageHeight: 1.1 }];
const MAX_PAGES = 9;

let engine;
before(async () => { engine = await loadEngineForNode(); });

function withBook(options, use) {
  const book = engine.Book.create(options);
  try {
    return use(book);
  } finally {
    book.delete();
  }
}

// Pixel coordinates agree to 1e-6 of the canvas.
function assertRectClose(actual, expected, size, where) {
  const tolerance = 1e-6 * Math.max(size.width, size.height);
  for (const key of ['x', 'y', 'width', 'height']) {
    assert.ok(Math.abs(actual[key] - expected[key]) <= tolerance,
      `${where}: ${key} ${actual[key]}, the engine's ${expected[key]}`);
  }
}

function assertPlacesClose(actual, expected, size, where) {
  assert.deepEqual(actual.map((place) => [place.page, place.turned]), expected.map((place) => [place.page, place.turned]), `${where}: pages, sides`);
  actual.forEach((place, i) => assertRectClose(place, expected[i], size, `${where}, place ${i}`));
}

function assertZoomClose(actual, expected, where) {
  for (const key of ['scale', 'offsetX', 'offsetY']) {
    assert.ok(Math.abs(actual[key] - expected[key]) <= 1e-9, `${where}: ${key} ${actual[key]}, the engine's ${expected[key]}`);
  }
}

/** Calls `check(book, shape, where)` for every display, direction, page shape, page count 0..9 and center on and off. */
function everyBook(check) {
  for (const display of ['single', 'double']) {
    for (const direction of Object.keys(BINDING)) {
      for (const page of PAGES) {
        for (const center of [true, false]) {
          for (let pageCount = 0; pageCount <= MAX_PAGES; pageCount++) {
            const shape = { pageCount, display, direction, center };
            if (page.pageWidth) shape.pageAspect = page.pageWidth / page.pageHeight;
            // Stacks without depth: the 2D surface draws no edge bands, so it centres a closed book on its page alone.
            withBook({ pageCount, display, binding: BINDING[direction], center, thickness: false, ...page }, (book) => {
              check(book, shape, `${pageCount} pages, ${display}, ${direction}, page ${page.pageWidth ?? 'default'}, center ${center}`);
            });
          }
        }
      }
    }
  }
}

// Positions per book over page counts 0..9: single max(1, n) (46), double ceil(n / 2) + 1 (35); each for
// 3 directions, 2 page shapes, center on and off.
const POSITIONS = (46 + 35) * 3 * 2 * 2;

test('node: layout.js positions, first visible and open pages equal the engine Book\'s at every position of 0 to 9 pages (needs the wasm built)', () => {
  let positions = 0;
  everyBook((book, { pageCount, display }, where) => {
    assert.equal(layout.lastPosition(pageCount, display), book.lastPosition(), where);
    for (let page = 0; page < pageCount; page++) {
      assert.equal(layout.positionOfPage(page, pageCount, display), book.positionOfPage(page), `${where}, page ${page}`);
    }
    for (let position = 0; position <= book.lastPosition(); position++) {
      book.jumpTo(position);
      const at = `${where}, position ${position}`;
      const first = layout.firstVisiblePage(position, pageCount, display);
      assert.equal(first, book.firstVisiblePage(), at);
      // Announced: the pages lying open, except at an odd book's blank last spread, its face-down last page.
      const shown = book.openPagePlaces(100, 100).map((place) => place.page).filter((page) => page >= 0).sort((a, b) => a - b);
      assert.deepEqual(layout.openPages(position, pageCount, display), shown.length > 0 || first < 0 ? shown : [first], at);
      positions++;
    }
  });
  assert.equal(positions, POSITIONS);
});

test('node: layout.js restingRect and openPagePlaces equal the engine\'s, unzoomed, zoomed about a point and panned (needs the wasm built)', () => {
  let cases = 0;
  everyBook((book, shape, where) => {
    for (let position = 0; position <= book.lastPosition(); position++) {
      book.jumpTo(position);
      for (const size of SIZES) {
        const { width, height } = size;
        const at = `${where}, position ${position}, ${width}x${height}`;
        const rect = layout.restingRect(size, shape, position);
        assertRectClose(rect, book.restingRect(width, height), size, `${at}: restingRect`);
        assertPlacesClose(layout.openPagePlaces(position, shape, size), book.openPagePlaces(width, height), size, at);

        // A point that moves with the position, so some zooms reach the offset limits and some do not.
        const x = width * ((position * 0.37) % 1);
        const y = height * ((position * 0.61 + 0.2) % 1);
        let zoom = layout.zoomAbout({ scale: 1, offsetX: 0, offsetY: 0 }, 2.5, x, y, width, height);
        assert.equal(book.zoomAbout(2.5, x, y, width, height), 2.5, at);
        for (const [dx, dy] of [[0, 0], [-37, 23], [5000, -5000]]) {
          if (dx !== 0 || dy !== 0) {
            zoom = layout.panBy(zoom, dx, dy, width, height);
            book.panBy(dx, dy, width, height);
          }
          const zoomed = `${at}, zoomed about (${x}, ${y}), panned (${dx}, ${dy})`;
          assertZoomClose(zoom, book.zoom(), zoomed);
          assertRectClose(layout.zoomRect(rect, zoom, width, height), book.restingRect(width, height), size, `${zoomed}: restingRect`);
          assertPlacesClose(layout.openPagePlaces(position, shape, size, zoom), book.openPagePlaces(width, height), size, zoomed);
        }
        book.resetZoom();
        cases++;
      }
    }
  });
  assert.equal(cases, POSITIONS * SIZES.length);
});

test('node: openPagePlaces of a book with turns in flight are where the turns land (needs the wasm built)', () => {
  const size = { width: 640, height: 480 };
  for (const display of ['single', 'double']) {
    withBook({ pageCount: 9, display }, (book) => {
      book.jumpTo(2);
      assert.ok(book.startTurn('forward') && book.startTurn('forward') && book.startTurn('backward') === false);
      assert.ok(book.animating());
      const places = layout.openPagePlaces(book.position(), { pageCount: 9, display }, size);
      assertPlacesClose(places, book.openPagePlaces(size.width, size.height), size, `${display}, two turns in flight`);
    });
  }
});

test('node: dist/engine-constants.js holds every constant of cpp/core/book_constants.hpp under its JS name (needs the wasm built)', () => {
  const header = fs.readFileSync(new URL('../../cpp/core/book_constants.hpp', import.meta.url), 'utf8');
  const expected = {};
  for (const [, camel, value] of header.matchAll(/^inline constexpr [\w:]+ k(\w+) = ([^;]+);/gm)) {
    // A number, or a string literal (the binding names, std::string_view).
    expected[camel.replace(/([a-z0-9])([A-Z])/g, '$1_$2').toUpperCase()] = /^".*"$/.test(value) ? JSON.parse(value) : Number(value);
  }
  assert.equal(Object.keys(expected).length, header.match(/^inline constexpr/gm).length, 'a constant the pattern missed');
  assert.ok(Object.keys(expected).length >= 8, 'book_constants.hpp unexpectedly small');
  assert.deepEqual({ ...generated }, expected, 'dist/engine-constants.js is stale: run bash scripts/build-wasm.sh');
});

test('node: the engine keeps the limits and defaults layout.js exports (needs the wasm built)', () => {
  const { DEFAULT_PAGE_HEIGHT, DEFAULT_PAGE_WIDTH, FRAME_MARGIN } = generated;
  withBook({ pageCount: 30, display: 'double' }, (book) => {
    // The default page.
    assert.equal(book.pageWidth(), DEFAULT_PAGE_WIDTH);
    assert.equal(book.pageHeight(), DEFAULT_PAGE_HEIGHT);
    assert.equal(layout.DEFAULT_PAGE_ASPECT, book.pageWidth() / book.pageHeight());
    // The frame margin: a 2 x 0.8 by 1 spread on a wide canvas fills its height less the margin.
    assert.ok(Math.abs(book.restingRect(1600, 600).height - 600 / FRAME_MARGIN) < 1e-9);
    // Turns in flight: the next one past the limit is refused (from position 1, so both stacks rest too).
    book.jumpTo(1);
    let started = 0;
    while (book.startTurn('forward')) started++;
    assert.equal(started, layout.MAX_TURNS_IN_FLIGHT);
    assert.equal(book.frame().length, layout.MAX_TURNS_IN_FLIGHT + 2);
    // Zoom: MAX_ZOOM is the most it takes, and its pan reaches MAX_ZOOM - 1 each way.
    assert.equal(book.zoomAbout(layout.MAX_ZOOM, 0, 0, 800, 600), layout.MAX_ZOOM);
    assert.throws(() => book.zoomAbout(layout.MAX_ZOOM + 1e-9, 0, 0, 800, 600), RangeError);
    book.panBy(-1e6, 1e6, 800, 600);
    assert.deepEqual(book.zoom(), { scale: layout.MAX_ZOOM, offsetX: -(layout.MAX_ZOOM - 1), offsetY: -(layout.MAX_ZOOM - 1) });
    assert.deepEqual(layout.clampZoom({ scale: 10, offsetX: -1e6, offsetY: 1e6 }),
      { scale: layout.MAX_ZOOM, offsetX: -(layout.MAX_ZOOM - 1), offsetY: layout.MAX_ZOOM - 1 });
  });
  assert.equal(layout.PAPER, `rgb(${generated.PAPER_RED}, ${generated.PAPER_GREEN}, ${generated.PAPER_BLUE})`);
  assert.match(layout.PAPER, /^rgb\(\d{1,3}, \d{1,3}, \d{1,3}\)$/);
});

test('node: a single page fills its box to 1 / SINGLE_FRAME_MARGIN (at least 92%) in the dimension the box limits, on phone boxes, as the engine does (needs the wasm built)', () => {
  const { FRAME_MARGIN, SINGLE_FRAME_MARGIN } = generated;
  assert.ok(1 / SINGLE_FRAME_MARGIN >= 0.92, `SINGLE_FRAME_MARGIN ${SINGLE_FRAME_MARGIN} leaves the page under 92%`);
  // The demo's box on a portrait and a landscape phone, and a square one; tall, default and wide pages.
  for (const size of [{ width: 374, height: 468 }, { width: 828, height: 300 }, { width: 300, height: 300 }]) {
    for (const page of [{}, { pageWidth: 0.5, pageHeight: 1 }, { pageWidth: 1.4, pageHeight: 1.1 }]) {
      for (const direction of Object.keys(BINDING)) {
        for (const display of ['single', 'double']) {
          const shape = { pageCount: 8, display, direction };
          if (page.pageWidth) shape.pageAspect = page.pageWidth / page.pageHeight;
          const rect = layout.restingRect(size, shape, 2);
          const where = `${display}, ${direction}, page ${page.pageWidth ?? 'default'}, ${size.width}x${size.height}`;
          const fill = Math.max(rect.width / size.width, rect.height / size.height);
          assert.ok(Math.abs(fill - 1 / (display === 'single' ? SINGLE_FRAME_MARGIN : FRAME_MARGIN)) < 1e-9, `${where}: fills ${fill}`);
          withBook({ pageCount: 8, display, binding: BINDING[direction], ...page }, (book) => {
            book.jumpTo(2);
            assertRectClose(rect, book.restingRect(size.width, size.height), size, `${where}: restingRect`);
          });
        }
      }
    }
  }
});

test('node: clampZoom treats non-finite values as no zoom, as the engine does', () => {
  // -0 (an offset clamped to -0 at scale 1, as std::clamp gives too) reads as 0.
  const clamped = (zoom) => Object.fromEntries(Object.entries(layout.clampZoom(zoom)).map(([key, value]) => [key, value + 0]));
  assert.deepEqual(clamped({ scale: NaN, offsetX: NaN, offsetY: Infinity }), { scale: 1, offsetX: 0, offsetY: 0 });
  assert.deepEqual(clamped({ scale: 0.5, offsetX: 0.3, offsetY: -0.3 }), { scale: 1, offsetX: 0, offsetY: 0 });
  assert.deepEqual(clamped({ scale: 2, offsetX: 0.5, offsetY: -2 }), { scale: 2, offsetX: 0.5, offsetY: -1 });
});

test('node: one direction module answers what depends on direction, and the engine takes its spine sides (needs the wasm built)', async () => {
  const { DIRECTIONS, directionFacts, freeEdge, halfOf } = await import('../../web/src/engine/direction.js');
  const engine = await loadEngineForNode();
  for (const direction of DIRECTIONS) {
    const { binding } = directionFacts(direction);
    const book = engine.Book.create({ pageCount: 4, binding });
    assert.equal(book.binding(), binding, `the engine keeps ${direction}'s spine side`);
    book.delete();
  }
  assert.deepEqual(DIRECTIONS.map((d) => [freeEdge(d, true), freeEdge(d, false)]), [['left', 'right'], ['right', 'left'], ['top', 'bottom']]);
  assert.deepEqual(DIRECTIONS.map((d) => halfOf(d, 100, 100, 10, 90)), ['left', 'left', 'bottom']);
  assert.throws(() => directionFacts('sideways'), /direction must be 'ltr', 'rtl' or 'vertical', got sideways/);
  assert.throws(() => directionFacts('constructor'), TypeError);
});

test('node: layout.js centres a closed book on its page and its stack\'s edge band as the engine does, for thin, default and thickest paper, soft and hard covers, 0 to 2001 pages (needs the wasm built)', () => {
  const size = { width: 800, height: 600 };
  let cases = 0;
  for (const direction of Object.keys(BINDING)) {
    for (const thickness of [true, 0.001, layout.MAX_LEAF_THICKNESS]) {
      for (const pageCount of [0, 1, 2, 3, 9, 40, 301, 2001]) {
        for (const hard of [[], [0, pageCount - 1], [1]]) {
          const hardPages = hard.filter((p) => p >= 0 && p < pageCount);  // no covers, both covers hard, the first leaf's back hard
          withBook({ pageCount, display: 'double', binding: BINDING[direction], thickness, hardPages }, (book) => {
            const shape = { pageCount, display: 'double', direction, leafThickness: layout.leafThicknessOf(thickness), hardPages };
            for (const position of [0, 1, book.lastPosition()]) {
              if (position > book.lastPosition()) continue;
              book.jumpTo(position);
              const at = `${pageCount} pages, ${direction}, thickness ${thickness}, hard ${hardPages}, position ${position}`;
              assertRectClose(layout.restingRect(size, shape, position), book.restingRect(size.width, size.height), size, `${at}: restingRect`);
              assertPlacesClose(layout.openPagePlaces(position, shape, size), book.openPagePlaces(size.width, size.height), size, at);
              cases++;
            }
          });
        }
      }
    }
  }
  assert.ok(cases > 150, `${cases} cases`);
  // The band is there to see: a 301-page book's front cover alone sits further left (towards the middle, its
  // band on its right) than where a book without stacks puts it.
  const plain = layout.openPagePlaces(0, { pageCount: 301 }, size)[0].x;
  const stacked = layout.openPagePlaces(0, { pageCount: 301, leafThickness: layout.leafThicknessOf(true) }, size)[0].x;
  assert.ok(stacked < plain - 5, `${stacked} vs ${plain}`);
});
