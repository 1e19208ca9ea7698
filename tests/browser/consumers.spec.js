// Browser: the packed npm package in real consumers. Once per run, `npm pack` makes the tarball; a Vite
// app (tests/consumers/vite-app) installs it and is built with the repository's vite, and a static page
// (tests/consumers/static-page) gets the tarball unpacked beside it; a page on another origin loads the
// package's CDN build (conecurl/cdn) from a server of the unpacked package, as from a CDN. What shows is
// judged from screenshots.
import { test, expect } from '@playwright/test';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { serveDirectory } from '../../scripts/serve.mjs';
import {
  copyTemplate, installTarball, packTo, repositoryRoot, unpackTo, writePageImages,
} from '../consumers/package-tools.mjs';
import { ABSENT, SHOWN, pageShares as sharesOf, watchProblems } from './consumer-checks.js';

const PAGE_COUNT = 6;
const pageShares = (locator) => sharesOf(locator, PAGE_COUNT);
let work;
let viteApp;
let viteSite;
let staticSite;
let cdnSite;

test.describe.configure({ mode: 'serial' });  // the tests share one tarball, one build, two servers
test.use({ viewport: { width: 800, height: 900 } });

test.beforeAll(async () => {
  work = fs.mkdtempSync(path.join(os.tmpdir(), 'conecurl-consumers-'));
  const tarball = packTo(work);

  viteApp = copyTemplate('vite-app', path.join(work, 'vite-app'));
  writePageImages(path.join(viteApp, 'public/pages'), PAGE_COUNT);
  installTarball(tarball, viteApp);
  execFileSync(path.join(repositoryRoot, 'node_modules/.bin/vite'), ['build', viteApp, '--logLevel', 'warn'],
    { cwd: viteApp, stdio: 'pipe' });
  viteSite = await serveDirectory(path.join(viteApp, 'dist'));

  const site = copyTemplate('static-page', path.join(work, 'static-page'));
  writePageImages(path.join(site, 'pages'), PAGE_COUNT);
  unpackTo(tarball, path.join(site, 'node_modules/conecurl'));
  staticSite = await serveDirectory(site);
  // The unpacked package as a CDN serves it (any origin may read it), on a port of its own: another origin.
  cdnSite = await serveDirectory(path.join(site, 'node_modules/conecurl'), { cors: true });
  const manifest = JSON.parse(fs.readFileSync(path.join(site, 'node_modules/conecurl/package.json'), 'utf8'));
  const cdnModule = new URL(manifest.exports['./cdn'].default, cdnSite.url).href;
  fs.writeFileSync(path.join(site, 'cdn.html'), fs.readFileSync(path.join(site, 'index.html'), 'utf8')
    .replace(/<script type="importmap">[\s\S]*?<\/script>\n<script type="module">[\s\S]*?<\/script>/,
      `<script type="module" src="${cdnModule}"></script>\n<script type="module">\n  import { Flipbook } from '${cdnModule}';\n  window.Flipbook = Flipbook;\n</script>`));
});

test.afterAll(async () => {
  viteSite?.server.close();
  staticSite?.server.close();
  cdnSite?.server.close();
  if (work) fs.rmSync(work, { recursive: true, force: true });
});

async function waitForFlag(page) {
  await page.waitForFunction(() => document.body.dataset.ready || document.body.dataset.error);
  expect(await page.evaluate(() => document.body.dataset.error || null), 'the page reported an error').toBeNull();
}


test('browser: a Vite app built from the packed tarball shows a Flipbook from conecurl and a <cone-flipbook> from conecurl/element, with the wasm in its build', async ({ page }) => {
  const assets = fs.readdirSync(path.join(viteApp, 'dist/assets'));
  expect(assets.filter((name) => /^conecurl-engine-[\w-]+\.wasm$/.test(name))).toHaveLength(1);
  const problems = watchProblems(page);
  await page.goto(viteSite.url);
  await waitForFlag(page);

  const flipbook = await pageShares(page.locator('#flipbook'));  // opens at page 0, alone on the right
  expect(flipbook[0]).toBeGreaterThan(SHOWN);
  for (const share of flipbook.slice(1)) expect(share).toBeLessThan(ABSENT);

  const element = await pageShares(page.locator('cone-flipbook'));  // start-page="2": the spread 1, 2
  expect(element[1]).toBeGreaterThan(SHOWN);
  expect(element[2]).toBeGreaterThan(SHOWN);
  for (const index of [0, 3, 4, 5]) expect(element[index]).toBeLessThan(ABSENT);

  const state = await page.evaluate(() => ({ book: window.app.book.page, element: window.app.element.page }));
  expect(state).toEqual({ book: 0, element: 1 });
  expect(problems).toEqual([]);
});

