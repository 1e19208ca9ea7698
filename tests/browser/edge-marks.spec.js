// Browser (WebGL2 on SwiftShader): marks on the book's edge. Index tabs for the outline's sections and
// ticks for search hits are drawn by the engine on the page blocks at their leaves (read back from the
// frame and compared with where the engine says they lie and with the leaf's depth in its block), move
// to the other block as leaves turn, and have buttons over them that riffle there.
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';

const FIXTURE = '/tests/browser/fixtures/flipbook-fixture.html';
const OUTLINE = [
  { title: 'Preface', page: 6 }, { title: 'Methods', page: 70 }, { title: 'Results', page: 120 }, { title: 'Appendix', page: 180 },
];

// A book with an outline (the `outline` option: outline() gives it, and edge-marks.js reads outline()).
// `edgeMarks: null` leaves the option out.
async function openWithOutline(page, { pages = 200, startPage = 0, outline = OUTLINE, edgeMarks = true } = {}) {
  // A large book, so a block of 80 leaves is some 40 pixels deep: a leaf's place shows to a few leaves.
  await page.setViewportSize({ width: 1280, height: 860 });
  await openReady(page, FIXTURE);
  await page.evaluate(async (options) => {
    document.getElementById('container').style.cssText = 'width: 1240px; height: 820px';
    if (options.edgeMarks === null) delete options.edgeMarks;
    await window.openBook({ ...options, display: 'double', duration: 300 });
  }, { pages, startPage, outline, edgeMarks });
  // outline() is loaded on first use: the tabs come once it answers (their buttons say so).
  if (edgeMarks) await expect(page.locator('[data-edge-mark="tab"]')).toHaveCount(outline.length);
}

// The drawn frame read back, and for each mark that shows: where the engine says it lies (buffer px),
// and what the pixels say along the row through its middle: where its colour starts and ends, and
// how far the block's edge reaches on a row with no mark (the block's depth in pixels).
function readMarks() {
  const view = window.book.surface;
  view.drawNow();
  const pixels = view.readPixels();
  const toBuffer = pixels.width / view.canvas.clientWidth;
  const rect = view.book.restingRect(pixels.width, pixels.height);
  const at = (x, y) => pixels.data.subarray((y * pixels.width + x) * 4, (y * pixels.width + x) * 4 + 4);
  const coloured = (x, y) => { const [r, g, b, a] = at(x, y); return a > 128 && Math.max(r, g, b) - Math.min(r, g, b) > 60; };
  const opaque = (x, y) => at(x, y)[3] > 128;
  const leafCount = view.book.leafCount();
  const position = view.book.position();
  return view.edgeMarkPlaces().map((place) => {
    const x0 = place.x * toBuffer;
    const x1 = (place.x + place.width) * toBuffer;
    const y0 = place.y * toBuffer;
    const y1 = (place.y + place.height) * toBuffer;
    // Outward from the page's free edge on this block's side.
    const edge = place.turned ? Math.floor(rect.x) - 2 : Math.ceil(rect.x + rect.width) + 1;
    const step = place.turned ? -1 : 1;
    const outward = (x) => (x - edge) * step;
    const row = Math.round((y0 + y1) / 2);
    let first = null;
    let last = null;
    for (let x = edge; x >= 0 && x < pixels.width; x += step) {
      if (coloured(x, row)) { if (first === null) first = x; last = x; }
    }
    const plainRow = Math.round(rect.y + rect.height * 0.85);
    let band = 0;
    for (let x = edge; x >= 0 && x < pixels.width && opaque(x, plainRow); x += step) band++;
    // Rows of the mark's colour through its middle column (a tick's: the one its colour was found in).
    const column = place.kind === 'tick' && first !== null ? first : Math.round((x0 + x1) / 2);
    let top = null;
    let bottom = null;
    for (let y = Math.max(0, Math.floor(y0) - 6); y < Math.min(pixels.height, Math.ceil(y1) + 6); y++) {
      if (coloured(column, y)) { if (top === null) top = y; bottom = y; }
    }
    const leaf = Math.floor(place.page / 2);
    const fromTop = place.turned ? position - 1 - leaf : leaf - position;
    const leaves = place.turned ? position : leafCount - position;
    return {
      page: place.page, kind: place.kind, turned: place.turned,
      engine: { inner: outward(place.turned ? x1 : x0), outer: outward(place.turned ? x0 : x1), top: y0, bottom: y1 },
      pixels: { inner: first === null ? null : outward(first), outer: last === null ? null : outward(last), top, bottom, band },
      depthFraction: fromTop / leaves,
      [place.kind === 'tab' ? 'colour' : 'tickColour']: [...at(column, Math.round((y0 + y1) / 2))].slice(0, 3),
    };
  });
}

