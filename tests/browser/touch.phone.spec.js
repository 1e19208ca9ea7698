// Browser (phone): a thumb reads the book (issue 28). On each phone screen a book that fills it shows one
// page (display 'auto' chooses for legibility); a tap on the page's outer third turns forward, on its inner
// third back, on its middle third says `middletap`; a double tap or a pinch zooms; zoomed in, one finger
// pans and never turns. Touch goes through CDP with its own timestamps (phone.js), as Chrome on Android sends it.
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';
import { touchscreen } from './phone.js';
import { CLICK_SERIES_MS } from '../../web/src/input/input-taps.js';

const FIXTURE = '/tests/browser/fixtures/phone-book-fixture.html';
const open = (page, options) => page.evaluate((o) => window.openBook(o), { pages: 12, duration: 150, startPage: 4, ...options });
const settle = (page) => page.evaluate(() => window.settle());
const state = (page) => page.evaluate(() => ({
  page: window.book.page, display: window.book.display, zoom: window.book.zoom,
  turnstarts: window.count('turnstart'), middletaps: window.events.filter((e) => e.type === 'middletap').map((e) => e.detail),
}));
const pointAt = (page, fx, fy) => page.evaluate(([fx, fy]) => window.halfPoint(fx, fy), [fx, fy]);

/** A double tap: both taps sent at once, stamped 150 ms apart. */
async function doubleTap(touch, p) {
  await Promise.all([
    touch.send('touchStart', [p], 1000), touch.send('touchEnd', [], 60),
    touch.send('touchStart', [p], 150), touch.send('touchEnd', [], 60),
  ]);
}

/**
 * A double tap the page is given as one, then `done()` (a page function: true once it did what the test
 * waits for). A busy machine's Chromium can hand the page the second tap after the book's series has closed
 * on its clock (CDP delivers the four events one after another), so that at 1x the first tap acts alone;
 * that was no double tap. Then the page's clock says so (its two lifts further apart than the series' time),
 * `restore()` puts the book back and it taps again, 3 tries at most.
 */
async function doubleTapSeen(page, touch, p, done, restore) {
  for (let attempt = 1; ; attempt++) {
    await page.evaluate(() => {
      window.lifts = [];
      window.addEventListener('pointerup', () => window.lifts.push(performance.now()), { capture: true });
    });
    await doubleTap(touch, p);
    await page.waitForFunction(() => window.lifts.length >= 2);
    const gap = await page.evaluate(() => window.lifts[1] - window.lifts[0]);
    if (gap <= CLICK_SERIES_MS || attempt === 3) {
      await page.waitForFunction(done);
      return;
    }
    await settle(page);
    if (await page.evaluate(done)) return;
    await restore();
  }
}

test.beforeEach(async ({ page }) => {
  await openReady(page, FIXTURE);
});

test('browser (phone): a tap on the outer third turns forward, on the inner third back, on the middle third says middletap (x, y in the book) and turns nothing', async ({ page }) => {
  expect(await open(page, {})).toEqual({ page: 4, display: 'single' });
  const touch = await touchscreen(page);
  await touch.tap(await pointAt(page, 0.85, 0.5));  // ltr single: the free edge is on the right
  await settle(page);
  expect(await state(page)).toMatchObject({ page: 5, turnstarts: 1, middletaps: [] });
  await touch.tap(await pointAt(page, 0.15, 0.5));
  await settle(page);
  expect(await state(page)).toMatchObject({ page: 4, turnstarts: 2, middletaps: [] });
  const middle = await pointAt(page, 0.5, 0.4);
  await touch.tap(middle);
  await settle(page);
  const after = await state(page);
  expect(after).toMatchObject({ page: 4, turnstarts: 2 });
  const box = await page.evaluate(() => window.book.element.getBoundingClientRect().toJSON());
  expect(after.middletaps).toHaveLength(1);
  expect(after.middletaps[0].x).toBeCloseTo(middle.x - box.x, 0);
  expect(after.middletaps[0].y).toBeCloseTo(middle.y - box.y, 0);
  // turnArea limits turning, not the event: with 'none' the outer third turns nothing, the middle still says middletap.
  await open(page, { turnArea: 'none' });
  await touch.tap(await pointAt(page, 0.85, 0.5));
  await touch.tap(await pointAt(page, 0.5, 0.5));
  await settle(page);
  expect(await state(page)).toMatchObject({ page: 4, turnstarts: 0 });
  expect((await state(page)).middletaps).toHaveLength(1);
});

test('browser (phone): in rtl the left third turns forward, in vertical the bottom third; the middle third turns neither', async ({ page }, testInfo) => {
  test.skip(testInfo.project.name !== 'phone-portrait', 'the thirds follow the direction the same way on every screen: one is enough');
  const touch = await touchscreen(page);
  expect(await open(page, { direction: 'rtl' })).toEqual({ page: 4, display: 'single' });
  await touch.tap(await pointAt(page, 0.15, 0.5));
  await settle(page);
  expect((await state(page)).page).toBe(5);
  await touch.tap(await pointAt(page, 0.85, 0.5));
  await settle(page);
  expect((await state(page)).page).toBe(4);
  await touch.tap(await pointAt(page, 0.5, 0.5));
  await settle(page);
  expect(await state(page)).toMatchObject({ page: 4, turnstarts: 2 });
  expect((await state(page)).middletaps).toHaveLength(1);

  expect(await open(page, { direction: 'vertical' })).toEqual({ page: 4, display: 'single' });
  await touch.tap(await pointAt(page, 0.5, 0.85));
  await settle(page);
  expect((await state(page)).page).toBe(5);
  await touch.tap(await pointAt(page, 0.5, 0.15));
  await settle(page);
  expect((await state(page)).page).toBe(4);
  await touch.tap(await pointAt(page, 0.2, 0.5));
  await settle(page);
  expect(await state(page)).toMatchObject({ page: 4, turnstarts: 2 });
  expect((await state(page)).middletaps).toHaveLength(1);
});

