// Browser: pages that change on a live book (live-pages.js): insertPages, removePages and replacePage
// keep the page the reader has open (read back from the canvas), keep the textures of untouched pages
// (counted uploads), fire one pageschange each, wait for turns in flight, and refuse bad arguments.
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';

const FIXTURE = '/tests/browser/fixtures/flipbook-fixture.html';

// In the page: counts page uploads to the surface, and reads which page colour each open place shows.
async function instrument(page) {
  await page.evaluate(() => {
    window.uploads = [];
    window.changes = [];
    const surface = window.book.surface;
    const setPageImage = surface.setPageImage.bind(surface);
    surface.setPageImage = (index, ...rest) => { window.uploads.push(index); return setPageImage(index, ...rest); };
    window.book.addEventListener('pageschange', (event) => window.changes.push(event.detail));
    // The page colour (its index in the numbered set, -1 for none) in the lower middle of each open place.
    window.openColours = () => {
      const view = window.book.surface;
      let pixel;
      if (view.kind === 'webgl') {
        view.drawNow();
        const pixels = view.readPixels();
        const ratio = pixels.width / view.canvas.clientWidth;
        pixel = (x, y) => {
          const i = (Math.round(y * ratio) * pixels.width + Math.round(x * ratio)) * 4;
          return [pixels.data[i], pixels.data[i + 1], pixels.data[i + 2]];
        };
      } else {
        const ratio = view.canvas.width / view.canvas.clientWidth;
        const g = view.canvas.getContext('2d');
        pixel = (x, y) => [...g.getImageData(Math.round(x * ratio), Math.round(y * ratio), 1, 1).data].slice(0, 3);
      }
      return window.book.openPagePlaces().map((p) => window.pageAtColor(pixel(p.x + p.width * 0.5, p.y + p.height * 0.88), 12));
    };
  });
}

const FLAT = { lighting: false, shadows: false, gutter: false };

for (const kind of ['Flipbook', 'StaticBook']) {
  test(`browser: insertPages, removePages and replacePage on a live ${kind} keep the open page, re-upload no untouched page and fire one pageschange each`, async ({ page }) => {
    const problems = await openReady(page, FIXTURE);
    await page.evaluate(async ({ flat, kind }) => {
      const options = { display: 'double', startPage: 3, ...flat };
      if (kind === 'Flipbook') {
        await window.openBook({ pages: 6, ...options });
      } else {
        const { StaticBook } = await import('/web/src/book/static-book.js');
        const pages = Array.from({ length: 6 }, (_, i) => window.makeNumberedPage(i));
        window.book = await StaticBook.create(document.getElementById('container'), { pages, ...options });
      }
      await window.book.whenIdle();
    }, { flat: FLAT, kind });
    await instrument(page);
    expect(await page.evaluate(() => [window.book.surface.kind, window.book.page, window.openColours()]))
      .toEqual([kind === 'Flipbook' ? 'webgl' : 'canvas', 3, [3, 4]]);

    // Two pages before the open spread: the reader's pages 3 and 4 are now 5 and 6, still in view.
    const inserted = await page.evaluate(async () => {
      const detail = await window.book.insertPages(1, [window.makeNumberedPage(6), window.makeNumberedPage(7)]);
      await window.book.whenIdle();
      return {
        detail, page: window.book.page, pageCount: window.book.pageCount, colours: window.openColours(),
        uploads: [...window.uploads].sort(), resident: window.book.residentPages,
        announced: window.book.element.querySelector('[aria-live]')?.textContent,
      };
    });
    expect(inserted).toEqual({
      detail: { change: 'insert', at: 1, count: 2, pageCount: 8, page: 5 }, page: 5, pageCount: 8, colours: [3, 4],
      uploads: [1, 2],  // only the new pages: the six kept theirs, renumbered
      resident: [0, 1, 2, 3, 4, 5, 6, 7],
      announced: 'Pages 6\u20137 of 8',
    });

    // The open page (old page 3, now 5) removed: the page that took its place (old page 4) opens.
    const removed = await page.evaluate(async () => {
      window.uploads.length = 0;
      const detail = await window.book.removePages(5);
      await window.book.whenIdle();
      return { detail, page: window.book.page, colours: window.openColours(), uploads: window.uploads, states: window.book.progress };
    });
    expect(removed).toEqual({
      detail: { change: 'remove', at: 5, count: 1, pageCount: 7, page: 5 }, page: 5, colours: [4, 5], uploads: [],
      states: { loaded: 7, total: 7, pending: 0 },
    });

    // A page on screen replaced: only it is uploaded again, and shows the new image.
    const replaced = await page.evaluate(async () => {
      window.uploads.length = 0;
      const detail = await window.book.replacePage(6, window.makeNumberedPage(8));
      await window.book.whenIdle();
      return { detail, page: window.book.page, colours: window.openColours(), uploads: window.uploads };
    });
    expect(replaced).toEqual({ detail: { change: 'replace', at: 6, count: 1, pageCount: 7, page: 5 }, page: 5, colours: [4, 8], uploads: [6] });
    expect(await page.evaluate(() => window.changes.map((c) => c.change))).toEqual(['insert', 'remove', 'replace']);
    expect(problems).toEqual([]);
  });
}

