// Browser: a PDF book's selectable text (text-layer.js): a generated multi-page PDF (pdf-lib, standard
// Helvetica) and a typeset one found on the machine get one `data-text-layer` per open flat page whose
// spans lie over the rendered words (dark pixels of a screenshot); a mouse drag over a line selects that
// line and never turns; the layer is gone while a leaf moves and back after; it follows zoom; its fonts
// are at least 12 px on a small page, with the same boxes; turnArea
// defaults to 'edges' (text in the band still selects); passage links round-trip through the address.
import { test, expect } from '@playwright/test';
import AxeBuilder from '@axe-core/playwright';
import { existsSync, readFileSync } from 'node:fs';
import { PDFDocument, StandardFonts, rgb } from 'pdf-lib';
import { openReady, withoutWebGL2 } from './helpers.js';
import { decodePng } from './png.js';

const PAGE_COUNT = 6;
const PAGE_SIZE = [300, 400];  // points, portrait: two pages side by side in the 640x400 fixture
const FONT_SIZE = 14;
const LINE_GAP = 44;           // points between lines: room to look for ink around each line
/** Line `n` (0-based) of page `index` (0-based): words unique to that page and line, ending clear of the turn band. */
const lineText = (index, n) => `${n + 1}.${index + 1} alpha${index + 1} bravo${n + 1} charlie`;
const LINES = 5;
// The last line runs into the right margin, into the free edge's turn band of a right-hand page.
const EDGE_LINE = (index) => `Edge${index + 1} words reach the margin here`;
// A typeset PDF (DocBook through a TeX toolchain) many Debian machines carry; the test that uses it skips without it.
const TYPESET_PDF = '/usr/share/doc/shared-mime-info/shared-mime-info-spec.pdf';

async function makePdf() {
  const pdf = await PDFDocument.create();
  const font = await pdf.embedFont(StandardFonts.Helvetica);
  for (let i = 0; i < PAGE_COUNT; i++) {
    const page = pdf.addPage(PAGE_SIZE);
    for (let n = 0; n < LINES; n++) {
      page.drawText(lineText(i, n), { x: 30, y: PAGE_SIZE[1] - 50 - n * LINE_GAP, size: FONT_SIZE, font, color: rgb(0, 0, 0) });
    }
    const edge = EDGE_LINE(i);
    page.drawText(edge, { x: PAGE_SIZE[0] - 8 - font.widthOfTextAtSize(edge, FONT_SIZE), y: 60, size: FONT_SIZE, font, color: rgb(0, 0, 0) });
  }
  return Buffer.from(await pdf.save()).toString('base64');
}

let pdfBase64;
test.beforeAll(async () => { pdfBase64 = await makePdf(); });

/** Opens the fixture (with `hash` in the address, if given) and a PDF book in it with `options`. */
async function openBook(page, options = {}, { hash = '', base64 = pdfBase64, textLayers = true } = {}) {
  await openReady(page, `/tests/browser/fixtures/pdf-fixture.html${hash}`);
  await page.evaluate(async ({ base64, options }) => {
    window.events = [];
    const on = Object.fromEntries(['turnstart', 'turned', 'passagelink'].map((type) => [type, (e) => window.events.push({ type, detail: e.detail })]));
    window.book = await window.Flipbook.create(window.container, {
      pdf: window.bytesFromBase64(base64), display: 'double', duration: 400, lighting: false, shadows: false, gutter: false, on, ...options,
    });
    await window.book.whenIdle();
    window.idleAt = performance.now();  // the first spread's pages are drawn
  }, { base64, options });
  if (textLayers) await waitForTextLayers(page);
}

/** Waits until every open page has its text layer, with spans in it. */
async function waitForTextLayers(page) {
  await page.waitForFunction(() => {
    const open = window.book.openPages;
    const layers = [...document.querySelectorAll('[data-text-layer]')];
    return !window.book.animating && layers.length === open.length
      && open.every((p) => layers.some((l) => Number(l.dataset.page) === p && l.querySelector('span')));
  });
}

/** The box (viewport CSS px) of the span on page `index` whose text is `text`. */
function spanBox(page, index, text) {
  return page.evaluate(({ index, text }) => {
    const span = [...document.querySelectorAll(`[data-text-layer][data-page="${index}"] span`)].find((s) => s.textContent === text);
    if (!span) return null;
    const { x, y, width, height } = span.getBoundingClientRect();
    return { x, y, width, height };
  }, { index, text });
}

