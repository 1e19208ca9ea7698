// The elements a Flipbook puts in its container: a focusable region that holds the canvas, a polite
// live region announcing the open pages, and visually hidden text of those pages for screen readers.
import { keyShortcuts } from '../input/input-keys.js';
import { directionFacts } from '../engine/direction.js';

// The focus ring, and HTML pages with turnArea 'page': a press on their content turns the page unless
// it lands on something interactive (html-pages.js).
const BOOK_CSS = `
.conecurl-book:focus { outline: none; }
.conecurl-book:focus-visible {
  outline: var(--conecurl-focus-ring, 3px solid #1a5fd6);
  outline-offset: var(--conecurl-focus-ring-offset, -3px);
}
.conecurl-html-page[data-turn-area="page"] { pointer-events: none !important; }
.conecurl-html-page[data-turn-area="page"] :is(a, button, input, select, textarea, label, summary, video, audio,
  iframe, [contenteditable], [tabindex], [data-conecurl-interactive]) { pointer-events: auto; }`;
// Out of sight but read by screen readers (the usual clip pattern).
const VISUALLY_HIDDEN = 'position:absolute;width:1px;height:1px;margin:-1px;padding:0;border:0;'
  + 'overflow:hidden;clip:rect(0 0 0 0);clip-path:inset(50%);white-space:nowrap';

let sharedSheet = null;

// A :focus-visible rule cannot be an inline style. A constructed sheet adopted by the container's
// document or shadow root works under a strict CSP; a <style> in the book is the fallback.
function installFocusRing(container, root) {
  const scope = container.getRootNode();
  const canAdopt = typeof CSSStyleSheet === 'function' && 'replaceSync' in CSSStyleSheet.prototype
    && scope && 'adoptedStyleSheets' in scope;
  if (canAdopt) {
    if (!sharedSheet) {
      sharedSheet = new CSSStyleSheet();
      sharedSheet.replaceSync(BOOK_CSS);
    }
    if (!scope.adoptedStyleSheets.includes(sharedSheet)) scope.adoptedStyleSheets = [...scope.adoptedStyleSheets, sharedSheet];
    return;
  }
  const style = document.createElement('style');
  style.textContent = BOOK_CSS;
  root.append(style);
}

/** Text of the live region: 1-based page numbers, an en dash between two. */
export function describeOpenPages(pages, pageCount) {
  if (pages.length === 0) return `No page of ${pageCount}`;
  const [first, last] = [pages[0] + 1, pages[pages.length - 1] + 1];
  return first === last ? `Page ${first} of ${pageCount}` : `Pages ${first}\u2013${last} of ${pageCount}`;
}

export function createShell(container, { label, direction }) {
  const root = document.createElement('div');
  root.className = 'conecurl-book';
  root.tabIndex = 0;
  root.setAttribute('role', 'region');
  root.setAttribute('aria-roledescription', 'book');
  root.setAttribute('aria-label', label);
  root.setAttribute('aria-keyshortcuts', keyShortcuts(direction));
  // touch-action on the whole book (the text and link layers, HTML pages): the browser may scroll the
  // host page across the turn, never pinch-zoom it or zoom it on a double tap over the book.
  const touchAction = directionFacts(direction).touchAction;
  root.style.cssText = `position:relative;width:100%;height:100%;touch-action:${touchAction}`;

  const canvas = document.createElement('canvas');
  canvas.setAttribute('aria-hidden', 'true');
  // The browser keeps the scrolling that does not turn pages (swipes go along the turn): a stroke across
  // the turn still scrolls the host page. Pinches and double taps stay with the book (it zooms itself);
  // zoomed in, book-zoom.js makes it 'none' (one finger pans the book).
  canvas.style.cssText = `position:relative;display:block;width:100%;height:100%;touch-action:${touchAction}`;  // positioned: over the first-view poster

  const status = document.createElement('div');
  status.setAttribute('role', 'status');
  status.setAttribute('aria-live', 'polite');
  status.setAttribute('aria-atomic', 'true');
  status.style.cssText = VISUALLY_HIDDEN;

  const pageText = document.createElement('div');
  pageText.style.cssText = VISUALLY_HIDDEN;

  root.append(canvas, status, pageText);
  container.append(root);
  installFocusRing(container, root);

  return {
    root,
    canvas,
    /** A fresh canvas (no context) in the present one's place, with its attributes and style; returns it. */
    replaceCanvas() {
      const fresh = this.canvas.cloneNode(false);
      this.canvas.replaceWith(fresh);
      this.canvas = fresh;
      return fresh;
    },
    /**
     * Shows the open pages: `pages` are their indices, `alts` their alt text (or undefined). Text
     * only ever goes in as textContent: alt strings come from the page author.
     */
    showOpenPages(pages, pageCount, alts) {
      const summary = describeOpenPages(pages, pageCount);
      if (status.textContent !== summary) status.textContent = summary;
      const lines = pages.map((page, i) => {
        const line = document.createElement('p');
        line.textContent = alts[i] ? `Page ${page + 1}: ${alts[i]}` : `Page ${page + 1}`;
        return line;
      });
      pageText.replaceChildren(...lines);
    },
    get announcement() { return status.textContent; },
    remove() { root.remove(); },
  };
}
