// Browser: a closed book sits centred and slides open as its cover turns (`center`), and a flip to a
// far page riffles: several leaves in flight at once (counted from the engine's frame), landing within
// RIFFLE_SPAN (under 2) turn durations of the engine's clock, showing the pages between on the way.
import { test, expect } from '@playwright/test';
import { dragAlong, openReady } from './helpers.js';

const FIXTURE = '/tests/browser/fixtures/flipbook-fixture.html';

// Columns of the canvas holding opaque book pixels (alpha > 200: pages, not the faint shadow), as
// { left, right } margins in pixels, for the frame the book shows now.
async function margins(page) {
  return page.evaluate(() => {
    const view = window.book.surface;
    view.drawNow();
    const { width, height, data } = view.readPixels();
    let first = width;
    let last = -1;
    for (let y = 0; y < height; y += 2) {
      for (let x = 0; x < width; x++) {
        if (data[4 * (y * width + x) + 3] > 200) {
          first = Math.min(first, x);
          last = Math.max(last, x);
        }
      }
    }
    return { left: first, right: width - 1 - last };
  });
}

test('browser: a closed book is centred (margins within 2 px) at its front and back cover, and the open book lies where it does with center off', async ({ page }) => {
  await openReady(page, FIXTURE);
  for (const direction of ['ltr', 'rtl']) {
    await page.evaluate((direction) => window.openBook({ pages: 8, display: 'double', direction, hardCovers: true }), direction);
    const front = await margins(page);
    expect(Math.abs(front.left - front.right), `${direction} front cover ${JSON.stringify(front)}`).toBeLessThanOrEqual(2);
    await page.evaluate(() => window.book.flip(7, { animate: false }));
    const back = await margins(page);
    expect(Math.abs(back.left - back.right), `${direction} back cover ${JSON.stringify(back)}`).toBeLessThanOrEqual(2);
    await page.evaluate(() => window.book.flip(3, { animate: false }));
    const open = await margins(page);
    await page.evaluate((direction) => window.openBook({ pages: 8, display: 'double', direction, hardCovers: true, center: false, startPage: 3 }), direction);
    expect(await margins(page), `${direction}: the open book where it always was`).toEqual(open);
    await page.evaluate(() => window.book.flip(0, { animate: false }));
    const offFront = await margins(page);
    expect(offFront.left - offFront.right, `${direction}: center false leaves the cover off-centre`).not.toBe(0);
    expect(Math.abs(offFront.left - offFront.right)).toBeGreaterThan(100);
  }
});

test('browser: the book slides to the open position as the cover turns, step by step with no jump, and its open pages follow', async ({ page }) => {
  await openReady(page, FIXTURE);
  await page.evaluate(() => window.openBook({ pages: 8, display: 'double', hardCovers: true }));
  const closed = await page.evaluate(() => window.book.openPagePlaces());
  // The front cover's page place is where it is drawn: its spine edge is the drawn book's left edge
  // (the stack's edge band lies on the other three sides).
  expect(Math.abs(closed[0].x - (await margins(page)).left)).toBeLessThan(1.5);
  const rights = [];
  for (let t = 0; t <= 1.0001; t += 0.1) {
    await page.evaluate((t) => window.book.previewTurn('forward', t), t);
    rights.push((await margins(page)).right);
  }
  // The right margin shrinks (the book moves right) from the closed book's to the open one's.
  for (let i = 1; i < rights.length; i++) expect(rights[i], rights.join(' ')).toBeLessThanOrEqual(rights[i - 1] + 1);
  const steps = rights.slice(1).map((r, i) => rights[i] - r);
  expect(Math.max(...steps), rights.join(' ')).toBeLessThan(0.4 * (rights[0] - rights[rights.length - 1]));
  expect(rights[0] - rights[rights.length - 1]).toBeGreaterThan(80);  // half a page
});

