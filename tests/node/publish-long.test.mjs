// Node test of `conecurl publish` on a 300-page book (tests/fixtures/publish-pdfs.mjs), small images so
// that it stays quick: every page's files, its text groups, the bookmarks, and progress lines when stdout
// is not a terminal.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { TEXT_GROUP_PAGES, checkManifest, checkTextGroup, decodePageText } from '../../web/src/document/format.js';
import { LONG_CHAPTER, makeLongPdf } from '../fixtures/publish-pdfs.mjs';
import { publish, readJson, tempDir } from './publish-run.mjs';

test('node: conecurl publish of a 300-page book writes every page\'s image, thumbnail and text, one bookmark a chapter, and a progress line each 10% (needs pdfjs-dist, @napi-rs/canvas)', async (t) => {
  const dir = tempDir(t);
  const pdf = path.join(dir, 'long.pdf');
  fs.writeFileSync(pdf, await makeLongPdf(300));
  const out = path.join(dir, 'site');
  const run = await publish([pdf, '--out', out, '--height', '200', '--zoom', '0']);
  assert.equal(run.code, 0, run.stderr);
  const manifest = checkManifest(readJson(path.join(out, 'book/book.json')), 'book.json');
  assert.equal(manifest.pageCount, 300);
  assert.equal(manifest.title, 'A Long Book');
  manifest.pages.forEach((page, i) => {
    for (const file of [page.src, page.thumbSrc, page.text]) {
      assert.ok(fs.statSync(path.join(out, 'book', file)).size > 50, `page ${i + 1}: ${file}`);
    }
    const where = path.join(out, 'book', page.text);
    assert.match(decodePageText(readJson(where), where).text, new RegExp(`^Page ${i + 1}\\b`));
  });
  // The text groups: every page once, in order, TEXT_GROUP_PAGES a file, each page's record as its own file's.
  assert.deepEqual(manifest.textGroups.map(({ first, count }) => [first, count]),
    Array.from({ length: Math.ceil(300 / TEXT_GROUP_PAGES) }, (_, k) => [k * TEXT_GROUP_PAGES, Math.min(TEXT_GROUP_PAGES, 300 - k * TEXT_GROUP_PAGES)]));
  assert.equal(manifest.textGroups[0].src, `text/pages-0001-${String(TEXT_GROUP_PAGES).padStart(4, '0')}.json`);
  for (const group of manifest.textGroups) {
    const where = path.join(out, 'book', group.src);
    checkTextGroup(readJson(where), where, group).forEach((page, k) => {
      const own = path.join(out, 'book', manifest.pages[group.first + k].text);
      assert.deepEqual(decodePageText(page, where), decodePageText(readJson(own), own), `page ${group.first + k + 1} in ${group.src}`);
    });
  }
  assert.deepEqual(manifest.outline.map((e) => [e.title, e.page]), Array.from({ length: 30 }, (_, k) => [`Chapter ${k + 1}`, k * LONG_CHAPTER]));
  const progress = run.stdout.split('\n').filter((line) => /^\d+%: \d+\/300 pages/.test(line));
  assert.deepEqual(progress.map((line) => line.split('%')[0]), ['10', '20', '30', '40', '50', '60', '70', '80', '90', '100']);
  const html = fs.readFileSync(path.join(out, 'index.html'), 'utf8');
  // Each page's noscript text is cut (NOSCRIPT_CHARS): about 1 KB a page with its alt text and markup.
  assert.ok(html.length < 300 * 1000, `index.html is ${html.length} characters`);
});