function expectTabsAtTheirLeaves(marks) {
  for (const mark of marks) {
    const { engine, pixels } = mark;
    const name = `tab for page ${mark.page} (${mark.turned ? 'left' : 'right'} block)`;
    expect(pixels.inner, `${name}: its colour is drawn`).not.toBeNull();
    // The pixels of the tab's colour are where the engine says the tab lies (to a pixel and its edge's antialiasing).
    expect(Math.abs(pixels.inner - engine.inner), `${name}: inner end`).toBeLessThanOrEqual(2.5);
    expect(Math.abs(pixels.outer - engine.outer), `${name}: tip`).toBeLessThanOrEqual(2.5);
    expect(Math.abs(pixels.top - engine.top), `${name}: top`).toBeLessThanOrEqual(2.5);
    expect(Math.abs(pixels.bottom - engine.bottom), `${name}: bottom`).toBeLessThanOrEqual(2.5);
    // Its inner end lies as deep in the block as its leaf lies among the block's leaves, and its tip
    // sticks out past the block.
    expect(Math.abs(pixels.inner - mark.depthFraction * pixels.band), `${name}: depth in the block (px)`).toBeLessThanOrEqual(2.5);
    expect(pixels.outer, `${name}: sticks out`).toBeGreaterThan(pixels.band + 4);
  }
}

test('browser: index tabs are drawn at their leaves\' depth in each block, where the engine places them, and move blocks as leaves turn (readback)', async ({ page }) => {
  await openWithOutline(page, { startPage: 40 });
  const before = await page.evaluate(readMarks);
  console.log('tabs at page 40:', JSON.stringify(before.map(({ page: p, turned, pixels, depthFraction }) => ({ p, turned, ...pixels, depthFraction }))));
  expect(before.map((m) => [m.page, m.turned])).toEqual([[6, true], [70, false], [120, false], [180, false]]);
  expectTabsAtTheirLeaves(before);
  // A tab near the front of the right block lies shallow, one near the back deep.
  expect(before[1].pixels.inner).toBeLessThan(before[3].pixels.inner);
  // Each tab its own colour.
  expect(new Set(before.map((m) => m.colour.join())).size).toBe(4);

  // Riffle to page 150: Methods and Results go over to the left block; the Appendix stays on the right,
  // now near its top.
  await page.evaluate(() => window.book.flip(150));
  const after = await page.evaluate(readMarks);
  console.log('tabs at page 150:', JSON.stringify(after.map(({ page: p, turned, pixels, depthFraction }) => ({ p, turned, ...pixels, depthFraction }))));
  expect(after.map((m) => [m.page, m.turned])).toEqual([[6, true], [70, true], [120, true], [180, false]]);
  expectTabsAtTheirLeaves(after);
  expect(after[3].pixels.inner).toBeLessThan(before[3].pixels.inner);
  // On the left block the front section's tab is now the deepest.
  expect(after[0].pixels.inner).toBeGreaterThan(after[2].pixels.inner);
});

