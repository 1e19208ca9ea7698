// Browser: PDF books through pdf.js (an optional dependency, imported only for a PDF): a generated
// 300-page PDF opens, shows and turns to the right pages (colour blocks read from pixels), its text
// becomes the pages' accessible text, its page shape is kept, and resident textures stay bounded.
import { test, expect } from '@playwright/test';
import { mkdirSync, writeFileSync } from 'node:fs';
import { PDFDocument, StandardFonts, rgb } from 'pdf-lib';
import { openReady } from './helpers.js';

const PAGE_COUNT = 300;
const PAGE_SIZE = [500, 400];  // points: landscape, so a kept shape shows

/** The colour block of page `index` (0-based): distinct and far from white and from its neighbours. */
function pageColor(index) {
  return [(index * 67) % 200 + 30, (index * 131) % 200 + 30, (index * 29) % 200 + 30];
}

async function makePdf() {
  const pdf = await PDFDocument.create();
  const font = await pdf.embedFont(StandardFonts.Helvetica);
  for (let i = 0; i < PAGE_COUNT; i++) {
    const page = pdf.addPage(PAGE_SIZE);
    const [r, g, b] = pageColor(i);
    page.drawRectangle({ x: 50, y: 50, width: 400, height: 300, color: rgb(r / 255, g / 255, b / 255) });
    page.drawText(`Page ${i + 1} word${i + 1}`, { x: 60, y: 360, size: 20, font, color: rgb(0, 0, 0) });
  }
  return Buffer.from(await pdf.save()).toString('base64');
}

let pdfBase64;
test.beforeAll(async () => { pdfBase64 = await makePdf(); });

/** Colour at the middle of the left and right page of the open spread. */
function spreadColors(page) {
  return page.evaluate(() => {
    const view = window.book.surface;
    view.drawNow();
    const { width, height, data } = view.readPixels();
    const rect = view.book.restingRect(width, height);  // drawing-buffer pixels
    const at = (fx, fy) => {
      const x = Math.round(rect.x + fx * rect.width);
      const y = Math.round(rect.y + fy * rect.height);
      const i = (y * width + x) * 4;
      return [data[i], data[i + 1], data[i + 2]];
    };
    return { left: at(0.25, 0.5), right: at(0.75, 0.5), aspect: rect.width / rect.height };
  });
}

const near = (a, b) => a.every((v, i) => Math.abs(v - b[i]) <= 12);

test('browser: a generated 300-page PDF opens as a book with its pages, text and shape, turns, and keeps textures bounded', async ({ page }) => {
  await openReady(page, '/tests/browser/fixtures/pdf-fixture.html');
  const opened = await page.evaluate(async (base64) => {
    const bytes = window.bytesFromBase64(base64);
    const started = performance.now();
    window.book = await window.Flipbook.create(window.container, {
      pdf: bytes, display: 'double', startPage: 1, duration: 300, lighting: false, shadows: false, gutter: false,
    });
    const ready = performance.now() - started;
    await window.book.whenIdle();
    return { ready, firstSpread: performance.now() - started, pageCount: window.book.pageCount, bytesKept: bytes.length };
  }, pdfBase64);
  expect(opened.pageCount).toBe(PAGE_COUNT);
  expect(opened.bytesKept).toBeGreaterThan(0);  // the caller's bytes were not taken over by pdf.js
  let colors = await spreadColors(page);
  expect(colors.aspect).toBeCloseTo(2 * (PAGE_SIZE[0] / PAGE_SIZE[1]), 2);  // two landscape pages
  expect(near(colors.left, pageColor(1)), `left ${colors.left} vs ${pageColor(1)}`).toBe(true);
  expect(near(colors.right, pageColor(2)), `right ${colors.right} vs ${pageColor(2)}`).toBe(true);
  // The open pages' text, from the PDF, is there for screen readers.
  await expect(page.locator('#container')).toContainText('word2');
  await expect(page.locator('#container')).toContainText('word3');

  // Jump deep into the book, then turn: the right pages, and the cache stays bounded.
  await page.evaluate(() => window.book.flip(150, { animate: false }));
  await page.evaluate(() => window.book.whenIdle());
  colors = await spreadColors(page);
  expect(near(colors.left, pageColor(149)), `left ${colors.left}`).toBe(true);
  expect(near(colors.right, pageColor(150)), `right ${colors.right}`).toBe(true);
  await page.evaluate(() => window.book.next());
  await page.evaluate(() => window.book.whenIdle());
  colors = await spreadColors(page);
  expect(near(colors.left, pageColor(151)), `left ${colors.left}`).toBe(true);
  expect(near(colors.right, pageColor(152)), `right ${colors.right}`).toBe(true);
  for (const target of [10, 290, 75, 299, 0]) await page.evaluate((t) => window.book.flip(t, { animate: false }), target);
  await page.evaluate(() => window.book.whenIdle());
  const resident = await page.evaluate(() => window.book.surface.renderer.residentPageImages());
  expect(resident).toBeLessThanOrEqual(14);
  const cdp = await page.context().newCDPSession(page);
  await cdp.send('HeapProfiler.collectGarbage');
  const heap = (await cdp.send('Runtime.getHeapUsage')).usedSize;
  // The JS heap after GC holds the parsed PDF and the cached pages' canvases, not 300 pages' worth.
  expect(heap).toBeLessThan(64 * 1024 * 1024);
  console.log(`pdf: ${PAGE_COUNT} pages, ready in ${opened.ready.toFixed(0)} ms, first spread drawn with its pages in `
    + `${opened.firstSpread.toFixed(0)} ms, ${resident} resident page textures, JS heap ${heap} bytes`);
});

