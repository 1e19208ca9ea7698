// Browser: a site `conecurl publish --narration` wrote (issue 37) reads itself with the recorded voice: with
// no speech voice in the browser, the toolbar's Read aloud button shows for the narration alone, and a
// press plays each narrated page's audio from the site's book/narration/, marking its words.
import { test, expect } from '@playwright/test';
import { READER_ENTRY } from '../node/publish-run.mjs';
import { execFileSync } from 'node:child_process';
import { mkdirSync, rmSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { makeDocumentPdf } from './document-pdf.js';
import { narrationFolder, silentWav, timed, wordTimesVtt } from '../fixtures/narration-files.mjs';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const SITES = path.join(root, 'build/test-sites');
// A name of its own per worker: two workers never publish into the same folder.
const siteName = () => `narration-${test.info().workerIndex}`;
const siteUrl = () => `/build/test-sites/${siteName()}/`;
// The first words of the PDF's pages 1 and 2 (tests/fixtures/document-pdf.mjs), as their narration says them.
const SAID = { 0: ['Contents', 'A', 'book', 'about'], 1: ['Chapter', 'One:', 'Zebras'] };

test.beforeAll(async () => {
  const name = siteName();
  mkdirSync(SITES, { recursive: true });
  const pdf = path.join(SITES, `${name}.pdf`);
  writeFileSync(pdf, Buffer.from((await makeDocumentPdf()).base64, 'base64'));
  rmSync(path.join(SITES, name), { recursive: true, force: true });  // this test's own folders, from an earlier run
  rmSync(path.join(SITES, `${name}-voice`), { recursive: true, force: true });
  // Page 1's word times as WebVTT, page 2's as JSON; each audio a silent WAV a little longer than its words.
  const voice = narrationFolder(SITES, `${name}-voice`, {
    'page-1.wav': silentWav(1), 'page-1.vtt': wordTimesVtt(timed(SAID[0])),
    'page-2.wav': silentWav(0.8), 'page-2.json': JSON.stringify(timed(SAID[1])),
  });
  execFileSync(process.execPath, [path.join(root, 'cli/conecurl.mjs'), 'publish', pdf, '--out', path.join(SITES, name),
    '--height', '400', '--zoom', '0', '--no-download', '--narration', voice], { stdio: 'pipe' });
});

test('browser: a site published with --narration shows Read aloud without a speech voice, and its button plays each narrated page\'s audio from book/narration/ and marks its words (needs chromium, pdfjs-dist)', async ({ page }) => {
  test.setTimeout(180_000);
  // No speech voice: only the narration can read this book.
  await page.addInitScript(() => {
    const synth = new EventTarget();
    Object.assign(synth, { getVoices: () => [], speak() { throw new Error('no voice'); }, cancel() {}, pause() {}, resume() {} });
    Object.defineProperty(window, 'speechSynthesis', { value: synth, configurable: true });
  });
  const problems = [];
  page.on('pageerror', (error) => problems.push(error.message));
  await page.goto(`${siteUrl()}index.html`);
  await page.evaluate(async (url) => {
    window.book = await (await import(document.querySelector(url).src)).book;
    await window.book.whenIdle();
    window.log = [];
    window.book.addEventListener('readaloudpage', (e) => window.log.push({ type: 'page', page: e.detail.page, source: e.detail.source }));
    window.book.addEventListener('readaloudword', (e) => window.log.push({
      type: 'word', page: e.detail.page, text: e.detail.text, audio: window.book.readingAloud?.audio?.src ?? null,
    }));
    window.book.addEventListener('readaloudend', (e) => window.log.push({ type: 'end', reason: e.detail.reason, error: e.detail.error?.stack }));
  }, READER_ENTRY);
  const read = page.locator('[data-control="readAloud"]:not([role="menuitem"])');  // the toolbar's, not the More menu's
  await expect(read).toBeVisible();
  await read.click();
  // Until the reading has gone past page 2 (index 1) or ended.
  await page.waitForFunction(() => window.log.some((e) => (e.type === 'page' && e.page > 1) || e.type === 'end'));
  const log = await page.evaluate(() => {
    window.book.readingAloud?.stop();
    return window.log;
  });
  expect(problems).toEqual([]);
  expect(log.filter((e) => e.type === 'end' && e.reason !== 'stopped')).toEqual([]);
  expect(log.filter((e) => e.type === 'page' && e.page <= 1)).toEqual([{ type: 'page', page: 0, source: 'narration' }, { type: 'page', page: 1, source: 'narration' }]);
  for (const [index, words] of Object.entries(SAID)) {
    const said = log.filter((e) => e.type === 'word' && e.page === Number(index));
    expect(said.map((e) => e.text)).toEqual(words);
    const file = `book/narration/000${Number(index) + 1}.wav`;
    expect(said.every((e) => new URL(e.audio).pathname === `${siteUrl()}${file}`), file).toBe(true);
  }
});