test('browser: a tab leaves its block with its leaf: mid-turn the leaf in flight shows no tab, the others stay at their leaves, and the overlay buttons hide (readback)', async ({ page }) => {
  await openWithOutline(page, { startPage: 69 });  // Methods (page 70) is on the right page's leaf
  const resting = await page.evaluate(readMarks);
  expect(resting.map((m) => [m.page, m.turned])).toEqual([[6, true], [70, false], [120, false], [180, false]]);
  expect(resting[1].pixels.inner, 'the open leaf\'s tab starts at the page\'s edge').toBeLessThanOrEqual(2);
  await expect(page.locator('[data-edge-mark]')).toHaveCount(4);
  const flying = await page.evaluate((measure) => {
    const marks = new Function(`return (${measure})`)();  // eslint-disable-line no-new-func
    window.book.previewTurn('forward', 0.5);
    return marks();
  }, readMarks.toString());
  expect(flying.map((m) => [m.page, m.turned])).toEqual([[6, true], [120, false], [180, false]]);
  expectTabsAtTheirLeaves(flying);
  await expect(page.locator('[data-edge-mark]')).toHaveCount(0);
});

test('browser: a tab\'s button is named by its section, and a click on it riffles to the section\'s page (waits for turned)', async ({ page }) => {
  await openWithOutline(page, { startPage: 40 });
  const tab = page.getByRole('button', { name: 'Appendix' });
  await expect(tab).toHaveAttribute('title', 'Appendix');
  const turned = page.evaluate(() => new Promise((resolve) => {
    window.book.addEventListener('turnstart', (event) => { window.riffled = Boolean(event.detail.riffle); }, { once: true });
    window.book.addEventListener('turned', (event) => resolve(event.detail.page), { once: true });
  }));
  await tab.click();
  await turned;
  expect(await page.evaluate(() => window.riffled)).toBe(true);
  expect(await page.evaluate(() => window.book.openPages)).toContain(180);
  // At rest again the buttons are laid out anew: the Appendix's tab is on top of the right block now.
  await expect(page.getByRole('button', { name: 'Preface' })).toBeVisible();
  const places = await page.evaluate(() => window.book.surface.edgeMarkPlaces().map((p) => [p.page, p.turned]));
  expect(places).toEqual([[6, true], [70, true], [120, true], [180, false]]);
});

test('browser: search hits are ticks on the blocks at their leaves, and go when the search is cleared (readback)', async ({ page }) => {
  await openWithOutline(page, { startPage: 60, outline: [] });
  const hits = [{ page: 20, snippet: 'a hit', rects: [[0.1, 0.1, 0.2, 0.05]] }, { page: 20, snippet: 'same page', rects: [] },
    { page: 150, snippet: 'later', rects: [[0.2, 0.5, 0.3, 0.05]] }];
  await page.evaluate((h) => window.book.dispatchEvent(new CustomEvent('searchchange', { detail: { query: 'hit', hits: h, current: null } })), hits);
  const ticks = await page.evaluate(readMarks);
  console.log('ticks:', JSON.stringify(ticks.map(({ page: p, turned, pixels, engine, depthFraction }) => ({ p, turned, ...pixels, e: engine, depthFraction }))));
  expect(ticks.map((m) => [m.page, m.kind, m.turned])).toEqual([[20, 'tick', true], [150, 'tick', false]]);
  for (const tick of ticks) {
    expect(tick.pixels.inner, `tick on page ${tick.page}`).not.toBeNull();
    // A line across the block at its leaf: its pixels within the engine's place, at the leaf's depth.
    expect(tick.pixels.inner).toBeGreaterThanOrEqual(tick.engine.inner - 2);
    expect(tick.pixels.outer).toBeLessThanOrEqual(tick.engine.outer + 2);
    expect(Math.abs((tick.pixels.inner + tick.pixels.outer) / 2 - tick.depthFraction * tick.pixels.band), 'at its leaf (px)').toBeLessThanOrEqual(2.5);
    expect(tick.pixels.bottom - tick.pixels.top, 'head to tail').toBeGreaterThan(100);
  }
  await expect(page.getByRole('button', { name: /^Search hit on page / })).toHaveCount(2);
  // A click on a tick goes to its hit's page (riffling: it is far).
  const turned = page.evaluate(() => new Promise((resolve) => window.book.addEventListener('turned', resolve, { once: true })));
  await page.getByRole('button', { name: 'Search hit on page 151: later' }).click();
  await turned;
  expect(await page.evaluate(() => window.book.openPages)).toContain(150);
  await page.evaluate(() => window.book.dispatchEvent(new CustomEvent('searchchange', { detail: { query: '', hits: [], current: null } })));
  expect(await page.evaluate(readMarks)).toEqual([]);
  await expect(page.getByRole('button', { name: /^Search hit on page / })).toHaveCount(0);
});