/** The bounding box of the dark pixels (viewport CSS px) in `box` grown by `margin` on every side. */
async function inkBox(page, box, margin) {
  const clip = { x: Math.floor(box.x - margin), y: Math.floor(box.y - margin), width: Math.ceil(box.width + 2 * margin), height: Math.ceil(box.height + 2 * margin) };
  const png = decodePng(await page.screenshot({ clip }));
  let [x0, y0, x1, y1, count] = [Infinity, Infinity, -Infinity, -Infinity, 0];
  for (let y = 0; y < png.height; y++) {
    for (let x = 0; x < png.width; x++) {
      const i = (y * png.width + x) * 4;
      if (png.data[i] + png.data[i + 1] + png.data[i + 2] < 3 * 110) {
        count++;
        [x0, y0, x1, y1] = [Math.min(x0, x), Math.min(y0, y), Math.max(x1, x + 1), Math.max(y1, y + 1)];
      }
    }
  }
  return count === 0 ? null : { x: clip.x + x0, y: clip.y + y0, width: x1 - x0, height: y1 - y0, count };
}

/** The ink around a span lies within it (a few px of slack) and fills most of its width. */
function expectInkUnder(ink, box, slack = 3) {
  expect(ink, 'dark pixels near the span').not.toBeNull();
  expect(ink.x).toBeGreaterThanOrEqual(box.x - slack);
  expect(ink.y).toBeGreaterThanOrEqual(box.y - slack);
  expect(ink.x + ink.width).toBeLessThanOrEqual(box.x + box.width + slack);
  expect(ink.y + ink.height).toBeLessThanOrEqual(box.y + box.height + slack);
  expect(ink.width).toBeGreaterThan(0.85 * box.width);
}

test('browser: a PDF book lays one data-text-layer per open flat page, its spans over the rendered words, read once in page order', async ({ page }) => {
  await openBook(page, { startPage: 1 });
  const laid = await page.evaluate(() => performance.now() - window.idleAt);
  const spans = await page.locator('[data-text-layer] span').count();
  console.log(`text layer: ${spans} spans over 2 open pages, there at most ${laid.toFixed(0)} ms after the first spread was drawn`);
  const layers = await page.evaluate(() => [...document.querySelectorAll('[data-text-layer]')].map((l) => ({
    page: Number(l.dataset.page), hidden: l.closest('[aria-hidden="true"]') !== null, text: l.textContent,
  })));
  expect(layers.map((l) => l.page)).toEqual([1, 2]);
  for (const layer of layers) {
    expect(layer.hidden).toBe(false);
    // Reading order: the page's lines top to bottom.
    const at = [0, 1, 2, 3, 4].map((n) => layer.text.indexOf(lineText(layer.page, n)));
    expect(at.every((i) => i >= 0)).toBe(true);
    expect([...at].sort((a, b) => a - b)).toEqual(at);
  }
  // The words are read once: the book's hidden page list no longer repeats the PDF's text.
  const alpha = await page.evaluate(() => window.book.element.textContent.split('alpha2 ').length - 1);
  expect(alpha).toBe(LINES);
  // Each line's span lies over its ink, on both pages.
  for (const index of [1, 2]) {
    for (const n of [0, 3]) {
      const box = await spanBox(page, index, lineText(index, n));
      expect(box, `span of ${lineText(index, n)}`).not.toBeNull();
      expectInkUnder(await inkBox(page, box, 14), box);
    }
  }
});

test('browser: a mouse drag over a line of a flat PDF page selects that line and does not turn; the passage button appears', async ({ page }) => {
  await openBook(page, { startPage: 1 });
  const box = await spanBox(page, 2, lineText(2, 1));
  const y = box.y + box.height / 2;
  await page.mouse.move(box.x + 1, y);
  await page.mouse.down();
  for (let i = 1; i <= 10; i++) await page.mouse.move(box.x + 1 + (box.width - 2) * (i / 10), y);
  // While the button is held the passage button stays away (it would lie under the dragging pointer).
  expect(await page.evaluate(() => [window.getSelection().isCollapsed, document.querySelector('[data-passage-link]').hidden])).toEqual([false, true]);
  await page.mouse.up();
  const after = await page.evaluate(() => ({
    selected: window.getSelection().toString(), page: window.book.page, animating: window.book.animating,
    events: window.events.map((e) => e.type),
  }));
  expect(after.selected).toContain('alpha3 bravo2 charli');
  expect(after.page).toBe(1);
  expect(after.animating).toBe(false);
  expect(after.events).toEqual([]);
  await expect(page.locator('[data-passage-link]')).toBeVisible();
  await expect(page.locator('[data-passage-link]')).toHaveText('Copy link to this passage');
  await page.screenshot({ path: test.info().outputPath('text-selected.png') });
});

