// Browser: the book's document API around its pages: pageThumbnail() draws a page small from its source
// (pdf.js for a PDF, the image decoded small) without touching the book's textures, a few at a time,
// and rejects for a failed page; toggleFullscreen() enters and leaves fullscreen with its event and the
// book laid out sharp at the new size; download() and print() fire cancelable events and, unless
// prevented, download the PDF and print its pages.
import { test, expect } from '@playwright/test';
import { readFileSync } from 'node:fs';
import { openReady } from './helpers.js';
import { PAGES, PAGE_SIZE, makeDocumentPdf, openPdfBook as openPdf } from './document-pdf.js';

let made;
test.beforeAll(async () => { made = await makeDocumentPdf(); });

const openPdfBook = (page, options) => openPdf(page, made, options);

test('browser: pageThumbnail() draws a PDF page at the size asked from pdf.js, never touching the book\'s textures or kept pages', async ({ page }) => {
  await openPdfBook(page);
  const result = await page.evaluate(async () => {
    const book = window.book;
    const far = book.pageCount - 1;  // not loaded by the book
    const before = { resident: book.residentPages, texture: book.surface.pageImageSize(far), state: book.pageState(far).state };
    const small = await book.pageThumbnail(far, { width: 120 });
    const fixed = await book.pageThumbnail(3, { width: 90, height: 100 });
    // Dark pixels: the page's text drawn in the thumbnail.
    const g = small.getContext('2d');
    const { data } = g.getImageData(0, 0, small.width, small.height);
    let dark = 0;
    for (let i = 0; i < data.length; i += 4) if (data[i] < 100 && data[i + 1] < 100 && data[i + 2] < 100) dark += 1;
    const after = { resident: book.residentPages, texture: book.surface.pageImageSize(far), state: book.pageState(far).state };
    const errors = [];
    for (const [index, size] of [[99, { width: 100 }], [1, { width: 0 }], [1, {}], [1.5, { width: 10 }]]) {
      try { await book.pageThumbnail(index, size); } catch (error) { errors.push(error.name); }
    }
    return { small: [small.width, small.height], fixed: [fixed.width, fixed.height], dark, before, after, errors, isCanvas: small instanceof HTMLCanvasElement };
  });
  expect(result.isCanvas).toBe(true);
  expect(result.small).toEqual([120, Math.round(120 * PAGE_SIZE[1] / PAGE_SIZE[0])]);
  expect(result.fixed).toEqual([90, 100]);
  expect(result.dark).toBeGreaterThan(20);
  expect(result.after).toEqual(result.before);
  expect(result.before.texture).toBeNull();
  expect(result.errors).toEqual(['RangeError', 'TypeError', 'TypeError', 'RangeError']);
});

test('browser: pageThumbnail() of image pages decodes them small, draws at most three at once, and rejects with a clear Error for a failed page', async ({ page }) => {
  await openReady(page, '/tests/browser/fixtures/pdf-fixture.html');
  const result = await page.evaluate(async () => {
    let counting = false;
    let running = 0;
    let most = 0;
    let calls = 0;
    // Page sources that take a task to draw: how many thumbnails draw at once is counted in them.
    const drawn = (i) => async (index, size) => {
      if (counting) {
        calls += 1;
        running += 1;
        most = Math.max(most, running);
      }
      await new Promise((resolve) => setTimeout(resolve, 0));  // yields: other thumbnails could start meanwhile
      if (counting) running -= 1;
      const canvas = document.createElement('canvas');
      canvas.width = size.width;
      canvas.height = Math.round(size.width * 1.25);
      canvas.getContext('2d').fillRect(0, 0, i + 1, 1);
      return canvas;
    };
    const pages = ['/tests/browser/references/curl-t0-00.png', '/no/such/page.png', ...Array.from({ length: 12 }, (_, i) => drawn(i))];
    const book = await window.Flipbook.create(window.container, { pages, display: 'double' });
    await book.whenIdle();
    const image = await book.pageThumbnail(0, { width: 64 });
    let failure = null;
    try { await book.pageThumbnail(1, { width: 64 }); } catch (error) { failure = { name: error.name, message: error.message }; }
    counting = true;
    const many = await Promise.all(Array.from({ length: 12 }, (_, i) => book.pageThumbnail(i + 2, { width: 40 })));
    counting = false;
    book.destroy();
    return { image: [image.width, image.height], failure, calls, most, sizes: many.map((c) => `${c.width}x${c.height}`) };
  });
  expect(result.image).toEqual([64, 40]);  // the 640x400 image in its own shape
  expect(result.failure.name).toBe('Error');
  expect(result.failure.message).toMatch(/pageThumbnail\(1\).*404/);
  expect(result.calls).toBe(12);
  expect(result.most).toBe(3);
  expect(new Set(result.sizes)).toEqual(new Set(['40x50']));
});