test('browser: a static page imports <cone-flipbook> from the unpacked package (import map): its child images become the book, and next() turns it and fires turned', async ({ page }) => {
  await page.addInitScript(() => {
    // Capture-phase listeners on the document hear the element's (non-bubbling) events from the start.
    window.bookEvents = [];
    for (const type of ['ready', 'turnstart', 'turned', 'pageerror', 'error']) {
      document.addEventListener(type, (event) => {
        if (event.target.localName === 'cone-flipbook') window.bookEvents.push([type, event.detail]);
      }, true);
    }
  });
  const problems = watchProblems(page);
  await page.goto(staticSite.url);
  await page.waitForFunction(() => window.bookEvents.some(([type]) => type === 'ready' || type === 'error'));
  const book = page.locator('cone-flipbook');

  const before = await pageShares(book);
  expect(before[0]).toBeGreaterThan(SHOWN);
  for (const share of before.slice(1)) expect(share).toBeLessThan(ABSENT);

  const turned = await book.evaluate((element) => element.next());
  expect(turned).toBe(true);
  const after = await pageShares(book);
  expect(after[0]).toBeLessThan(ABSENT);
  expect(after[1]).toBeGreaterThan(SHOWN);
  expect(after[2]).toBeGreaterThan(SHOWN);

  const events = await page.evaluate(() => window.bookEvents);
  expect(events).toEqual([
    ['ready', { page: 0 }],
    ['turnstart', { direction: 'forward', page: 1 }],
    ['turned', { page: 1 }],
  ]);
  expect(await book.evaluate((element) => element.book.pageCount)).toBe(PAGE_COUNT);
  expect(problems).toEqual([]);
});

test('browser: a page on another origin loads conecurl/cdn, one module from a CDN: <cone-flipbook> and Flipbook work, and the wasm comes from beside the module', async ({ page }) => {
  const requests = [];
  page.on('request', (request) => requests.push(request.url()));
  const problems = watchProblems(page);
  await page.goto(`${staticSite.url}cdn.html`);
  const book = page.locator('cone-flipbook');
  await page.waitForFunction(() => document.querySelector('cone-flipbook')?.book?.pageCount > 0 && window.Flipbook);
  await book.evaluate((element) => element.book.whenIdle());
  const shares = await pageShares(book);
  expect(shares[0]).toBeGreaterThan(SHOWN);
  for (const share of shares.slice(1)) expect(share).toBeLessThan(ABSENT);
  expect(await book.evaluate((element) => element.next())).toBe(true);
  const after = await pageShares(book);
  expect(after[1]).toBeGreaterThan(SHOWN);
  expect(after[2]).toBeGreaterThan(SHOWN);
  // The module's Flipbook is the element's: one engine, one class.
  expect(await book.evaluate((element) => element.book instanceof window.Flipbook)).toBe(true);
  // From the CDN: the one module and the wasm beside it, nothing else; nothing of the package from the page's origin.
  const fromCdn = requests.filter((url) => url.startsWith(cdnSite.url)).map((url) => new URL(url).pathname).sort();
  expect(fromCdn).toEqual(['/dist/cdn/conecurl-engine.wasm', '/dist/cdn/conecurl.js']);
  expect(requests.filter((url) => url.includes('node_modules'))).toEqual([]);
  expect(problems).toEqual([]);
});

test('browser: without JavaScript the static page shows the child images of <cone-flipbook> instead of a blank box', async ({ browser }) => {
  const context = await browser.newContext({ javaScriptEnabled: false, viewport: { width: 800, height: 900 } });
  try {
    const page = await context.newPage();
    await page.goto(staticSite.url, { waitUntil: 'load' });
    const shares = await pageShares(page.locator('cone-flipbook'));
    expect(shares[0]).toBeGreaterThan(SHOWN);  // the cover image, laid out as a plain <img>
  } finally {
    await context.close();
  }
});
