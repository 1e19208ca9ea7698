// Node tests of `conecurl publish` on the document fixture (tests/fixtures/document-pdf.mjs): the site's
// files, that the page images show the page (pixels, not exit codes: pdf.js on Node 20 can draw blank
// pages), that book.json and the text files hold what pdf.js reads from the same PDF, links, index.html.
// They need pdfjs-dist and @napi-rs/canvas installed, and dist/ built.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { documentOptions, loadCanvas, loadPdfjs } from '../../cli/publish/pdfjs-node.mjs';
import { runtimeFiles } from '../../cli/publish/runtime-files.mjs';
import { DESCRIPTION_CHARS, describe } from '../../cli/publish/index-html.mjs';
import { checkManifest, decodePageText } from '../../web/src/document/format.js';
import { pdfOutline, pdfPageText } from '../../web/src/document/pdf-document.js';
import { BOOKMARKS, PAGES, PAGE_SIZE, lineAt, makeDocumentPdf } from '../fixtures/document-pdf.mjs';
import { LINKS, makeLinkPdf } from '../fixtures/publish-pdfs.mjs';
import { publish, readJson, root, tempDir } from './publish-run.mjs';
import { PLACEHOLDER } from '../../cli/publish/render-page.mjs';

const HEIGHT = 400;

async function documentSite(t, extra = []) {
  const dir = tempDir(t);
  const pdf = path.join(dir, 'animals.pdf');
  const bytes = Buffer.from((await makeDocumentPdf()).base64, 'base64');
  fs.writeFileSync(pdf, bytes);
  const out = path.join(dir, 'site');
  const run = await publish([pdf, '--out', out, '--height', String(HEIGHT), '--jobs', '2', ...extra]);
  assert.equal(run.code, 0, run.stderr);
  return { dir, pdf, bytes, out, run, book: path.join(out, 'book'), manifest: readJson(path.join(out, 'book/book.json')) };
}

/** Dark pixels of an image file inside [x0, x1) x [y0, y1) (fractions of its size), and of all of it. */
async function darkPixels(file, [x0, y0, x1, y1] = [0, 0, 1, 1]) {
  const { createCanvas, loadImage } = loadCanvas();
  const image = await loadImage(fs.readFileSync(file));
  const canvas = createCanvas(image.width, image.height);
  const context = canvas.getContext('2d');
  context.drawImage(image, 0, 0);
  const { data } = context.getImageData(0, 0, image.width, image.height);
  let inside = 0;
  let all = 0;
  for (let y = 0; y < image.height; y++) {
    for (let x = 0; x < image.width; x++) {
      const at = (y * image.width + x) * 4;
      if (data[at] > 100 || data[at + 1] > 100 || data[at + 2] > 100) continue;
      all += 1;
      if (x >= x0 * image.width && x < x1 * image.width && y >= y0 * image.height && y < y1 * image.height) inside += 1;
    }
  }
  return { inside, all, width: image.width, height: image.height };
}

test('node: conecurl publish writes every page\'s image, zoom image, thumbnail and text file, the cover, the PDF and the reader (needs pdfjs-dist, @napi-rs/canvas, dist/)', async (t) => {
  const { out, book, manifest, run } = await documentSite(t);
  assert.equal(manifest.pageCount, PAGES.length);
  for (let i = 0; i < PAGES.length; i++) {
    const n = String(i + 1).padStart(4, '0');
    for (const [file, max] of [[`pages/${n}.webp`, 200_000], [`zoom/${n}.webp`, 600_000], [`thumbs/${n}.webp`, 40_000], [`text/${n}.json`, 20_000]]) {
      const size = fs.statSync(path.join(book, file)).size;
      assert.ok(size > 100 && size < max, `${file}: ${size} bytes`);
    }
  }
  assert.ok(fs.statSync(path.join(book, 'cover.jpg')).size > 1000);
  assert.deepEqual(fs.readFileSync(path.join(book, 'animals.pdf')), fs.readFileSync(path.join(path.dirname(out), 'animals.pdf')));
  assert.equal(manifest.download, 'animals.pdf');
  // The reader is the bundle as built (dist/reader/), copied byte for byte, flat under conecurl/.
  const reader = runtimeFiles(root);
  assert.deepEqual(fs.readdirSync(path.join(out, 'conecurl')).sort(), reader.files);
  for (const file of reader.files) assert.ok(fs.readFileSync(path.join(out, 'conecurl', file)).equals(fs.readFileSync(path.join(reader.dir, file))), file);
  assert.match(run.stdout, /Published 8 of 8 pages .*pages\/s/);
  assert.match(run.stdout, /python3 -m http\.server -d /);
});

