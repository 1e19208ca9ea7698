// Browser: the book's document API over a real PDF (tests/browser/document-pdf.js: fonts, headings,
// bookmarks by explicit and named destinations) and over HTML pages: outline() is pdf.js's outline with
// destinations resolved, search() finds exactly the pages whose pdf.js text holds a word (case and
// diacritics folded), aborts, and its hits' rectangles lie over the word's glyphs; showHit() turns
// there and marks the hit, flat (data-search-hit elements) and curling (in the page's texture).
import { test, expect } from '@playwright/test';
import { existsSync, readFileSync } from 'node:fs';
import { openReady } from './helpers.js';
import { BOOKMARKS, PAGES, PAGE_SIZE, lineAt, makeDocumentPdf, openPdfBook as openPdf } from './document-pdf.js';

let made;
test.beforeAll(async () => { made = await makeDocumentPdf(); });

/** The test PDF's book, drawn without light, shadows or gutter (plain pixels under the marks), and pdf.js beside it. */
const openPdfBook = (page, options) => openPdf(page, made, { lighting: false, shadows: false, gutter: false, ...options });

test('browser: outline() of a PDF is pdf.js\'s outline with each destination resolved to its page, and an entry opens its page', async ({ page }) => {
  await openPdfBook(page);
  const { outline, reference } = await page.evaluate(async () => {
    const doc = window.refDoc;
    const resolve = async (items) => Promise.all(items.map(async (item) => {
      const dest = typeof item.dest === 'string' ? await doc.getDestination(item.dest) : item.dest;
      return { title: item.title, page: await doc.getPageIndex(dest[0]), children: await resolve(item.items) };
    }));
    return { outline: await window.book.outline(), reference: await resolve(await doc.getOutline()) };
  });
  expect(outline).toEqual(reference);
  // And it is the outline the PDF was made with (named destinations included).
  const strip = (entries) => entries.map(({ title, page, children }) => ({ title, page, children: strip(children ?? []) }));
  expect(outline).toEqual(strip(BOOKMARKS));
  // An entry opens its destination page: the page whose heading is the entry's title.
  const entry = outline[2].children[0];  // Section 2.1, page 4
  const shown = await page.evaluate(async (to) => {
    await window.book.flip(to);
    await window.book.whenIdle();
    return window.book.openPages;
  }, entry.page);
  expect(shown).toContain(entry.page);
  expect(PAGES[entry.page].heading).toBe(entry.title);
});

// A typeset PDF found on the machine (Debian's shared-mime-info package ships its specification, made
// by a real typesetter: embedded fonts, kerned text runs, bookmarks); the test is skipped where it is absent.
const TYPESET_PDF = '/usr/share/doc/shared-mime-info/shared-mime-info-spec.pdf';