test('browser: a real search() of HTML pages puts a tick on the leaf of each page it finds, and clearSearch() takes them away', async ({ page }) => {
  await openReady(page, FIXTURE);
  await page.evaluate(async () => {
    const pages = Array.from({ length: 40 }, (_, i) => {
      const div = document.createElement('div');
      div.style.cssText = 'width: 320px; height: 400px; background: #fbf8f1; font: 16px sans-serif; padding: 20px; box-sizing: border-box';
      div.textContent = i === 9 || i === 31 ? `Page ${i}: a needle in the hay.` : `Page ${i}: only hay here.`;
      return div;
    });
    await window.openBook({ pages, startPage: 20, display: 'double', edgeMarks: true });
  });
  const hits = await page.evaluate(async () => (await window.book.search('needle')).map((hit) => hit.page));
  expect(hits).toEqual([9, 31]);
  await expect(page.locator('[data-edge-mark="tick"]')).toHaveCount(2);
  const ticks = await page.evaluate(() => window.book.surface.edgeMarkPlaces().map((p) => [p.page, p.kind, p.turned]));
  expect(ticks).toEqual([[9, 'tick', true], [31, 'tick', false]]);
  await page.evaluate(() => window.book.clearSearch());
  await expect(page.locator('[data-edge-mark="tick"]')).toHaveCount(0);
  expect(await page.evaluate(() => window.book.surface.edgeMarkPlaces())).toEqual([]);
});

test('browser: without edgeMarks (the default without controls) nothing is drawn outside the pages but the blocks, and no buttons are made (readback)', async ({ page }) => {
  await openWithOutline(page, { startPage: 40, edgeMarks: null });
  const colouredOutside = await page.evaluate(() => {
    const view = window.book.surface;
    view.drawNow();
    const pixels = view.readPixels();
    const rect = view.book.restingRect(pixels.width, pixels.height);
    let count = 0;
    for (let y = 0; y < pixels.height; y++) {
      for (let x = 0; x < pixels.width; x++) {
        if (x >= rect.x - 1 && x <= rect.x + rect.width + 1 && y >= rect.y - 1 && y <= rect.y + rect.height + 1) continue;
        const i = (y * pixels.width + x) * 4;
        const [r, g, b, a] = pixels.data.subarray(i, i + 4);
        if (a > 128 && Math.max(r, g, b) - Math.min(r, g, b) > 60) count++;
      }
    }
    return count;
  });
  await page.screenshot({ path: test.info().outputPath('no-marks.png') });
  expect(colouredOutside).toBe(0);
  expect(await page.evaluate(() => window.book.options.edgeMarks)).toBe(false);
  await expect(page.locator('[data-edge-mark]')).toHaveCount(0);
});

test('browser: after a lost WebGL context is restored the tabs are drawn again at their leaves (readback)', async ({ page }) => {
  await openWithOutline(page, { startPage: 40 });
  const after = await page.evaluate(async (measure) => {
    const marks = new Function(`return (${measure})`)();  // eslint-disable-line no-new-func
    const view = window.book.surface;
    const lose = view.canvas.getContext('webgl2').getExtension('WEBGL_lose_context');
    const event = (name) => new Promise((resolve) => view.canvas.addEventListener(name, resolve, { once: true }));
    const lost = event('webglcontextlost');
    lose.loseContext();
    await lost;
    // Chrome allows a restore only once the lost event's dispatch has returned: any later task.
    await new Promise((resolve) => setTimeout(resolve, 0));
    const restored = event('webglcontextrestored');
    lose.restoreContext();
    await restored;  // the view made its GL objects again in its own listener, registered first
    return marks();
  }, readMarks.toString());
  expect(after.map((m) => [m.page, m.turned])).toEqual([[6, true], [70, false], [120, false], [180, false]]);
  expectTabsAtTheirLeaves(after);
});

