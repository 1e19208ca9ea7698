// Browser: conecurl/react and conecurl/vue in real apps built from the packed tarball: Vite apps
// (tests/consumers/react-app, vue-app) and a server-rendered Next.js app-router app (next-app, a
// production build served by `next start`); React, Vue and Next come from the devDependencies. The
// books show the right pages (screenshots), props apply live without a new canvas, the ref and
// useFlipbook/exposed methods turn, children are pages, and StrictMode mounts leave one book and no leak.
import { test, expect } from '@playwright/test';
import { execFileSync, spawn } from 'node:child_process';
import fs from 'node:fs';
import net from 'node:net';
import path from 'node:path';
import { serveDirectory } from '../../scripts/serve.mjs';
import { copyTemplate, installTarball, packTo, repositoryRoot, writePageImages } from '../consumers/package-tools.mjs';
import { SHOWN, pageShares as sharesOf, watchProblems } from './consumer-checks.js';
import { decodePng } from './png.js';

const PAGE_COUNT = 6;
const pageShares = (locator) => sharesOf(locator, PAGE_COUNT);
let work;
const sites = {};
let nextServer;

// A port free now, for `next start`.
const freePort = () => new Promise((resolve) => {
  const server = net.createServer().listen(0, '127.0.0.1', () => {
    const { port } = server.address();
    server.close(() => resolve(port));
  });
});

async function startNext(dir) {
  const port = await freePort();
  const child = spawn(path.join(repositoryRoot, 'node_modules/.bin/next'), ['start', '-p', String(port), '-H', '127.0.0.1'],
    { cwd: dir, env: { ...process.env, NEXT_TELEMETRY_DISABLED: '1' }, stdio: 'ignore' });
  const url = `http://127.0.0.1:${port}/`;
  for (let tries = 0; ; tries++) {
    try {
      if ((await fetch(url)).ok) return { child, url };
    } catch { /* not listening yet */ }
    // Polled every 0.2 s; the bound is only for a server that never answers (it answers in seconds).
    if (tries > 1000) throw new Error('next start did not answer in 200 s');
    await new Promise((resolve) => setTimeout(resolve, 200));
  }
}

// One tarball, two builds, two servers. Each app test takes 8-14 s alone: a limit for a machine
// several times slower.
test.describe.configure({ mode: 'serial', timeout: 120_000 });
test.use({ viewport: { width: 800, height: 900 } });

test.beforeAll(async () => {
  // Packing, installing and three production builds: about 75 s alone on two cores; a limit for a
  // machine several times slower.
  test.setTimeout(600_000);
  // Inside the repository (build/ is ignored), so that the apps find React and Vue in its node_modules.
  fs.mkdirSync(path.join(repositoryRoot, 'build'), { recursive: true });
  work = fs.mkdtempSync(path.join(repositoryRoot, 'build/frameworks-'));
  const tarball = packTo(work);
  for (const app of ['react-app', 'vue-app']) {
    const dir = copyTemplate(app, path.join(work, app));
    writePageImages(path.join(dir, 'public/pages'), PAGE_COUNT);
    installTarball(tarball, dir);
    execFileSync(path.join(repositoryRoot, 'node_modules/.bin/vite'), ['build', dir, '--logLevel', 'warn'], { cwd: dir, stdio: 'pipe' });
    sites[app] = await serveDirectory(path.join(dir, 'dist'));
  }
  const next = copyTemplate('next-app', path.join(work, 'next-app'));
  writePageImages(path.join(next, 'public/pages'), PAGE_COUNT);
  installTarball(tarball, next);
  execFileSync(path.join(repositoryRoot, 'node_modules/.bin/next'), ['build'],
    { cwd: next, stdio: 'pipe', env: { ...process.env, NEXT_TELEMETRY_DISABLED: '1' } });
  nextServer = await startNext(next);
});