test('browser: a typeset PDF found on the machine: outline() is pdf.js\'s outline, search() finds exactly the pages whose pdf.js text holds each word', async ({ page }) => {
  test.skip(!existsSync(TYPESET_PDF), `${TYPESET_PDF} is not on this machine`);
  await openReady(page, '/tests/browser/fixtures/pdf-fixture.html');
  const result = await page.evaluate(async (base64) => {
    const bytes = window.bytesFromBase64(base64);
    window.book = await window.Flipbook.create(window.container, { pdf: bytes, display: 'double', duration: 300 });
    const pdfjs = await import('pdfjs-dist');
    const doc = await pdfjs.getDocument({ data: bytes.slice() }).promise;
    const resolve = async (items) => {
      const out = [];
      for (const item of items ?? []) {
        const dest = typeof item.dest === 'string' ? await doc.getDestination(item.dest) : item.dest;
        const children = await resolve(item.items);
        const page = Array.isArray(dest) ? await doc.getPageIndex(dest[0]) : children[0]?.page;
        if (page !== undefined) out.push({ title: item.title, page, children });
      }
      return out;
    };
    const fold = (s) => s.normalize('NFKD').replace(/\p{M}/gu, '').toLowerCase().replace(/\s+/g, ' ');
    const texts = [];
    for (let i = 1; i <= doc.numPages; i++) {
      const content = await (await doc.getPage(i)).getTextContent();
      texts.push(fold(content.items.map((item) => (item.str ?? '') + (item.hasEOL ? ' ' : '')).join('')));
    }
    const words = {};
    for (const word of ['magic', 'glob', 'Namespace', 'sub-class', 'freedesktop']) {
      const hits = await window.book.search(word);
      words[word] = { pages: [...new Set(hits.map((h) => h.page))], expected: texts.map((t, i) => (t.includes(fold(word)) ? i : -1)).filter((i) => i >= 0),
        rectsOnPage: hits.every((h) => h.rects.length > 0 && h.rects.every(([x, y, w, hh]) => x >= 0 && y >= 0 && x + w <= 1.001 && y + hh <= 1.001)) };
    }
    return { outline: await window.book.outline(), reference: await resolve(await doc.getOutline()), words, pages: doc.numPages };
  }, readFileSync(TYPESET_PDF).toString('base64'));
  expect(result.outline).toEqual(result.reference);
  for (const [word, r] of Object.entries(result.words)) {
    expect(r.pages, word).toEqual(r.expected);
    expect(r.rectsOnPage, word).toBe(true);
  }
  expect(result.words.magic.pages.length).toBeGreaterThan(0);
  console.log(`typeset PDF: ${result.pages} pages, ${result.outline.length} top-level bookmarks, 'magic' on ${result.words.magic.pages.length} pages`);
});

test('browser: outline() of an image book is its checked `outline` option; a bad entry is a TypeError naming it', async ({ page }) => {
  await openReady(page, '/tests/browser/fixtures/pdf-fixture.html');
  const result = await page.evaluate(async () => {
    const pages = Array.from({ length: 6 }, (_, i) => {
      const canvas = document.createElement('canvas');
      canvas.width = 60;
      canvas.height = 80;
      canvas.getContext('2d').fillRect(0, 0, 10 + i, 10);
      return canvas;
    });
    const outline = [{ title: 'One', page: 0 }, { title: 'Two', page: 2, children: [{ title: 'Two A', page: 3 }] }];
    const book = await window.Flipbook.create(window.container, { pages, outline });
    const got = await book.outline();
    outline[0].title = 'changed';  // the book keeps its own copy
    const again = await book.outline();
    book.destroy();
    const errors = [];
    for (const bad of [[{ title: 'x', page: 9 }], [{ title: 'a', page: 0 }, { title: 'ok', page: 1, children: [{ page: 1 }] }], 'toc']) {
      try {
        await window.Flipbook.create(window.container, { pages, outline: bad });
      } catch (error) {
        errors.push(`${error.name}: ${error.message}`);
      }
    }
    const plain = await window.Flipbook.create(window.container, { pages });
    const none = await plain.outline();
    plain.destroy();
    return { got, again, errors, none };
  });
  expect(result.got).toEqual([{ title: 'One', page: 0, children: [] },
    { title: 'Two', page: 2, children: [{ title: 'Two A', page: 3, children: [] }] }]);
  expect(result.again[0].title).toBe('One');
  expect(result.none).toEqual([]);
  expect(result.errors).toHaveLength(3);
  expect(result.errors[0]).toMatch(/^TypeError: .*'outline\[0\]\.page'.*0 to 5.*9/);
  expect(result.errors[1]).toMatch(/^TypeError: .*'outline\[1\]\.children\[0\]\.title'/);
  expect(result.errors[2]).toMatch(/^TypeError: .*'outline'/);
});