test('node: conecurl publish page images show the page: ink where the fixture drew the heading, white elsewhere (needs pdfjs-dist, @napi-rs/canvas)', async (t) => {
  const { book } = await documentSite(t);
  const heading = lineAt(1, -1);
  const [w, h] = PAGE_SIZE;
  // The heading's box, from its baseline up by its size, as fractions of the page.
  const box = [heading.x / w, (heading.baseline - heading.size) / h, 0.9, (heading.baseline + 4) / h];
  const reading = await darkPixels(path.join(book, 'pages/0002.webp'), box);
  assert.equal(reading.height, HEIGHT);
  assert.equal(reading.width, Math.round(HEIGHT * w / h));
  assert.ok(reading.inside > 200, `${reading.inside} dark pixels in the heading's box`);
  assert.ok(reading.all < reading.width * reading.height * 0.1, `${reading.all} dark pixels in all: the background is white`);
  const zoom = await darkPixels(path.join(book, 'zoom/0002.webp'), box);
  assert.equal(zoom.height, HEIGHT * 2, 'the zoom image is twice the reading one by default');
  assert.ok(zoom.inside > reading.inside * 3, 'the zoom image has the heading, sharper');
  const thumb = await darkPixels(path.join(book, 'thumbs/0002.webp'));
  assert.equal(thumb.width, 240);
  assert.ok(thumb.all > 20, 'the thumbnail is not blank');
  // The space below the last body line of the page is blank paper.
  const below = await darkPixels(path.join(book, 'pages/0002.webp'), [0, (lineAt(1, 3).baseline + 10) / h, 1, 0.9]);
  assert.equal(below.inside, 0);
});

test('node: conecurl publish gives the first page an inline placeholder in book.json (a data: URL of a WebP 128 px wide, a few KB, showing the page\'s heading) and no other page one; checkManifest passes (needs pdfjs-dist, @napi-rs/canvas)', async (t) => {
  const { dir, manifest } = await documentSite(t);
  checkManifest(manifest, 'book.json');
  const [first, ...others] = manifest.pages;
  const match = /^data:image\/webp;base64,([A-Za-z0-9+/=]+)$/.exec(first.placeholder ?? '');
  assert.ok(match, `page 1's placeholder is an inline WebP: ${String(first.placeholder).slice(0, 40)}`);
  const bytes = Buffer.from(match[1], 'base64');
  assert.equal(bytes.subarray(8, 12).toString('latin1'), 'WEBP');
  assert.ok(bytes.length > 100 && bytes.length < 6000, `${bytes.length} bytes`);
  for (const page of others) assert.equal(page.placeholder, undefined, 'only the first spread is inlined (the reader draws the others\' thumbnails)');
  // It shows the page: dark pixels where the heading is, the rest paper.
  const file = path.join(dir, 'placeholder.webp');
  fs.writeFileSync(file, bytes);
  const heading = lineAt(0, -1);
  const [w, h] = PAGE_SIZE;
  const { createCanvas, loadImage } = loadCanvas();
  const image = await loadImage(fs.readFileSync(file));
  assert.equal(image.width, PLACEHOLDER.width);
  assert.equal(image.height, Math.round(PLACEHOLDER.width * h / w));
  const canvas = createCanvas(image.width, image.height);
  canvas.getContext('2d').drawImage(image, 0, 0);
  const { data } = canvas.getContext('2d').getImageData(0, 0, image.width, image.height);
  const darkest = (y0, y1) => {
    let min = 255;
    for (let y = Math.floor(y0 * image.height); y < Math.ceil(y1 * image.height); y++) {
      for (let x = 0; x < image.width; x++) min = Math.min(min, data[(y * image.width + x) * 4]);
    }
    return min;
  };
  assert.ok(darkest((heading.baseline - heading.size) / h, (heading.baseline + 4) / h) < 160, 'ink in the heading\'s band');
  assert.ok(darkest(0, (heading.baseline - heading.size - 12) / h) > 230, 'paper above it');
});