test.afterAll(async () => {
  nextServer?.child.kill();
  for (const site of Object.values(sites)) site.server.close();
  if (work) fs.rmSync(work, { recursive: true, force: true });
});

/** Share of a book's pixels near the HTML page's green. */
async function greenShare(locator) {
  const { width, height, data } = decodePng(await locator.screenshot());
  let green = 0;
  for (let i = 0; i < width * height * 4; i += 4) {
    if (Math.abs(data[i] - 30) < 25 && Math.abs(data[i + 1] - 160) < 25 && Math.abs(data[i + 2] - 90) < 25) green++;
  }
  return green / (width * height);
}

const shownPages = (shares) => shares.map((share, i) => (share > SHOWN ? i : -1)).filter((i) => i >= 0);

async function openApp(page, app) {
  const problems = watchProblems(page, { webglWarnings: true });
  await page.goto(app === 'next-app' ? nextServer.url : sites[app].url);
  await page.waitForFunction(() => document.body.dataset.ready || document.body.dataset.error);
  expect(await page.evaluate(() => document.body.dataset.error || null), 'the app reported an error').toBeNull();
  return problems;
}

// Waits until the book's state (through the app's window hooks) says `predicate` (a wait that is met
// returns at once: the bound is only for one that never is).
const waitFor = (page, predicate, arg) => page.waitForFunction(predicate, arg, { timeout: 60_000 });
// Polls a screenshot of the book until it shows `pages` (a book drawn once its pages have loaded).
const showsPages = (locator, pages) => expect.poll(async () => shownPages(await pageShares(locator)), { timeout: 60_000 }).toEqual(pages);

test('browser (React): a controlled <Flipbook> under StrictMode is one book on one canvas; useFlipbook controls elsewhere turn it, page, pages and display props apply live, children are its pages', async ({ page }) => {
  const problems = await openApp(page, 'react-app');
  const book = page.locator('#book');
  expect(await book.locator('canvas').count()).toBe(1);  // StrictMode mounted it twice: one book left
  await waitFor(page, () => window.app.flipbook.ready);
  expect(shownPages(await pageShares(book))).toEqual([1, 2]);  // page={2}: the spread 1, 2
  expect(await page.locator('#page').textContent()).toBe('page 2 of 6');
  await page.evaluate(() => { window.firstCanvas = document.querySelector('#book canvas'); });

  await page.click('#next');  // useFlipbook().next(), a control outside the book
  await waitFor(page, () => window.app.page === 3 && !window.app.flipbook.book.animating);
  expect(shownPages(await pageShares(book))).toEqual([3, 4]);
  expect(await page.locator('#page').textContent()).toBe('page 4 of 6');

  await page.evaluate(() => window.app.setPage(0));  // the controlled prop turns the book back
  await waitFor(page, () => window.app.flipbook.page === 0 && !window.app.flipbook.book.animating);
  expect(shownPages(await pageShares(book))).toEqual([0]);

  await page.evaluate(() => window.app.setDisplay('single'));
  await waitFor(page, () => window.app.flipbook.display === 'single');
  expect(await page.evaluate(() => document.querySelector('#book canvas') === window.firstCanvas)).toBe(true);
  await page.evaluate(() => window.app.flipbook.flip(4, { animate: false }));
  await waitFor(page, () => window.app.page === 4);
  expect(shownPages(await pageShares(book))).toEqual([4]);
  expect(await page.evaluate(() => window.events.filter(([type]) => type === 'ready').length)).toBe(1);

  // Pages replaced by a longer list: the same book and canvas, a page inserted live; then one inserted
  // before the page shown, which moves the page prop on with it.
  await page.evaluate(() => window.app.setPages([...window.app.pages, 'pages/page-1.svg']));
  await waitFor(page, () => window.app.flipbook.ready && window.app.flipbook.pageCount === 7);
  expect(await page.evaluate(() => window.app.flipbook.page)).toBe(4);
  expect(shownPages(await pageShares(book))).toEqual([4]);
  await page.evaluate(() => window.app.setPages(['pages/page-5.svg', ...window.app.pages, 'pages/page-1.svg']));
  await waitFor(page, () => window.app.flipbook.pageCount === 8 && window.app.page === 5);
  expect(shownPages(await pageShares(book))).toEqual([4]);  // the same page, now page 5
  expect(await page.evaluate(() => ({
    sameCanvas: document.querySelector('#book canvas') === window.firstCanvas,
    ready: window.events.filter(([type]) => type === 'ready').length,
    changes: window.events.filter(([type]) => type === 'pageschange').map(([, detail]) => detail),
  }))).toEqual({
    sameCanvas: true,
    ready: 1,
    changes: [{ change: 'insert', at: 6, count: 1, pageCount: 7, page: 4 }, { change: 'insert', at: 0, count: 1, pageCount: 8, page: 5 }],
  });

  // Children: an <img>, an HTML <section> (React keeps rendering it), an <img>.
  const children = page.locator('#children-book');
  await showsPages(children, [0]);  // its own pages loaded (the app says nothing of this book's ready)
  // Focus the book (a click would have to find the middle of a cover that now sits centred).
  await page.evaluate(() => document.querySelector('#children-book [tabindex="0"]').focus());
  await page.keyboard.press('ArrowRight');
  await expect.poll(() => greenShare(children), { timeout: 60_000 }).toBeGreaterThan(0.15);
  expect(await page.locator('#html-page h2').textContent()).toBe('An HTML page');

  // A bad prop is an error the app hears, naming it; the other books go on.
  await waitFor(page, () => window.badBookError);
  expect(await page.evaluate(() => window.badBookError)).toMatch(/option 'duration' must be a positive number/);
  expect(problems).toEqual([]);
});

