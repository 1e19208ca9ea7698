// Browser (WebGL2 on SwiftShader): the whole book. Which page shows where (pages are colour-coded),
// that backs read the right way round, render on demand, the light/shadow options, and reference
// frames of every kind of turn.
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';

const FIXTURE = '/tests/browser/fixtures/book-fixture.html';

// Probe points on the 640x400 canvas, away from each page's number, marker and the gutter.
const LEFT = [110, 300];
const RIGHT = [530, 300];
const TOP = [370, 90];
const BOTTOM = [370, 330];
const SINGLE = [420, 330];

/** Opens the fixture with `query` and returns the page index seen at each probe point. */
async function pagesAt(page, query, points) {
  await openReady(page, `${FIXTURE}?${query}`);
  return page.evaluate((points) => {
    const { view, pageAt } = window.fixture;
    view.drawNow();
    const pixels = view.readPixels();
    return points.map(([x, y]) => pageAt(pixels, x, y));
  }, points);
}

/** Counts pixels of each page colour (index -> count) in the frame just drawn. */
async function pageCounts(page) {
  return page.evaluate(() => {
    const { view, pageAt } = window.fixture;
    view.drawNow();
    const pixels = view.readPixels();
    const counts = {};
    for (let y = 0; y < pixels.height; y += 2) {
      for (let x = 0; x < pixels.width; x += 2) {
        const p = pageAt(pixels, x, y);
        if (p >= 0) counts[p] = (counts[p] || 0) + 1;
      }
    }
    return counts;
  });
}

test('browser: resting spreads show the right pages for ltr, rtl, vertical and single display', async ({ page }) => {
  expect(await pagesAt(page, 'position=1', [LEFT, RIGHT])).toEqual([1, 2]);
  expect(await pagesAt(page, 'position=3', [LEFT, RIGHT])).toEqual([5, 6]);
  expect(await pagesAt(page, 'position=0&center=off', [LEFT, RIGHT])).toEqual([-1, 0]);  // the cover alone
  expect(await pagesAt(page, 'position=0', [LEFT, [320, 300], RIGHT])).toEqual([-1, 0, -1]);  // centred (center: true)
  expect(await pagesAt(page, 'position=1&direction=rtl', [LEFT, RIGHT])).toEqual([2, 1]);
  expect(await pagesAt(page, 'position=1&direction=vertical', [TOP, BOTTOM])).toEqual([1, 2]);
  expect(await pagesAt(page, 'position=2&display=single', [SINGLE])).toEqual([2]);
});

test('browser: a forward turn reveals the right page beneath and shows the next page on its back', async ({ page }) => {
  expect(await pagesAt(page, 'position=1&turn=forward&t=0.3', [LEFT, RIGHT])).toEqual([1, 4]);
  const counts = await pageCounts(page);
  expect(counts[3], 'back of the turning leaf (page 3) is seen').toBeGreaterThan(500);
  expect(counts[2] || 0, 'its front (page 2) has turned away by t=0.3').toBeLessThan(counts[3]);
  // Landed: the leaf's back is the new left page.
  expect(await pagesAt(page, 'position=1&turn=forward&t=1', [LEFT, RIGHT])).toEqual([3, 4]);
});

test('browser: a backward turn lifts the left page and uncovers the page before it', async ({ page }) => {
  await openReady(page, `${FIXTURE}?position=2&turn=backward&t=0.6`);
  const counts = await pageCounts(page);
  expect(counts[1], 'page 1 uncovered on the left').toBeGreaterThan(2000);
  expect(counts[2], 'the leaf shows its front (page 2) as it comes over').toBeGreaterThan(2000);
  expect(await pagesAt(page, 'position=2&turn=backward&t=1', [LEFT, RIGHT])).toEqual([1, 2]);
});