test('browser: search() finds exactly the pages whose pdf.js text holds the word, case and diacritics folded, in page order', async ({ page }) => {
  await openPdfBook(page);
  const result = await page.evaluate(async () => {
    const doc = window.refDoc;
    // The reference: each page's text as pdf.js gives it, lower-cased and without diacritics.
    const fold = (s) => s.normalize('NFKD').replace(/\p{M}/gu, '').toLowerCase();
    const texts = [];
    for (let i = 1; i <= doc.numPages; i++) {
      const content = await (await doc.getPage(i)).getTextContent();
      texts.push(fold(content.items.map((item) => item.str ?? '').join(' ')));
    }
    const out = {};
    for (const word of ['zebra', 'ZEBRA', 'café', 'CAFE', 'cafe', 'naïve', 'Naive', 'coffee', 'stripes', 'nowhere']) {
      const t0 = performance.now();
      const hits = await window.book.search(word);
      out[word] = {
        pages: [...new Set(hits.map((h) => h.page))],
        expected: texts.map((t, i) => (t.includes(fold(word)) ? i : -1)).filter((i) => i >= 0),
        count: hits.length,
        ordered: hits.every((h, i) => i === 0 || h.page > hits[i - 1].page
          || (h.page === hits[i - 1].page && (h.rects[0][1] > hits[i - 1].rects[0][1] || h.rects[0][0] > hits[i - 1].rects[0][0]))),
        snippets: hits.map((h) => h.snippet),
        ms: performance.now() - t0,
      };
    }
    return out;
  });
  for (const [word, r] of Object.entries(result)) {
    expect(r.pages, word).toEqual(r.expected);
    expect(r.ordered, word).toBe(true);
  }
  expect(result.zebra.pages).toEqual([1, 4]);
  expect(result.cafe.pages).toEqual([3, 4, 5]);
  expect(result['café']).toEqual({ ...result.cafe, ms: result['café'].ms });
  expect(result.naïve.pages).toEqual([1, 4]);
  expect(result.nowhere.count).toBe(0);
  expect(result.stripes.count).toBe(2);  // "stripes." and "Stripes confuse" on page 1
  // A snippet: the hit with some words around it, cut with an ellipsis.
  expect(result.coffee.snippets[0]).toMatch(/Coffee In a Café/);
  expect(result['café'].snippets[0]).toMatch(/Café/);
});

test('browser: a hit\'s rectangles lie over the word as the PDF drew it (one per line, fractions of the page)', async ({ page }) => {
  await openPdfBook(page);
  const hits = await page.evaluate(() => window.book.search('zebra'));
  // Page 1, line 0: "The zebra has stripes." — where pdf-lib put the word, in points.
  const line = lineAt(1, 0);
  const x = line.x + made.widthOf('The ', 'body');
  const width = made.widthOf('zebra', 'body');
  const hit = hits.filter((h) => h.page === 1)[1];  // the first is the heading's "Zebras"
  expect(hit.rects).toHaveLength(1);
  const [fx, fy, fw, fh] = hit.rects[0];
  const [pw, ph] = PAGE_SIZE;
  expect(Math.abs(fx * pw - x)).toBeLessThan(1.5);
  expect(Math.abs(fw * pw - width)).toBeLessThan(2);
  // The box spans the glyphs: from above the x-height to the baseline and below, about a line high.
  expect(fy * ph).toBeLessThan(line.baseline - 0.6 * line.size);
  expect((fy + fh) * ph).toBeGreaterThan(line.baseline);
  expect(fh * ph).toBeLessThan(1.5 * line.size);
  // The heading's hit on page 4 ("THE CAFE OF THE ZEBRA" is body text; "Chapter One: Zebras" a heading on page 1).
  const heading = await page.evaluate(() => window.book.search('Chapter One'));
  const h = lineAt(1, -1);
  expect(Math.abs(heading[0].rects[0][0] * pw - h.x)).toBeLessThan(1.5);
  expect(Math.abs(heading[0].rects[0][2] * pw - made.widthOf('Chapter One', 'heading'))).toBeLessThan(3);
  // A phrase across two lines of text gives one rectangle per line.
  const across = await page.evaluate(() => window.book.search('coffee comes'));
  expect(across).toHaveLength(1);
  expect(across[0].rects).toHaveLength(2);
  expect(across[0].rects[1][1]).toBeGreaterThan(across[0].rects[0][1]);
});

