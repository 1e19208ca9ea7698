// The address of a page and of a passage in it: #page=N (N from 1) and #page=N&text=... (the passage's
// words, which search finds again). Written by passage links (passage-link.js), read by the page memory.
const HASH = /^#page=(\d+)(?:&text=([^&]*))?$/;

/** The page (from 0) the address names (#page=N, N from 1), or null. */
export function hashPage() {
  const match = HASH.exec(globalThis.location?.hash ?? '');
  return match ? Number(match[1]) - 1 : null;
}

/** The passage the address names (#page=N&text=...): { page (from 0), text }, or null. */
export function hashPassage(hash = globalThis.location?.hash ?? '') {
  const match = HASH.exec(hash);
  if (!match || match[2] === undefined) return null;
  let text;
  try {
    text = decodeURIComponent(match[2]).trim();
  } catch {
    return null;  // a malformed escape is no passage
  }
  return text ? { page: Number(match[1]) - 1, text } : null;
}

/** The link to a passage on page `page` (from 0): this document's address with #page=N&text=... */
export function passageUrl(page, text, location = globalThis.location) {
  return `${location.origin}${location.pathname}${location.search}#page=${page + 1}&text=${encodeURIComponent(text)}`;
}
