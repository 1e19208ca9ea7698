// Browser: one book controller over two surfaces. A Flipbook (WebGL2, the engine's layout) and a
// StaticBook (2D canvas, layout.js) of the same pages in containers of the same size answer the same:
// open pages, where they lie, links over them, zoom by keys, wheel and code, turning; the still book
// zooms and pans as the WebGL one does (it could not before the controller was shared).
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';

const FIXTURE = '/tests/browser/fixtures/flipbook-fixture.html';

async function openBoth(page, options) {
  await page.evaluate(async (options) => {
    const { StaticBook } = await import('/web/src/book/static-book.js');
    const box = (id) => {
      const el = document.createElement('div');
      el.id = id;
      el.style.cssText = 'width:640px;height:400px';
      document.body.append(el);
      return el;
    };
    const pages = Array.from({ length: 9 }, (_, i) => ({ src: window.makeNumberedPage(i), alt: `Page ${i + 1}` }));
    pages[3].links = [{ rect: [0.1, 0.1, 0.5, 0.2], href: 'https://example.com/three' }];
    pages[4].links = [{ rect: [0.2, 0.7, 0.6, 0.2], page: 0, title: 'Back to the cover' }];
    window.books = {
      webgl: await window.Flipbook.create(box('webgl'), { pages, ...options }),
      canvas: await StaticBook.create(box('canvas'), { pages, ...options }),
    };
    window.zooms = { webgl: [], canvas: [] };
    for (const [kind, book] of Object.entries(window.books)) book.addEventListener('zoom', (e) => window.zooms[kind].push(e.detail.scale));
  }, options);
}

/** What each book says of itself, and where its link anchors are (relative to its element). */
const report = (page) => page.evaluate(() => Object.fromEntries(Object.entries(window.books).map(([kind, book]) => {
  const origin = book.element.getBoundingClientRect();
  const anchors = [...book.element.querySelectorAll('.conecurl-links a')].map((a) => {
    const r = a.getBoundingClientRect();
    return { page: Number(a.dataset.page), x: r.x - origin.x, y: r.y - origin.y, w: r.width, h: r.height };
  });
  return [kind, {
    surface: book.surface.kind, page: book.page, display: book.display, openPages: book.openPages,
    places: book.openPagePlaces(), rect: book.restingRect(), zoom: book.zoom, anchors,
    live: book.element.querySelector('[aria-live]').textContent,
  }];
})));

function expectSameLayout(both) {
  const { webgl, canvas } = both;
  expect([webgl.surface, canvas.surface]).toEqual(['webgl', 'canvas']);
  for (const key of ['page', 'display', 'openPages', 'zoom', 'live']) expect(canvas[key], key).toEqual(webgl[key]);
  expect(canvas.places.map((p) => p.page)).toEqual(webgl.places.map((p) => p.page));
  const close = (a, b, what) => {
    for (const k of ['x', 'y', 'width', 'height', 'w', 'h']) if (k in a) expect(Math.abs(a[k] - b[k]), `${what} ${k}`).toBeLessThan(0.5);
  };
  close(canvas.rect, webgl.rect, 'restingRect');
  canvas.places.forEach((p, i) => close(p, webgl.places[i], `place ${i}`));
  expect(canvas.anchors.length).toBe(webgl.anchors.length);
  canvas.anchors.forEach((a, i) => close(a, webgl.anchors[i], `anchor ${i}`));
}

