// Browser: 32 books on one scrolling page share the page's WebGL contexts (web/src/surfaces/context-budget.js):
// each book scrolled into view draws its own pages and turns, at most MAX_LIVE_CONTEXTS contexts are live
// at any time, and Chrome never has to lose one ("Too many active WebGL contexts").
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';
import { decodePng } from './png.js';

const FIXTURE = '/tests/browser/fixtures/many-books-fixture.html';
const MAX_LIVE = 8;         // MAX_LIVE_CONTEXTS in web/src/surfaces/context-budget.js
const TOO_MANY = 'Too many active WebGL contexts';

// Before any page script: record every WebGL context made, and count the live (not lost) ones on
// every frame and whenever a context is made.
function countContexts() {
  const contexts = [];
  const original = HTMLCanvasElement.prototype.getContext;
  window.maxLiveContexts = 0;
  window.liveContexts = () => contexts.filter((context) => !context.isContextLost()).length;
  window.sampleLiveContexts = () => {
    window.maxLiveContexts = Math.max(window.maxLiveContexts, window.liveContexts());
  };
  HTMLCanvasElement.prototype.getContext = function getContext(type, ...rest) {
    const context = original.call(this, type, ...rest);
    if (context && /^(webgl|webgl2|experimental-webgl)$/.test(type) && !contexts.includes(context)) contexts.push(context);
    window.sampleLiveContexts();
    return context;
  };
  const sample = () => { window.sampleLiveContexts(); requestAnimationFrame(sample); };
  requestAnimationFrame(sample);
}

async function open(page) {
  const warnings = [];
  page.on('console', (message) => { if (message.text().includes(TOO_MANY)) warnings.push(message.text()); });
  await page.addInitScript(countContexts);
  await openReady(page, FIXTURE);
  return warnings;
}

/** Scrolls book `b` to the middle of the viewport and waits until it has its context and has drawn with it. */
async function showBook(page, b) {
  await page.evaluate((b) => document.getElementById(`slot-${b}`).scrollIntoView({ block: 'center' }), b);
  await page.waitForFunction((b) => {
    const lease = window.books[b].surface.contextLease;
    return lease.state === 'live' && !window.books[b].surface.canvas.getContext('webgl2').isContextLost() && !lease.showingSnapshot;
  }, b);
  await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
}

const twoFrames = (page) => page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));

/** [book, page] codes on screen at the middle of the left and right resting pages of book `b`. */
async function pagesOnScreen(page, b) {
  const { box, rect } = await page.evaluate((b) => {
    const view = window.books[b].surface;
    const r = view.canvas.getBoundingClientRect();
    return { box: { x: r.left, y: r.top, width: r.width, height: r.height }, rect: view.restingRect() };
  }, b);
  const shot = decodePng(await page.screenshot({ clip: box }));
  const at = (fx, fy) => {
    const x = Math.round(rect.x + fx * rect.width);
    const y = Math.round(rect.y + fy * rect.height);
    const i = (y * shot.width + x) * 4;
    return [shot.data[i], shot.data[i + 1], shot.data[i + 2]];
  };
  return page.evaluate((colors) => colors.map((c) => window.codeOf(c)), [at(0.25, 0.5), at(0.75, 0.5)]);
}

test('browser: the console check sees Chrome lose a context when a page makes more WebGL contexts than it allows', async ({ page }) => {
  const warnings = await open(page);
  // 20 bare canvases, no budget: Chrome's own limit (16) strikes. This proves the check below can fail.
  const lost = await page.evaluate(async () => {
    const canvases = Array.from({ length: 20 }, () => document.createElement('canvas'));
    // The first context Chrome takes away says so with webglcontextlost (the test's timeout bounds it).
    const firstLost = new Promise((resolve) => {
      for (const canvas of canvases) canvas.addEventListener('webglcontextlost', resolve, { once: true });
    });
    const contexts = canvases.map((canvas) => canvas.getContext('webgl2'));
    await firstLost;
    return contexts.filter((context) => context.isContextLost()).length;
  });
  await expect.poll(() => warnings.length).toBeGreaterThan(0);
  expect(lost).toBeGreaterThan(0);
});

