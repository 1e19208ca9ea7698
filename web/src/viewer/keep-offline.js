// The More menu's "Keep offline" (the `keepOffline` part, which a published site's reader turns on): the
// service worker that controls the page (conecurl publish's sw.js) says which of the site's files it
// keeps; the item shows the size of those it lacks, and a press fetches them through it, with progress
// in a live region, until the whole book reads offline. Present only while such a worker controls the page.
import { fill } from './viewer-labels.js';

/** Files fetched at once. */
const AT_ONCE = 4;
/** The live region says the progress at each step of this many percent (not at every file). */
const STEP = 10;

/**
 * What the controlling service worker says of the site ({ version, files: [{ url, bytes, kept }] }),
 * or null where none controls the page or it does not answer the question.
 */
export function offlinePlan(container = globalThis.navigator?.serviceWorker) {
  const worker = container?.controller;
  if (!worker || typeof MessageChannel !== 'function') return Promise.resolve(null);
  return new Promise((resolve) => {
    const channel = new MessageChannel();
    channel.port1.onmessage = ({ data }) => resolve(Array.isArray(data?.files) ? data : null);
    worker.postMessage({ type: 'conecurl-offline-plan' }, [channel.port2]);
  });
}

/** A size for people: "840 KB", "12.5 MB". */
export function sizeText(bytes) {
  if (bytes < 1e6) return `${Math.max(1, Math.round(bytes / 1e3))} KB`;
  return `${(bytes / 1e6).toFixed(bytes < 1e8 ? 1 : 0)} MB`;
}

/** Fetches `files` ([{ url, bytes }]) AT_ONCE at a time, each read whole; `onFile(file)` after each. Rejects on the first failure. */
export async function fetchFiles(files, onFile) {
  const queue = [...files];
  const next = async () => {
    for (let file = queue.shift(); file; file = queue.shift()) {
      const response = await fetch(file.url, { credentials: 'same-origin' });
      if (!response.ok) throw new Error(`${file.url}: HTTP ${response.status}`);
      await response.arrayBuffer();
      onFile(file);
    }
  };
  await Promise.all(Array.from({ length: Math.min(AT_ONCE, files.length) }, next));
}

/**
 * The Keep offline part of the viewer `element`: its item in `toolbar`'s More menu (texts from `text`),
 * its live region, and what a press does. Returns { press(), remove() }.
 */
export function keepOfflinePart(book, toolbar, text, element, container = globalThis.navigator?.serviceWorker) {
  const status = document.createElement('div');
  status.className = 'conecurl-offline-status';
  status.setAttribute('role', 'status');
  status.hidden = true;
  const words = document.createElement('span');
  const bar = document.createElement('progress');
  bar.max = 100;
  bar.setAttribute('aria-hidden', 'true');  // the words say it
  status.append(words, bar);
  element.append(status);
  let busy = false;
  let removed = false;
  const say = (message, percent = null) => {
    status.hidden = false;
    words.textContent = message;
    bar.hidden = percent === null;
    if (percent !== null) bar.value = percent;
  };
  const disabled = (off) => toolbar.menu.items.keepOffline?.setAttribute('aria-disabled', String(off));

  /** The item as the worker's answer says: absent without one, the size left to fetch, or kept. */
  async function refresh() {
    const plan = await offlinePlan(container);
    if (removed || busy) return;
    if (!plan) {
      toolbar.setPresent('keepOffline', false);
      return;
    }
    const left = plan.files.filter((file) => !file.kept).reduce((sum, file) => sum + file.bytes, 0);
    const kept = plan.files.every((file) => file.kept);
    toolbar.relabel('keepOffline', kept ? 'keptOffline' : 'keepOffline', 'keepOffline', kept ? text.keptOffline : fill(text.keepOffline, { size: sizeText(left) }));
    disabled(kept);
    toolbar.setPresent('keepOffline', true);
  }

  async function press() {
    if (busy) return;
    busy = true;
    disabled(true);
    try {
      const plan = await offlinePlan(container);
      const missing = plan?.files.filter((file) => !file.kept) ?? [];
      const total = missing.reduce((sum, file) => sum + file.bytes, 0);
      let done = 0;
      let said = -1;
      const progress = () => {
        const percent = total > 0 ? Math.floor((done / total) * 100) : 100;
        bar.value = percent;
        if (Math.floor(percent / STEP) === said) return;
        said = Math.floor(percent / STEP);
        say(fill(text.keepingOffline, { percent, size: sizeText(total) }), percent);
      };
      progress();
      await fetchFiles(missing, (file) => {
        done += file.bytes;
        progress();
      });
      const after = await offlinePlan(container);
      if (!after || after.files.some((file) => !file.kept)) throw new Error('the service worker did not keep every file');
      say(text.keptOffline);
    } catch {
      say(text.keepOfflineFailed);
    } finally {
      busy = false;
      if (!removed) await refresh();
    }
  }

  // The note goes once the reader turns on after it finished.
  const turned = () => { if (!busy) status.hidden = true; };
  book.addEventListener('turned', turned);
  container?.addEventListener?.('controllerchange', refresh);
  // The size said again each time the More menu opens: the worker keeps pages as they are read.
  const opened = new MutationObserver(() => { if (toolbar.menu.isOpen()) refresh(); });
  opened.observe(toolbar.menu.button, { attributes: true, attributeFilter: ['aria-expanded'] });
  refresh();
  return {
    press,
    remove() {
      removed = true;
      opened.disconnect();
      book.removeEventListener('turned', turned);
      container?.removeEventListener?.('controllerchange', refresh);
      status.remove();
    },
  };
}