for (const direction of ['ltr', 'rtl', 'vertical']) {
  test(`browser: Flipbook and StaticBook lay out, link, zoom and turn alike (${direction}, double)`, async ({ page }) => {
    await openReady(page, FIXTURE);
    await openBoth(page, { display: 'double', direction, startPage: 3, duration: 200 });
    const atRest = await report(page);
    expect(atRest.webgl.openPages).toEqual([3, 4]);
    expect(atRest.webgl.anchors.map((a) => a.page)).toEqual([3, 4]);
    expectSameLayout(atRest);

    // Zoom by code, then by the + key on each focused book: the same places, anchors and events.
    await page.evaluate(() => { for (const book of Object.values(window.books)) book.zoom = 2; });
    expectSameLayout(await report(page));
    for (const kind of ['webgl', 'canvas']) {
      await page.evaluate((kind) => window.books[kind].element.focus(), kind);
      await page.keyboard.press('+');
    }
    const zoomed = await report(page);
    expect(zoomed.canvas.zoom).toBeCloseTo(2.5, 6);
    expectSameLayout(zoomed);
    expect(zoomed.canvas.places[0].width).toBeGreaterThan(2.4 * atRest.canvas.places[0].width);

    // A pan moves both pictures alike; 0 zooms back out.
    for (const kind of ['webgl', 'canvas']) {
      const box = await page.evaluate((kind) => window.books[kind].element.getBoundingClientRect().toJSON(), kind);
      await page.mouse.move(box.x + 300, box.y + 200);
      await page.mouse.down();
      await page.mouse.move(box.x + 360, box.y + 230, { steps: 4 });
      await page.mouse.up();
    }
    await page.evaluate(() => Promise.all(Object.values(window.books).map((book) => book.whenIdle())));
    expectSameLayout(await report(page));
    for (const kind of ['webgl', 'canvas']) {
      await page.evaluate((kind) => window.books[kind].element.focus(), kind);
      await page.keyboard.press('0');
    }
    expect(await page.evaluate(() => window.zooms)).toEqual({ webgl: [2, 2.5, 1], canvas: [2, 2.5, 1] });
    expectSameLayout(await report(page));

    // Turning: both land on the next spread and say so.
    await page.evaluate(() => Promise.all(Object.values(window.books).map((book) => book.next())));
    const turned = await report(page);
    expect(turned.webgl.openPages).toEqual([5, 6]);
    expectSameLayout(turned);
  });
}

test('browser: the still book zooms about the pointer with Ctrl + wheel, and draws the zoomed page (pixels)', async ({ page }) => {
  await openReady(page, FIXTURE);
  await openBoth(page, { display: 'single', startPage: 2 });
  await page.evaluate(() => window.books.canvas.element.scrollIntoView());
  const box = await page.evaluate(() => window.books.canvas.element.getBoundingClientRect().toJSON());
  // Canvas pixels (CSS px of the book's element) of the still book's own drawing.
  const pixels = (points) => page.evaluate((points) => {
    const canvas = window.books.canvas.element.querySelector('canvas');
    const context = canvas.getContext('2d');
    const ratio = canvas.width / canvas.clientWidth;
    return points.map(([x, y]) => [...context.getImageData(Math.round(x * ratio), Math.round(y * ratio), 1, 1).data]);
  }, points);
  const before = await report(page);
  const r0 = before.canvas.rect;
  // A whole viewport pixel: mouse events carry whole CSS pixels.
  const at = { x: Math.round(box.x + r0.x + r0.width * 0.3) - box.x, y: Math.round(box.y + r0.y + r0.height * 0.4) - box.y };
  const beside = [r0.x - 20, at.y];  // left of the page at 1x: the bare canvas
  const [underBefore, besideBefore] = await pixels([[at.x, at.y], beside]);
  await page.mouse.move(box.x + at.x, box.y + at.y);
  await page.keyboard.down('Control');
  await page.mouse.wheel(0, -300);
  await page.keyboard.up('Control');
  await page.waitForFunction(() => window.books.canvas.zoom > 1.5);
  const after = await report(page);
  // The point under the pointer stays under it: the same fraction of the page before and after.
  const fraction = (rect) => [(at.x - rect.x) / rect.width, (at.y - rect.y) / rect.height];
  const [fx0, fy0] = fraction(r0);
  const [fx1, fy1] = fraction(after.canvas.rect);
  expect(Math.abs(fx1 - fx0)).toBeLessThan(1e-3);
  expect(Math.abs(fy1 - fy0)).toBeLessThan(1e-3);
  expect(await page.evaluate(() => window.zooms.canvas.length)).toBeGreaterThan(0);
  // What is drawn follows: the same colour under the pointer, and the page now covers the point beside it.
  expect(after.canvas.rect.x).toBeLessThan(beside[0]);
  const [underAfter, besideAfter] = await pixels([[at.x, at.y], beside]);
  expect(underAfter).toEqual(underBefore);
  expect(besideBefore[3]).toBe(0);      // nothing drawn there at 1x
  expect(besideAfter[3]).toBe(255);     // the page drawn there zoomed in
});