test('browser: the text layer is gone while a leaf moves and back, on the new pages, after it lands', async ({ page }) => {
  await openBook(page, { startPage: 1 });
  const frames = await page.evaluate(async () => {
    const seen = [];
    let landed = false;
    const turn = window.book.next().then(() => { landed = true; });
    while (!landed) {
      seen.push({ animating: window.book.animating, layers: document.querySelectorAll('[data-text-layer]').length });
      await new Promise(requestAnimationFrame);
    }
    await turn;
    return seen;
  });
  const moving = frames.filter((f) => f.animating);
  expect(moving.length).toBeGreaterThan(0);
  expect(moving.every((f) => f.layers === 0)).toBe(true);
  await waitForTextLayers(page);
  const pages = await page.evaluate(() => [...document.querySelectorAll('[data-text-layer]')].map((l) => Number(l.dataset.page)));
  expect(pages).toEqual([3, 4]);
});

test('browser: the text layer follows zoom: spans scale with the page and keep their place on it', async ({ page }) => {
  await openBook(page, { startPage: 1 });
  const measure = () => page.evaluate(() => {
    const place = window.book.openPagePlaces().find((p) => p.page === 1);
    const span = [...document.querySelectorAll('[data-text-layer][data-page="1"] span')].find((s) => s.textContent.startsWith('1.2 '));
    const r = span.getBoundingClientRect();
    const c = window.book.element.getBoundingClientRect();
    return { place, fx: (r.x - c.x - place.x) / place.width, fy: (r.y - c.y - place.y) / place.height, width: r.width, height: r.height };
  });
  const before = await measure();
  await page.evaluate(() => { window.book.zoom = 2; });
  await page.waitForFunction(() => {
    const layer = document.querySelector('[data-text-layer][data-page="1"]');
    const place = window.book.openPagePlaces().find((p) => p.page === 1);
    return layer && place && Math.abs(parseFloat(layer.style.width) - place.width) < 0.5;
  });
  const after = await measure();
  expect(after.place.width / before.place.width).toBeCloseTo(2, 2);
  expect(after.width / before.width).toBeCloseTo(2, 1);
  expect(after.height / before.height).toBeCloseTo(2, 1);
  expect(Math.abs(after.fx - before.fx)).toBeLessThan(0.005);
  expect(Math.abs(after.fy - before.fy)).toBeLessThan(0.005);
});

test('browser: on a small page the text layer\'s spans get fonts of at least 12 px, scaled back down: their boxes stay where they were', async ({ page }) => {
  await openBook(page, { startPage: 1 });
  // Half the fixture's size: the 14 pt text is about 7.5 CSS px on the page, illegible by Lighthouse's 12 px.
  await page.evaluate(() => { Object.assign(window.container.style, { width: '320px', height: '200px' }); });
  await page.waitForFunction(() => {
    const layer = document.querySelector('[data-text-layer][data-page="1"]');
    const place = window.book.openPagePlaces().find((p) => p.page === 1);
    return layer?.querySelector('span') && place && place.width < 200 && Math.abs(parseFloat(layer.style.width) - place.width) < 0.5;
  });
  const measure = () => page.evaluate(() => [...document.querySelectorAll('[data-text-layer] span')].map((span) => {
    const { x, y, width, height } = span.getBoundingClientRect();
    return { font: parseFloat(getComputedStyle(span).fontSize), x, y, width, height };
  }));
  const legible = await measure();
  expect(legible.length).toBeGreaterThan(0);
  expect(Math.min(...legible.map((span) => span.font))).toBeGreaterThanOrEqual(12);
  // The same spans at factor 1 (pdf.js's own --min-font-size): a font under 12 px, and the same boxes.
  await page.evaluate(() => { for (const layer of document.querySelectorAll('[data-text-layer]')) layer.style.setProperty('--min-font-size', '1'); });
  const plain = await measure();
  expect(Math.max(...plain.map((span) => span.font))).toBeLessThan(12);
  plain.forEach((span, i) => {
    for (const key of ['x', 'y', 'width', 'height']) expect(Math.abs(span[key] - legible[i][key]), `${key} of span ${i}`).toBeLessThan(0.5);
  });
});