test('node: conecurl publish text files, outline and manifest hold what pdf.js reads from the same PDF, and checkManifest passes', async (t) => {
  const { bytes, book, manifest } = await documentSite(t);
  checkManifest(manifest, 'book.json');
  const pdfjs = await loadPdfjs();
  // The PDF as a browser's pdf.js reads it (the standard fonts by their metrics: useSystemFonts, its default there).
  const doc = await pdfjs.getDocument({ ...documentOptions(new Uint8Array(bytes)), useSystemFonts: true }).promise;
  t.after(() => doc.loadingTask.destroy());
  const strip = (entries) => entries.map(({ title, page, children }) => ({ title, page, children: strip(children ?? []) }));
  assert.deepEqual(manifest.outline, await pdfOutline(doc));
  assert.deepEqual(strip(manifest.outline), strip(BOOKMARKS));
  const round = (v) => Math.round(v * 100) / 100;
  for (let i = 0; i < PAGES.length; i++) {
    const page = manifest.pages[i];
    assert.deepEqual([page.width, page.height], PAGE_SIZE);
    const file = path.join(book, page.text);
    const published = decodePageText(readJson(file), file);
    const expected = await pdfPageText(await doc.getPage(i + 1));
    assert.equal(published.text, expected.text);
    assert.match(published.text, new RegExp(PAGES[i].heading.replace(/[.*+?^${}()|[\]\\]/g, '\\$&')));
    assert.deepEqual(published.items.map((item) => [item.start, item.end, item.str]), expected.items.map((item) => [item.start, item.end, item.str]));
    published.items.forEach((item, k) => {
      assert.deepEqual(item.tx, expected.items[k].tx.map(round), `page ${i + 1} item ${k}`);
      assert.deepEqual([item.family, item.ascent, item.descent], [expected.items[k].family, round(expected.items[k].ascent), round(expected.items[k].descent)]);
    });
    assert.equal(page.alt, undefined, 'no alt: the reader takes it from the text file');
  }
  assert.equal(manifest.title, 'animals', 'the file name, as the PDF has no Title');
});

test('node: conecurl publish keeps a page\'s web link and page link as rectangles of the page', async (t) => {
  const dir = tempDir(t);
  fs.writeFileSync(path.join(dir, 'links.pdf'), await makeLinkPdf());
  const run = await publish([path.join(dir, 'links.pdf'), '--out', path.join(dir, 'site'), '--height', '200', '--zoom', '0', '--no-download']);
  assert.equal(run.code, 0, run.stderr);
  const manifest = readJson(path.join(dir, 'site/book/book.json'));
  const [web, inner] = manifest.pages[0].links;
  assert.equal(web.href, LINKS.href);
  const [x1, y1, x2, y2] = LINKS.rect;
  [x1 / 400, 1 - y2 / 500, (x2 - x1) / 400, (y2 - y1) / 500].forEach((v, k) => assert.ok(Math.abs(web.rect[k] - v) < 1e-6, `rect[${k}]`));
  assert.equal(inner.page, LINKS.toPage);
  assert.equal(manifest.download, null);
  assert.ok(!fs.readdirSync(path.join(dir, 'site/book')).some((f) => f.endsWith('.pdf')), '--no-download leaves the PDF out');
  assert.ok(!fs.existsSync(path.join(dir, 'site/book/zoom')), '--zoom 0 writes no zoom images');
  assert.equal(manifest.pages[0].zoomSrc, undefined);
});

