// Browser (phone, ratio 3): the `resolution` option. A fixed resolution draws a turn's moving frames at
// that many device pixels per CSS pixel (offscreen, scaled up: the canvas keeps its size) and the book
// at rest whole; 'full' draws every frame whole; and a frame drawn at half scale shows the same turn
// as one drawn whole (the same place, coverage and colours, only softer). The adaptation of 'auto' is
// timed by frames, so it is tested in Node with frame times given (tests/node/moving-resolution.test.mjs).
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';

async function openPhoneBook(page, options = {}) {
  await openReady(page, '/tests/browser/fixtures/phone-book-fixture.html');
  await page.evaluate(async (options) => {
    await window.openBook({ pages: 8, display: 'single', startPage: 2, ...options });
    await window.book.whenIdle();
  }, options);
}

/** Turns a page forward; returns the scales of the frames drawn while it moved, the scale after it landed, the canvas's sizes. */
function turnAndWatch(page) {
  return page.evaluate(async () => {
    const view = window.book.surface;
    const canvas = view.canvas;
    const before = [canvas.width, canvas.height];
    const during = new Set();
    let watching = true;
    const watch = () => {
      if (view.animating) during.add(view.renderer.lastFrameScale());
      if (watching) requestAnimationFrame(watch);
    };
    requestAnimationFrame(watch);
    const landed = await window.book.next();
    watching = false;
    return { landed, during: [...during].sort(), after: view.renderer.lastFrameScale(), before, sizes: [canvas.width, canvas.height],
      css: [canvas.clientWidth * devicePixelRatio, canvas.clientHeight * devicePixelRatio].map(Math.round) };
  });
}

test('browser (phone): resolution 1.5 draws a turn\'s moving frames at half the ratio-3 scale, offscreen (the canvas keeps its size), and the landed book whole', async ({ page }) => {
  expect(await page.evaluate(() => devicePixelRatio)).toBe(3);
  await openPhoneBook(page, { resolution: 1.5 });
  const watched = await turnAndWatch(page);
  expect(watched.landed).toBe(true);
  expect(watched.during).toContain(0.5);
  expect(watched.during.every((scale) => scale === 0.5 || scale === 1)).toBe(true);
  expect(watched.after).toBe(1);
  expect(watched.sizes).toEqual(watched.before);
  expect(watched.sizes).toEqual(watched.css);
});

test("browser (phone): resolution 'full' draws every frame of a turn whole; setOptions switches it live to 1.5, then back", async ({ page }) => {
  await openPhoneBook(page, { resolution: 'full' });
  let watched = await turnAndWatch(page);
  expect(watched.during).toEqual([1]);
  await page.evaluate(() => window.book.setOptions({ resolution: 1.5 }));
  watched = await turnAndWatch(page);
  expect(watched.during).toContain(0.5);
  await page.evaluate(() => window.book.setOptions({ resolution: 'full' }));
  watched = await turnAndWatch(page);
  expect(watched.during).toEqual([1]);
});

test('browser (phone): a turn drawn at half scale shows what the whole frame shows at t = 0.15, 0.6 and 0.95 (coverage within 1%, colours within 6 of 255 on average)', async ({ page }) => {
  await openPhoneBook(page, { resolution: 'full' });
  const compared = await page.evaluate(() => {
    const view = window.book.surface;
    const pixelsAt = (t, scale) => {
      view.renderer.setOptions({ movingScale: scale });
      view.showTurn('forward', t);
      return view.readPixels();
    };
    return [0.15, 0.6, 0.95].map((t) => {
      const whole = pixelsAt(t, 1);
      const half = pixelsAt(t, 0.5);
      let coveredWhole = 0;
      let coveredHalf = 0;
      let difference = 0;
      for (let i = 0; i < whole.data.length; i += 4) {
        coveredWhole += whole.data[i + 3] > 0 ? 1 : 0;
        coveredHalf += half.data[i + 3] > 0 ? 1 : 0;
        for (let c = 0; c < 3; c++) difference += Math.abs(whole.data[i + c] - half.data[i + c]);
      }
      return { t, size: [whole.width, half.width], coverage: coveredHalf / coveredWhole, difference: difference / (3 * coveredWhole) };
    });
  });
  for (const { t, size, coverage, difference } of compared) {
    expect(size[1], `t=${t}`).toBe(size[0]);
    expect(Math.abs(coverage - 1), `t=${t}`).toBeLessThan(0.01);
    expect(difference, `t=${t}`).toBeLessThan(6);
  }
});
