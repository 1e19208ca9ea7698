// Browser: zoom and pan — Ctrl+wheel, double-click, pinch and keys zoom about the pointer from 1x to
// 4x, a drag pans while zoomed, turning input is off while zoomed and back at 1x, and zoomed pages get
// sharper textures (a zoomSrc, or a page function called again for the larger size).
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';

const FIXTURE = '/tests/browser/fixtures/flipbook-fixture.html';

async function openZoomBook(page) {
  await openReady(page, FIXTURE);
  await page.evaluate(async () => {
    const small = (i) => window.makeNumberedPage(i);  // 400x500 numbered pages
    const pages = Array.from({ length: 8 }, (_, i) => ({
      src: small(i),
      // A big version for zooming: 4x the pixels, same picture.
      zoomSrc: (() => { const c = document.createElement('canvas'); c.width = 1600; c.height = 2000; c.getContext('2d').drawImage(small(i), 0, 0, 1600, 2000); return c; })(),
    }));
    // Page 3 is drawn by a function, at whatever size the book asks for.
    pages[3] = { src: (index, size) => { const c = document.createElement('canvas'); c.width = size.width; c.height = size.height; c.getContext('2d').drawImage(small(index), 0, 0, size.width, size.height); return c; } };
    await window.openBook({ pages, display: 'double', startPage: 2, duration: 300 });
    window.events = [];
    for (const type of ['zoom', 'turnstart', 'turned', 'sharpened']) window.book.addEventListener(type, (e) => window.events.push({ type, ...e.detail }));
    await window.settle();
  });
}

/** The page fraction under a viewport point, from the resting pages' rectangle. */
function fractionAt(page, point) {
  return page.evaluate(({ x, y }) => {
    const box = window.book.surface.canvas.getBoundingClientRect();
    const r = window.book.restingRect();
    return { fx: (x - box.left - r.x) / r.width, fy: (y - box.top - r.y) / r.height, width: r.width };
  }, point);
}

test('browser: Ctrl+wheel zooms about the pointer, a drag pans, clicks and keys do not turn while zoomed, 0 zooms back and turning returns', async ({ page }) => {
  await openZoomBook(page);
  const point = await page.evaluate(() => window.halfPoint(0.7, 0.4));
  const before = await fractionAt(page, point);
  await page.mouse.move(point.x, point.y);
  await page.keyboard.down('Control');
  await page.mouse.wheel(0, -300);
  await page.keyboard.up('Control');
  await page.waitForFunction(() => window.book.zoom > 1.5);
  const after = await fractionAt(page, point);
  expect(after.fx).toBeCloseTo(before.fx, 3);  // the same point of the book stays under the pointer
  expect(after.fy).toBeCloseTo(before.fy, 3);
  expect(after.width / before.width).toBeCloseTo(await page.evaluate(() => window.book.zoom), 3);
  expect(await page.evaluate(() => window.events.filter((e) => e.type === 'zoom').length)).toBeGreaterThan(0);

  // A drag pans the view by as much as the pointer moved.
  const rectBefore = await page.evaluate(() => window.book.restingRect());
  await page.mouse.down();
  await page.mouse.move(point.x - 60, point.y - 30, { steps: 4 });
  await page.mouse.up();
  const rectAfter = await page.evaluate(() => window.book.restingRect());
  expect(rectAfter.x - rectBefore.x).toBeCloseTo(-60, 0);
  expect(rectAfter.y - rectBefore.y).toBeCloseTo(-30, 0);

  // No turning while zoomed: a click and an arrow key leave the page.
  await page.mouse.click(point.x, point.y);
  await page.evaluate(() => window.book.element.focus());
  await page.keyboard.press('ArrowRight');
  // The click's series is over (it waits to tell a double-click) and no turn moves or waits.
  await page.evaluate(() => window.settle());
  expect(await page.evaluate(() => ({ page: window.book.page, turns: window.events.filter((e) => e.type === 'turnstart').length })))
    .toEqual({ page: 1, turns: 0 });
  // 0 goes back to the whole book, and a click turns again.
  await page.keyboard.press('0');
  expect(await page.evaluate(() => window.book.zoom)).toBe(1);
  const right = await page.evaluate(() => window.halfPoint(0.75, 0.5));
  await page.mouse.click(right.x, right.y);
  await page.waitForFunction(() => window.events.some((e) => e.type === 'turned'));
  expect(await page.evaluate(() => window.book.page)).toBe(3);
});