test('browser: the back of a turned leaf reads unmirrored: its marker is at its own top-left', async ({ page }) => {
  // The turned page lies left of the spine in ltr (its image's left edge is the outer edge, x ~ 74)
  // and right of it in rtl (its left edge is the spine, x = 320). A mirrored back would put the
  // marker at the other edge of that page.
  for (const [query, from, to, near] of [
    ['position=1&turn=forward&t=1', 0, 320, 74],
    ['position=1&direction=rtl&turn=forward&t=1', 320, 640, 320],
  ]) {
    await openReady(page, `${FIXTURE}?${query}`);
    const marker = await page.evaluate(([from, to]) => {
      const { view } = window.fixture;
      view.drawNow();
      const { width, height, data } = view.readPixels();
      let sx = 0; let sy = 0; let n = 0;
      for (let y = 0; y < height; y++) {
        for (let x = from; x < to; x++) {
          const i = (y * width + x) * 4;
          if (data[i + 3] > 200 && data[i] < 40 && data[i + 1] < 40 && data[i + 2] < 40) { sx += x; sy += y; n++; }
        }
      }
      return { x: sx / n, y: sy / n, n };
    }, [from, to]);
    expect(marker.n, query).toBeGreaterThan(500);
    expect(marker.y, query).toBeLessThan(140);
    expect(Math.abs(marker.x - near), query).toBeLessThan(80);
  }
});

test('browser: a hard cover turns flat (rigid) and uncovers page 2 beneath it', async ({ page }) => {
  await openReady(page, `${FIXTURE}?position=0&hard=0,1&turn=forward&t=0.35`);
  const draws = await page.evaluate(() => window.fixture.view.book.frame().filter((l) => !l.resting));
  expect(draws).toHaveLength(1);
  expect(draws[0].hard).toBe(true);
  expect(draws[0].curl.theta).toBeCloseTo(Math.PI / 2, 12);  // no curl
  const counts = await pageCounts(page);
  // Samples (every other row and column): the cover, ~50 degrees up and nearer the eye, covers
  // ~16500; page 2 shows in the strip it uncovers (~3400).
  expect(counts[0]).toBeGreaterThan(8000);
  expect(counts[2]).toBeGreaterThan(2000);
});

test('browser: two leaves in flight are both drawn over the right page beneath', async ({ page }) => {
  await openReady(page, `${FIXTURE}?position=1&turn=forward&t=0.45&then=0.12`);
  const flying = await page.evaluate(() => window.fixture.view.book.frame().filter((l) => !l.resting).map((l) => l.leaf));
  expect(flying).toEqual([1, 2]);
  const counts = await pageCounts(page);
  for (const p of [1, 3, 4, 6]) expect(counts[p] || 0, `page ${p} seen`).toBeGreaterThan(300);
  expect(await pagesAt(page, 'position=1&turn=forward&t=0.45&then=0.12', [RIGHT])).toEqual([6]);
});

test('browser: nothing is drawn and no animation frame is requested while the book rests', async ({ page }) => {
  // The page runs on Playwright's clock, paused once the book is up: timers and animation frames come
  // only as runFor() lets them, so a turn lasts as many frames (1 s: ~60), and "a second at rest" is as
  // many frames, on any machine however loaded.
  await page.clock.install();
  await page.addInitScript(() => {
    window.rafCalls = 0;
    const raf = window.requestAnimationFrame.bind(window);
    window.requestAnimationFrame = (callback) => { window.rafCalls++; return raf(callback); };
  });
  await openReady(page, `${FIXTURE}?position=1`);
  await page.clock.pauseAt(await page.evaluate(() => Date.now() + 1000));
  await page.clock.runFor(500);  // the frame the book asked for as it opened
  const idle = async () => page.evaluate(() => ({ frames: window.fixture.view.framesDrawn, raf: window.rafCalls }));
  const before = await idle();
  await page.clock.runFor(1000);
  expect(await idle()).toEqual(before);
  await page.evaluate(() => { window.turning = window.fixture.view.next(); });
  await page.clock.runFor(1500);  // the turn lasts 1 s
  expect(await page.evaluate(() => window.turning)).toBe(true);
  const after = await idle();
  expect(after.frames - before.frames, 'a turn draws frames').toBeGreaterThan(5);
  expect(after.raf - before.raf, 'one animation frame asked for each').toBeGreaterThan(5);
  await page.clock.runFor(1000);
  expect(await idle(), 'and stops once it lands').toEqual(after);
});