test('browser: flip() to page 300 of 400 riffles: more than one leaf in flight, pages between shown, landing within RIFFLE_SPAN turns of the engine\'s clock', async ({ page }) => {
  await openReady(page, FIXTURE);
  const result = await page.evaluate(async () => {
    const { RIFFLE_SPAN } = await import('/dist/engine-constants.js');
    await window.openBook({ pages: 400, display: 'double', duration: 400 });
    const book = window.book;
    const view = book.surface;
    const events = [];
    for (const type of ['turnstart', 'turned']) book.addEventListener(type, (e) => events.push([type, e.detail]));
    // The engine's clock advances each frame by the time since the last, capped at 0.25 s: sum the
    // same from the frames' own timestamps, so the figure is the engine's, not the wall clock's.
    let engineSeconds = 0;
    let last = performance.now();
    let mostInFlight = 0;
    const pagesSeen = new Set();
    let frames = 0;
    const watch = (now) => {
      engineSeconds += Math.min(Math.max(0, now - last), 250) / 1000;
      last = now;
      frames++;
      mostInFlight = Math.max(mostInFlight, view.book.frame().filter((leaf) => !leaf.resting && leaf.curl.rho > 1e-6).length);
      for (const p of view.pagesOnScreen()) pagesSeen.add(p);
      if (book.animating) requestAnimationFrame(watch);
    };
    const flipping = book.flip(300);
    requestAnimationFrame(watch);
    await flipping;
    return {
      page: book.page, engineSeconds, mostInFlight, frames, riffleSpan: RIFFLE_SPAN, events,
      between: [...pagesSeen].filter((p) => p > 3 && p < 297).sort((a, b) => a - b),
    };
  });
  console.log(`riffle 0 -> 300 of 400: ${result.frames} frames, ${result.engineSeconds.toFixed(3)} s on the engine's clock `
    + `(one turn 0.4 s), at most ${result.mostInFlight} leaves in flight, pages between shown: ${result.between.join(' ')}`);
  expect(result.page).toBe(299);
  expect(result.mostInFlight).toBeGreaterThan(1);
  expect(result.riffleSpan).toBeLessThanOrEqual(2);
  expect(result.engineSeconds).toBeLessThanOrEqual(0.4 * result.riffleSpan + 0.25);  // + at most one capped frame
  expect(result.between.length).toBeGreaterThanOrEqual(4);
  expect(result.events).toEqual([['turnstart', { direction: 'forward', page: 299, riffle: true }], ['turned', { page: 299 }]]);
});

test('browser: End, Home and a link to a far page riffle too; a near flip still turns leaf by leaf', async ({ page }) => {
  await openReady(page, FIXTURE);
  await page.evaluate(() => window.openBook({
    pages: Array.from({ length: 60 }, (_, i) => ({ src: window.makeNumberedPage(i), links: i === 0 ? [{ rect: [0.2, 0.2, 0.5, 0.3], page: 41 }] : undefined })),
    display: 'double', duration: 300,
  }));
  // Watches from before the action: turnstart events, and the most leaves lifted in one frame.
  const watch = () => page.evaluate(() => {
    const book = window.book;
    const seen = { most: 0, starts: [], done: false };
    book.addEventListener('turnstart', (e) => seen.starts.push(e.detail));
    const count = () => {
      seen.most = Math.max(seen.most, book.surface.book.frame().filter((leaf) => !leaf.resting && leaf.curl.rho > 1e-6).length);
      if (!seen.done) requestAnimationFrame(count);
    };
    requestAnimationFrame(count);
    window.seen = seen;
  });
  // Once the action's first turnstart is heard (each action here turns), waits until the book rests.
  const outcome = async () => {
    await page.waitForFunction(() => window.seen.starts.length > 0);
    return page.evaluate(async () => {
      await window.settle();
      const { seen, book } = window;
      seen.done = true;
      return { most: seen.most, page: book.page, starts: seen.starts.length, riffle: seen.starts.some((s) => s.riffle) };
    });
  };
  await page.evaluate(() => window.book.element.focus());
  await watch();
  await page.keyboard.press('End');
  const end = await outcome();
  expect(end).toMatchObject({ page: 59, riffle: true, starts: 1 });
  expect(end.most).toBeGreaterThan(1);
  await watch();
  await page.keyboard.press('Home');
  const home = await outcome();
  expect(home).toMatchObject({ page: 0, riffle: true, starts: 1 });
  expect(home.most).toBeGreaterThan(1);
  await watch();
  await page.locator('.conecurl-links a').first().click();  // the front cover's link to page 41
  const link = await outcome();
  expect(link).toMatchObject({ page: 41, riffle: true, starts: 1 });
  expect(link.most).toBeGreaterThan(1);
  await watch();
  await page.evaluate(() => window.book.flip(window.book.page + 4));  // two leaves away: one by one
  const near = await outcome();
  expect(near).toMatchObject({ page: 45, riffle: false, starts: 2 });
});