test('browser: search() rejects with an AbortError when its signal aborts, and a later search still answers', async ({ page }) => {
  await openPdfBook(page);
  const result = await page.evaluate(async () => {
    const names = [];
    const before = new AbortController();
    before.abort();
    try { await window.book.search('zebra', { signal: before.signal }); } catch (error) { names.push(error.name); }
    const during = new AbortController();
    const running = window.book.search('zebra', { signal: during.signal });
    during.abort();
    try { await running; names.push('resolved'); } catch (error) { names.push(error.name); }
    let typeError = '';
    try { await window.book.search(42); } catch (error) { typeError = error.name; }
    const after = await window.book.search('zebra');
    return { names, typeError, after: after.map((h) => h.page) };
  });
  expect(result.names).toEqual(['AbortError', 'AbortError']);
  expect(result.typeError).toBe('TypeError');
  expect(result.after).toEqual([1, 1, 4]);  // page 1: the heading's "Zebras" and "The zebra"
});

/** Pixels in the drawing buffer inside `box` (CSS px of the canvas): how many are dark (text) and how many marked (yellow/orange). */
function pixelsIn(page, box) {
  return page.evaluate((b) => {
    const view = window.book.surface;
    view.drawNow();
    const { width, height, data } = view.readPixels();  // bottom-up rows? readPixels gives top-down here
    const ratio = width / window.book.element.querySelector('canvas').clientWidth;
    let dark = 0;
    let marked = 0;
    let all = 0;
    for (let y = Math.round(b.y * ratio); y < Math.round((b.y + b.height) * ratio); y++) {
      for (let x = Math.round(b.x * ratio); x < Math.round((b.x + b.width) * ratio); x++) {
        const i = (y * width + x) * 4;
        const [r, g, bl] = [data[i], data[i + 1], data[i + 2]];
        all += 1;
        if (r < 110 && g < 110 && bl < 110) dark += 1;
        if (r > 180 && g > 110 && bl < 120) marked += 1;
      }
    }
    return { dark, marked, all, height };
  }, box);
}

/** Yellow/orange pixels over the whole drawing buffer: the marks drawn in the pages' textures. */
function markedPixels(page) {
  return page.evaluate(() => {
    window.markedPixels ??= () => {
      const view = window.book.surface;
      view.drawNow();
      const { data } = view.readPixels();
      let marked = 0;
      for (let i = 0; i < data.length; i += 4) if (data[i] > 180 && data[i + 1] > 110 && data[i + 2] < 120) marked += 1;
      return marked;
    };
    return window.markedPixels();
  });
}

test('browser: showHit() turns to the hit and marks it: data-search-hit elements over the word, yellow in the page, searchchange; clearSearch() removes all', async ({ page }) => {
  await openPdfBook(page);
  const shown = await page.evaluate(async () => {
    const events = [];
    window.book.addEventListener('searchchange', (e) => events.push({ query: e.detail.query, hits: e.detail.hits.length, current: e.detail.current?.page ?? null }));
    const hits = await window.book.search('cafe');
    const turned = new Promise((resolve) => window.book.addEventListener('turned', resolve, { once: true }));
    await window.book.showHit(hits[1]);  // page 4: a far page from the cover, so the book turns there
    await turned;
    await window.book.whenIdle();
    const canvasBox = window.book.element.querySelector('canvas').getBoundingClientRect();
    const marks = [...window.book.element.querySelectorAll('[data-search-hit]')].map((m) => {
      const r = m.getBoundingClientRect();
      return { page: Number(m.dataset.page), current: m.hasAttribute('data-current'),
        box: { x: r.left - canvasBox.left, y: r.top - canvasBox.top, width: r.width, height: r.height } };
    });
    return { events, openPages: window.book.openPages, marks, hit: hits[1] };
  });
  expect(shown.openPages).toContain(4);
  expect(shown.events).toEqual([{ query: 'cafe', hits: 3, current: null }, { query: 'cafe', hits: 3, current: 4 }]);
  // Open pages 3 and 4: the hits on both are marked, the one shown is current.
  expect(shown.marks.map((m) => [m.page, m.current]).sort()).toEqual([[3, false], [4, true]]);
  const current = shown.marks.find((m) => m.current);
  const inside = await pixelsIn(page, current.box);
  expect(inside.dark / inside.all, 'the word\'s glyphs under the mark').toBeGreaterThan(0.05);
  expect(inside.marked / inside.all, 'the mark drawn in the page').toBeGreaterThan(0.3);
  // Just above the mark, the line's gap: no glyph there.
  const above = await pixelsIn(page, { ...current.box, y: current.box.y - current.box.height * 0.9, height: current.box.height * 0.5 });
  expect(above.dark).toBe(0);

  const cleared = await page.evaluate(async () => {
    const events = [];
    window.book.addEventListener('searchchange', (e) => events.push(e.detail));
    window.book.clearSearch();
    await window.book.whenIdle();
    return { events, marks: window.book.element.querySelectorAll('[data-search-hit]').length };
  });
  expect(cleared.events).toEqual([{ query: '', hits: [], current: null }]);
  expect(cleared.marks).toBe(0);
  expect(await markedPixels(page)).toBe(0);
});

