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

test('browser: the opening pages\' placeholders named by URL show as images under the canvas where the surface then draws those pages, from before the book is ready until that frame is on screen and they have painted, then go; a page without one gets none (WebGL)', async ({ page }) => {
  const problems = await openReady(page, FIXTURE);
  const seen = await page.evaluate(async () => {
    const container = document.getElementById('container');
    const log = [];  // the posters added (their images' places in the container) and removed, and `ready`, in order
    let gone = () => {};
    new MutationObserver((records) => {
      const origin = container.getBoundingClientRect();
      for (const record of records) {
        for (const node of record.addedNodes) {
          if (!node.classList?.contains('conecurl-poster')) continue;
          const images = [...node.querySelectorAll('img')].map((img) => {
            const r = img.getBoundingClientRect();
            return { page: Number(img.dataset.page), x: r.x - origin.x, y: r.y - origin.y, width: r.width, height: r.height, src: img.src.slice(0, 15) };
          });
          // Both positioned, neither with a z-index: the canvas, later in the document, paints over the poster.
          const next = node.nextElementSibling;
          const order = { before: next?.tagName, canvasPosition: getComputedStyle(next).position, zIndex: getComputedStyle(node).zIndex, position: getComputedStyle(node).position };
          log.push({ at: 'added', images, order });
        }
        for (const node of record.removedNodes) {
          if (node.classList?.contains('conecurl-poster')) {
            log.push({ at: 'removed', decoded: [...node.querySelectorAll('img')].every((img) => img.complete && img.naturalWidth > 0) });
            gone();
          }
        }
      }
    }).observe(container, { childList: true, subtree: true });
    const placeholder = (i) => window.makeNumberedPage(i, 32, 40).toDataURL('image/png');
    // Every page names a placeholder by URL but page 2.
    const pages = Array.from({ length: 8 }, (_, i) => ({ src: window.makeNumberedPage(i), ...(i === 2 ? {} : { placeholder: placeholder(i) }) }));
    const places = () => window.book.surface.openPagePlaces().map(({ page: p, x, y, width, height }) => ({ page: p, x, y, width, height }));
    // `ready` goes out in the task after create() resolved (book-events.js); each book is waited for until it
    // is told and its poster has gone by itself (not by the next book's destroy()).
    const open = async (options) => {
      let told;
      const ready = new Promise((resolve) => { told = resolve; });
      const removed = new Promise((resolve) => { gone = resolve; });
      await window.openBook({ pages, display: 'double', ...options, on: { ready: () => { log.push({ at: 'ready' }); told(); } } });
      await Promise.all([ready, removed]);
      return places();
    };
    const spread = await open({ startPage: 1 });  // pages 1 and 2
    const cover = await open({});  // the front cover alone, centred
    return { log, spread, cover, left: container.querySelectorAll('.conecurl-poster').length };
  });
  // Each poster is laid before its book is ready (create() resolves at the first frame, ready is told in the
  // next task; the poster goes two frames after that frame and its images' decoding, before or after ready).
  const order = seen.log.map((e) => e.at);
  expect([order[0], order[3], [order[1], order[2]].sort(), [order[4], order[5]].sort()])
    .toEqual(['added', 'added', ['ready', 'removed'], ['ready', 'removed']]);
  expect(seen.log.filter((e) => e.at === 'removed').map((e) => e.decoded)).toEqual([true, true]);
  const [spreadPoster, coverPoster] = seen.log.filter((e) => e.at === 'added');
  for (const poster of [spreadPoster, coverPoster]) {
    expect(poster.order).toEqual({ before: 'CANVAS', canvasPosition: 'relative', zIndex: 'auto', position: 'absolute' });
  }
  expect(seen.spread.map((p) => p.page)).toEqual([1, 2]);
  expect(spreadPoster.images.map((p) => p.page)).toEqual([1]);  // page 2 names no placeholder
  expect(coverPoster.images.map((p) => p.page)).toEqual([0]);
  const near = (a, b) => Math.abs(a - b) < 0.75;
  for (const [poster, drawn] of [[spreadPoster, seen.spread], [coverPoster, seen.cover]]) {
    for (const image of poster.images) {
      const place = drawn.find((p) => p.page === image.page);
      expect(['x', 'y', 'width', 'height'].every((k) => near(image[k], place[k])), JSON.stringify({ image, place })).toBe(true);
      expect(image.src).toBe('data:image/png;');
    }
  }
  expect(seen.left).toBe(0);
  expect(problems).toEqual([]);
});

