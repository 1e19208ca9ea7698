// <cone-flipbook>: the Flipbook as an HTML element, for pages without a build step. Attributes mirror
// the options (every option but `on`, whose listeners go on the element: element-attributes.js), and
// so do properties; its child elements can be the pages (an <img> an image page, any other element a
// live HTML page), and are what a browser without JavaScript shows.
import { Flipbook } from './book/flipbook.js';
import { BOOK_EVENTS } from './book/book-events.js';
import { DEFAULTS } from './book/options.js';
import { BOX_CSS } from './components/book-box.js';
import {
  ATTRIBUTES, ATTRIBUTE_OF_OPTION, LIVE_ATTRIBUTES, PROPERTY_OPTIONS, TAG, keepsValue, propertyOf, readOptionAttribute, setOptionAttribute,
} from './components/element-attributes.js';

// On a server (no DOM) the module still imports: the class has no element to be, and nothing is defined.
const ElementBase = globalThis.HTMLElement ?? class {};
const NOT_PAGES = ['script', 'style', 'template', 'link', 'meta', 'noscript'];  // children that are never pages

/**
 * Flipbook's TypeErrors name options ('startPage'); an element's user knows attributes ('start-page'),
 * or the property that gave a value kept as given (`kept`).
 */
function inAttributeTerms(error, element, kept) {
  const option = error instanceof TypeError && /option '(\w+)/.exec(error.message)?.[1];
  const attribute = option && ATTRIBUTE_OF_OPTION[option];
  if (!attribute) return error;
  const raw = element.getAttribute(attribute);
  const given = option in kept ? `property '${option}'` : `attribute '${attribute}' ${raw === null ? '(from the child elements)' : `"${raw}"`}`;
  return new TypeError(`conecurl: <${TAG}> ${given} is not valid: ${error.message.replace(/^conecurl: /, '')}`, { cause: error });
}

function deferred() {
  const handle = {};
  handle.promise = new Promise((resolve, reject) => Object.assign(handle, { resolve, reject }));
  handle.promise.catch(() => {});  // a failure nobody waited for is reported by the error event, not as unhandled
  return handle;
}

const TEMPLATE = `
<style>
  :host([hidden]) { display: none; }
  .book { width: 100%; height: 100%; }
  .failed { box-sizing: border-box; height: 100%; overflow: auto; padding: 1em; border: 2px solid #b3261e;
            background: #fff8f7; color: #5c1512; font: 14px/1.4 system-ui, sans-serif; }
  ::slotted(img) { max-width: 100%; }
</style>
<div class="book" part="book"></div>
<div class="failed" part="error" role="alert" hidden><p></p><slot></slot></div>`;

export class ConeFlipbookElement extends ElementBase {
  static get observedAttributes() { return Object.keys(ATTRIBUTES); }

  constructor() {
    super();
    // No default <slot> while the book shows: child <img> elements are page sources, and other children
    // (HTML pages) show through named slots the book makes for them.
    this.attachShadow({ mode: 'open' }).innerHTML = TEMPLATE;
    const box = document.createElement('style');  // the box a book fills, as the components' (book-box.js)
    box.textContent = `:host { ${BOX_CSS} }`;
    this.shadowRoot.prepend(box);
    this._container = this.shadowRoot.querySelector('.book');
    this._failure = this.shadowRoot.querySelector('.failed');
    this._book = null;           // the Flipbook once it is ready
    this._building = null;       // the Flipbook its create() is building: destroyed at once when the build is dropped
    this._waiter = null;         // deferred of the build scheduled or in flight
    this._error = null;          // why the last build failed
    this._generation = 0;        // a build superseded by a later one is dropped: what it made is destroyed
    this._scheduled = false;
    this._reopenAt = null;       // page to open at when the book is built again
    this._destroyed = false;
    this._held = {};             // property values no attribute holds (KEPT_VALUES): over attributes and children
    this._children = new MutationObserver((records) => {
      if (!this.hasAttribute('pages') && !('pages' in this._held) && records.some((record) => this._touchesChildPages(record))) this._schedule();
    });
  }

  /** The Flipbook inside, once ready (null before, and after a failure or destroy). */
  get book() { return this._book; }
  /** First visible page; before `ready`, the page the book will open at. */
  get page() {
    if (this._book) return this._book.page;
    if (this._reopenAt !== null) return this._reopenAt;
    const start = Number(this.getAttribute('start-page'));
    return Number.isInteger(start) && start >= 0 ? start : 0;
  }
  /** Number of pages; 0 until `ready`. */
  get pageCount() { return this._book ? this._book.pageCount : 0; }
  /** 'single' or 'double' as shown; null until `ready`. Setting it sets the display attribute (live). */
  get display() { return this._book ? this._book.display : null; }
  set display(value) { this._writeOption('display', value); }