test('browser: lighting, shadows and gutter each change the frame, and a flat page keeps its colour', async ({ page }) => {
  const frame = async (query) => {
    await openReady(page, `${FIXTURE}?position=1&${query}`);
    const base64 = await page.evaluate(() => {
      window.fixture.view.drawNow();
      const { data } = window.fixture.view.readPixels();
      let text = '';
      for (let i = 0; i < data.length; i += 0x8000) text += String.fromCharCode(...data.subarray(i, i + 0x8000));
      return btoa(text);
    });
    return Buffer.from(base64, 'base64');
  };
  const turning = await frame('turn=forward&t=0.3');
  const diff = (a, b) => {
    let n = 0;
    for (let i = 0; i < a.length; i++) if (Math.abs(a[i] - b[i]) > 8) n++;
    return n / 4;
  };
  expect(diff(turning, await frame('turn=forward&t=0.3&lighting=off')), 'lighting').toBeGreaterThan(2000);
  expect(diff(turning, await frame('turn=forward&t=0.3&shadows=off')), 'shadows').toBeGreaterThan(2000);
  // The lifted leaf hides the gutter mid-turn: compare resting spreads (a strip ~6% of a page wide).
  expect(diff(await frame(''), await frame('gutter=off')), 'gutter').toBeGreaterThan(500);
  // With shadows off, the resting right page far from the spine shows the texture's own colour.
  const plain = await frame('turn=forward&t=0.3&shadows=off');
  const [r, g, b] = plain.subarray((RIGHT[1] * 640 + RIGHT[0]) * 4, (RIGHT[1] * 640 + RIGHT[0]) * 4 + 3);
  const { pageColor } = await import('./fixtures/test-pages.js');
  const want = pageColor(4);
  for (const [got, expected] of [[r, want[0]], [g, want[1]], [b, want[2]]]) expect(Math.abs(got - expected)).toBeLessThanOrEqual(2);
});

// Reference images: scripts/update-references.sh rewrites them (look at each before committing).
// Tolerance: SwiftShader is deterministic on one machine; other CPUs may rasterise antialiased edges
// and text a little differently, so up to 0.5% of pixels may differ by more than the 0.1 threshold.
const FRAMES = {
  'forward-t0.05': 'position=1&turn=forward&t=0.05',
  'forward-t0.15': 'position=1&turn=forward&t=0.15',
  'forward-t0.30': 'position=1&turn=forward&t=0.3',
  'forward-t0.60': 'position=1&turn=forward&t=0.6',
  'forward-t0.90': 'position=1&turn=forward&t=0.9',
  'backward-t0.20': 'position=2&turn=backward&t=0.2',
  'backward-t0.60': 'position=2&turn=backward&t=0.6',
  'hard-cover-t0.35': 'position=0&hard=0,1&turn=forward&t=0.35',
  'rtl-t0.30': 'position=1&direction=rtl&turn=forward&t=0.3',
  'vertical-t0.30': 'position=1&direction=vertical&turn=forward&t=0.3',
  'single-t0.30': 'position=2&display=single&turn=forward&t=0.3',
  'no-light-shadow-gutter-t0.30': 'position=1&turn=forward&t=0.3&lighting=off&shadows=off&gutter=off',
  'two-in-flight': 'position=1&turn=forward&t=0.45&then=0.12',
  'closed-centred': 'pages=40&position=0&hard=0,39',
  'closed-back-centred': 'pages=40&position=20&hard=0,39',
  'riffle-forward': 'pages=40&position=2&riffle=16&at=0.55',
  'riffle-home': 'pages=40&position=14&riffle=0&at=0.6&hard=0,39',
};
for (const [name, query] of Object.entries(FRAMES)) {
  test(`browser: book frame ${name} matches its reference image`, async ({ page }) => {
    await openReady(page, `${FIXTURE}?${query}`);
    await expect(page.locator('#book')).toHaveScreenshot(`book-${name}.png`, { maxDiffPixelRatio: 0.005, threshold: 0.1 });
  });
}

