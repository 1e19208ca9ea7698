// Node tests of the phone reader's two rules (issue 28): display 'auto' shows two pages only where each is
// wide enough to read (layout.js displayFor), and a tap's place on the book: outer thirds turn, the middle
// third is the reader's (input-taps.js zoneAt, direction.js thirdOf). Plain functions: no DOM, no engine.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as layout from '../../web/src/engine/layout.js';
import { zoneAt } from '../../web/src/input/input-taps.js';

const PHONES = { portrait: { width: 390, height: 844 }, landscape: { width: 844, height: 390 }, small: { width: 320, height: 568 } };

test('node: displayFor keeps \'single\' and \'double\' as given, and \'auto\' shows two pages only where each lies at least minPageWidth (default 300) CSS px wide', () => {
  assert.equal(layout.AUTO_MIN_PAGE_WIDTH, 300);
  assert.equal(layout.displayFor('single', { width: 4000, height: 1000 }), 'single');
  assert.equal(layout.displayFor('double', { width: 100, height: 2000 }), 'double');
  // The demo-like book (the engine's 0.8 page) on the three phones, either way up: one page.
  for (const [name, size] of Object.entries(PHONES)) assert.equal(layout.displayFor('auto', size), 'single', name);
  // A desktop box: two pages of about 430 px.
  assert.equal(layout.displayFor('auto', { width: 1400, height: 700 }), 'double');
  // The boundary is the spread's page width as restingRect lays a spread, whatever the frame margin.
  const size = { width: 1000, height: 700 };
  const across = layout.spreadPageWidth(size);
  assert.ok(Math.abs(across - layout.restingRect(size, { display: 'double' }).width / 2) < 1e-9);
  assert.equal(layout.displayFor('auto', size, { minPageWidth: across }), 'double');
  assert.equal(layout.displayFor('auto', size, { minPageWidth: across + 0.01 }), 'single');
  // A landscape phone shows two pages of 150 px or more when the host allows them.
  assert.equal(layout.displayFor('auto', PHONES.landscape, { minPageWidth: 150 }), 'double');
  assert.equal(layout.displayFor('auto', { width: 10, height: 0 }), 'single');  // an empty box: one page
  assert.equal(layout.displayFor('auto', { width: 0, height: 0 }, { minPageWidth: 1 }), 'single');
});

test('node: displayFor measures the page across the turn: a vertical book\'s page height on screen, and a narrow page shape makes narrower pages', () => {
  const tall = { width: 600, height: 1000 };
  // Side by side, two 0.8 pages in 600 px are too narrow; stacked (vertical) each lies 0.8 x its width tall.
  assert.equal(layout.displayFor('auto', tall, { direction: 'ltr' }), 'single');
  assert.equal(layout.displayFor('auto', tall, { direction: 'vertical' }), 'double');
  const vertical = layout.restingRect(tall, { display: 'double', direction: 'vertical' });
  assert.ok(Math.abs(layout.spreadPageWidth(tall, { direction: 'vertical' }) - vertical.height / 2) < 1e-9);
  assert.equal(layout.displayFor('auto', tall, { direction: 'rtl' }), layout.displayFor('auto', tall, { direction: 'ltr' }));
  // The same box holds wide-enough pages of the default shape, but not of a narrow one (a PDF's aspect).
  const box = { width: 1000, height: 500 };
  assert.equal(layout.displayFor('auto', box), 'double');
  assert.equal(layout.displayFor('auto', box, { pageAspect: 0.5 }), 'single');
});

test('node: zoneAt splits the open page (or spread) in thirds along the turn: the free edge\'s third turns forward, the spine\'s backward, the middle third neither', () => {
  const page = { x: 100, y: 50, width: 300, height: 600 };
  const at = (direction, px, py) => zoneAt(page, page.x + px, page.y + py, direction);
  assert.deepEqual([at('ltr', 10, 300), at('ltr', 150, 300), at('ltr', 290, 300)], ['backward', 'middle', 'forward']);
  assert.deepEqual([at('rtl', 10, 300), at('rtl', 150, 300), at('rtl', 290, 300)], ['forward', 'middle', 'backward']);
  assert.deepEqual([at('vertical', 150, 10), at('vertical', 150, 300), at('vertical', 150, 590)], ['backward', 'middle', 'forward']);
  // The middle third's edges are middle; a point off the page is nothing.
  assert.deepEqual([at('ltr', 100, 0), at('ltr', 200, 600), at('ltr', 99.9, 0), at('ltr', 200.1, 0)], ['middle', 'middle', 'backward', 'forward']);
  assert.equal(at('ltr', -1, 300), null);
  assert.equal(at('vertical', 150, 601), null);
  // A spread 600 px wide: the band within a sixth of its width (100 px) either side of the spine is middle.
  const spread = { x: 0, y: 0, width: 600, height: 400 };
  assert.deepEqual([199, 201, 399, 401].map((x) => zoneAt(spread, x, 200, 'ltr')), ['backward', 'middle', 'middle', 'forward']);
});
