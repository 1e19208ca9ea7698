// One book kept in a container for a framework component (react.js, vue.js): built once the component
// is mounted, given each new set of props (the live options applied to the running book, changed pages
// inserted, removed or replaced in it, any other change builds a new book at the page shown), destroyed
// on unmount, however often that happens (StrictMode mounts twice); its events go to the handler props,
// its state to subscribers.
import { Flipbook } from '../book/flipbook.js';
import { BOOK_EVENTS } from '../book/book-events.js';
import { DEFAULTS, LIVE_OPTIONS } from '../book/options.js';
import { clampPage, fixedOptionsDiffer, optionsOf, pageChanges, samePages } from './framework-props.js';

export class BookMount {
  /**
   * @param {(type: string, event: CustomEvent) => void} emit  hands a book event to the component
   * @param {(page: number) => void} onPageChange  the page shown changed (a turn landed, a jump)
   */
  constructor(emit, onPageChange) {
    this._emit = emit;
    this._onPageChange = onPageChange;
    this._container = null;
    this._props = {};
    this._book = null;
    this._builds = 0;       // a book whose build is not the latest is destroyed as soon as it exists
    this._page = null;      // the page to open at: the page shown when the last book went
    this._reported = null;  // the page last told to onPageChange
    this._listeners = new Set();
    this._waiters = [];     // calls made before a book is ready
    this.handle = this._makeHandle();
  }

  /** The component is in the document: build the book in `container` from `props`. */
  mount(container, props) {
    this._container = container;
    this._props = props;
    this._build();
  }

  /** The component rendered again: apply what changed. */
  update(props) {
    const before = this._props;
    this._props = props;
    if (!this._container) return;
    const pagesChanged = !samePages(before.pages, props.pages);
    // Pages change on the running book; into or out of a PDF (no pages), or before it exists, a new one.
    if (fixedOptionsDiffer(before, props) || (pagesChanged && !(this._book && Array.isArray(before.pages) && Array.isArray(props.pages)))) {
      this._build();
      return;
    }
    if (pagesChanged) this._changePages(before.pages, props.pages);
    const live = {};
    for (const name of LIVE_OPTIONS) if (!Object.is(before[name], props[name])) live[name] = props[name] ?? DEFAULTS[name];
    if (this._book && Object.keys(live).length > 0) {
      try {
        this._book.setOptions(live);
      } catch (error) {
        this._report(error);  // the book keeps its previous settings
      }
    }
    // A controlled page that only echoes what onPageChange reported (a leaf of a longer flip landing)
    // is not a new wish: the flip under way goes on.
    if (props.page !== undefined && !Object.is(props.page, before.page) && props.page !== this._reported) {
      if (this._book) this._book.flip(clampPage(props.page, this._book.pageCount)).catch((error) => this._report(error));
      else this._page = props.page;
    }
  }

  // Called in order, applied in order (the book queues them); a failed one leaves the pages it found.
  _changePages(before, after) {
    const book = this._book;
    for (const [method, ...args] of pageChanges(before, after)) {
      book[method](...args).catch((error) => { if (book === this._book) this._report(error); });
    }
  }

  /** The component left the document: the book is destroyed now, a build under way as soon as it ends. */
  unmount() {
    this._container = null;
    this._builds++;
    this._dropBook();
    const gone = new Error('conecurl: the flipbook was unmounted before it was ready');
    for (const waiter of this._waiters.splice(0)) waiter.reject(gone);
    this._changed();
  }

  // ---- building ----------------------------------------------------------------------------------

  _build() {
    const build = ++this._builds;
    this._dropBook();
    this._changed();
    const props = this._props;
    const options = optionsOf(props);
    const wanted = this._page ?? props.page ?? props.defaultPage ?? 0;
    options.startPage = Array.isArray(options.pages) ? clampPage(wanted, options.pages.length) : wanted;
    // Listeners by option: what the book says while it is made is heard too (book-events.js).
    let errorHeard = false;
    options.on = Object.fromEntries(BOOK_EVENTS.map((type) => [type, (event) => {
      if (type === 'error') errorHeard = true;
      if (build === this._builds) this._onBookEvent(type, event);
    }]));
    const adopt = (book) => {
      if (build !== this._builds) {
        book.destroy();
        return;
      }
      this._book = book;
      this._page = book.page;
      for (const waiter of this._waiters.splice(0)) waiter.resolve(book);
      this._changed();
    };
    Flipbook.create(this._container, options).then(adopt, (error) => {
      // Without WebGL2 or the engine the still book that took its place is the book.
      if (error.fallback) {
        adopt(error.fallback);
        return;
      }
      if (build !== this._builds) return;
      if (!errorHeard) this._report(error);  // refused before a book existed (a bad option): no event told it
      for (const waiter of this._waiters.splice(0)) waiter.reject(error);
    });
  }

  _dropBook() {
    if (!this._book) return;
    this._page = this._book.page;
    this._book.destroy();
    this._book = null;
  }

  _onBookEvent(type, event) {
    // Pages inserted or removed before the page shown renumber it: the page prop follows.
    if (type === 'turned' || (type === 'pageschange' && event.detail.page !== this._page)) {
      this._page = event.detail.page;
      this._reported = event.detail.page;
      this._onPageChange(event.detail.page);
    }
    this._emit(type, event);
    if (type === 'turned' || type === 'resize' || type === 'ready' || type === 'pageschange') this._changed();
  }

  _report(error) {
    this._emit('error', new CustomEvent('error', { detail: { error } }));
  }

  // ---- state and calls ---------------------------------------------------------------------------

  /** { ready, page, pageCount, display } now. */
  get state() {
    const book = this._book;
    return book
      ? { ready: true, page: book.page, pageCount: book.pageCount, display: book.display }
      : { ready: false, page: this._page ?? this._props.page ?? this._props.defaultPage ?? 0, pageCount: 0, display: null };
  }

  _changed() {
    const state = this.state;
    for (const listener of this._listeners) listener(state);
  }

  // The book now, or once it is ready (a call made while it is built waits for it).
  _whenBook() {
    if (this._book) return Promise.resolve(this._book);
    return new Promise((resolve, reject) => this._waiters.push({ resolve, reject }));
  }

  _makeHandle() {
    const mount = this;
    return {
      next: () => mount._whenBook().then((book) => book.next()),
      prev: () => mount._whenBook().then((book) => book.prev()),
      flip: (index, options) => mount._whenBook().then((book) => book.flip(index, options)),
      get page() { return mount.state.page; },
      get pageCount() { return mount.state.pageCount; },
      get display() { return mount.state.display; },
      get ready() { return mount.state.ready; },
      get zoom() { return mount._book ? mount._book.zoom : 1; },
      set zoom(scale) { if (mount._book) mount._book.zoom = scale; },
      /** The Flipbook (or its StaticBook fallback) underneath, null while it is built. */
      get book() { return mount._book; },
      /** Calls `listener(state)` now and whenever ready, page, pageCount or display change; returns the unsubscribe. */
      subscribe(listener) {
        mount._listeners.add(listener);
        listener(mount.state);
        return () => mount._listeners.delete(listener);
      },
    };
  }
}