test('browser (React): 50 StrictMode mounts and unmounts leave no canvas, no live WebGL context, no context warning and a flat JS heap', async ({ page }) => {
  // 55 books made and destroyed (20-50 s alone on two cores): a limit for a machine 5x slower.
  test.setTimeout(300_000);
  await page.addInitScript(() => {
    // Every WebGL2 context made, to count those still live afterwards.
    window.contexts = [];
    const getContext = HTMLCanvasElement.prototype.getContext;
    HTMLCanvasElement.prototype.getContext = function counted(type, ...rest) {
      const context = getContext.call(this, type, ...rest);
      if (type === 'webgl2' && context && !window.contexts.includes(context)) window.contexts.push(context);
      return context;
    };
  });
  const problems = await openApp(page, 'react-app');
  const cdp = await page.context().newCDPSession(page);
  const heap = async () => {
    await cdp.send('HeapProfiler.collectGarbage');
    return (await cdp.send('Runtime.getHeapUsage')).usedSize;
  };
  await page.evaluate(() => window.cycle(5));  // warm up: code compiled, caches filled
  const before = await heap();
  const canvases = await page.evaluate(() => document.querySelectorAll('canvas').length);
  await page.evaluate(() => window.cycle(50));
  const after = await heap();
  const contexts = await page.evaluate(() => ({ made: window.contexts.length, live: window.contexts.filter((c) => !c.isContextLost()).length }));
  console.log(`React StrictMode 50 mounts: JS heap ${before} -> ${after} bytes (${after - before}); WebGL contexts made ${contexts.made}, live ${contexts.live}`);
  expect(await page.evaluate(() => document.querySelectorAll('canvas').length)).toBe(canvases);
  expect(contexts.made).toBeGreaterThanOrEqual(55);  // every mount made a book
  expect(contexts.live).toBeLessThanOrEqual(2);      // the app's own two books
  expect(after - before).toBeLessThan(1_000_000);
  expect(problems).toEqual([]);
});

