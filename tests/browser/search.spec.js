// Browser: the book's document API over a real PDF (tests/browser/document-pdf.js: fonts, headings,
// bookmarks by explicit and named destinations) and over HTML pages: outline() is pdf.js's outline with
// destinations resolved, search() finds exactly the pages whose pdf.js text holds a word (case and
// diacritics folded), aborts, and its hits' rectangles lie over the word's glyphs; showHit() turns
// there and marks the hit, flat (data-search-hit elements) and curling (in the page's texture).
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';
import { BOOKMARKS, PAGES, PAGE_SIZE, lineAt, makeDocumentPdf } from './document-pdf.js';

let made;
test.beforeAll(async () => { made = await makeDocumentPdf(); });

/** Opens the fixture with a book of the test PDF in `window.book` (extra options merged). */
async function openPdfBook(page, options = {}) {
  await openReady(page, '/tests/browser/fixtures/pdf-fixture.html');
  await page.evaluate(async ({ base64, options }) => {
    window.pdfBytes = window.bytesFromBase64(base64);
    window.book = await window.Flipbook.create(window.container, {
      pdf: window.pdfBytes, display: 'double', duration: 300, lighting: false, shadows: false, gutter: false, ...options,
    });
    await window.book.whenIdle();
    // pdf.js itself, as the page has it, to compare with: the same module the book imported.
    window.pdfjs = await import('pdfjs-dist');
    window.refDoc = await window.pdfjs.getDocument({ data: window.pdfBytes.slice() }).promise;
  }, { base64: made.base64, options });
}

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