test('browser: a page the poster shows asks for its own image only once its placeholder has painted (the small picture first; the page\'s largest contentful paint waits on no big image), a page without one at once (WebGL; Element Timing and the order of fetches)', async ({ page }) => {
  const problems = await openReady(page, FIXTURE);
  const seen = await page.evaluate(async () => {
    // Pages by URL (blob:), so the book fetches them; all but page 2 name a placeholder by URL.
    const blobUrl = async (i) => URL.createObjectURL(await new Promise((resolve) => window.makeNumberedPage(i).toBlob(resolve, 'image/png')));
    const sources = await Promise.all(Array.from({ length: 8 }, (_, i) => blobUrl(i)));
    const pages = sources.map((src, i) => ({ src, ...(i === 2 ? {} : { placeholder: window.makeNumberedPage(i, 32, 40).toDataURL('image/png') }) }));
    const asked = {};  // page -> performance.now() when its own image was fetched
    const fetchOf = window.fetch;
    window.fetch = (input, init) => {
      const page = sources.indexOf(String(input));
      if (page >= 0 && !(page in asked)) asked[page] = performance.now();
      return fetchOf(input, init);
    };
    const painted = {};  // page -> its poster image's paint (Element Timing's renderTime)
    new PerformanceObserver((list) => {
      for (const entry of list.getEntries()) {
        const match = /^conecurl-poster-\d+-(\d+)$/.exec(entry.identifier);
        if (match) painted[Number(match[1])] = entry.renderTime || entry.loadTime;
      }
    }).observe({ type: 'element', buffered: true });
    try {
      await window.openBook({ pages, display: 'double', startPage: 1 });
    } finally {
      window.fetch = fetchOf;
    }
    await window.book.whenIdle();
    return { asked, painted, open: window.book.surface.openPagePlaces().map((p) => p.page) };
  });
  console.log(`fetched at ${JSON.stringify(seen.asked)}; poster painted at ${JSON.stringify(seen.painted)} (ms)`);
  expect(seen.open).toEqual([1, 2]);
  expect(seen.painted[1]).toBeGreaterThan(0);
  expect(seen.asked[1]).toBeGreaterThanOrEqual(seen.painted[1]);
  expect(seen.asked[2]).toBeLessThan(seen.painted[1]);  // no placeholder: asked as the book opened
  expect(problems).toEqual([]);
});

test('browser: a poster whose placeholder never arrives waits under the canvas, and goes as soon as the surface shows other pages or another zoom, and on destroy (WebGL)', async ({ page }) => {
  // The placeholders' server never answers: their images never load, so nothing but the book's changes removes the poster.
  await page.route('**/never/*.png', () => {});
  const problems = await openReady(page, FIXTURE);
  const counts = await page.evaluate(async () => {
    const container = document.getElementById('container');
    const posters = () => container.querySelectorAll('.conecurl-poster').length;
    const pages = Array.from({ length: 8 }, (_, i) => ({ src: window.makeNumberedPage(i), placeholder: `/never/${i}.png` }));
    const seen = {};
    await window.openBook({ pages, display: 'double', startPage: 1 });  // resolves once its neighbours loaded too
    seen.idle = posters();
    await window.book.flip(3, { animate: false });  // pages 3 and 4: no leaf moves
    seen.flipped = posters();
    await window.openBook({ pages, display: 'double', startPage: 1 });
    seen.again = posters();
    window.book.zoom = 2;  // about the middle
    await window.book.whenIdle();
    seen.zoomed = posters();
    await window.openBook({ pages, display: 'double', startPage: 1 });
    window.book.destroy();
    seen.destroyed = posters();
    return seen;
  });
  expect(counts).toEqual({ idle: 1, flipped: 0, again: 1, zoomed: 0, destroyed: 0 });
  expect(problems).toEqual([]);
});