/** A viewport point at fractions (fx, fy) of open page `index`'s place. */
function pagePoint(page, index, fx, fy) {
  return page.evaluate(({ index, fx, fy }) => {
    const place = window.book.openPagePlaces().find((p) => p.page === index);
    const box = window.book.element.getBoundingClientRect();
    return { x: box.x + place.x + fx * place.width, y: box.y + place.y + fy * place.height };
  }, { index, fx, fy });
}

/** Drags the mouse from `from` by `dx` in 12 steps. */
async function dragBy(page, from, dx) {
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  for (let i = 1; i <= 12; i++) await page.mouse.move(from.x + (dx * i) / 12, from.y);
  await page.mouse.up();
}

test('browser: with a text layer turnArea defaults to edges: text in the edge band selects, a drag from the blank edge turns, one inside does not; textLayer: false has no layer', async ({ page }) => {
  await openBook(page, { startPage: 1 });
  expect(await page.evaluate(() => window.book.options.turnArea)).toBe('edges');
  // The right page's edge line reaches into its turn band: a word there is still the reader's.
  const box = await spanBox(page, 2, EDGE_LINE(2));
  const y = box.y + box.height / 2;
  const inBand = await pagePoint(page, 2, 0.97, 0);
  expect(box.x + box.width).toBeGreaterThan(inBand.x);
  expect(await page.evaluate(({ x, y }) => document.elementFromPoint(x, y).tagName, { x: box.x + box.width - 3, y })).toBe('SPAN');
  await dragBy(page, { x: box.x + 1, y }, box.width - 2);
  expect(await page.evaluate(() => window.getSelection().toString())).toContain('words reach the margin her');
  // A drag inside the page where no word lies (turnArea 'edges') neither turns nor selects.
  await dragBy(page, await pagePoint(page, 2, 0.5, 0.7), -150);
  expect(await page.evaluate(() => ({ page: window.book.page, events: window.events.length }))).toEqual({ page: 1, events: 0 });
  // A drag from the free edge where no word lies turns.
  await dragBy(page, await pagePoint(page, 2, 0.98, 0.7), -360);
  await page.waitForFunction(() => window.events.some((e) => e.type === 'turned'));
  expect(await page.evaluate(() => window.events.find((e) => e.type === 'turnstart').detail.drag)).toBe(true);
  expect(await page.evaluate(() => window.book.page)).toBe(3);

  await openBook(page, { startPage: 1, textLayer: false }, { textLayers: false });
  expect(await page.evaluate(() => window.book.options.turnArea)).toBe('page');
  expect(await page.locator('[data-text-layer]').count()).toBe(0);
});

test.describe('touch', () => {
  test.use({ hasTouch: true });

  test('browser (touch): on a touch screen (a coarse pointer) turnArea is \'page\': a finger\'s long press on a word turns nothing, its tap on a word turns', async ({ page }) => {
    await openBook(page, { startPage: 1 });
    expect(await page.evaluate(() => window.book.options.turnArea)).toBe('page');
    const line = await spanBox(page, 2, lineText(2, 2));
    const at = { x: line.x + line.width / 2, y: line.y + line.height / 2 };
    // A long press (800 ms by the events' own clock): the browser's way to select, never a tap.
    const cdp = await page.context().newCDPSession(page);
    const start = Date.now() / 1000;
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [{ x: at.x, y: at.y }], timestamp: start });
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [], timestamp: start + 0.8 });
    await page.evaluate(() => window.book.whenIdle());
    expect(await page.evaluate(() => ({ page: window.book.page, animating: window.book.animating, events: window.events.length })))
      .toEqual({ page: 1, animating: false, events: 0 });
    // A tap on the same word (the right-hand page's outer part): text-layer.js hands a finger's touch to the book.
    await page.touchscreen.tap(at.x, at.y);
    await page.waitForFunction(() => window.events.some((e) => e.type === 'turned'));
    expect(await page.evaluate(() => window.book.page)).toBe(3);
  });
});

test('browser: axe-core finds no serious or critical violation with the text layer and the passage button showing', async ({ page }) => {
  await openBook(page, { startPage: 1 });
  await selectLine(page, 2, 0);
  await expect(page.locator('[data-passage-link]')).toBeVisible();
  const { violations } = await new AxeBuilder({ page }).include('#container').analyze();
  const serious = violations.filter((v) => v.impact === 'serious' || v.impact === 'critical')
    .map((v) => `${v.impact} ${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`);
  expect(serious).toEqual([]);
});