test('browser: zoomed pages get sharper textures: the zoomSrc of an image page, a page function called for the larger size', async ({ page }) => {
  await openZoomBook(page);
  const sizeOf = (index) => page.evaluate((i) => window.book.surface.pageImageSize(i), index);
  await page.evaluate(() => window.book.flip(3, { animate: false }));  // pages 3 (a function) and 4 open
  await page.evaluate(() => window.settle());
  const before = { image: await sizeOf(4), drawn: await sizeOf(3) };
  await page.evaluate(() => { window.book.zoom = 3; });
  await page.waitForFunction(() => window.events.filter((e) => e.type === 'sharpened').length >= 2);
  const after = { image: await sizeOf(4), drawn: await sizeOf(3) };
  expect(after.image.width).toBeGreaterThan(before.image.width * 2);
  expect(after.drawn.width).toBeGreaterThan(before.drawn.width * 2);
  // Back at 1x the textures shrink again once the zoom rests (memory stays bounded).
  await page.evaluate(() => { window.book.zoom = 1; });
  await page.waitForFunction((w) => window.book.surface.pageImageSize(4).width < w, after.image.width);
  console.log(`zoom 3x: page texture ${before.image.width} -> ${after.image.width} px wide (zoomSrc), `
    + `${before.drawn.width} -> ${after.drawn.width} (page function)`);
});

test('browser: double-click zooms in 2x at the pointer and out again; + and - step; next() zooms out and turns', async ({ page }) => {
  await openZoomBook(page);
  const point = await page.evaluate(() => window.halfPoint(0.3, 0.6));
  await page.mouse.dblclick(point.x, point.y);
  await page.waitForFunction(() => window.book.zoom === 2);
  await page.evaluate(() => window.settle());  // its clicks' series is over, and no turn moves or waits
  expect(await page.evaluate(() => window.book.page)).toBe(1);  // the double-click did not turn
  await page.mouse.dblclick(point.x, point.y);
  await page.waitForFunction(() => window.book.zoom === 1);
  await page.evaluate(() => window.book.element.focus());
  await page.keyboard.press('+');
  await page.keyboard.press('+');
  expect(await page.evaluate(() => window.book.zoom)).toBeCloseTo(1.5625, 6);
  await page.keyboard.press('-');
  expect(await page.evaluate(() => window.book.zoom)).toBeCloseTo(1.25, 6);
  expect(await page.evaluate(() => window.book.next())).toBe(true);
  expect(await page.evaluate(() => ({ zoom: window.book.zoom, page: window.book.page }))).toEqual({ zoom: 1, page: 3 });
  const bad = await page.evaluate(() => { try { window.book.zoom = 9; return 'no error'; } catch (e) { return `${e.name}: ${e.message}`; } });
  expect(bad).toMatch(/^RangeError: conecurl: zoom must be a number from 1 to 4/);
});

test('browser (touch): a two-finger pinch zooms the book, not the page', async ({ browser }) => {
  const context = await browser.newContext({ hasTouch: true, viewport: { width: 800, height: 600 } });
  const page = await context.newPage();
  await openZoomBook(page);
  const c = await page.evaluate(() => window.halfPoint(0.5, 0.5));
  const cdp = await context.newCDPSession(page);
  const fingers = (type, d) => cdp.send('Input.dispatchTouchEvent', {
    type,
    touchPoints: type === 'touchEnd' ? [] : [{ x: c.x - d, y: c.y, id: 1 }, { x: c.x + d, y: c.y, id: 2 }],
  });
  await fingers('touchStart', 40);
  for (const d of [50, 60, 70, 80]) await fingers('touchMove', d);
  await fingers('touchEnd', 80);
  await page.waitForFunction(() => window.book.zoom > 1.5);
  expect(await page.evaluate(() => window.book.zoom)).toBeCloseTo(2, 1);
  expect(await page.evaluate(() => window.book.page)).toBe(1);
  await context.close();
});