test('browser (Vue): v-model:page, pages and display apply live on one canvas, the exposed next() turns, and the default slot holds the pages', async ({ page }) => {
  const problems = await openApp(page, 'vue-app');
  const book = page.locator('#book');
  expect(await book.locator('canvas').count()).toBe(1);
  await waitFor(page, () => window.app.book.value?.ready);
  expect(shownPages(await pageShares(book))).toEqual([1, 2]);
  await page.evaluate(() => { window.firstCanvas = document.querySelector('#book canvas'); });

  await page.click('#next');  // the exposed next()
  await waitFor(page, () => window.app.page.value === 3 && !window.app.book.value.book.animating);
  expect(shownPages(await pageShares(book))).toEqual([3, 4]);
  expect(await page.locator('#page').textContent()).toBe('page 4');

  await page.evaluate(() => { window.app.page.value = 0; });
  await waitFor(page, () => window.app.book.value.page === 0 && !window.app.book.value.book.animating);
  expect(shownPages(await pageShares(book))).toEqual([0]);

  await page.evaluate(() => { window.app.display.value = 'single'; });
  await waitFor(page, () => window.app.book.value.display === 'single');
  expect(await page.evaluate(() => document.querySelector('#book canvas') === window.firstCanvas)).toBe(true);

  // A page inserted before the page shown: the same book, v-model:page follows the page to its new index.
  await page.evaluate(() => { window.app.pages.value = ['pages/page-5.svg', ...window.app.pages.value]; });
  await waitFor(page, () => window.app.book.value.pageCount === 7 && window.app.page.value === 1);
  expect(await page.evaluate(() => ({
    sameCanvas: document.querySelector('#book canvas') === window.firstCanvas,
    ready: window.events.filter(([type]) => type === 'ready').length,
    changes: window.events.filter(([type]) => type === 'pageschange').map(([, detail]) => detail),
  }))).toEqual({ sameCanvas: true, ready: 1, changes: [{ change: 'insert', at: 0, count: 1, pageCount: 7, page: 1 }] });

  const children = page.locator('#children-book');
  await showsPages(children, [0]);  // its own pages loaded (the app says nothing of this book's ready)
  await page.evaluate(() => document.querySelector('#children-book [tabindex="0"]').focus());
  await page.keyboard.press('ArrowRight');
  await expect.poll(() => greenShare(children), { timeout: 60_000 }).toBeGreaterThan(0.15);
  expect(problems).toEqual([]);
});

test('browser (Next.js): the server-rendered page hydrates with no warning, the book turns through ref.current.next(), and a display prop change applies to the same canvas', async ({ page }) => {
  // The server's HTML holds the book's box, sized and empty (the page as the browser first gets it).
  const html = await (await fetch(nextServer.url)).text();
  expect(html).toMatch(/<div id="book" style="display:block;position:relative;width:640px;aspect-ratio:auto;height:400px"><\/div>/);
  const problems = await openApp(page, 'next-app');
  const book = page.locator('#book');
  expect(await book.locator('canvas').count()).toBe(1);
  expect(shownPages(await pageShares(book))).toEqual([0]);
  await page.evaluate(() => { window.firstCanvas = document.querySelector('#book canvas'); });

  expect(await page.evaluate(() => window.app.book.current.next())).toBe(true);
  await waitFor(page, () => !window.app.book.current.book.animating);
  expect(shownPages(await pageShares(book))).toEqual([1, 2]);
  await page.click('#next');
  await waitFor(page, () => window.app.book.current.page === 3 && !window.app.book.current.book.animating);
  expect(shownPages(await pageShares(book))).toEqual([3, 4]);

  await page.evaluate(() => window.app.setDisplay('single'));
  await waitFor(page, () => window.app.book.current.display === 'single');
  expect(await page.evaluate(() => document.querySelector('#book canvas') === window.firstCanvas)).toBe(true);
  expect(shownPages(await pageShares(book))).toEqual([3]);
  expect(problems).toEqual([]);  // no hydration warning, no error, no failed request
});