/** Waits for the book's current search hit and checks it lies over the span of `text` on page `index`. */
async function expectHitOver(page, index, text) {
  await page.waitForFunction(() => document.querySelector('[data-search-hit]'));
  const span = await spanBox(page, index, text);
  const marks = await page.evaluate((index) => [...document.querySelectorAll(`[data-search-hit][data-page="${index}"]`)].map((m) => {
    const { x, y, width, height } = m.getBoundingClientRect();
    return { x, y, width, height };
  }), index);
  const over = marks.filter((m) => m.x < span.x + span.width && span.x < m.x + m.width && m.y < span.y + span.height && span.y < m.y + m.height);
  expect(over.length, `a data-search-hit over "${text}"`).toBeGreaterThan(0);
  const x0 = Math.min(...over.map((m) => m.x));
  const x1 = Math.max(...over.map((m) => m.x + m.width));
  expect(Math.abs(x0 - span.x)).toBeLessThan(4);
  expect(Math.abs(x1 - (span.x + span.width))).toBeLessThan(4);
}

/** Selects line `n` of page `index` by dragging over it (viewport points from its span). */
async function selectLine(page, index, n) {
  const box = await spanBox(page, index, lineText(index, n));
  const y = box.y + box.height / 2;
  await page.mouse.move(box.x + 1, y);
  await page.mouse.down();
  for (let i = 1; i <= 8; i++) await page.mouse.move(box.x + 1 + (box.width - 2) * (i / 8), y);
  await page.mouse.up();
}

test('browser: a passage link round-trips: select, the button by keyboard, the link in the clipboard and the event; the link opens the book at that page with the passage marked', async ({ page, context }) => {
  await context.grantPermissions(['clipboard-read', 'clipboard-write']);
  await openBook(page, { startPage: 1 });
  await selectLine(page, 2, 3);
  await expect(page.locator('[data-passage-link]')).toBeVisible();
  // Keyboard: from the book, Tab reaches the button, Enter uses it.
  await page.evaluate(() => window.book.element.focus());
  await page.keyboard.press('Tab');
  expect(await page.evaluate(() => document.activeElement.hasAttribute('data-passage-link'))).toBe(true);
  await page.keyboard.press('Enter');
  await page.waitForFunction(() => window.events.some((e) => e.type === 'passagelink'));
  const detail = await page.evaluate(() => window.events.find((e) => e.type === 'passagelink').detail);
  expect(detail.page).toBe(2);
  expect(detail.text).toBe(lineText(2, 3).trim());
  const { pathname } = new URL(page.url());
  expect(detail.url).toBe(`${new URL(page.url()).origin}${pathname}#page=3&text=${encodeURIComponent(detail.text)}`);
  expect(detail.copied).toBe(true);
  expect(await page.evaluate(() => navigator.clipboard.readText())).toBe(detail.url);
  expect(await page.evaluate(() => window.book.page)).toBe(1);

  // A new page at that address, with hash: true, opens at the passage's page.
  const other = await context.newPage();
  const { hash } = new URL(detail.url);
  await openBook(other, { hash: true }, { hash });
  expect(await other.evaluate(() => window.book.openPages)).toContain(2);
  // ... and marks the passage there as a search hit, over its words.
  await expectHitOver(other, 2, lineText(2, 3));
  await other.screenshot({ path: test.info().outputPath('passage-marked.png') });
  // Followed on a book already open (a link within the document), it turns there.
  await other.evaluate((text) => { location.hash = `#page=5&text=${encodeURIComponent(text)}`; }, lineText(4, 0));
  await other.waitForFunction(() => window.book.openPages.includes(4) && !window.book.animating);
  await other.close();
});

test('browser: where the Clipboard API refuses, the passage link is copied through a hidden textarea, and the selection stays', async ({ page, context }) => {
  await context.grantPermissions(['clipboard-read', 'clipboard-write']);
  await openBook(page, { startPage: 1 });
  await page.evaluate(() => {
    window.refused = 0;
    navigator.clipboard.writeText = () => { window.refused++; return Promise.reject(new DOMException('refused', 'NotAllowedError')); };
  });
  await selectLine(page, 1, 2);
  await page.locator('[data-passage-link]').click();
  await page.waitForFunction(() => window.events.some((e) => e.type === 'passagelink'));
  const detail = await page.evaluate(() => window.events.find((e) => e.type === 'passagelink').detail);
  expect(await page.evaluate(() => window.refused)).toBe(1);
  expect(detail.copied).toBe(true);
  expect(await page.evaluate(() => navigator.clipboard.readText())).toBe(detail.url);
  expect(await page.evaluate(() => window.getSelection().toString())).toContain('alpha2 bravo3');
  expect(await page.evaluate(() => document.querySelectorAll('textarea').length)).toBe(0);
});

