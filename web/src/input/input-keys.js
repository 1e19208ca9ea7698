// Keys on the book's element: the arrows along the turn, PageUp/PageDown and Home/End turn pages;
// + - = and 0 zoom. The one map of the book's keys (the shell's aria-keyshortcuts is made from it).
import { directionFacts } from '../engine/direction.js';

const ZOOM_STEP = 1.25;  // one press of + or -

const COMMON_KEYS = { PageDown: 'forward', PageUp: 'backward', Home: 'first', End: 'last' };

/** The keys a book of `direction` answers, as aria-keyshortcuts lists them. */
export function keyShortcuts(direction) {
  return [...Object.keys(directionFacts(direction).keys), ...Object.keys(COMMON_KEYS)].join(' ');
}

/**
 * What a keydown on the book asks for: 'forward', 'backward', 'first', 'last', or null (not a key of
 * the book, or one with Ctrl, Alt or Meta, which stays the browser's).
 */
export function actionForKey(event, direction) {
  if (event.defaultPrevented || event.altKey || event.ctrlKey || event.metaKey) return null;
  return directionFacts(direction).keys[event.key] || COMMON_KEYS[event.key] || null;
}

// Elements inside a page (an HTML page's) that use these keys themselves: text fields, lists, media.
function keepsKeys(target) {
  return typeof target?.closest === 'function'
    && Boolean(target.closest('input, textarea, select, video, audio, [contenteditable]:not([contenteditable="false"])'));
}

/**
 * Listens for the book's keys on `element`. `book` is the controller's input port (book/book-wiring.js, attachBookInput).
 * Returns a function that stops listening.
 */
export function listenForKeys(element, book) {
  const onKeyDown = (event) => {
    if (event.defaultPrevented || event.altKey || event.ctrlKey || event.metaKey) return;
    if (event.target !== element && keepsKeys(event.target)) return;  // typing in an HTML page's field
    const zoomKey = { '+': ZOOM_STEP, '=': ZOOM_STEP, '-': 1 / ZOOM_STEP, 0: 0 }[event.key];
    if (zoomKey !== undefined) {
      event.preventDefault();
      book.zoomAboutCentre(zoomKey === 0 ? 1 : book.zoom * zoomKey);
      return;
    }
    const action = actionForKey(event, book.direction);
    if (!action || book.zoomed()) return;  // zoomed in, the keys do not turn: 0 (or -) comes back first
    event.preventDefault();
    // Home and End jump: animating a whole book's leaves one by one would take minutes.
    if (action === 'first' || action === 'last') book.jump(action);
    // A held key repeats fast: it keeps at most one turn waiting instead of piling them up.
    else if (!(event.repeat && book.queuedTurns() > 0)) book.turn(action);
  };
  element.addEventListener('keydown', onKeyDown);
  return () => element.removeEventListener('keydown', onKeyDown);
}