test('browser: ten quick turns end on the right spread, and a quick back-and-forth loses no click', async ({ page }) => {
  await openReady(page, `${FIXTURE}?pages=40&position=0`);
  const position = await page.evaluate(async () => {
    const { view } = window.fixture;
    const turns = [];
    for (let i = 0; i < 10; i++) {
      turns.push(view.next());
      // The next turn is asked for once this one has drawn a frame: quick, leaves still in flight.
      const drawn = view.framesDrawn;
      while (view.framesDrawn === drawn) await new Promise((r) => requestAnimationFrame(r));
    }
    await Promise.all(turns);
    return view.position;
  });
  expect(position).toBe(10);
  const after = await page.evaluate(async () => {
    const { view } = window.fixture;
    const a = view.next();
    const b = view.prev();  // needs the leaf that is still turning: waits for it, then turns back
    await Promise.all([a, b]);
    return { position: view.position, animating: view.animating };
  });
  expect(after).toEqual({ position: 10, animating: false });
});

test('browser: the grid is chosen for the canvas: finer on a larger canvas, error within half a pixel', async ({ page }) => {
  await openReady(page, `${FIXTURE}?position=1`);
  const sizes = await page.evaluate(() => {
    const { view } = window.fixture;
    const out = [];
    for (const [w, h] of [[320, 200], [640, 400], [1600, 1000]]) {
      view.canvas.style.width = `${w}px`;
      view.canvas.style.height = `${h}px`;
      view.drawNow();
      out.push({ rows: view.renderer.gridRows(), error: view.renderer.gridErrorPixels() });
    }
    return out;
  });
  for (const { error } of sizes) expect(error).toBeLessThanOrEqual(0.5);
  expect(sizes[0].rows).toBeLessThan(sizes[1].rows);
  expect(sizes[1].rows).toBeLessThan(sizes[2].rows);
});

test('browser: after WebGL context loss and restore every GPU object and page is back', async ({ page }) => {
  await openReady(page, `${FIXTURE}?position=1`);
  const before = await page.evaluate(() => {
    const { view, pageAt } = window.fixture;
    view.drawNow();
    const p = view.readPixels();
    return [pageAt(p, 110, 300), pageAt(p, 530, 300)];
  });
  expect(before).toEqual([1, 2]);
  const after = await page.evaluate(async () => {
    const { view, pageAt } = window.fixture;
    const gl = view.canvas.getContext('webgl2');
    const lose = gl.getExtension('WEBGL_lose_context');
    const event = (name) => new Promise((resolve) => view.canvas.addEventListener(name, resolve, { once: true }));
    const lost = event('webglcontextlost');
    lose.loseContext();
    await lost;
    // Chrome allows a restore only once the lost event's dispatch has returned (it reads preventDefault
    // then): any later task, however slow the machine.
    await new Promise((resolve) => setTimeout(resolve, 0));
    const restored = event('webglcontextrestored');
    lose.restoreContext();
    await restored;
    await new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve)));
    view.drawNow();
    const p = view.readPixels();
    return { pages: [pageAt(p, 110, 300), pageAt(p, 530, 300)], resident: view.renderer.residentPageImages() };
  });
  expect(after.pages).toEqual([1, 2]);
  expect(after.resident).toBe(8);
});