test('browser: showHit() called again while an earlier one still turns ends on the last hit\'s page (the latest wins)', async ({ page }) => {
  await openPdfBook(page);
  const ended = await page.evaluate(async () => {
    const hits = await window.book.search('cafe');
    const last = hits[hits.length - 1];
    // A reader stepping through hits quickly: each call comes before the one before has landed.
    await Promise.all([window.book.showHit(last), window.book.showHit(hits[0]), window.book.showHit(last)]);
    await window.book.whenIdle();
    return { openPages: window.book.openPages, last: last.page, current: [...window.book.element.querySelectorAll('[data-search-hit][data-current]')].map((m) => Number(m.dataset.page)) };
  });
  expect(ended.openPages).toContain(ended.last);
  expect(ended.current).toEqual([ended.last]);
});

test('browser: a marked hit, flat and while its page curls (drawn in its texture), matches its reference images', async ({ page }) => {
  await openPdfBook(page);
  await page.evaluate(async () => {
    const hits = await window.book.search('zebra');
    await window.book.showHit(hits.find((h) => h.page === 4));  // the right page of the spread 3-4
    await window.book.whenIdle();
  });
  const flatMarked = await markedPixels(page);
  expect(flatMarked).toBeGreaterThan(0);
  await expect(page.locator('#container')).toHaveScreenshot('search-hit-flat.png', { maxDiffPixelRatio: 0.005, threshold: 0.1 });
  const posed = await page.evaluate(() => {
    const shown = window.book.previewTurn('forward', 0.12);  // page 4's leaf lifted and curling
    return { shown, marks: window.book.element.querySelectorAll('[data-search-hit]').length };
  });
  expect(posed).toEqual({ shown: true, marks: 0 });  // the elements give way while the leaf moves...
  const curlingMarked = await markedPixels(page);
  expect(curlingMarked).toBeGreaterThan(flatMarked * 0.3);  // ...and the mark curls with the paper
  await expect(page.locator('#container')).toHaveScreenshot('search-hit-curling.png', { maxDiffPixelRatio: 0.005, threshold: 0.1 });
  // Cleared, the curling page shows no mark.
  await page.evaluate(() => window.book.clearSearch());
  await page.evaluate(() => window.book.whenIdle());
  expect(await markedPixels(page)).toBe(0);
});

