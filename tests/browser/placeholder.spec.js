// Browser: a page entry's `placeholder` (issue 38): the small image is drawn over the whole page while the
// page's own image loads, then the image replaces it in the same place with no paper between; a placeholder
// that fails is passed over, and an image that fails after it shows paper as without one. Needs WebGL2.
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';

const FIXTURE = '/tests/browser/fixtures/flipbook-fixture.html';

// Opens a book of 6 numbered pages (single, loadWindow 1: page 4 is not loaded when it opens) whose page 4
// has `placeholder` (page 1's colour, 32 x 40 px) and an image that waits for window.release(ok).
async function openWithHeldPage(page, placeholder) {
  await page.evaluate(async (placeholderKind) => {
    let release;
    const gate = new Promise((resolve) => { release = resolve; });
    window.release = release;
    window.errors = [];
    const small = window.makeNumberedPage(1, 32, 40);
    const placeholderOf = { canvas: small, missing: '/tests/browser/fixtures/no-such-placeholder.webp' };
    const pages = Array.from({ length: 6 }, (_, i) => window.makeNumberedPage(i));
    pages[4] = {
      src: () => gate.then((ok) => (ok ? window.makeNumberedPage(4) : Promise.reject(new Error('held image failed')))),
      placeholder: placeholderOf[placeholderKind],
    };
    await window.openBook({ pages, display: 'single', loadWindow: 1 });
    window.book.addEventListener('pageerror', (e) => window.errors.push([e.detail.index, e.detail.reason]));
  }, placeholder);
}

// The page open now, read back: the page whose colour is low in the middle of its place (below the number;
// -1 for paper), the place itself, and where the open pages lie.
function readOpenPage(page) {
  return page.evaluate(() => {
    const view = window.book.surface;
    view.drawNow();
    const pixels = view.readPixels();
    const ratio = pixels.width / view.canvas.clientWidth;
    const [{ page: index, x, y, width, height }] = view.openPagePlaces();
    const px = Math.round((x + width / 2) * ratio);
    const py = Math.round((y + height * 0.85) * ratio);
    const i = (py * pixels.width + px) * 4;
    const color = [pixels.data[i], pixels.data[i + 1], pixels.data[i + 2]];
    return {
      page: index, shows: window.pageAtColor(color, 6), color, place: { x, y, width, height },
      resting: window.book.restingRect(), texture: view.pageImageSize(index),
    };
  });
}

test('browser: a page with a placeholder draws it over the whole page at once, then its own image in the same place, with no paper between and no layout change (WebGL, pixels read back)', async ({ page }) => {
  const problems = await openReady(page, FIXTURE);
  await openWithHeldPage(page, 'canvas');
  // Turned to page 4 (no animation): its image is held, its placeholder comes at once.
  await page.evaluate(() => {
    window.released = [];
    const view = window.book.surface;
    const release = view.releasePageImage.bind(view);
    view.releasePageImage = (index) => { window.released.push(index); release(index); };
    window.book.flip(4, { animate: false });
  });
  await page.waitForFunction(() => window.book.surface.pageImageSize(4) !== null);  // the placeholder's texture is in
  const before = await readOpenPage(page);
  expect(before.page).toBe(4);
  expect(before.texture).toEqual({ width: 32, height: 40 });  // uploaded at its own size...
  expect(before.shows).toBe(1);                                // ...drawn over the page: its colour, not paper
  expect(await page.evaluate(() => window.book.pageState(4).state)).toBe('loading');

  await page.evaluate(async () => {
    window.release(true);
    await window.book.whenIdle();
  });
  const after = await readOpenPage(page);
  expect(await page.evaluate(() => window.book.pageState(4).state)).toBe('loaded');
  expect(after.shows).toBe(4);                     // the page's own image
  expect(after.texture.width).toBeGreaterThan(32);
  expect(after.place).toEqual(before.place);       // no layout change
  expect(after.resting).toEqual(before.resting);
  expect(await page.evaluate(() => window.released)).not.toContain(4);  // replaced in place: never paper between
  expect(await page.evaluate(() => window.book.residentPages)).toContain(4);
  expect(await page.evaluate(() => window.errors)).toEqual([]);
  expect(problems).toEqual([]);
});

test('browser: a placeholder that fails to load (404) is passed over: the page loads its own image and fires no pageerror (WebGL)', async ({ page }) => {
  const problems = await openReady(page, FIXTURE);
  await openWithHeldPage(page, 'missing');
  await page.evaluate(async () => {
    await window.book.flip(4, { animate: false });
    window.release(true);
    await window.book.whenIdle();
  });
  const shown = await readOpenPage(page);
  expect(shown.shows).toBe(4);
  expect(await page.evaluate(() => window.book.pageState(4).state)).toBe('loaded');
  expect(await page.evaluate(() => window.errors)).toEqual([]);
  expect(problems.filter((message) => !/404/.test(message))).toEqual([]);  // the browser logs the missing file
});

test('browser: an image that fails after its placeholder was drawn leaves paper and fires pageerror, as a page without one (WebGL, pixels read back)', async ({ page }) => {
  const problems = await openReady(page, FIXTURE);
  await openWithHeldPage(page, 'canvas');
  await page.evaluate(() => window.book.flip(4, { animate: false }));
  await page.waitForFunction(() => window.book.surface.pageImageSize(4) !== null);
  expect((await readOpenPage(page)).shows).toBe(1);
  await page.evaluate(async () => {
    window.release(false);
    await window.book.whenIdle();
  });
  const shown = await readOpenPage(page);
  expect(shown.shows).toBe(-1);  // paper
  expect(shown.texture).toBeNull();
  expect(await page.evaluate(() => window.book.pageState(4).state)).toBe('failed');
  expect(await page.evaluate(() => window.errors)).toEqual([[4, 'source']]);
  expect(problems).toEqual([]);
});