test('browser: toggleFullscreen() enters and leaves fullscreen on the book\'s container, asking the browser within the press, with fullscreenchange, and the book laid out sharp at the new size', async ({ page }) => {
  await openPdfBook(page);
  await page.evaluate(() => {
    const button = document.createElement('button');
    button.id = 'fullscreen';
    button.textContent = 'Fullscreen';
    // Counted: the browser grants the request only within the press, so it is made before the call returns.
    window.requests = 0;
    const request = window.container.requestFullscreen;
    window.container.requestFullscreen = function (...args) { window.requests += 1; return request.apply(this, args); };
    button.addEventListener('click', () => {
      window.entering = window.book.toggleFullscreen();
      window.requestedInPress = window.requests;
    });
    document.body.append(button);
    window.events = [];
    window.book.addEventListener('fullscreenchange', (e) => window.events.push(e.detail.fullscreen));
    window.resized = new Promise((resolve) => window.book.addEventListener('resize', (e) => resolve(e.detail), { once: true }));
  });
  await page.click('#fullscreen');  // a user gesture: the Fullscreen API asks for one
  const entered = await page.evaluate(async () => {
    const answer = await window.entering;
    const size = await window.resized;
    await new Promise((resolve) => requestAnimationFrame(resolve));
    const canvas = window.book.element.querySelector('canvas');
    return { answer, requestedInPress: window.requestedInPress, fullscreen: window.book.fullscreen, element: document.fullscreenElement === window.container, events: window.events.slice(),
      size, buffer: [canvas.width, canvas.height], css: [canvas.clientWidth * devicePixelRatio, canvas.clientHeight * devicePixelRatio],
      screen: [innerWidth, innerHeight] };
  });
  expect(entered.answer).toBe(true);
  expect(entered.requestedInPress).toBe(1);
  expect(entered.fullscreen).toBe(true);
  expect(entered.element).toBe(true);
  expect(entered.events).toEqual([true]);
  expect([entered.size.width, entered.size.height]).toEqual(entered.screen);  // laid out at the screen's size
  expect(entered.buffer).toEqual(entered.css.map(Math.round));  // a drawing-buffer pixel per device pixel: sharp
  const left = await page.evaluate(async () => {
    const answer = await window.book.toggleFullscreen(false);
    await new Promise((resolve) => { if (window.events.length >= 2) resolve(); else window.book.addEventListener('fullscreenchange', resolve, { once: true }); });
    return { answer, fullscreen: window.book.fullscreen, events: window.events.slice(), again: await window.book.toggleFullscreen(false) };
  });
  expect(left).toEqual({ answer: false, fullscreen: false, events: [true, false], again: false });
});

test('browser: leaving fullscreen is heard every time, also when the browser says it entered only after it left: enter, leave, enter, leave by the toolbar and exitFullscreen() dispatch fullscreenchange true, false, true, false', async ({ page }) => {
  await openReady(page, '/tests/browser/fixtures/pdf-fixture.html');
  await page.evaluate(async () => {
    window.book = await window.Flipbook.create(window.container, { pages: ['/tests/browser/references/curl-t0-00.png'], controls: true });
    window.heard = [];
    window.book.addEventListener('fullscreenchange', (e) => window.heard.push(e.detail.fullscreen));
    // Chrome changes document.fullscreenElement at once but sends its fullscreenchange frames later: after
    // a quick leave, the entry's event comes when the container is out again (seen on a second entry).
    // While `window.holding`, the browser's events are held back here, before any listener of the page,
    // and sent on (late, as Chrome may) by release().
    window.held = 0;
    window.holding = false;
    window.addEventListener('fullscreenchange', (event) => {
      if (!window.holding) return;
      event.stopImmediatePropagation();
      window.held += 1;
    }, true);
    window.release = () => {
      window.holding = false;
      for (; window.held > 0; window.held--) document.dispatchEvent(new Event('fullscreenchange', { bubbles: true }));
    };
  });
  const fullscreen = page.getByRole('toolbar').getByRole('button', { name: 'Fullscreen' });
  // Enter (a user gesture: the Fullscreen API asks for one) and leave, each heard.
  await fullscreen.click();
  await page.waitForFunction(() => window.heard.length === 1);
  await page.evaluate(() => document.exitFullscreen());
  await page.waitForFunction(() => window.heard.length === 2);
  // Again, the browser's events late: the entry's comes after the leave.
  await page.evaluate(() => { window.holding = true; });
  await fullscreen.click();
  await page.waitForFunction(() => window.book.fullscreen);
  await page.evaluate(() => document.exitFullscreen());
  await page.waitForFunction(() => window.held === 2 && !window.book.fullscreen);
  await page.evaluate(() => window.release());
  expect(await page.evaluate(() => window.heard)).toEqual([true, false, true, false]);
});