test('browser: without pdfjs-dist a PDF book is refused with an error that names the missing dependency', async ({ page }) => {
  await openReady(page, '/tests/browser/fixtures/pdf-fixture.html?nopdfjs');
  const message = await page.evaluate(async () => {
    try {
      await window.Flipbook.create(window.container, { pdf: new Uint8Array([37, 80, 68, 70]) });
      return 'no error';
    } catch (error) {
      return error.message;
    }
  });
  expect(message).toMatch(/pdfjs-dist/);
  expect(message).toMatch(/npm install pdfjs-dist/);
});

test('browser: pdf options are checked: a wrong pdf type, pdf with pages, a broken file', async ({ page }) => {
  await openReady(page, '/tests/browser/fixtures/pdf-fixture.html');
  const errors = await page.evaluate(async () => {
    const out = [];
    for (const options of [{ pdf: 42 }, { pdf: 'x.pdf', pages: ['a.png'] }, { pdf: new Uint8Array([1, 2, 3, 4]) }]) {
      try { await window.Flipbook.create(window.container, options); out.push('no error'); } catch (e) { out.push(`${e.name}: ${e.message}`); }
    }
    return out;
  });
  expect(errors[0]).toMatch(/^TypeError: conecurl: option 'pdf'/);
  expect(errors[1]).toMatch(/^TypeError: conecurl: option 'pages' cannot be given with 'pdf'/);
  expect(errors[2]).toMatch(/^Error: conecurl: could not open the PDF/);
});

test('browser: <cone-flipbook pdf="..."> shows a PDF served by URL', async ({ page }) => {
  mkdirSync('test-results', { recursive: true });
  const file = `test-results/pdf-element-${process.pid}.pdf`;
  writeFileSync(file, Buffer.from(pdfBase64, 'base64'));
  await openReady(page, '/tests/browser/fixtures/pdf-fixture.html');
  const result = await page.evaluate(async (url) => {
    const element = document.createElement('cone-flipbook');
    element.setAttribute('pdf', url);
    element.setAttribute('display', 'double');
    element.setAttribute('start-page', '3');
    element.style.cssText = 'display:block;width:640px;height:400px';
    const ready = new Promise((resolve) => element.addEventListener('ready', resolve, { once: true }));
    window.container.replaceWith(element);
    await ready;
    window.book = element.book;
    await element.book.whenIdle();
    return { pageCount: element.pageCount, page: element.page };
  }, `/${file}`);
  expect(result).toEqual({ pageCount: PAGE_COUNT, page: 3 });
  const colors = await spreadColors(page);
  expect(near(colors.left, pageColor(3)), `left ${colors.left}`).toBe(true);
  expect(near(colors.right, pageColor(4)), `right ${colors.right}`).toBe(true);
});
