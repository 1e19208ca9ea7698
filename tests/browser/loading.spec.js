// Browser: what a book loads and when. A plain book of images fetches none of the optional parts (page
// sound, autoplay, page memory, live pages, HTML pages, PDF, the 2D fallback): each is fetched only once
// an option or a call asks for it (counted by the module URLs the page requests).
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';

const FIXTURE = '/tests/browser/fixtures/flipbook-fixture.html';

// The optional modules, each loaded by a dynamic import() only when asked for.
const OPTIONAL = {
  sound: '/web/src/book/page-sound.js',
  autoplay: '/web/src/book/autoplay.js',
  memory: '/web/src/book/page-memory.js',
  live: '/web/src/book/live-pages.js',
  html: '/web/src/layers/html-pages.js',
  pdf: '/web/src/pages/pdf-pages.js',
  fallback: '/web/src/book/static-book.js',
  canvas: '/web/src/surfaces/canvas-surface.js',
};

// Every module path under /web/src/ the page requests, from now on.
function recordModules(page) {
  const modules = new Set();
  page.on('request', (request) => {
    const { pathname } = new URL(request.url());
    if (pathname.startsWith('/web/src/')) modules.add(pathname);
  });
  return modules;
}

test('browser: a plain book of images loads none of the optional modules (sound, autoplay, page memory, live pages, HTML, PDF, 2D fallback) (module count)', async ({ page }) => {
  const modules = recordModules(page);
  const problems = await openReady(page, FIXTURE);
  await page.evaluate(() => window.openBook({ pages: 6 }));
  expect(modules.has('/web/src/book/flipbook.js')).toBe(true);  // the recording sees the entry's modules
  expect(modules.has('/web/src/surfaces/book-view.js')).toBe(true);
  expect([...modules].filter((path) => Object.values(OPTIONAL).includes(path))).toEqual([]);
  // The sound, off, still answers what it is doing; setOptions({ sound: true }) brings its module.
  expect(await page.evaluate(() => window.book.sound.state)).toBe('off');
  await page.evaluate(() => window.book.setOptions({ sound: true }));
  await expect.poll(() => modules.has(OPTIONAL.sound)).toBe(true);
  await expect.poll(() => page.evaluate(() => window.book.sound.state)).toBe('waiting');
  expect(problems).toEqual([]);
});

test('browser: the optional modules load when their option or call asks for them: sound, autoplay, hash, insertPages (module count)', async ({ page }) => {
  const modules = recordModules(page);
  const problems = await openReady(page, FIXTURE);
  await page.evaluate(() => window.openBook({ pages: 6, sound: true, autoplay: { interval: 60_000 }, hash: true }));
  for (const name of ['sound', 'autoplay', 'memory']) expect(modules.has(OPTIONAL[name]), name).toBe(true);
  expect(modules.has(OPTIONAL.live)).toBe(false);
  expect(await page.evaluate(() => window.book.sound.state)).toBe('waiting');  // page-sound.js's own answer
  const count = await page.evaluate(async () => {
    await window.book.insertPages(6, [window.makeNumberedPage(6)]);
    return window.book.pageCount;
  });
  expect(count).toBe(7);
  expect(modules.has(OPTIONAL.live)).toBe(true);
  expect(problems).toEqual([]);
});

test('browser: hash: the first view opens at #page=N with page memory loaded only for it (module count)', async ({ page }) => {
  const modules = recordModules(page);
  const problems = await openReady(page, `${FIXTURE}#page=5`);
  expect(await page.evaluate(() => window.openBook({ pages: 8, display: 'single' }))).toEqual({ page: 0, display: 'single' });
  expect(modules.has(OPTIONAL.memory)).toBe(false);  // no hash option: the address is not read
  expect(await page.evaluate(() => window.openBook({ pages: 8, display: 'single', hash: true }))).toEqual({ page: 4, display: 'single' });
  expect(modules.has(OPTIONAL.memory)).toBe(true);
  expect(problems).toEqual([]);
});