test('browser: a page change asked for while a leaf turns waits for it to land, then keeps the page it landed on', async ({ page }) => {
  const problems = await openReady(page, FIXTURE);
  await page.evaluate(async (flat) => { await window.openBook({ pages: 6, display: 'single', duration: 400, ...flat }); }, FLAT);
  await instrument(page);
  const result = await page.evaluate(async () => {
    const order = [];
    window.book.addEventListener('turned', () => order.push(`turned ${window.book.page}`));
    window.book.addEventListener('pageschange', (e) => order.push(`pageschange ${e.detail.page}`));
    const turning = window.book.next();
    const animatingWhenAsked = window.book.animating;
    const change = window.book.insertPages(0, [window.makeNumberedPage(9)]);
    const countWhileTurning = window.book.pageCount;  // not applied yet: the leaf still moves
    await Promise.all([turning, change]);
    await window.settle();
    return { animatingWhenAsked, countWhileTurning, order, page: window.book.page, pageCount: window.book.pageCount, colours: window.openColours() };
  });
  expect(result).toEqual({
    animatingWhenAsked: true, countWhileTurning: 6, order: ['turned 1', 'pageschange 2'], page: 2, pageCount: 7, colours: [1],
  });
  expect(problems).toEqual([]);
});

test('browser: bad arguments to insertPages, removePages and replacePage are refused by name, and the book is unchanged', async ({ page }) => {
  const problems = await openReady(page, FIXTURE);
  await page.evaluate(async () => { await window.openBook({ pages: 4 }); });
  const errors = await page.evaluate(async () => {
    const b = window.book;
    const p = window.makeNumberedPage(5);
    const said = (promise) => promise.then(() => 'resolved', (e) => `${e.name}: ${e.message}`);
    return [
      await said(b.insertPages(5, [p])),
      await said(b.insertPages(1.5, [p])),
      await said(b.insertPages(0, [])),
      await said(b.insertPages(0, [42])),
      await said(b.insertPages(0, [{ src: p, links: [{ rect: [0, 0, 1, 1], page: 9 }] }])),
      await said(b.removePages(4)),
      await said(b.removePages(1, 4)),
      await said(b.removePages(0, 4)),
      await said(b.removePages(0, 0)),
      await said(b.replacePage(-1, p)),
      await said(b.replacePage(0, { src: p, side: 'left' })),
      b.pageCount,
    ];
  });
  expect(errors).toEqual([
    'RangeError: conecurl: insertPages at must be from 0 to 4, got 5',
    'TypeError: conecurl: insertPages at must be a whole number, got 1.5',
    'TypeError: conecurl: insertPages pages must be a non-empty array of page sources, got an array of 0',
    expect.stringMatching(/^TypeError: conecurl: insertPages 'pages\[0\]' must be a URL string/),
    "TypeError: conecurl: insertPages 'pages[0].links[0].page' must be a page index below 5; got 9",
    'RangeError: conecurl: removePages from must be from 0 to 3, got 4',
    'RangeError: conecurl: removePages count must be from 1 to 3 (the pages from 1 on), got 4',
    'RangeError: conecurl: removePages cannot remove all 4 pages: a book keeps at least one',
    'RangeError: conecurl: removePages count must be from 1 to 4 (the pages from 0 on), got 0',
    'RangeError: conecurl: replacePage index must be from 0 to 3, got -1',
    "TypeError: conecurl: replacePage 'page' has an unknown key 'side' (allowed: src, html, alt, hard, zoomSrc, thumbSrc, placeholder, links, narration)",
    4,
  ]);
  expect(problems).toEqual([]);
});

test('browser: HTML pages inserted into a live book are mounted and drawn, later HTML pages renumbered, and removed ones go back', async ({ page }) => {
  const problems = await openReady(page, '/tests/browser/fixtures/html-fixture.html');
  const result = await page.evaluate(async () => {
    const card = (text) => {
      const div = document.createElement('div');
      div.textContent = text;
      div.style.cssText = 'width:100%;height:100%;background:#fde68a';
      return div;
    };
    const home = document.createElement('section');
    document.body.append(home);
    const kept = card('kept');
    home.append(kept);
    window.book = await window.Flipbook.create(window.container,
      { pages: [window.makeNumberedPage(0), window.makeNumberedPage(1), kept], display: 'single' });
    const sheets = () => [...window.book.element.querySelectorAll('.conecurl-html-page')].map((s) => [s.dataset.page, s.textContent]);
    const before = sheets();
    const added = card('added');
    await window.book.insertPages(1, [added, window.makeNumberedPage(3)]);
    const afterInsert = sheets();
    await window.book.flip(1, { animate: false });
    await window.book.whenIdle();
    const shownLive = !window.book.element.querySelector('.conecurl-html-page[data-page="1"]').inert;
    await window.book.removePages(3, 2);  // the page 3 image and `kept`
    return { before, afterInsert, shownLive, afterRemove: sheets(), keptHome: kept.parentNode === home, state: window.book.pageState(1).state };
  });
  expect(result).toEqual({
    before: [['2', 'kept']],
    afterInsert: [['4', 'kept'], ['1', 'added']],
    shownLive: true,
    afterRemove: [['1', 'added']],
    keptHome: true,
    state: 'loaded',
  });
  expect(problems).toEqual([]);
});