test('browser: dragging the cover of a closed book keeps its corner under the pointer while the book slides open (GPU vertices)', async ({ page }) => {
  await openReady(page, FIXTURE);
  await page.evaluate(() => window.openBook({ pages: 8, display: 'double', duration: 600 }));
  // The pointer follows the path the cover's bottom free corner takes in a scheduled turn, as drawn:
  // a twin engine Book posed at each t gives the corner and the camera of that frame (it slides).
  const path = await page.evaluate(() => {
    const view = window.book.surface;
    const { engine } = view;
    const { width, height } = view.fitCanvas();
    const rect = view.canvas.getBoundingClientRect();
    const twin = engine.Book.create({ pageCount: 8, display: 'double' });
    const out = [];
    for (let i = 0; i <= 24; i++) {
      twin.jumpTo(0);
      twin.startTurn('forward');
      twin.setLatestTurnProgress((0.85 * i) / 24);
      const vp = twin.viewProjection(width, height);
      const draw = twin.frame().find((leaf) => !leaf.resting);
      const p = engine.leafPointToWorld(draw, 'left', twin.pageHeight(), twin.pageWidth(), 0);
      const cx = vp[0] * p.x + vp[4] * p.y + vp[8] * p.z + vp[12];
      const cy = vp[1] * p.x + vp[5] * p.y + vp[9] * p.z + vp[13];
      const cw = vp[3] * p.x + vp[7] * p.y + vp[11] * p.z + vp[15];
      out.push({ x: rect.left + ((cx / cw + 1) / 2) * rect.width, y: rect.top + ((1 - cy / cw) / 2) * rect.height });
    }
    twin.delete();
    return out;
  });
  // Where the GPU drew the held leaf's bottom free corner, under the camera of that frame.
  const corner = () => page.evaluate(() => {
    const view = window.book.surface;
    const { width, height } = view.fitCanvas();
    const vp = view.book.viewProjection(width, height);
    const rect = view.canvas.getBoundingClientRect();
    const index = view.book.frame().findIndex((leaf) => !leaf.resting);
    const vertices = view.renderer.captureLeaf(view.book, index);
    const points = view.renderer.gridPoints();
    const w = view.book.pageWidth();
    let best = 0;
    for (let i = 0; i < points.length / 2; i++) {
      if (Math.hypot(points[2 * i] - w, points[2 * i + 1]) < Math.hypot(points[2 * best] - w, points[2 * best + 1])) best = i;
    }
    const [x, y, z] = [vertices[6 * best], vertices[6 * best + 1], vertices[6 * best + 2]];
    const cx = vp[0] * x + vp[4] * y + vp[8] * z + vp[12];
    const cy = vp[1] * x + vp[5] * y + vp[9] * z + vp[13];
    const cw = vp[3] * x + vp[7] * y + vp[11] * z + vp[15];
    return { x: rect.left + ((cx / cw + 1) / 2) * rect.width, y: rect.top + ((1 - cy / cw) / 2) * rect.height };
  });
  const worst = await dragAlong(page, path, corner);
  console.log(`cover drag on a centred closed book: worst ${worst.toFixed(3)} CSS px from the pointer over ${path.length} moves`);
  expect(worst, 'distance from the pointer to the drawn corner, CSS px').toBeLessThan(2);
  await page.mouse.up();
  await page.waitForFunction(() => !window.book.animating);
  expect(await page.evaluate(() => window.book.page)).toBe(1);
});
