// The reader page: a book that fills the screen, with the toolbar. A published site's index.html (what
// `conecurl publish` writes) names its document in <main id="conecurl-reader" data-document="...">;
// reader.html (shipped in the package) opens a PDF at run time from its address: reader.html#file=book.pdf.
import { Flipbook } from '../src/index.js';

const main = document.getElementById('conecurl-reader');

/** The PDF the address names (#file=URL, as pdf.js's viewer takes it), or null. */
function fileFromHash() {
  const params = new URLSearchParams(location.hash.slice(1));
  const file = params.get('file');
  return file ? new URL(file, location.href).href : null;
}

function showProblem(text) {
  const message = document.createElement('p');
  message.className = 'conecurl-reader-problem';
  message.setAttribute('role', 'alert');
  message.textContent = text;
  main.replaceChildren(message);
}

async function open() {
  const published = main.dataset.document;
  const file = published ? null : fileFromHash();
  if (!published && !file) {
    showProblem('No document to show: open this page as reader.html#file=your.pdf');
    return null;
  }
  // A published book keeps its page in the address (#page=N, passage links #page=N&text=...); a PDF's
  // address is its #file=.
  const source = published ? { document: published } : { pdf: file };
  try {
    if (file) document.title = decodeURIComponent(new URL(file).pathname.split('/').pop() || document.title);
    // A page that fails shows plain paper; the reason goes to the console, for whoever runs the site.
    const pageerror = ({ detail }) => console.warn(`conecurl reader: page ${detail.index + 1} could not be shown (${detail.reason}): ${detail.error?.message ?? ''}`);
    // A published site's service worker (sw.js) may keep the whole book: the More menu's Keep offline.
    const controls = published ? { keepOffline: true } : true;
    return await Flipbook.create(main, { ...source, controls, hash: Boolean(published), on: { pageerror } });
  } catch (error) {
    if (error?.fallback) return error.fallback;  // no WebGL2: the pages still show, as still pages
    showProblem(`This book could not be opened. ${error?.message ?? error}`);
    return null;
  }
}

/** The book on the page, once open (null when it could not be opened): for the page's own scripts. */
export const book = open();

/** A question to the service worker `worker`, answered on a port of its own (web/reader/service-worker.js). */
function ask(worker, message) {
  return new Promise((resolve) => {
    const channel = new MessageChannel();
    channel.port1.onmessage = ({ data }) => resolve(data);
    worker.postMessage(message, [channel.port2]);
  });
}

/**
 * A published site's service worker (sw.js beside index.html, written by conecurl publish): registered
 * once the book is open and the page has loaded, so it never delays the first spread; where the browser
 * has service workers (https, localhost). Once it controls the page, it keeps the files the page read
 * before (the pages of the first spread and those near it). Resolves to the registration, null where
 * there is none.
 */
async function registerServiceWorker() {
  const container = navigator.serviceWorker;
  if (!main.dataset.document || !container) return null;
  await book;
  if (document.readyState !== 'complete') await new Promise((resolve) => addEventListener('load', resolve, { once: true }));
  const registration = await container.register(new URL('sw.js', location.href), { scope: './', updateViaCache: 'none' });
  takeOverWhenInstalled(registration);
  registration.update().catch(() => {});  // offline: the worker kept serves on
  // A page left open (a tab come back to, an installed app brought back) looks for a new publish too.
  document.addEventListener('visibilitychange', () => {
    if (document.visibilityState === 'visible') registration.update().catch(() => {});
  });
  if (!container.controller) await new Promise((resolve) => container.addEventListener('controllerchange', resolve, { once: true }));
  await (await book)?.whenIdle();  // the pages asked for before the worker took over have arrived
  await ask(container.controller, { type: 'conecurl-keep-read', urls: performance.getEntriesByType('resource').map((entry) => entry.name) });
  return registration;
}

/** How often, and how many times, a waiting worker is asked to take over (takeOverWhenInstalled). */
const TAKE_OVER = { everyMs: 1000, times: 60 };

/**
 * A new publish's worker, once installed, is asked to take over, and asked again each second while it
 * still waits. It asks for itself at install (skipWaiting), but Chromium abandons an activation when a
 * fetch reaches the outgoing worker at that moment (this page loading, its idle reads of the text files)
 * and then leaves the new worker waiting until every tab of the site is closed.
 */
function takeOverWhenInstalled(registration) {
  let asked = 0;
  let timer = 0;
  const ask = () => {
    clearTimeout(timer);
    const waiting = registration.waiting;
    if (!waiting || asked >= TAKE_OVER.times) return;
    asked += 1;
    waiting.postMessage({ type: 'conecurl-skip-waiting' });
    timer = setTimeout(ask, TAKE_OVER.everyMs);  // a retry's spacing: each ask is one more chance at a quiet moment
  };
  const installed = (worker) => {
    ask();
    // The page may be of the old version: it loads again now, whether or not the worker takes over. The worker
    // that installed is asked its version itself: by then it may have left `waiting` (its skipWaiting at install).
    reloadIfStale(worker);
  };
  const follow = (worker) => {
    if (worker?.state === 'installing') worker.addEventListener('statechange', () => { if (worker.state === 'installed') installed(worker); });
  };
  if (registration.waiting) installed(registration.waiting);
  follow(registration.installing);
  registration.addEventListener('updatefound', () => follow(registration.installing));
}

/**
 * A page shown by one version of the site loads again when the site's newest worker (`newest`, one just
 * installed; else one installed and waiting, else the controller) is of another: its version (index.html's conecurl-site-version, written
 * by conecurl publish) is asked of that worker at once, at each change of controller, and when a new
 * worker has installed. A worker that took over before this module ran leaves no controllerchange to
 * hear, so the page never counts changes, it compares versions. An old worker steps aside while a new
 * one waits (service-worker.js), so the reload gets the new version even while Chromium holds the new
 * worker back. One reload a version: a server still sending the old page cannot make it loop.
 */
async function reloadIfStale(newest = null) {
  const container = navigator.serviceWorker;
  const mine = document.querySelector('meta[name="conecurl-site-version"]')?.content;
  if (!main.dataset.document || !container || !mine) return;
  const worker = newest ?? (await container.getRegistration().catch(() => null))?.waiting ?? container.controller;
  if (!worker) return;
  const { version } = await ask(worker, { type: 'conecurl-version' });
  const key = `conecurl-reloaded ${mine} for ${version}`;
  if (!version || version === mine || sessionStorage.getItem(key)) return;
  sessionStorage.setItem(key, '1');
  location.reload();
}
if (main.dataset.document) {  // a published site's page: only those have a worker of the site's
  navigator.serviceWorker?.addEventListener('controllerchange', () => reloadIfStale());
  reloadIfStale();
}

/**
 * The service worker's registration once it controls the page and keeps what it read; null where there
 * is none (not a published site, no service workers, registration refused); pending while it installs.
 */
export const serviceWorker = registerServiceWorker().catch((error) => {
  console.warn(`conecurl reader: the service worker could not be registered (${error?.message ?? error}); the book reads online only`);
  return null;
});