  // The other option properties (defined below the class): the value kept as given (the pages as an
  // array, a PDF's bytes, an autoplay object: KEPT_VALUES), else the attribute's, parsed.
  _readOption(option) {
    return option in this._held ? this._held[option] : readOptionAttribute(this, option);
  }

  // A value an attribute cannot hold is kept and builds a new book; any other sets (null: removes) the
  // attribute, with the attribute's effect. A value neither takes is reported as a bad attribute is.
  _writeOption(option, value) {
    if (keepsValue(option, value)) {
      this._held[option] = value;
      this._schedule();
      return;
    }
    const had = option in this._held;
    delete this._held[option];
    try {
      setOptionAttribute(this, option, value);
    } catch (error) {
      if (LIVE_ATTRIBUTES.includes(ATTRIBUTE_OF_OPTION[option]) && this._book && !this._waiter) this._report(error);
      else this._fail(error);
      return;
    }
    if (had) this._schedule();  // the attribute may be as it was: the value kept is gone all the same
  }

  /**
   * Resolves with the Flipbook once it is ready, waiting for a build that is scheduled or running.
   * Rejects with the build's error, or at once when the element is not in the document or destroyed.
   */
  whenReady() {
    if (this._waiter) return this._waiter.promise;
    if (this._book) return Promise.resolve(this._book);
    if (this._destroyed) {
      return Promise.reject(new Error(`conecurl: this <${TAG}> was destroyed; put it in the document again to build a new book`));
    }
    if (!this.isConnected) {
      return Promise.reject(new Error(`conecurl: a <${TAG}> builds its book once it is in the document; append it first`));
    }
    return Promise.reject(this._error);
  }

  next() { return this.whenReady().then((book) => book.next()); }
  prev() { return this.whenReady().then((book) => book.prev()); }
  flip(index, options) { return this.whenReady().then((book) => book.flip(index, options)); }
  // Live page changes (live-pages.js). A changed pages attribute, property or child list still builds a new book.
  insertPages(at, pages) { return this.whenReady().then((book) => book.insertPages(at, pages)); }
  removePages(from, count) { return this.whenReady().then((book) => book.removePages(from, count)); }
  replacePage(index, page) { return this.whenReady().then((book) => book.replacePage(index, page)); }

  /** Destroys the book now; the element stays empty until it is put in the document again. */
  destroy() {
    this._destroyed = true;
    this._stop(new Error(`conecurl: this <${TAG}> was destroyed before its book was ready`));
  }

  connectedCallback() {
    // Properties a framework set before this element was defined are own properties: pass them on.
    for (const option of PROPERTY_OPTIONS) {
      if (!Object.prototype.hasOwnProperty.call(this, option)) continue;
      const value = this[option];
      delete this[option];
      this[option] = value;
    }
    this._destroyed = false;
    this._children.observe(this, { childList: true, subtree: true, attributes: true, attributeFilter: ['src', 'alt'] });
    if (!this._book && !this._waiter) this._schedule();  // else: moved within the document, the book lives on
  }

  disconnectedCallback() {
    // A move (removed and inserted in the same task) keeps the book; a removal destroys it.
    queueMicrotask(() => {
      if (this.isConnected) return;
      this._children.disconnect();
      this._stop(new Error(`conecurl: this <${TAG}> was removed from the document before its book was ready`));
    });
  }

  attributeChangedCallback(name, oldValue, value) {
    if (oldValue === value || !this.isConnected || this._destroyed) return;
    if (name === 'start-page') this._reopenAt = null;  // a new start page wins over the page kept
    if (LIVE_ATTRIBUTES.includes(name) && this._book && !this._waiter) {
      try {
        const [option, parse] = ATTRIBUTES[name];
        this._book.setOptions({ [option]: value === null ? DEFAULTS[option] : parse(value, name) });
      } catch (error) {
        this._report(error);  // the book keeps its previous setting and keeps working
      }
      return;
    }
    this._schedule();
  }

  _schedule() {
    if (!this.isConnected || this._destroyed) return;
    this._waiter ??= deferred();
    if (this._scheduled) return;
    this._scheduled = true;
    const build = () => { this._scheduled = false; this._build(); };
    // One build for a batch of changes; while the parser is still adding our child <img> elements, after it.
    if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', build, { once: true });
    else queueMicrotask(build);
  }