// WebGL calls a resting frame adds for the marks, once their buffer is up: the depth test asked,
// their program, its matrix, one draw, and the program before them back.
const EDGE_MARK_GL_CALLS = 5;

test('browser: the marks cost a resting frame a fixed number of WebGL calls, however many there are, and none without marks (counts)', async ({ page }) => {
  await openWithOutline(page, { startPage: 40, outline: [] });
  const counts = await page.evaluate(() => {
    const proto = WebGL2RenderingContext.prototype;
    let calls = 0;
    for (const name of Object.getOwnPropertyNames(proto)) {
      const original = Object.getOwnPropertyDescriptor(proto, name).value;
      if (name === 'constructor' || typeof original !== 'function') continue;
      proto[name] = function counted(...args) { calls++; return original.apply(this, args); };
    }
    const view = window.book.surface;
    const frame = () => { const before = calls; view.drawNow(); return calls - before; };
    frame();
    const none = frame();
    const out = { none };
    for (const n of [1, 12]) {
      view.setEdgeMarks(Array.from({ length: n }, (_, i) => ({ page: 100 + 6 * i, kind: i % 2 ? 'tick' : 'tab' })));
      frame();  // the buffer is filled
      out[n] = frame();
    }
    view.setEdgeMarks([]);
    frame();
    out.cleared = frame();
    return out;
  });
  console.log('WebGL calls a resting frame:', JSON.stringify(counts));
  expect(counts[1] - counts.none).toBe(EDGE_MARK_GL_CALLS);
  expect(counts[12] - counts.none).toBe(EDGE_MARK_GL_CALLS);
  expect(counts.cleared).toBe(counts.none);
});

// Paper-like pages for the reference image: a heading and lines of grey "text" on cream paper.
function paperPages(count) {
  return Array.from({ length: count }, (_, index) => {
    const canvas = document.createElement('canvas');
    canvas.width = 320;
    canvas.height = 400;
    const g = canvas.getContext('2d');
    g.fillStyle = '#fbf8f1';
    g.fillRect(0, 0, 320, 400);
    g.fillStyle = '#3b3b3b';
    g.font = 'bold 20px "DejaVu Sans", sans-serif';
    g.fillText(index % 8 === 0 ? `Part ${index / 8 + 1}` : '', 28, 56);
    g.fillStyle = '#b9b4aa';
    for (let line = 0; line < 16; line++) g.fillRect(28, 84 + line * 18, line % 5 === 4 ? 150 : 264, 6);
    g.fillStyle = '#777';
    g.font = '12px "DejaVu Sans", sans-serif';
    g.fillText(String(index + 1), index % 2 ? 28 : 280, 384);
    return canvas;
  });
}

test('browser: a book with index tabs and search ticks on its edge matches its reference image', async ({ page }) => {
  await page.setViewportSize({ width: 1000, height: 660 });
  await openReady(page, FIXTURE);
  await page.evaluate(async (pagesOf) => {
    document.getElementById('container').style.cssText = 'width: 960px; height: 620px';
    const outline = [
      { title: 'Introduction', page: 2 }, { title: 'History', page: 24, children: [{ title: 'Early books', page: 30 }] },
      { title: 'Design', page: 56 }, { title: 'Materials', page: 88 }, { title: 'Methods', page: 120 }, { title: 'Index', page: 150 },
    ];
    const pages = new Function(`return (${pagesOf})`)()(160);  // eslint-disable-line no-new-func
    await window.openBook({ pages, startPage: 70, display: 'double', edgeMarks: true, outline });
    window.book.dispatchEvent(new CustomEvent('searchchange', { detail: {
      query: 'paper', current: null,
      hits: [{ page: 30, snippet: 'paper', rects: [] }, { page: 100, snippet: 'paper', rects: [] }, { page: 131, snippet: 'paper', rects: [] }],
    } }));
    await window.book.whenIdle();
  }, paperPages.toString());
  await expect(page.locator('[data-edge-mark="tab"]')).toHaveCount(6);
  await expect(page.locator('#container')).toHaveScreenshot('edge-marks-tabs-and-ticks.png', { maxDiffPixelRatio: 0.005, threshold: 0.1 });
});