test('browser: search() over HTML pages finds their text, with rects from a Range over the word', async ({ page }) => {
  await openReady(page, '/tests/browser/fixtures/html-fixture.html');
  const result = await page.evaluate(async () => {
    const make = window.makeTextPage;
    const pages = [make('Cover'), make('An Élan of words here.'), make('Nothing'), make('élan again, and ELAN')];
    window.book = await window.Flipbook.create(window.container, { pages, display: 'double', duration: 300 });
    await window.book.whenIdle();
    const hits = await window.book.search('elan');
    // Where the word is in its page, measured here with a Range over the text itself.
    const p = pages[1].querySelector('p');
    const range = document.createRange();
    range.setStart(p.firstChild, 3);
    range.setEnd(p.firstChild, 7);
    const r = range.getBoundingClientRect();
    const box = pages[1].parentElement.getBoundingClientRect();
    const expected = [(r.left - box.left) / box.width, (r.top - box.top) / box.height, r.width / box.width, r.height / box.height];
    // Pages inserted: the hits' page numbers no longer hold, so the search ends.
    await window.book.showHit(hits[1]);
    const ended = new Promise((resolve) => window.book.addEventListener('searchchange', (e) => resolve(e.detail), { once: true }));
    await window.book.insertPages(0, [make('A new first page')]);
    const afterInsert = await ended;
    return { hits, expected, afterInsert, marks: window.book.element.querySelectorAll('[data-search-hit]').length };
  });
  expect(result.afterInsert).toEqual({ query: '', hits: [], current: null });
  expect(result.marks).toBe(0);
  expect(result.hits.map((h) => h.page)).toEqual([1, 3, 3]);
  const got = result.hits[0].rects[0];
  result.expected.forEach((v, i) => expect(Math.abs(got[i] - v)).toBeLessThan(0.002));
  expect(result.hits[0].snippet).toContain('Élan');
});

/** A longer PDF for the timing: `count` pages of body text, the word "needle" on every tenth. */
async function makeLongPdf(count) {
  const { PDFDocument, StandardFonts } = await import('pdf-lib');
  const pdf = await PDFDocument.create();
  const font = await pdf.embedFont(StandardFonts.Helvetica);
  for (let i = 0; i < count; i++) {
    const page = pdf.addPage(PAGE_SIZE);
    for (let line = 0; line < 30; line++) {
      const words = `Line ${line + 1} of page ${i + 1}: some ordinary words to read through${i % 10 === 0 && line === 5 ? ' and a needle' : ''}.`;
      page.drawText(words, { x: 30, y: PAGE_SIZE[1] - 40 - line * 16, size: 11, font });
    }
  }
  return Buffer.from(await pdf.save()).toString('base64');
}

test('browser: the time of the first and of a repeated search on the test PDFs (reported, not asserted)', async ({ page }) => {
  test.setTimeout(300_000);
  await openPdfBook(page);
  const measure = (words) => page.evaluate(async (list) => {
    const times = [];
    for (const word of list) {
      const t = performance.now();
      const hits = await window.book.search(word);
      times.push({ word, ms: performance.now() - t, hits: hits.length });
    }
    return { pages: window.book.pageCount, times };
  }, words);
  const small = await measure(['zebra', 'coffee']);
  // 300 pages, searched at once after the book opened: the first search reads what the background has not yet.
  const long = await makeLongPdf(300);
  await page.evaluate(async (base64) => {
    window.book.destroy();
    window.book = await window.Flipbook.create(window.container, { pdf: window.bytesFromBase64(base64), display: 'double' });
  }, long);
  const large = await measure(['needle', 'ordinary words', 'needle']);
  for (const { pages, times } of [small, large]) {
    console.log(`search on the ${pages}-page test PDF: ${times.map((t) => `${t.word} ${t.ms.toFixed(1)} ms (${t.hits} hits)`).join(', then ')}`);
  }
  expect(small.times.map((t) => t.hits)).toEqual([3, 4]);
  expect(large.times.map((t) => t.hits)).toEqual([30, 9000, 30]);
});