test('browser: a passage link marks its passage as a search hit over its words, on its page (the same words elsewhere are not the hit shown)', async ({ page, context }) => {
  const text = lineText(4, 2);
  await openBook(page, { hash: true }, { hash: `#page=5&text=${encodeURIComponent(text)}` });
  expect(await page.evaluate(() => window.book.openPages)).toContain(4);
  await expectHitOver(page, 4, text);
  // "charlie" is on every page: the hit shown is the one on the link's page (a new document: a goto
  // that changes only the hash would stay in this one).
  const other = await context.newPage();
  await openBook(other, { hash: true }, { hash: '#page=4&text=charlie' });
  await other.waitForFunction(() => document.querySelector('[data-search-hit][data-current]'));
  expect(await other.evaluate(() => document.querySelector('[data-search-hit][data-current]').dataset.page)).toBe('3');
  await other.close();
});

test('browser: without WebGL2 the still-page fallback of a PDF book has its text layer too, over its words', async ({ page }) => {
  await withoutWebGL2(page);
  await openReady(page, '/tests/browser/fixtures/pdf-fixture.html');
  const code = await page.evaluate(async (base64) => {
    try {
      await window.Flipbook.create(window.container, { pdf: window.bytesFromBase64(base64), display: 'double', startPage: 1 });
      return 'no error';
    } catch (error) {
      window.book = error.fallback;
      window.events = [];
      await window.book.whenIdle();
      return error.code;
    }
  }, pdfBase64);
  expect(code).toBe('webgl2-unavailable');
  expect(await page.evaluate(() => window.book.surface.kind)).not.toBe('webgl');
  await waitForTextLayers(page);
  expect(await page.evaluate(() => window.book.options.turnArea)).toBe('edges');
  const box = await spanBox(page, 2, lineText(2, 0));
  expectInkUnder(await inkBox(page, box, 14), box);
});

test('browser: a typeset PDF found on the machine gets a text layer whose spans lie over its words', async ({ page }) => {
  test.skip(!existsSync(TYPESET_PDF), `no typeset PDF at ${TYPESET_PDF}`);
  const base64 = readFileSync(TYPESET_PDF).toString('base64');
  await openBook(page, { startPage: 2, display: 'single' }, { base64 });
  const open = await page.evaluate(() => window.book.openPages);
  // Its body text is 5 px high at zoom 1: look at it magnified (at 4 the middle of this page shows no line of 12 letters).
  await page.evaluate(() => { window.book.zoom = 3; });
  await page.waitForFunction((index) => {
    const layer = document.querySelector(`[data-text-layer][data-page="${index}"]`);
    const place = window.book.openPagePlaces().find((p) => p.page === index);
    return !window.book.animating && layer && place && Math.abs(parseFloat(layer.style.width) - place.width) < 0.5;
  }, open[0]);
  // Words of several letters, whole on the page: each one's span has ink under it and none around it.
  const boxes = await page.evaluate((index) => {
    const layer = document.querySelector(`[data-text-layer][data-page="${index}"]`);
    const c = window.book.element.getBoundingClientRect();
    return [...layer.querySelectorAll('span')].filter((s) => /^[A-Za-z][A-Za-z ,.]{12,}$/.test(s.textContent)).map((s) => {
      const { x, y, width, height } = s.getBoundingClientRect();
      return { x, y, width, height, text: s.textContent, inside: x > c.x && y > c.y && x + width < c.right && y + height < c.bottom };
    }).filter((b) => b.inside && b.height > 10).slice(0, 8);
  }, open[0]);
  expect(boxes.length).toBeGreaterThan(2);
  await page.screenshot({ path: test.info().outputPath('typeset-zoomed.png') });
  for (const box of boxes) {
    const ink = await inkBox(page, box, 0);
    expect(ink, `ink under "${box.text}"`).not.toBeNull();
    expect(ink.width, `"${box.text}": ink across the span`).toBeGreaterThan(0.85 * box.width);
    expect(ink.height, `"${box.text}": ink down the span`).toBeGreaterThan(0.4 * box.height);
  }
});