test('browser (phone): a double tap zooms in about the finger without turning (nor middletap), and another zooms back out', async ({ page }) => {
  await open(page, {});
  const touch = await touchscreen(page);
  const outer = await pointAt(page, 0.85, 0.5);  // on the outer third: its first tap must not turn
  await doubleTapSeen(page, touch, outer, () => window.book.zoom > 1, async () => {
    await page.evaluate(async () => { await window.book.flip(4); window.events.length = 0; });
    await settle(page);
  });
  await settle(page);
  expect(await state(page)).toMatchObject({ page: 4, zoom: 2, turnstarts: 0, middletaps: [] });
  expect(await page.evaluate(() => window.book.surface.canvas.style.touchAction)).toBe('none');
  // Zoomed in a tap does nothing, so the book judges this one by the taps' own stamps however late the second comes.
  await doubleTap(touch, await pointAt(page, 0.5, 0.5));
  await page.waitForFunction(() => window.book.zoom === 1);
  await settle(page);
  expect(await state(page)).toMatchObject({ page: 4, zoom: 1, turnstarts: 0, middletaps: [] });
  expect(await page.evaluate(() => window.book.surface.canvas.style.touchAction)).toBe('pan-y');
});

test('browser (phone): a pinch zooms the book; zoomed in, one finger pans it and no stroke or tap turns', async ({ page }) => {
  await open(page, {});
  const touch = await touchscreen(page);
  const centre = await pointAt(page, 0.5, 0.5);
  await touch.pinch(centre, 60, 240);
  await settle(page);
  expect((await state(page)).zoom).toBeGreaterThan(2);
  const placeOf = () => page.evaluate(() => window.book.openPagePlaces()[0]);
  const before = await placeOf();
  // A stroke along the turn that would be a swipe (and from the free edge, a drag) at 1x: a pan.
  await touch.drag({ x: centre.x + 60, y: centre.y }, { x: centre.x - 60, y: centre.y + 30 });
  await settle(page);
  const panned = await placeOf();
  expect(panned.x).toBeLessThan(before.x - 20);
  expect(panned.y).toBeGreaterThan(before.y + 10);
  const edge = await page.evaluate(() => {
    const box = window.book.surface.canvas.getBoundingClientRect();
    return { x: box.right - 12, y: box.top + box.height / 2 };
  });
  await touch.drag(edge, { x: edge.x - 200, y: edge.y });
  await touch.tap(edge);
  await touch.tap(centre);
  await settle(page);
  expect(await state(page)).toMatchObject({ page: 4, turnstarts: 0, middletaps: [] });
});

test('browser (phone): the book\'s element and canvas keep the host page\'s pinch and double-tap zoom off the book (touch-action pan-y)', async ({ page }) => {
  await open(page, {});
  const actions = await page.evaluate(() => [getComputedStyle(window.book.element).touchAction, getComputedStyle(window.book.surface.canvas).touchAction]);
  expect(actions).toEqual(['pan-y', 'pan-y']);
});

test('browser (phone): display \'auto\' shows one page of the demo-like book on the phone, two in a 1400x700 box; shrinking the box says displaychange once', async ({ page }) => {
  expect((await open(page, {})).display).toBe('single');
  await page.evaluate(() => Object.assign(document.getElementById('container').style, { width: '1400px', height: '700px' }));
  await page.waitForFunction(() => window.book.display === 'double');
  await page.evaluate(() => { window.events.length = 0; });
  await page.evaluate(() => Object.assign(document.getElementById('container').style, { width: '100vw', height: '100vh' }));
  await page.waitForFunction(() => window.count('resize') > 0);
  expect(await page.evaluate(() => window.events.filter((e) => e.type === 'displaychange').map((e) => e.detail)))
    .toEqual([{ display: 'single', previous: 'double' }]);
  expect((await state(page)).display).toBe('single');
  // A box that opens wide shows two pages from the start, and says nothing (no change).
  await page.evaluate(() => Object.assign(document.getElementById('container').style, { width: '1400px', height: '700px' }));
  expect((await open(page, {})).display).toBe('double');
  expect(await page.evaluate(() => window.count('displaychange'))).toBe(0);
});

test('browser (phone): minPageWidth 150 lets the landscape phone show two pages, and setOptions changes it live with displaychange', async ({ page }, testInfo) => {
  test.skip(testInfo.project.name !== 'phone-landscape', 'only the landscape phone has room for two 150 px pages');
  expect((await open(page, { minPageWidth: 150 })).display).toBe('double');
  await page.evaluate(() => window.book.setOptions({ minPageWidth: 300 }));
  expect(await page.evaluate(() => [window.book.display, window.events.filter((e) => e.type === 'displaychange').map((e) => e.detail)]))
    .toEqual(['single', [{ display: 'single', previous: 'double' }]]);
});
