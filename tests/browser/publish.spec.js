// Browser: the site `conecurl publish` writes (cli/), served as a static folder: its reader page opens
// the book and turns it with no request for pdf.js; search marks the same words with the same rectangles
// as the same PDF opened through pdf.js; the text layer selects; outline() and the Contents panel go
// where pdf.js says; thumbnails come from the thumbnail images. And the package's reader.html#file=.
import { test, expect } from '@playwright/test';
import { READER_ENTRY } from '../node/publish-run.mjs';
import { runtimeFiles } from '../../cli/publish/runtime-files.mjs';
import { execFileSync } from 'node:child_process';
import { mkdirSync, rmSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { BOOKMARKS, PAGES, makeDocumentPdf, openPdfBook } from './document-pdf.js';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const SITES = path.join(root, 'build/test-sites');
// A name of its own per worker: two workers never publish into the same folder.
const siteName = () => `document-${test.info().workerIndex}`;
const siteUrl = (name) => `/build/test-sites/${name}/`;

let made;
test.beforeAll(async () => {
  made = await makeDocumentPdf();
  const name = siteName();
  mkdirSync(SITES, { recursive: true });
  const pdf = path.join(SITES, `${name}.pdf`);
  writeFileSync(pdf, Buffer.from(made.base64, 'base64'));
  rmSync(path.join(SITES, name), { recursive: true, force: true });  // this test's own folder, from an earlier run
  execFileSync(process.execPath, [path.join(root, 'cli/conecurl.mjs'), 'publish', pdf, '--out', path.join(SITES, name),
    '--height', '800', '--title', 'The document test'], { stdio: 'pipe' });
});

const flat = (entries) => entries.flatMap((e) => [{ title: e.title, page: e.page }, ...flat(e.children ?? [])]);

/** Opens the published site's index.html; `window.book` is its book once open. Returns every URL requested. */
async function openSite(page, hash = '') {
  const requests = [];
  page.on('request', (request) => requests.push(request.url()));
  const problems = [];
  page.on('pageerror', (error) => problems.push(error.message));
  await page.goto(`${siteUrl(siteName())}index.html${hash}`);
  await page.evaluate(async (url) => {
    window.book = await (await import(document.querySelector(url).src)).book;
    await window.book.whenIdle();
  }, READER_ENTRY);
  expect(problems).toEqual([]);
  return requests;
}

test('browser: the published site opens its book filling the screen, turns, and never asks for pdf.js', async ({ page }) => {
  const requests = await openSite(page);
  const beforeReady = [...requests];  // until the first spread was drawn
  const state = await page.evaluate(() => ({
    count: window.book.pageCount, label: window.book.options.label, title: document.title,
    box: (({ width, height }) => ({ width, height }))(document.getElementById('conecurl-reader').getBoundingClientRect()),
    screen: { width: innerWidth, height: innerHeight },
    toolbar: Boolean(document.querySelector('[role="toolbar"]')),
  }));
  expect(state.count).toBe(8);
  expect(state.label).toBe('The document test');
  expect(state.title).toBe('The document test');
  expect(state.box).toEqual(state.screen);
  expect(state.toolbar).toBe(true);
  const turned = await page.evaluate(() => new Promise((resolve) => {
    window.book.addEventListener('turned', (e) => resolve(e.detail.page), { once: true });
    window.book.next();
  }));
  expect(turned).toBeGreaterThan(0);
  await page.evaluate(() => window.book.search('zebra'));
  await page.evaluate(() => window.book.outline());
  const pdfjs = requests.filter((url) => /pdfjs|pdf\.worker|pdf\.min|\.pdf$/.test(url));
  expect(pdfjs).toEqual([]);
  // The page images are the reading-size ones; the modules come from the site's own conecurl/ folder.
  expect(requests.some((url) => url.includes('/book/pages/0001.'))).toBe(true);
  expect(requests.filter((url) => url.includes('/node_modules/'))).toEqual([]);
  // What index.html asks for is what the book needs, each fetched once: the reader's first chunks (as
  // the bundler listed them), the manifest, the engine, page 1; no other script comes before the first
  // spread but the lazy chunks the reader imports on its way (requests counted: the bundle's point).
  const site = siteUrl(siteName());
  const fetched = (file) => beforeReady.filter((url) => new URL(url).pathname === `${site}${file}`).length;
  const reader = runtimeFiles(root);
  for (const file of [reader.entry, ...reader.preload, reader.wasm]) expect(fetched(`conecurl/${file}`), file).toBe(1);
  for (const file of ['book/book.json', 'book/pages/0001.webp']) expect(fetched(file), file).toBe(1);
  const html = await (await page.request.get(`${site}index.html`)).text();
  const preloaded = [...html.matchAll(/<link rel="modulepreload" href="conecurl\/([^"]+)">/g)].map((m) => m[1]);
  expect(preloaded).toEqual(reader.preload);
  const scripts = beforeReady.filter((url) => new URL(url).pathname.endsWith('.js')).map((url) => new URL(url).pathname.slice(site.length));
  expect(scripts.every((file) => file.startsWith('conecurl/') && reader.files.includes(file.slice('conecurl/'.length))), scripts.join(', ')).toBe(true);
  await page.screenshot({ path: test.info().outputPath('published-site.png') });
});

test('browser: search in the published site finds the same hits, with the same rectangles, as the PDF through pdf.js', async ({ page, browser }) => {
  await openSite(page);
  const words = ['zebra', 'CAFE', 'naïve', 'coffee comes', 'Chapter One', 'nowhere'];
  const published = await page.evaluate(async (words) => {
    const out = {};
    for (const word of words) out[word] = await window.book.search(word);
    return out;
  }, words);
  const other = await browser.newPage();
  await openPdfBook(other, made);
  const fromPdf = await other.evaluate(async (words) => {
    const out = {};
    for (const word of words) out[word] = await window.book.search(word);
    return out;
  }, words);
  await other.close();
  for (const word of words) {
    const a = published[word];
    const b = fromPdf[word];
    expect(a.map((h) => [h.page, h.snippet]), word).toEqual(b.map((h) => [h.page, h.snippet]));
    a.forEach((hit, i) => {
      expect(hit.rects.length, word).toBe(b[i].rects.length);
      // The text file keeps positions to 1/100 of a PDF unit: the same rectangles to well under a pixel.
      hit.rects.forEach((rect, k) => rect.forEach((v, j) => expect(Math.abs(v - b[i].rects[k][j]), `${word} rect ${k}`).toBeLessThan(0.002)));
    });
  }
  expect(published.zebra.map((h) => h.page)).toEqual([1, 1, 4]);
  // The mark shows over the word once shown.
  await page.evaluate(async () => window.book.showHit((await window.book.search('coffee'))[0]));
  await expect(page.locator('[data-search-hit]').first()).toBeVisible();
});

test('browser: the published site reads the book\'s text for search a text group a request, not a file a page; a page whose own text file cannot be read takes its text from its group (counts requests; no service worker, which would answer the requests out of the routes\' sight)', async ({ browser }) => {
  const context = await browser.newContext({ serviceWorkers: 'block' });
  const page = await context.newPage();
  const requests = await openSite(page);
  await page.evaluate(() => window.book.search('zebra'));  // every page read: the background's, or the search's own
  const texts = () => requests.map((url) => new URL(url).pathname).filter((file) => file.includes('/book/text/'));
  const own = texts().filter((file) => /\/text\/\d{4}\.json$/.test(file));
  const groups = texts().filter((file) => /\/text\/pages-\d{4}-\d{4}\.json$/.test(file));
  expect(groups.map((file) => file.split('/').pop())).toEqual(['pages-0001-0008.json']);  // 8 pages: one group
  // The pages' own files: only those the text layer read for the pages shown (the first spread's).
  expect(own.length).toBeLessThanOrEqual(2);
  // The document alone, a page's own file refused: its text comes from the group, and the other pages' with it.
  const site = siteUrl(siteName());
  await page.route(`**${site}book/text/0003.json`, (route) => route.abort());
  const read = await page.evaluate(async (url) => {
    const { openPublished } = await import('/web/src/document/published-document.js');
    const doc = await openPublished(url);
    const third = await doc.pageText(2);
    const fourth = await doc.pageText(3);
    return { third: third.text, fourth: fourth.text, items: third.items.length };  // a record, as its own file's
  }, `${site}book/book.json`);
  expect(read.third).toContain(PAGES[2].heading);
  expect(read.fourth).toContain(PAGES[3].heading);
  expect(read.items).toBeGreaterThan(0);
  const after = texts().slice(own.length + groups.length);
  expect(after.map((file) => file.split('/').pop())).toEqual(['0003.json', 'pages-0001-0008.json']);  // page 4's from the group too
  await context.close();
});

test('browser: the published text layer lies over the words and a mouse drag selects a line without turning', async ({ page }) => {
  await openSite(page, '#page=2');
  await page.waitForFunction(() => document.querySelectorAll('[data-text-layer] span').length > 0);
  const layer = await page.evaluate(() => [...document.querySelectorAll('[data-text-layer]')].map((el) => ({
    page: Number(el.dataset.page), text: [...el.querySelectorAll('span')].map((s) => s.textContent).join('|'),
  })));
  const open = await page.evaluate(() => window.book.openPages);
  expect(layer.map((l) => l.page)).toEqual(open);
  const second = layer.find((l) => l.page === 1);
  expect(second.text).toContain('Chapter One: Zebras|The zebra has stripes.');
  const span = page.locator('[data-text-layer][data-page="1"] span', { hasText: 'The zebra has stripes.' });
  const box = await span.boundingBox();
  const pageBefore = await page.evaluate(() => window.book.page);
  const y = box.y + box.height / 2;
  await page.mouse.move(box.x + 1, y);
  await page.mouse.down();
  for (let i = 1; i <= 10; i++) await page.mouse.move(box.x + 1 + (box.width - 2) * (i / 10), y);
  await page.mouse.up();
  const after = await page.evaluate(() => ({ selected: window.getSelection().toString(), page: window.book.page, animating: window.book.animating }));
  expect(after.selected).toContain('zebra has stripes');
  expect(after.page).toBe(pageBefore);
  expect(after.animating).toBe(false);
});

test('browser: the published outline is pdf.js\'s, and a Contents entry opens its page; thumbnails come from the thumbnail images', async ({ page }) => {
  const requests = await openSite(page);
  const outline = await page.evaluate(() => window.book.outline());
  expect(flat(outline)).toEqual(flat(BOOKMARKS));
  await page.getByRole('toolbar').getByRole('button', { name: 'Contents' }).click();
  const panel = page.getByRole('dialog', { name: 'Contents' });
  await expect(panel.locator('.conecurl-tree button')).toHaveCount(flat(BOOKMARKS).length);
  const target = flat(BOOKMARKS).find((entry) => entry.title === 'Section 2.1');
  await page.evaluate(() => { window.turnedTo = new Promise((resolve) => window.book.addEventListener('turned', (e) => resolve(e.detail.page), { once: true })); });
  await panel.getByRole('button', { name: 'Section 2.1' }).click();
  await page.evaluate(() => window.turnedTo);
  expect(await page.evaluate(() => window.book.openPages)).toContain(target.page);
  const thumb = await page.evaluate(async () => {
    const canvas = await window.book.pageThumbnail(5, { width: 120 });
    return { width: canvas.width, height: canvas.height };
  });
  expect(thumb.width).toBe(120);
  expect(requests.some((url) => url.includes('/book/thumbs/0006.'))).toBe(true);
  // Download fetches the PDF published beside the pages.
  const download = await page.evaluate(() => new Promise((resolve) => {
    window.book.addEventListener('download', (e) => { e.preventDefault(); resolve(e.detail.url); }, { once: true });
    window.book.download();
  }));
  expect(download).toMatch(/\/book\/[^/]+\.pdf$/);
});

test('browser: the published site draws its first page at once from the placeholder inlined in book.json (no request of its own), then the reading image over it; the next pages take their thumbnails as placeholders (texture uploads in order, reading images held back)', async ({ page }) => {
  await page.addInitScript(() => {
    const upload = WebGL2RenderingContext.prototype.texImage2D;
    WebGL2RenderingContext.prototype.texImage2D = function recorded(...args) {
      const source = args.length === 6 ? args[5] : null;
      if (source && source.width > 1) (window.uploads ??= []).push(source.width);  // page images, not the renderer's own
      return upload.apply(this, args);
    };
  });
  let release;
  const held = new Promise((resolve) => { release = resolve; });
  await page.route('**/book/pages/*.webp', async (route) => { await held; await route.continue(); });
  const images = [];
  page.on('request', (request) => { if (/\/book\/(pages|thumbs)\//.test(request.url())) images.push(new URL(request.url()).pathname.split('/book/')[1]); });
  await page.goto(`${siteUrl(siteName())}index.html`);
  await page.waitForFunction(() => (window.uploads ?? []).includes(128));  // the cover's placeholder is drawn
  expect(images).toEqual(['pages/0001.webp']);  // held: the placeholder came with book.json
  release();
  await page.evaluate(async (url) => {
    window.book = await (await import(document.querySelector(url).src)).book;
    await window.book.whenIdle();
  }, READER_ENTRY);
  const uploads = await page.evaluate(() => window.uploads);
  expect(uploads[0]).toBe(128);
  expect(uploads[1]).toBeGreaterThan(256);  // the reading image, over it
  expect(images).toContain('thumbs/0002.webp');  // the next page's placeholder
});

test('browser: a bad document is refused with an error naming the file; a page that was not published shows its placeholder', async ({ page }) => {
  await page.goto('/tests/browser/fixtures/flipbook-fixture.html');
  await page.waitForFunction(() => document.body.dataset.ready || document.body.dataset.error);
  const errors = await page.evaluate(async (base) => {
    const out = [];
    for (const url of [`${base}missing/book.json`, `${base}index.html`]) {
      try {
        await window.Flipbook.create(window.container, { document: url });
        out.push('opened');
      } catch (error) {
        out.push(error.message);
      }
    }
    return out;
  }, siteUrl(siteName()));
  expect(errors[0]).toMatch(/could not fetch the document .*missing\/book\.json.*404/);
  expect(errors[1]).toMatch(/index\.html is not JSON/);
  // A manifest whose page 3 failed to draw when published: that page is a placeholder and a pageerror.
  const manifest = await (await page.request.get(`${siteUrl(siteName())}book/book.json`)).json();
  manifest.pages[2] = { width: manifest.pages[2].width, height: manifest.pages[2].height, failed: 'the page could not be drawn' };
  await page.route('**/book/edited.json', (route) => route.fulfill({ json: manifest }));  // beside book.json: its paths hold
  const failed = await page.evaluate(async (base) => {
    let heard;
    const third = new Promise((resolve) => { heard = resolve; });
    const book = await window.Flipbook.create(window.container, {
      document: `${base}book/edited.json`, startPage: 2, display: 'single',
      on: { pageerror: (e) => { if (e.detail.index === 2) heard(e.detail); } },
    });
    const error = await third;  // the event that says the page failed
    return { index: error.index, message: String(error.error?.message ?? ''), state: book.pageState(2).state, count: book.pageCount };
  }, siteUrl(siteName()));
  expect(failed.count).toBe(8);
  expect(failed.state).toBe('failed');
  expect(failed.message).toMatch(/page 3 was not published/);
});

test('browser: reader.html#file= opens a PDF at run time with the toolbar', async ({ page }) => {
  const name = `${siteName()}.pdf`;
  await page.goto(`/web/reader/reader.html#file=/build/test-sites/${name}`);
  await page.waitForFunction(async () => {
    const { book } = await import('/web/reader/reader.js');
    return Boolean(await book);
  });
  const state = await page.evaluate(async () => {
    const book = await (await import('/web/reader/reader.js')).book;
    await book.whenIdle();
    return { count: book.pageCount, title: document.title, toolbar: Boolean(document.querySelector('[role="toolbar"]')), hash: location.hash };
  });
  expect(state).toEqual({ count: 8, title: name, toolbar: true, hash: `#file=/build/test-sites/${name}` });
  // Without a file the page says what to do.
  await page.goto('/web/reader/reader.html');
  await expect(page.getByRole('alert')).toContainText('reader.html#file=');
});

test('browser: the bundled reader.html#file= (dist/reader/, made by build-bundles.mjs) opens a PDF at run time with the toolbar, its code from the bundle and pdf.js through its import map (needs dist/)', async ({ page }) => {
  const name = `${siteName()}.pdf`;
  const scripts = [];
  page.on('request', (request) => { if (request.resourceType() === 'script') scripts.push(new URL(request.url()).pathname); });
  await page.goto(`/dist/reader/reader.html#file=/build/test-sites/${name}`);
  const state = await page.evaluate(async () => {
    const book = await (await import(document.querySelector('script[type="module"][src]').src)).book;
    await book.whenIdle();
    return { count: book.pageCount, title: document.title, toolbar: Boolean(document.querySelector('[role="toolbar"]')), shown: book.openPages.map((i) => book.pageState(i).state) };
  });
  expect(state).toEqual({ count: 8, title: name, toolbar: true, shown: ['loaded'] });
  // The book's code came from dist/reader/ (none of web/src's modules), pdf.js from node_modules.
  expect(scripts.filter((file) => file.startsWith('/web/'))).toEqual([]);
  expect(scripts.some((file) => /^\/dist\/reader\/pdf-[\w-]+\.js$/.test(file))).toBe(true);
  expect(scripts.some((file) => file.startsWith('/node_modules/pdfjs-dist/'))).toBe(true);
});