  async _build() {
    if (!this.isConnected || this._destroyed || !this._waiter) return;
    const generation = ++this._generation;
    this._removeBook();
    this._error = null;
    this._failure.hidden = true;
    this._container.hidden = false;
    let options;
    try {
      options = this._options();
    } catch (error) {
      this._fail(error);
      return;
    }
    const host = this;
    // Flipbook fires ready and the first progress events inside create(): hear them from the start.
    class HostedFlipbook extends Flipbook {
      // The book being built is the element's to destroy (_removeBook): removed from the document while the
      // engine loads, it stops there and never makes a renderer. One superseded before it was made (while
      // its document opened) never starts.
      constructor(...args) {
        super(...args);
        if (generation === host._generation) host._building = this;
        else this.destroy();
      }

      dispatchEvent(event) {
        super.dispatchEvent(event);
        if (generation === host._generation) host._forward(this, event);
        return !event.defaultPrevented;  // cancelled by the book's listeners or the element's
      }
    }
    try {
      const book = await HostedFlipbook.create(this._container, options);
      if (generation !== this._generation) book.destroy();
      else if (!this._book) this._ready(book);  // ready normally came as an event already
    } catch (error) {
      if (generation === this._generation) this._building = null;
      // Superseded, or dropped by _removeBook (create() rejected with an AbortError): nothing to report.
      if (generation !== this._generation || error.name === 'AbortError') error.fallback?.destroy();
      else if (error.fallback) this._adoptFallback(error.fallback, error);
      else this._fail(inAttributeTerms(error, this, this._held));
    }
  }

  _options() {
    const options = {};
    for (const [attribute, [option, parse]] of Object.entries(ATTRIBUTES)) {
      const raw = this.getAttribute(attribute);
      if (raw !== null) options[option] = parse(raw, attribute);
    }
    Object.assign(options, this._held);
    if (options.pdf === undefined && options.document === undefined) options.pages ??= this._childPages();  // a document brings its own pages
    if (this._reopenAt !== null) {
      options.startPage = options.pages ? Math.min(this._reopenAt, options.pages.length - 1) : this._reopenAt;
    }
    return options;
  }

  _childPages() {
    const children = [...this.children].filter((child) => !NOT_PAGES.includes(child.localName));
    if (children.length === 0) {
      throw new TypeError(`conecurl: <${TAG}> has no pages: give it a 'pages' attribute (image URLs separated by `
        + 'spaces) or child elements (<img> elements, or any element as an HTML page)');
    }
    // An <img> child is an image page; any other element is a live HTML page (it stays a child).
    return children.map((child) => (child.localName === 'img'
      ? { src: child.currentSrc || child.src, alt: child.alt }
      : { html: child, ...(child.hasAttribute('aria-label') ? { alt: child.getAttribute('aria-label') } : {}) }));
  }

  _touchesChildPages(record) {
    if (record.type === 'attributes') return record.target.localName === 'img' && record.target.parentNode === this;
    return record.target === this && [...record.addedNodes, ...record.removedNodes]
      .some((node) => node.nodeType === 1 && !NOT_PAGES.includes(node.localName));
  }

  _forward(book, event) {
    if (event.type === 'error' && !this._book) return;  // a failed build: _fail or _adoptFallback reports it
    if (event.type === 'ready') this._ready(book);
    // The element's listeners get a copy; cancelling the copy (a link) cancels the book's own event.
    const copy = new CustomEvent(event.type, { detail: event.detail, cancelable: event.cancelable });
    if (!this.dispatchEvent(copy)) event.preventDefault();
  }

  _ready(book) {
    this._book = book;
    this._building = null;
    const waiter = this._waiter;
    this._waiter = null;
    waiter?.resolve(book);
  }

  // No WebGL2 (or no engine): the book shows its pages as still images (a StaticBook), with next/prev,
  // keys and clicks. The failure is still reported; then the fallback is the element's book.
  _adoptFallback(fallback, error) {
    this._report(error);
    for (const type of BOOK_EVENTS) {
      if (type === 'ready' || type === 'error') continue;  // the element reports these itself, here
      fallback.addEventListener(type, (event) => { if (this._book === fallback) this._forward(fallback, event); });
    }
    this._ready(fallback);
    this.dispatchEvent(new CustomEvent('ready', { detail: { page: fallback.page } }));
  }

  _fail(error) {
    this._error = error;
    this._removeBook();
    this._container.hidden = true;
    this._failure.querySelector('p').textContent = error.message;
    this._failure.hidden = false;  // shows the message and, through the slot, the child images
    const waiter = this._waiter;
    this._waiter = null;
    this._report(error);
    waiter?.reject(error);
  }

  _report(error) {
    console.error(error);
    this.dispatchEvent(new CustomEvent('error', { detail: { error } }));
  }

  _stop(reason) {
    this._generation++;
    this._removeBook();
    const waiter = this._waiter;
    this._waiter = null;
    waiter?.reject(reason);
  }

  _removeBook() {
    this._building?.destroy();  // its create() stops where it is and rejects (AbortError)
    this._building = null;
    if (this._book) {
      this._reopenAt = this._book.page;
      this._book.destroy();
      this._book = null;
    }
    this._container.replaceChildren();
  }
}

for (const option of PROPERTY_OPTIONS) {
  if (option === 'display') continue;  // the class's own: it reads the display shown
  Object.defineProperty(ConeFlipbookElement.prototype, propertyOf(option), {
    configurable: true,
    get() { return this._readOption(option); },
    set(value) { this._writeOption(option, value); },
  });
}

if (globalThis.customElements && !customElements.get(TAG)) customElements.define(TAG, ConeFlipbookElement);
