// Browser: a site `conecurl publish` wrote, as an offline, installable web app (its sw.js and
// manifest.webmanifest): once loaded its service worker controls the page, and offline a reload shows the
// first spread, turns and searches; Keep offline fetches the whole book; the manifest and icons meet
// Chromium's install criteria; a re-publish's worker replaces the old version's cache and what is shown.
// The sites are served under a sub-path (/build/test-sites/<name>/). Every wait is for an event or a state.
import { test, expect } from '@playwright/test';
import { execFileSync } from 'node:child_process';
import { mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { makeDocumentPdf } from './document-pdf.js';
import { READER_ENTRY } from '../node/publish-run.mjs';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const SITES = path.join(root, 'build/test-sites');
const TITLE = 'The offline test';
// Folders of their own per worker: two workers never publish into the same one.
const siteName = (kind) => `offline-${kind}-${test.info().workerIndex}`;
const siteUrl = (name) => `/build/test-sites/${name}/`;
const CACHE_PREFIX = 'conecurl-site ';  // web/reader/service-worker.js names its caches so

let pdf;
/** Publishes the test PDF into build/test-sites/`name` (over an earlier publish there, as a re-publish does). */
function publish(name, title) {
  execFileSync(process.execPath, [path.join(root, 'cli/conecurl.mjs'), 'publish', pdf, '--out', path.join(SITES, name),
    '--height', '400', '--title', title], { stdio: 'pipe' });
}

test.beforeAll(async () => {
  mkdirSync(SITES, { recursive: true });
  pdf = path.join(SITES, `offline-${test.info().workerIndex}.pdf`);
  writeFileSync(pdf, Buffer.from((await makeDocumentPdf()).base64, 'base64'));
  for (const kind of ['read', 'keep', 'install', 'update', 'stale', 'reload']) rmSync(path.join(SITES, siteName(kind)), { recursive: true, force: true });
  for (const kind of ['read', 'keep', 'install']) publish(siteName(kind), TITLE);
});

/**
 * The site's book once open (`window.book`) and, online, its service worker once it controls the page and
 * has kept what the page read (the reader's `serviceWorker` promise). Resolves whether a worker controls it.
 */
async function openBook(page, site) {
  return page.evaluate(async (entry) => {
    const module = await import(document.querySelector(entry).src);
    window.book = await module.book;
    await window.book.whenIdle();
    window.registration = await module.serviceWorker;
    return Boolean(window.registration && navigator.serviceWorker.controller);
  }, READER_ENTRY);
}

/** Opens the site of `kind` (published first as `title`, when given) and its book; returns its name and URL. */
async function openSite(page, kind, title) {
  const name = siteName(kind);
  const site = siteUrl(name);
  if (title) publish(name, title);
  await page.goto(`${site}index.html`);
  expect(await openBook(page, site)).toBe(true);
  return { name, site };
}

const VERSION_META = /<meta name="conecurl-site-version" content="([0-9a-f]{16})">/;
/** The version conecurl publish wrote into the site's index.html. */
const versionOf = (name) => readFileSync(path.join(SITES, name, 'index.html'), 'utf8').match(VERSION_META)[1];

/**
 * Resolves once a worker of the page's own version controls it and has activated (its activation moved what
 * it keeps from the old cache and deleted that). A page of the old version reloads as soon as a new worker
 * has installed (the old one steps aside meanwhile), so the new page can come before the new worker takes over.
 */
const ownWorkerInCharge = (page) => page.evaluate(async () => {
  const mine = document.querySelector('meta[name="conecurl-site-version"]').content;
  const versionOf = (worker) => new Promise((resolve) => {
    const channel = new MessageChannel();
    channel.port1.onmessage = ({ data }) => resolve(data.version);
    worker.postMessage({ type: 'conecurl-version' }, [channel.port2]);
  });
  for (;;) {
    const worker = navigator.serviceWorker.controller;
    const changed = new Promise((resolve) => {  // listened for before looking: no change is missed
      navigator.serviceWorker.addEventListener('controllerchange', resolve, { once: true });
      worker?.addEventListener('statechange', resolve, { once: true });
    });
    if (worker?.state === 'activated' && await versionOf(worker) === mine) return;
    await changed;
  }
});

/** Turns to the next spread; resolves to the open pages' states once their images are in. */
const turnNext = (page) => page.evaluate(async () => {
  const turned = new Promise((resolve) => window.book.addEventListener('turned', resolve, { once: true }));
  window.book.next();
  await turned;
  await window.book.whenIdle();
  return window.book.openPages.map((index) => window.book.pageState(index).state);
});

/** What the controlling worker says of the site's files (Keep offline's question). */
const plan = (page) => page.evaluate(() => new Promise((resolve) => {
  const channel = new MessageChannel();
  channel.port1.onmessage = ({ data }) => resolve(data);
  navigator.serviceWorker.controller.postMessage({ type: 'conecurl-offline-plan' }, [channel.port2]);
}));

test('browser: once loaded online, the published site reads offline: a reload offline shows the first spread, turns, and search finds its words (needs conecurl publish and Chromium\'s service workers)', async ({ page, context }) => {
  await page.setViewportSize({ width: 390, height: 844 });  // a phone's screen, for the picture below
  const problems = [];
  page.on('pageerror', (error) => problems.push(error.message));
  const { site } = await openSite(page, 'read');

  await context.setOffline(true);
  await page.reload();
  expect(await openBook(page, site)).toBe(true);
  const first = await page.evaluate(() => ({
    online: navigator.onLine, title: document.title, open: window.book.openPages,
    states: window.book.openPages.map((index) => window.book.pageState(index).state),
  }));
  expect(first).toEqual({ online: false, title: TITLE, open: [0], states: ['loaded'] });
  mkdirSync(path.join(root, 'build'), { recursive: true });
  await page.screenshot({ path: path.join(root, 'build/offline-shot.png') });
  // The next page was read online (near the first, the book fetched it before the worker took over).
  const next = await turnNext(page);
  expect(next.length).toBeGreaterThan(0);
  expect(next.every((state) => state === 'loaded')).toBe(true);
  // Every page's text is precached: search finds the words offline, on the pages pdf.js puts them.
  expect((await page.evaluate(() => window.book.search('zebra'))).map((hit) => hit.page)).toEqual([1, 1, 4]);
  expect(problems).toEqual([]);
});

test('browser: Keep offline in the More menu says the size it will fetch, fetches the whole book with progress, and then the site opens offline from its start_url at a page never read (needs conecurl publish, service workers)', async ({ page, context }) => {
  const { site } = await openSite(page, 'keep');
  const before = await plan(page);
  const left = before.files.filter((file) => !file.kept);
  const lastPage = new URL(`${site}book/pages/0008.webp`, page.url()).href;
  expect(left.map((file) => file.url)).toContain(lastPage);  // the last page was never read
  const { sizeText } = await import('../../web/src/viewer/keep-offline.js');
  const size = sizeText(left.reduce((sum, file) => sum + file.bytes, 0));

  // Everything the live region says, as it says it.
  await page.evaluate(() => {
    window.said = [];
    const status = document.querySelector('.conecurl-offline-status');
    new MutationObserver(() => window.said.push(status.textContent)).observe(status, { subtree: true, childList: true, characterData: true });
  });
  await page.getByRole('button', { name: 'More' }).click();
  const item = page.getByRole('menuitem', { name: `Keep offline (${size})` });
  await item.click();
  await expect(page.getByRole('status').filter({ hasText: 'Kept offline' })).toBeVisible();
  const said = await page.evaluate(() => window.said);
  expect(said[0]).toBe(`Keeping offline: 0% of ${size}`);
  expect(said.at(-1)).toBe('Kept offline');
  expect(said.every((text) => /^Keeping offline: \d+% of /.test(text) || text === 'Kept offline')).toBe(true);
  expect((await plan(page)).files.filter((file) => !file.kept)).toEqual([]);
  await page.getByRole('button', { name: 'More' }).click();
  await expect(page.getByRole('menuitem', { name: 'Kept offline' })).toHaveAttribute('aria-disabled', 'true');
  await page.keyboard.press('Escape');

  // Offline, the site opened as its home screen icon opens it (the manifest's start_url, ./), at the last page.
  const manifest = await (await page.request.get(`${site}manifest.webmanifest`)).json();
  await context.setOffline(true);
  await page.goto(`${new URL(manifest.start_url, page.url()).href}#page=8`);
  expect(await openBook(page, site)).toBe(true);
  const last = await page.evaluate(() => ({ online: navigator.onLine, open: window.book.openPages, state: window.book.pageState(7).state }));
  expect(last.online).toBe(false);
  expect(last.open).toContain(7);
  expect(last.state).toBe('loaded');
});

test('browser: the published site meets Chromium\'s install criteria: the manifest\'s name, start_url, scope, display and icons, the icons\' sizes, a service worker (needs conecurl publish, service workers)', async ({ page, context }) => {
  const { site } = await openSite(page, 'install');
  const manifestUrl = await page.evaluate(() => document.querySelector('link[rel="manifest"]').href);
  expect(new URL(manifestUrl).pathname).toBe(`${site}manifest.webmanifest`);
  const manifest = await (await page.request.get(manifestUrl)).json();
  expect(manifest).toMatchObject({ name: TITLE, short_name: 'The offline…', start_url: './', scope: './', display: 'standalone' });
  const icons = await page.evaluate((list) => Promise.all(list.map(async (icon) => {
    const image = new Image();
    image.src = new URL(icon.src, document.querySelector('link[rel="manifest"]').href).href;
    await image.decode();
    return { sizes: icon.sizes, type: icon.type, drawn: `${image.naturalWidth}x${image.naturalHeight}` };
  })), manifest.icons);
  expect(icons).toEqual([
    { sizes: '192x192', type: 'image/png', drawn: '192x192' },
    { sizes: '512x512', type: 'image/png', drawn: '512x512' },
  ]);
  // Chromium's own verdict, as its install prompt would ask it.
  const cdp = await context.newCDPSession(page);
  const { url, errors } = await cdp.send('Page.getAppManifest');
  expect({ url, errors }).toEqual({ url: manifestUrl, errors: [] });
  const { installabilityErrors } = await cdp.send('Page.getInstallabilityErrors');
  // Playwright's browser contexts are incognito ones, where Chromium offers no install whatever the site.
  expect(installabilityErrors.filter((error) => error.errorId !== 'in-incognito')).toEqual([]);
});

test('browser: a re-publish replaces the site online: the page loads again with the new book, and once the new version\'s worker takes over (when no page of the old one is open), the pages read move to the new cache where unchanged and the old version\'s cache is deleted (needs conecurl publish twice, service workers)', async ({ page, context }) => {
  const { name, site } = await openSite(page, 'update', 'First edition');
  const caches = (tab) => tab.evaluate((prefix) => caches.keys().then((names) => names.filter((n) => n.startsWith(prefix))), CACHE_PREFIX);
  const first = await caches(page);
  expect(first).toHaveLength(1);
  expect(await page.evaluate(() => window.book.options.label)).toBe('First edition');
  // The last pages read too (kept as read), then back to the start: the second edition's images are the
  // same bytes, so the ones its page does not read itself must move over from the first edition's cache.
  await page.evaluate(async () => {
    window.book.flip(window.book.pageCount - 1, { animate: false });
    await window.book.whenIdle();
    window.book.flip(0, { animate: false });
    await window.book.whenIdle();
  });
  const images = (tab, cache) => tab.evaluate(async (cache) => (await (await caches.open(cache)).keys())
    .map((request) => request.url).filter((url) => /\/book\/pages\//.test(url)).sort(), cache);
  const read = await images(page, first[0]);

  publish(name, 'Second edition');
  // The page looks for a new publish as when its tab is come back to (the reader's visibilitychange): once
  // the new worker has installed, the page, of the first version, loads again as the second (through the
  // old worker, which steps aside while a new one waits).
  const reloaded = page.waitForEvent('load');
  await page.evaluate(() => document.dispatchEvent(new Event('visibilitychange')));
  await reloaded;
  await expect(page).toHaveTitle('Second edition');
  expect(await openBook(page, site)).toBe(true);
  expect(await page.evaluate(() => window.book.options.label)).toBe('Second edition');
  // Chromium may hold the new worker back while a page of the site is open, whatever skipWaiting says (a
  // fetch through the old worker at the moment of activation, such as that reload, makes it give up). It
  // takes over once none is: the site opened again in a new tab is the new worker's.
  await page.close();
  const tab = await context.newPage();
  await tab.goto(`${site}index.html`);
  expect(await openBook(tab, site)).toBe(true);
  await ownWorkerInCharge(tab);
  const second = await caches(tab);
  expect(second).toHaveLength(1);
  expect(second[0]).not.toBe(first[0]);
  const cachedIndex = await tab.evaluate(async (name) => (await (await caches.open(name)).match('index.html')).text(), second[0]);
  expect(cachedIndex).toContain('<title>Second edition</title>');
  const readAgain = await tab.evaluate(() => performance.getEntriesByType('resource').map((entry) => entry.name));
  const carried = read.filter((url) => !readAgain.includes(url));
  expect(carried.length).toBeGreaterThan(0);
  expect(await images(tab, second[0])).toEqual(expect.arrayContaining(carried));
});

test('browser: a page of one version under another version\'s worker from its first moment (a new worker that took over before the reader ran: no controllerchange to hear) loads again once, and a server still sending it cannot make it loop (needs conecurl publish, service workers)', async ({ page }) => {
  const { name, site } = await openSite(page, 'stale', TITLE);
  // A page the worker does not serve (no file of the site): the server's copy, with another version in it,
  // controlled by this version's worker from its start.
  const index = readFileSync(path.join(SITES, name, 'index.html'), 'utf8');
  const stale = index.replace(/(<meta name="conecurl-site-version" content=")[0-9a-f]{16}/, `$1${'0'.repeat(16)}`);
  expect(stale).not.toBe(index);
  writeFileSync(path.join(SITES, name, 'stale.html'), stale);
  let loads = 0;
  page.on('load', () => { loads += 1; });
  const reloaded = page.waitForEvent('load').then(() => page.waitForEvent('load'));
  await page.goto(`${site}stale.html`);
  await reloaded;
  expect(await openBook(page, site)).toBe(true);
  // The reader asked the worker its version when its module ran; a question asked now is answered after
  // that one, and by then a reload it made would have begun.
  const version = await page.evaluate(() => new Promise((resolve) => {
    const channel = new MessageChannel();
    channel.port1.onmessage = ({ data }) => setTimeout(() => resolve(data.version));
    navigator.serviceWorker.controller.postMessage({ type: 'conecurl-version' }, [channel.port2]);
  }));
  expect(version).toBe(versionOf(name));
  expect(loads).toBe(2);
  expect(await page.evaluate(() => window.book.pageCount)).toBeGreaterThan(0);
});

test('browser: a reload pressed as a re-publish is found shows the new edition, even while Chromium holds the new worker back (the old one steps aside while a new one waits) (needs conecurl publish twice, service workers)', async ({ page }) => {
  const { name } = await openSite(page, 'reload', 'First edition');
  publish(name, 'Second edition');
  // The reload is answered by the first version's worker; the new one installs while the page loads
  // through the old one, and the page, told a worker of another version is there, loads again.
  await page.reload();
  await expect(page).toHaveTitle('Second edition', { timeout: 60_000 });
  await page.evaluate(async (entry) => { await (await import(document.querySelector(entry).src)).book; }, READER_ENTRY);
  expect(await page.evaluate(() => document.querySelector('meta[name="conecurl-site-version"]').content))
    .toBe(versionOf(name));
});