test('browser: 32 books on one page: each scrolled into view draws its own pages and turns; never more than 8 live contexts, none lost by Chrome', async ({ page }) => {
  test.setTimeout(300_000);
  const warnings = await open(page);
  await page.evaluate(() => window.makeBooks(32));
  const afterCreate = await page.evaluate(() => ({ live: window.liveContexts(), budget: window.budget.liveCount }));
  expect(afterCreate.live).toBeLessThanOrEqual(MAX_LIVE);
  expect(afterCreate.budget).toBeLessThanOrEqual(MAX_LIVE);

  // Book 20 is far out of view, without a context: it still turns (its promise resolves) and keeps its page.
  expect(await page.evaluate(() => window.books[20].surface.contextLease.state)).toBe('parked');
  expect(await page.evaluate(() => window.books[20].next())).toBe(true);
  expect(await page.evaluate(() => window.books[20].page)).toBe(3);

  const seen = [];
  for (let b = 0; b < 32; b++) {
    await showBook(page, b);
    const first = b === 20 ? 3 : 1;
    expect(await pagesOnScreen(page, b), `book ${b} before its turn`).toEqual([[b, first], [b, first + 1]]);
    expect(await page.evaluate((b) => window.books[b].next(), b)).toBe(true);
    await twoFrames(page);
    expect(await pagesOnScreen(page, b), `book ${b} after next()`).toEqual([[b, first + 2], [b, first + 3]]);
    seen.push(await page.evaluate(() => window.liveContexts()));
  }
  // Back to the top: the first book takes a context again and shows the page it turned to.
  await showBook(page, 0);
  expect(await pagesOnScreen(page, 0)).toEqual([[0, 3], [0, 4]]);

  const { most, states } = await page.evaluate(() => ({
    most: window.maxLiveContexts,
    states: window.books.map((book) => book.surface.contextLease.state),
  }));
  console.log(`many books: 32 books, live WebGL contexts at most ${most} (budget ${MAX_LIVE}); `
    + `after each book's turn: ${seen.join(' ')}; at the end ${states.filter((s) => s === 'live').length} live`);
  test.info().annotations.push({ type: 'live contexts', description: `most ${most} of 32 books` });
  expect(most).toBeLessThanOrEqual(MAX_LIVE);
  expect(warnings).toEqual([]);
});

test('browser: a book whose context is lost by accident recovers its pages, and the budget still holds', async ({ page }) => {
  test.setTimeout(180_000);  // about 20 s alone: 16 books, 12 of them scrolled to and drawn
  const warnings = await open(page);
  await page.evaluate(() => window.makeBooks(16));
  await showBook(page, 2);
  // Lost outside the budget (as a GPU reset would), mid-turn, then restored by the browser.
  const turned = await page.evaluate(async () => {
    const book = window.books[2];
    const canvas = book.surface.canvas;
    const gl = canvas.getContext('webgl2');
    const extension = gl.getExtension('WEBGL_lose_context');
    const event = (name) => new Promise((resolve) => canvas.addEventListener(name, resolve, { once: true }));
    const turning = book.next();
    const lost = event('webglcontextlost');
    extension.loseContext();
    await lost;
    // Chrome ignores a restore asked for in the task that dispatched webglcontextlost: one task later
    // it takes it, on any machine.
    await new Promise((resolve) => setTimeout(resolve));
    const restored = event('webglcontextrestored');
    extension.restoreContext();
    await restored;
    return turning;
  });
  expect(turned).toBe(true);
  await showBook(page, 2);
  expect(await pagesOnScreen(page, 2)).toEqual([[2, 3], [2, 4]]);
  // Scrolling on through the others parks book 2 (the longest out of view); back in view it is intact.
  for (let b = 5; b < 16; b++) await showBook(page, b);
  expect(await page.evaluate(() => window.books[2].surface.contextLease.state)).toBe('parked');
  await showBook(page, 2);
  expect(await pagesOnScreen(page, 2)).toEqual([[2, 3], [2, 4]]);
  expect(await page.evaluate(() => window.maxLiveContexts)).toBeLessThanOrEqual(MAX_LIVE);
  expect(warnings).toEqual([]);
});

test('browser: with more books in view than contexts, those without one show their last frame, and a turn takes a context back', async ({ page }) => {
  test.setTimeout(120_000);
  const warnings = await open(page);
  await page.evaluate(() => window.makeBooks(12, { grid: true }));  // 12 small books, all in view
  // Once the budget has settled: 8 books drawing, 4 showing a snapshot of their last frame.
  await page.waitForFunction(() => window.books.every((book) => {
    const lease = book.surface.contextLease;
    return (lease.state === 'live' && !lease.showingSnapshot) || (lease.state === 'parked' && lease.showingSnapshot);
  }));
  await twoFrames(page);
  const parked = await page.evaluate(() => window.books.flatMap((book, b) => (book.surface.contextLease.state === 'parked' ? [b] : [])));
  expect(parked).toHaveLength(12 - MAX_LIVE);
  for (let b = 0; b < 12; b++) expect(await pagesOnScreen(page, b), `book ${b}`).toEqual([[b, 1], [b, 2]]);

  // A turn of a parked book takes a context back (from another book at rest) and is drawn.
  const turner = parked[0];
  expect(await page.evaluate((b) => window.books[b].next(), turner)).toBe(true);
  await showBook(page, turner);
  expect(await pagesOnScreen(page, turner)).toEqual([[turner, 3], [turner, 4]]);
  await page.waitForFunction(() => window.books.every((book) => book.surface.contextLease.state !== 'parked' || book.surface.contextLease.showingSnapshot));
  const parkedNow = await page.evaluate(() => window.books.flatMap((book, b) => (book.surface.contextLease.state === 'parked' ? [b] : [])));
  expect(parkedNow).toHaveLength(12 - MAX_LIVE);
  expect(parkedNow).not.toContain(turner);
  for (const b of parkedNow) expect(await pagesOnScreen(page, b), `book ${b}, parked`).toEqual([[b, 1], [b, 2]]);
  expect(await page.evaluate(() => window.maxLiveContexts)).toBeLessThanOrEqual(MAX_LIVE);
  expect(warnings).toEqual([]);
});
