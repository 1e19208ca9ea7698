// Where a book opens and what remembers its page: `hash: true` keeps #page=N (N counted from 1) in the
// address, so a link opens the book there and the back and forward buttons turn it; `rememberPage:
// 'key'` keeps the page in localStorage and opens there next time. The address wins over the memory.
// A passage link, #page=N&text=..., opens the book at page N and marks the text there as a search hit
// (the address's form: document/passage-address.js).
import { hashPage, hashPassage } from '../document/passage-address.js';

const storageKey = (key) => `conecurl:page:${key}`;

/**
 * Marks the passage the address names with the book's search (search() and showHit(), the hit on the
 * passage's page, else the nearest). Resolves with the hit shown, or null.
 */
export async function markPassage(book, passage) {
  if (!passage || typeof book.search !== 'function' || typeof book.showHit !== 'function') return null;
  const hits = await book.search(passage.text);
  if (!hits.length) return null;
  const hit = hits.reduce((best, h) => (Math.abs(h.page - passage.page) < Math.abs(best.page - passage.page) ? h : best));
  await book.showHit(hit);
  return hit;
}

function storedPage(key) {
  try {
    const raw = globalThis.localStorage?.getItem(storageKey(key));
    return raw === null || raw === undefined ? null : Number(raw);
  } catch {
    return null;  // storage switched off (private mode, a sandboxed frame): nothing remembered
  }
}

/** The page to open at: the address's #page=N, else the remembered page, else startPage; within the book. */
export function openingPage(settings, pageCount) {
  const wanted = [settings.hash ? hashPage() : null, settings.rememberPage ? storedPage(settings.rememberPage) : null]
    .find((page) => Number.isInteger(page) && page >= 0 && page < pageCount);
  return wanted ?? settings.startPage;
}

/**
 * Follows the book's page into the address and the memory, and the address (back, forward, a link
 * to #page=N) into the book. `book` has page, pageCount, flip() and turned events; returns the detach.
 */
export function followPage(book, settings) {
  if (!settings.hash && !settings.rememberPage) return () => {};
  // Flips the address asked for (a hash change fires popstate and hashchange: two) are not written back
  // as new entries while any is under way.
  let fromAddress = 0;
  // A turn is a new history entry; pages inserted or removed before the page shown only renumber it
  // (the entry there now says the new number).
  const onTurned = (event) => {
    const page = book.page;
    if (settings.rememberPage) {
      try { globalThis.localStorage?.setItem(storageKey(settings.rememberPage), String(page)); } catch { /* off */ }
    }
    if (!settings.hash || fromAddress !== 0 || hashPage() === page) return;
    if (event.type === 'pageschange') history.replaceState(null, '', `#page=${page + 1}`);
    else history.pushState(null, '', `#page=${page + 1}`);
  };
  const onAddress = () => {
    const page = hashPage();
    if (page === null || page >= book.pageCount) return;
    fromAddress++;
    const passage = hashPassage();
    book.flip(page).then(() => markPassage(book, passage)).catch(() => {}).finally(() => { fromAddress--; });
  };
  // The book opened at a passage link's page: once ready, its text is marked there.
  const onReady = () => { if (settings.hash) markPassage(book, hashPassage()).catch(() => {}); };
  book.addEventListener('ready', onReady, { once: true });
  book.addEventListener('turned', onTurned);
  book.addEventListener('pageschange', onTurned);
  if (settings.hash) {
    addEventListener('popstate', onAddress);
    addEventListener('hashchange', onAddress);
  }
  return () => {
    book.removeEventListener('ready', onReady);
    book.removeEventListener('turned', onTurned);
    book.removeEventListener('pageschange', onTurned);
    removeEventListener('popstate', onAddress);
    removeEventListener('hashchange', onAddress);
  };
}