test('browser: a mark on an image page whose decoded image was let go after upload is drawn in by loading it again; clearing restores the clean page', async ({ page }) => {
  await openReady(page, '/tests/browser/fixtures/pdf-fixture.html');
  const opened = await page.evaluate(async () => {
    // URL pages: decoded to ImageBitmaps the store closes once uploaded (only their size is kept).
    const pages = Array.from({ length: 4 }, (_, i) => `/tests/browser/references/curl-t0-00.png?page=${i}`);
    window.book = await window.Flipbook.create(window.container, { pages, display: 'double', lighting: false, shadows: false, gutter: false });
    await window.book.whenIdle();
    await window.book.showHit({ page: 2, snippet: '', rects: [[0.1, 0.1, 0.5, 0.2]] });
    return { open: window.book.openPages, marks: window.book.element.querySelectorAll('[data-search-hit][data-current]').length };
  });
  expect(opened).toEqual({ open: [1, 2], marks: 1 });
  // The page's image comes back from its URL, marked, once loaded again: wait until the pixels show it.
  await markedPixels(page);  // defines window.markedPixels
  await page.waitForFunction(() => window.markedPixels() > 1000, null, { polling: 100, timeout: 30_000 }).catch(() => {});
  expect(await markedPixels(page)).toBeGreaterThan(1000);
  await page.evaluate(() => window.book.clearSearch());
  await page.waitForFunction(() => window.markedPixels() === 0, null, { polling: 100, timeout: 30_000 }).catch(() => {});
  expect(await markedPixels(page)).toBe(0);
});

test('browser: <cone-flipbook outline="..."> gives its book the outline from JSON; a bad JSON is an error naming the attribute', async ({ page }) => {
  await openReady(page, '/tests/browser/fixtures/pdf-fixture.html');
  const result = await page.evaluate(async () => {
    const pages = ['/tests/browser/references/curl-t0-00.png', '/tests/browser/references/curl-t0-00.png?b'];
    const element = document.createElement('cone-flipbook');
    element.setAttribute('pages', pages.join(' '));
    element.setAttribute('outline', '[{"title": "Second", "page": 1}]');
    element.setAttribute('download', '/files/x.pdf');
    element.style.cssText = 'display:block;width:400px;height:300px';
    document.body.append(element);
    const book = await element.whenReady();
    const outline = await book.outline();
    const download = book.options.download;
    element.remove();
    const bad = document.createElement('cone-flipbook');
    bad.setAttribute('pages', pages.join(' '));
    bad.setAttribute('outline', '[{title: Second}]');
    const failed = new Promise((resolve) => bad.addEventListener('error', (e) => resolve(e.detail.error.message), { once: true }));
    document.body.append(bad);
    const message = await failed;
    bad.remove();
    return { outline, download, message };
  });
  expect(result.outline).toEqual([{ title: 'Second', page: 1, children: [] }]);
  expect(result.download).toBe('/files/x.pdf');
  expect(result.message).toMatch(/attribute 'outline' must be JSON/);
});

test('browser: on a StaticBook (2D canvas) with HTML pages, showHit() lays its data-search-hit mark over the word on the live page', async ({ page }) => {
  await openReady(page, '/tests/browser/fixtures/html-fixture.html');
  const result = await page.evaluate(async () => {
    const make = window.makeTextPage;
    const pages = [make('Cover'), make('First'), make('Second'), make('Where the heron stands'), make('Last')];
    window.book = await window.StaticBook.create(window.container, { pages, display: 'double' });
    await window.book.whenIdle();
    const hits = await window.book.search('HERON');
    await window.book.showHit(hits[0]);
    const mark = window.book.element.querySelector('[data-search-hit][data-current]');
    const p = pages[3].querySelector('p');
    const range = document.createRange();
    range.setStart(p.firstChild, 10);
    range.setEnd(p.firstChild, 15);
    const word = range.getBoundingClientRect();
    const box = mark.getBoundingClientRect();
    return { pages: hits.map((h) => h.page), open: window.book.openPages, markPage: mark.dataset.page, kind: window.book.surface.kind,
      word: [word.left, word.top, word.width, word.height], box: [box.left, box.top, box.width, box.height] };
  });
  expect(result.kind).toBe('canvas');
  expect(result.pages).toEqual([3]);
  expect(result.open).toContain(3);
  expect(result.markPage).toBe('3');
  result.box.forEach((v, i) => expect(Math.abs(v - result.word[i])).toBeLessThan(1.5));
});
