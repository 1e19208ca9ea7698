// Browser: links inside pages — image pages' { links: [{ rect, href | page }] } and a PDF's link
// annotations become real anchors over the flat open pages: placed where the page says, clickable
// without starting a turn, reachable with Tab, hidden while a leaf moves; javascript: never.
import { test, expect } from '@playwright/test';
import { PDFDocument, PDFName, PDFString, StandardFonts } from 'pdf-lib';
import { openReady } from './helpers.js';

const FIXTURE = '/tests/browser/fixtures/flipbook-fixture.html';

async function openLinkedBook(page) {
  await openReady(page, FIXTURE);
  await page.evaluate(async () => {
    const pages = Array.from({ length: 8 }, (_, i) => ({ src: window.makeNumberedPage(i), alt: `Page ${i + 1}` }));
    pages[1].links = [{ rect: [0.1, 0.2, 0.3, 0.1], href: 'https://example.com/a', title: 'Example A' }];
    pages[2].links = [
      { rect: [0.5, 0.6, 0.4, 0.2], page: 6, title: 'To page 7' },
      { rect: [0, 0, 0.2, 0.2], href: 'javascript:window.pwned=1' },  // never made a link
    ];
    await window.openBook({ pages, display: 'double', startPage: 1, duration: 250 });
    window.events = [];
    for (const type of ['link', 'turnstart', 'turned']) window.book.addEventListener(type, (e) => window.events.push({ type, ...e.detail }));
    await window.settle();
  });
}

const anchors = (page) => page.evaluate(() => [...window.book.element.querySelectorAll('.conecurl-links a')].map((a) => {
  const r = a.getBoundingClientRect();
  return { text: a.textContent, href: a.getAttribute('href'), page: Number(a.dataset.page), x: r.x, y: r.y, w: r.width, h: r.height };
}));

test('browser: page links are anchors placed over the open pages, a click fires link (cancelable) and never turns, an internal link flips', async ({ page }) => {
  await openLinkedBook(page);
  const list = await anchors(page);
  expect(list.map((a) => [a.page, a.text, a.href])).toEqual([[1, 'Example A', 'https://example.com/a'], [2, 'To page 7', '#']]);
  // Placed by page fractions: page 1 is the left half of the spread, page 2 the right.
  const spread = await page.evaluate(() => {
    const box = window.book.surface.canvas.getBoundingClientRect();
    const r = window.book.restingRect();
    return { x: box.left + r.x, y: box.top + r.y, w: r.width, h: r.height };
  });
  expect(list[0].x).toBeCloseTo(spread.x + 0.1 * spread.w / 2, 0);
  expect(list[0].y).toBeCloseTo(spread.y + 0.2 * spread.h, 0);
  expect(list[0].w).toBeCloseTo(0.3 * spread.w / 2, 0);
  expect(list[1].x).toBeCloseTo(spread.x + spread.w / 2 + 0.5 * spread.w / 2, 0);

  // The external link: the page's listener cancels navigation; no turn starts.
  await page.evaluate(() => window.book.addEventListener('link', (e) => { if (e.detail.href.startsWith('https:')) e.preventDefault(); }));
  await page.mouse.click(list[0].x + 5, list[0].y + 5);
  await page.evaluate(() => window.settle());  // no click held back to tell a double-click, no turn moving or waiting
  expect(await page.evaluate(() => ({ events: window.events.map((e) => e.type), page: window.book.page, url: location.pathname })))
    .toEqual({ events: ['link'], page: 1, url: '/tests/browser/fixtures/flipbook-fixture.html' });
  expect(await page.evaluate(() => window.pwned)).toBeUndefined();

  // The internal link flips to its page; the links hide while leaves move and come back for the new spread.
  await page.mouse.click(list[1].x + 5, list[1].y + 5);
  await page.waitForFunction(() => window.events.some((e) => e.type === 'turnstart'));
  expect(await anchors(page)).toEqual([]);
  await page.evaluate(() => window.settle());
  expect(await page.evaluate(() => window.book.page)).toBe(5);
});

test('browser: page links are reachable with Tab, announced by their title, and Enter follows them', async ({ page }) => {
  await openLinkedBook(page);
  await page.evaluate(() => window.book.element.focus());
  await page.keyboard.press('Tab');
  expect(await page.evaluate(() => document.activeElement.textContent)).toBe('Example A');
  await page.keyboard.press('Tab');
  expect(await page.evaluate(() => document.activeElement.textContent)).toBe('To page 7');
  await page.keyboard.press('Enter');
  await page.evaluate(() => window.settle());
  expect(await page.evaluate(() => window.book.page)).toBe(5);
});

test('browser: a PDF\'s link annotations (a URI and a page destination) become links over its pages', async ({ page }) => {
  const pdf = await PDFDocument.create();
  const font = await pdf.embedFont(StandardFonts.Helvetica);
  const pages = Array.from({ length: 6 }, (_, i) => {
    const p = pdf.addPage([400, 500]);
    p.drawText(`Page ${i + 1}`, { x: 40, y: 440, size: 24, font });
    return p;
  });
  const link = (target, rect, action) => {
    const annotation = pdf.context.obj({ Type: 'Annot', Subtype: 'Link', Rect: rect, Border: [0, 0, 0], ...action });
    target.node.set(PDFName.of('Annots'), pdf.context.obj([pdf.context.register(annotation)]));
  };
  // Page 2 (index 1): a web link in its top-left; page 3 (index 2): a link to page 6 near its bottom.
  link(pages[1], [40, 400, 240, 440], { A: { Type: 'Action', S: 'URI', URI: PDFString.of('https://example.org/pdf') } });
  link(pages[2], [40, 40, 240, 90], { Dest: [pages[5].ref, PDFName.of('XYZ'), null, null, null] });
  const base64 = Buffer.from(await pdf.save()).toString('base64');
  await openReady(page, '/tests/browser/fixtures/pdf-fixture.html');
  await page.evaluate(async (b) => {
    window.book = await window.Flipbook.create(window.container, { pdf: window.bytesFromBase64(b), display: 'double', startPage: 1, duration: 250 });
    await window.book.whenIdle();
  }, base64);
  await page.waitForFunction(() => window.book.element.querySelectorAll('.conecurl-links a').length === 2);
  const list = await anchors(page);
  expect(list.map((a) => [a.page, a.href])).toEqual([[1, 'https://example.org/pdf'], [2, '#']]);
  // The URI link sits in the top part of the left page; the destination link low on the right page.
  const spread = await page.evaluate(() => {
    const box = window.book.surface.canvas.getBoundingClientRect();
    const r = window.book.restingRect();
    return { x: box.left + r.x, y: box.top + r.y, w: r.width, h: r.height };
  });
  expect(list[0].y).toBeCloseTo(spread.y + (60 / 500) * spread.h, 0);
  expect(list[1].x).toBeGreaterThan(spread.x + spread.w / 2);
  await page.mouse.click(list[1].x + 5, list[1].y + 5);
  await page.waitForFunction(() => window.book.page === 5 && !window.book.animating);  // bounded by the test's timeout
});
