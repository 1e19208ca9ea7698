// A published site's service worker: `conecurl publish` writes it as sw.js at the site's root with SITE
// filled in (cli/publish/web-app.mjs), so the reader and the pages read stay readable offline.
// At install it precaches SITE.shell (the page, the reader, book.json, the icons); every other file of
// the site is kept as it is read (cache first), and those the page read before it took over when the
// reader says ("conecurl-keep-read"); the More menu's Keep offline asks it for SITE.files
// ("conecurl-offline-plan") and fetches those it lacks through it. Its cache is named by the site's
// folder and SITE.version (a hash of the files written): a new publish installs a new worker that
// takes over at once, moves what the old version's cache kept and it serves unchanged (SITE.files names
// each file's hash) into its own, and deletes the old cache; a page of another version asks it its version
// ("conecurl-version") and loads again. Every URL is relative to its scope, so the
// site works under any sub-path. Requests for anything else pass by untouched.
const SITE = null;  // replaced by conecurl publish

const PREFIX = 'conecurl-site ';
const scope = self.registration.scope;
const OWN = `${PREFIX}${scope} `;
const CACHE = `${OWN}${SITE.version}`;
/** A site file's absolute URL, its path encoded as index.html's links encode it. */
const urlOf = (file) => new URL(file.split('/').map(encodeURIComponent).join('/'), scope).href;
const FILES = new Map(SITE.files.map(([file, bytes, hash]) => [urlOf(file), { bytes, hash }]));
const INDEX = urlOf('index.html');

self.addEventListener('install', (event) => {
  event.waitUntil((async () => {
    const cache = await caches.open(CACHE);
    // From the server, not the HTTP cache: a file kept there an hour may be the last publish's.
    await cache.addAll(SITE.shell.map((file) => new Request(urlOf(file), { cache: 'reload' })));
    await self.skipWaiting();
  })());
});

/** A response's body hashed as publish hashes a file (sha-256, its first 16 hex digits). */
async function contentHash(response) {
  const digest = new Uint8Array(await crypto.subtle.digest('SHA-256', await response.arrayBuffer()));
  return Array.from(digest.slice(0, 8), (byte) => byte.toString(16).padStart(2, '0')).join('');
}

/**
 * What an older version's cache `name` kept (pages read, or the whole book by Keep offline) and this
 * version's has not: each file this version still serves with the same contents moves over, so a reader
 * who kept the book offline keeps it across a re-publish that left those files as they were.
 */
async function carryOver(name, cache) {
  const old = await caches.open(name);
  for (const request of await old.keys()) {
    const file = FILES.get(request.url);
    if (!file || await cache.match(request.url)) continue;
    const response = await old.match(request);
    if (response?.status === 200 && await contentHash(response.clone()) === file.hash) await cache.put(request.url, response);
  }
}

self.addEventListener('activate', (event) => {
  event.waitUntil((async () => {
    const cache = await caches.open(CACHE);
    for (const name of await caches.keys()) {
      if (!name.startsWith(OWN) || name === CACHE) continue;
      await carryOver(name, cache).catch(() => {});  // what cannot move is fetched again as it is read
      await caches.delete(name);
    }
    await self.clients.claim();
  })());
});

/** The site file a request asks for (its URL without query), or null: the folder itself is index.html. */
function siteFile(request) {
  const url = new URL(request.url);
  url.search = '';
  url.hash = '';
  if (request.mode === 'navigate' && url.href === scope) return INDEX;
  return FILES.has(url.href) ? url.href : null;
}

/** The file from this version's cache; else from the server (revalidated), kept for next time. */
async function cacheFirst(file, request = null) {
  const cache = await caches.open(CACHE);
  const kept = await cache.match(file);
  if (kept) return kept;
  // A range of a recording not kept (narration's <audio>): the server answers it, nothing is kept.
  if (request?.headers.has('range')) return fetch(request);
  const response = await fetch(file, { cache: 'no-cache', credentials: 'same-origin' });
  // Kept before it is answered, so a page that fetched it (Keep offline) finds it kept when the fetch ends.
  if (response.status === 200) await cache.put(file, response.clone()).catch(() => {});
  return response;
}

/**
 * While a newer publish's worker is installed and waiting, this one answers from the server (from its own
 * cache offline): Chromium can hold the new worker back for as long as a tab is open (an activation it
 * abandons when a fetch reaches this worker at that moment), and a page reloaded meanwhile must get the
 * new version, not this one's.
 */
async function fromServer(file, request) {
  try {
    return await (request.headers.has('range') ? fetch(request) : fetch(file, { cache: 'no-cache', credentials: 'same-origin' }));
  } catch {
    return cacheFirst(file, request);
  }
}

self.addEventListener('fetch', (event) => {
  if (event.request.method !== 'GET') return;
  const file = siteFile(event.request);
  if (!file) return;
  event.respondWith(self.registration.waiting ? fromServer(file, event.request) : cacheFirst(file, event.request));
});

/** Keep offline's question: every file of the site, its size, and whether this version's cache holds it. */
async function plan() {
  const kept = new Set((await (await caches.open(CACHE)).keys()).map((request) => request.url));
  return { version: SITE.version, files: [...FILES].map(([url, { bytes }]) => ({ url, bytes, kept: kept.has(url) })) };
}

/**
 * The reader's, once this worker controls its page: `urls` the page read before (its resource timing),
 * those of the site kept as if read through this worker. Answers how many of the site's it holds.
 */
async function keepRead(urls) {
  if (self.registration.waiting) return { kept: 0 };  // stepping aside: the newer worker keeps what is read
  const files = [...new Set(urls.map((url) => siteFile({ url, mode: 'cors' })).filter(Boolean))];
  const kept = await Promise.all(files.map((file) => cacheFirst(file).then((response) => response.ok, () => false)));
  return { kept: kept.filter(Boolean).length };
}

// The page's questions, each answered on the port it sent.
self.addEventListener('message', (event) => {
  // The reader's, while this worker waits and an older one still controls its page (reader.js).
  if (event.data?.type === 'conecurl-skip-waiting') {
    event.waitUntil(self.skipWaiting());
    return;
  }
  const port = event.ports?.[0];
  const answer = {
    'conecurl-version': async () => ({ version: SITE.version }),
    'conecurl-offline-plan': () => plan(),
    'conecurl-keep-read': () => keepRead(event.data.urls ?? []),
  }[event.data?.type];
  if (!port || !answer) return;
  event.waitUntil(answer().then((reply) => port.postMessage(reply)));
});
