// Events a user can always hear, for Flipbook and its static fallback alike: what a book dispatches
// while create() runs is held and delivered, in order, just after create() resolves (so a listener
// added right after `await Flipbook.create(...)` hears the first view's page errors), and the `on`
// option's listeners are registered before anything happens.

/**
 * Every event a book dispatches and the fields of its detail ('?': not always there), as
 * FlipbookEventMap in flipbook.d.ts types them (tests/node/typings.test.mjs compares the two, and
 * tests/browser/element.spec.js each event dispatched with this).
 */
export const EVENT_DETAILS = {
  ready: ['page'],
  progress: ['loaded', 'total', 'pending'],
  pageerror: ['index', 'error', 'reason'],
  turnstart: ['direction', 'page', 'drag?', 'riffle?'],
  turned: ['page'],
  turncancel: ['page'],
  resize: ['width', 'height', 'display'],
  zoom: ['scale'],
  sharpened: ['index', 'width'],
  link: ['page', 'href', 'toPage?'],
  pageschange: ['change', 'at', 'count', 'pageCount', 'page'],
  error: ['error'],
  // docapi (issue 23): the document API's events (download and print are cancelable).
  searchchange: ['query', 'hits', 'current'],
  fullscreenchange: ['fullscreen'],
  download: ['url'],
  print: ['pages'],
  // textlayer (issue 23)
  passagelink: ['page', 'text', 'url', 'copied'],
  // phone (issue 28): the display in effect changed (display 'auto' chose again, or setOptions); a tap or
  // click on the middle of the book (CSS px from the book element's corner), which turns nothing.
  displaychange: ['display', 'previous'],
  middletap: ['x', 'y'],
  // read-aloud (issue 31): a reading started, moved to a page (what it reads there: 'narration', 'text',
  // 'alt' or 'none'), said a word (its rects as fractions of the page), paused, resumed, and ended
  // (reason 'finished', 'stopped', 'turned', 'pageschange', 'destroyed' or 'error').
  readaloudstart: ['page', 'lang', 'voice'],
  readaloudpage: ['page', 'source'],
  readaloudword: ['page', 'index', 'text', 'rects'],
  // a sentence (or a long sentence's clause) begins: its first and last word's indices, one rect a line
  readaloudsentence: ['page', 'from', 'to', 'text', 'rects'],
  // the browser listed its voices after canReadAloud() had answered false: ask again
  readaloudvoices: ['count'],
  readaloudpause: ['page'],
  readaloudresume: ['page'],
  readaloudend: ['reason', 'page', 'error?'],
};
/** Every event a book dispatches. */
export const BOOK_EVENTS = Object.keys(EVENT_DETAILS);

export class BookEvents {
  /** @param {EventTarget} target the book @param {Record<string, Function>} [on] listeners by event type */
  constructor(target, on = {}) {
    this._target = target;
    this._held = [];          // null once released: events then go out at once
    this._resolved = false;   // create() has resolved: the caller can listen now
    for (const [type, listener] of Object.entries(on)) target.addEventListener(type, listener);
  }

  /**
   * Dispatches `event` now, or holds it while create() runs. An event of the book's life after
   * create() resolved (a turn asked for at once) first lets out what was held, so the order stays and
   * nothing waits. Returns dispatchEvent's answer (true when held).
   */
  dispatch(event) {
    if (this._held && !this._resolved) {
      this._held.push(event);
      return true;
    }
    if (this._held) this.releaseNow();
    return this._target.dispatchEvent(event);
  }

  /** create() resolved: what was held goes out in the next task, after the caller's continuation. */
  releaseSoon() {
    this._resolved = true;
    setTimeout(() => this.releaseNow(), 0);
  }

  /** The book is about to change under what is held (its pages): once create() resolved, let it out first. */
  flush() {
    if (this._held && this._resolved) this.releaseNow();
  }

  releaseNow() {
    const held = this._held ?? [];
    this._held = null;
    this._resolved = true;
    for (const event of held) this._target.dispatchEvent(event);
  }

  /** The book is destroyed: what is held is dropped, nothing more goes out. */
  drop() {
    this._held = [];
  }
}