test('browser: download() fires a cancelable download event; unless prevented it downloads the PDF\'s bytes, or the `download` URL', async ({ page }) => {
  await openPdfBook(page);
  const prevented = await page.evaluate(async () => {
    let url = null;
    const stop = (e) => { url = e.detail.url; e.preventDefault(); };
    window.book.addEventListener('download', stop);
    const answer = await window.book.download();
    window.book.removeEventListener('download', stop);
    return { answer, url };
  });
  expect(prevented.answer).toBe(false);
  expect(prevented.url).toMatch(/^blob:/);
  const [download, answer] = await Promise.all([page.waitForEvent('download'), page.evaluate(() => window.book.download())]);
  expect(answer).toBe(true);
  expect(download.suggestedFilename()).toBe('document.pdf');
  expect(readFileSync(await download.path()).equals(Buffer.from(made.base64, 'base64'))).toBe(true);

  // A book with a `download` URL offers that; a book with nothing to download answers false.
  const others = await page.evaluate(async () => {
    window.book.destroy();
    const canvas = document.createElement('canvas');
    const withUrl = await window.Flipbook.create(window.container, { pages: [canvas, canvas], download: '/files/brochure.pdf' });
    let url = null;
    withUrl.addEventListener('download', (e) => { url = e.detail.url; e.preventDefault(); });
    const answer = await withUrl.download();
    withUrl.destroy();
    const plain = await window.Flipbook.create(window.container, { pages: [canvas, canvas] });
    let heard = false;
    plain.addEventListener('download', () => { heard = true; });
    const nothing = await plain.download();
    plain.destroy();
    return { url, answer, nothing, heard };
  });
  expect(others).toEqual({ url: '/files/brochure.pdf', answer: false, nothing: false, heard: false });
});

test('browser: print() fires a cancelable print event with the pages; unless prevented it prints every page, drawn, from a hidden frame', async ({ page }) => {
  await openPdfBook(page);
  const result = await page.evaluate(async () => {
    let pages = null;
    const stop = (e) => { pages = e.detail.pages; e.preventDefault(); };
    window.book.addEventListener('print', stop);
    const prevented = await window.book.print();
    const framesAfterPrevented = document.querySelectorAll('iframe[data-conecurl-print]').length;
    window.book.removeEventListener('print', stop);
    // The frame printed: its pages seen as it is handed to the printer (beforeprint in the frame).
    const seen = new Promise((resolve) => new MutationObserver((records, observer) => {
      const frame = document.querySelector('iframe[data-conecurl-print]');
      if (!frame) return;
      observer.disconnect();
      frame.contentWindow.addEventListener('beforeprint', () => resolve([...frame.contentDocument.images].map((img) => ({ alt: img.alt, width: img.naturalWidth }))));
    }).observe(document.body, { childList: true }));
    const printed = await window.book.print();
    return { pages, prevented, framesAfterPrevented, printed, images: await seen };
  });
  expect(result.prevented).toBe(false);
  expect(result.pages).toEqual(PAGES.map((_, i) => i));
  expect(result.framesAfterPrevented).toBe(0);
  expect(result.printed).toBe(true);
  expect(result.images.map((i) => i.alt)).toEqual(PAGES.map((_, i) => `Page ${i + 1}`));
  expect(result.images.every((i) => i.width === 1600)).toBe(true);
});