test('browser: the first HTML pages inserted into a book of images bring their layer: each is mounted and drawn, also when asked while a leaf turns (the fuzz test found them loaded unmounted: no texture)', async ({ page }) => {
  const problems = await openReady(page, '/tests/browser/fixtures/html-fixture.html');
  const result = await page.evaluate(async () => {
    const card = (text) => {
      const div = document.createElement('div');
      div.textContent = text;
      div.style.cssText = 'width:100%;height:100%;background:#86efac';
      return div;
    };
    window.book = await window.Flipbook.create(window.container,
      { pages: [0, 1, 2].map((i) => window.makeNumberedPage(i)), display: 'double', startPage: 2, duration: 40 });
    const book = window.book;
    const changes = [];
    for (let k = 0; k < 3; k++) {
      book.next();
      changes.push(book.insertPages(0, [card(`card ${k}`)]));  // waits for the turn, the first for the layer's module
    }
    await Promise.all(changes);
    while (book.animating) await new Promise((resolve) => requestAnimationFrame(resolve));
    await book.whenIdle();
    const html = [0, 1, 2].map((i) => ({ state: book.pageState(i).state, texture: Boolean(book.surface.pageImageSize(i)) }));
    return { html, sheets: book.element.querySelectorAll('.conecurl-html-page').length, count: book.pageCount };
  });
  expect(result.count).toBe(6);
  expect(result.sheets).toBe(3);
  expect(result.html.map((p) => p.state)).toEqual(['loaded', 'loaded', 'loaded']);
  expect(problems).toEqual([]);
});

test('browser: a page change asked for right after create() lets the held events out first, so ready tells of the book as it was (fuzz seed 275635925)', async ({ page }) => {
  const problems = await openReady(page, FIXTURE);
  const heard = await page.evaluate(async () => {
    const pages = [0, 1, 2, 3].map((i) => window.makeNumberedPage(i));
    const book = await window.Flipbook.create(window.container, { pages, startPage: 1, display: 'single' });
    const heard = [];
    for (const type of ['ready', 'pageschange']) book.addEventListener(type, (e) => heard.push([type, e.detail.page, book.pageCount]));
    const ready = new Promise((resolve) => book.addEventListener('ready', resolve, { once: true }));
    await book.removePages(1, 3);  // at once, before the held events' task
    await ready;  // let out by the page change, or by the held events' task if it held them on
    return heard;
  });
  expect(heard).toEqual([['ready', 1, 4], ['pageschange', 0, 1]]);
  expect(problems).toEqual([]);
});

test('browser: with hash: true, pages inserted before the open page rewrite #page=N in place (no new history entry)', async ({ page }) => {
  const problems = await openReady(page, `${FIXTURE}#page=3`);
  const result = await page.evaluate(async () => {
    await window.openBook({ pages: 6, display: 'single', hash: true });
    const length = history.length;
    await window.book.insertPages(0, [window.makeNumberedPage(7), window.makeNumberedPage(8)]);
    return { page: window.book.page, hash: location.hash, newEntries: history.length - length };
  });
  expect(result).toEqual({ page: 4, hash: '#page=5', newEntries: 0 });
  expect(problems).toEqual([]);
});

test('browser: a PDF book refuses insertPages, removePages and replacePage with an Error saying its pages are its PDF\'s', async ({ page }) => {
  const { PDFDocument } = await import('pdf-lib');
  const pdf = await PDFDocument.create();
  pdf.addPage([300, 400]);
  pdf.addPage([300, 400]);
  const base64 = Buffer.from(await pdf.save()).toString('base64');
  const problems = await openReady(page, '/tests/browser/fixtures/pdf-fixture.html');
  const result = await page.evaluate(async (bytes) => {
    window.book = await window.Flipbook.create(window.container, { pdf: window.bytesFromBase64(bytes) });
    const said = (promise) => promise.then(() => 'resolved', (e) => `${e.name}: ${e.message}`);
    return [
      await said(window.book.insertPages(0, ['a.png'])),
      await said(window.book.removePages(0)),
      await said(window.book.replacePage(0, 'a.png')),
      window.book.pageCount,
    ];
  }, base64);
  expect(result).toEqual([
    "Error: conecurl: insertPages: a PDF book's pages are its PDF's; they cannot change on a live book",
    "Error: conecurl: removePages: a PDF book's pages are its PDF's; they cannot change on a live book",
    "Error: conecurl: replacePage: a PDF book's pages are its PDF's; they cannot change on a live book",
    2,
  ]);
  expect(problems).toEqual([]);
});