test('node: conecurl publish index.html holds the reader contract, preloads, Open Graph and an escaped noscript copy', async (t) => {
  const { out, manifest } = await documentSite(t, ['--title', 'Cats & <Dogs> "quoted"', '--url', 'https://example.com/b']);
  const html = fs.readFileSync(path.join(out, 'index.html'), 'utf8');
  assert.match(html, /^<!doctype html>\n<html lang="en">/);
  assert.match(html, /<meta name="viewport" content="width=device-width, initial-scale=1, viewport-fit=cover">/);
  assert.match(html, /<title>Cats &amp; &lt;Dogs&gt; &quot;quoted&quot;<\/title>/);
  // The description (search results, link previews): the first pages' words, the second page's where the first's run out.
  const description = /<meta name="description" content="([^"]*)">/.exec(html)?.[1];
  assert.match(description ?? '', /^Contents A book about animals and drinks\. Read it in any order\. .*Chapter One: Zebras/);
  assert.ok(description.length <= DESCRIPTION_CHARS + 1, description);
  assert.ok(html.includes(`<meta property="og:description" content="${description}">`));
  assert.ok(!html.includes('<Dogs>'), 'the title is escaped everywhere');
  assert.match(html, /<meta property="og:image" content="https:\/\/example\.com\/b\/book\/cover\.jpg">/);
  assert.match(html, /<meta property="og:url" content="https:\/\/example\.com\/b\/">/);
  assert.match(html, /<main id="conecurl-reader" data-document="book\/book\.json">/);
  assert.match(html, /<link rel="preload" href="book\/book\.json" as="fetch" crossorigin>/);
  assert.ok(!/<link rel="preload" href="book\/pages\//.test(html), 'no page image preloaded (see index-html.mjs)');
  const reader = runtimeFiles(root);
  assert.match(html, new RegExp(`<link rel="preload" href="conecurl/${reader.wasm}" as="fetch" crossorigin>`));
  assert.match(reader.wasm, /^conecurl-engine-[\w-]{8}\.wasm$/, 'the engine\'s binary has a hashed name');
  assert.match(html, /<link rel="icon" href="data:,">/);
  // The reader's CSS in the page itself (no style sheet to wait for before the first paint).
  assert.ok(html.includes(`<style>\n${reader.style.trim()}\n</style>`) && reader.style.includes('#conecurl-reader'));
  assert.ok(!/<link rel="stylesheet"/.test(html));
  assert.match(html, new RegExp(`<script type="module" src="conecurl/${reader.entry}"></script>`));
  // Preloaded: the chunks the entry imports, as the bundler's output says (bundle.json), each in the site.
  const preloaded = [...html.matchAll(/<link rel="modulepreload" href="conecurl\/([^"]+)">/g)].map((m) => m[1]);
  assert.deepEqual(preloaded, reader.preload);
  for (const file of preloaded) assert.ok(fs.existsSync(path.join(out, 'conecurl', file)), file);
  const images = [...html.matchAll(/<img src="book\/pages\/(\d{4})\.webp" width="(\d+)" height="(\d+)" loading="lazy" alt="([^"]*)">/g)];
  assert.equal(images.length, PAGES.length);
  assert.match(images[1][4], /^Page 2: Chapter One: Zebras The zebra has stripes\./);
  assert.match(html, /The zebra has stripes\./);
  assert.equal(manifest.title, 'Cats & <Dogs> "quoted"');
});

test('node: the published page\'s description is its first words, cut at a word, escaped by its caller; a book without text gets its title and page count', () => {
  const long = Array.from({ length: 60 }, (_, i) => `word${i}`).join(' ');
  const cut = describe('T', [{ text: long }]);
  assert.ok(cut.length <= DESCRIPTION_CHARS + 1 && cut.endsWith('…') && long.startsWith(cut.slice(0, -1)), cut);
  assert.equal(describe('T', [{ text: '  Title\n page ' }, { failed: 'x' }, { text: 'Two.' }]), 'Title page Two.');
  assert.equal(describe('Photos', [{ text: '' }, { text: ' ' }, { failed: 'x' }]), 'Photos: 3 pages');
  assert.equal(describe('One', [{ text: '' }]), 'One: 1 page');
});

