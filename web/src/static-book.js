// The book without WebGL2 (or without the wasm engine): the open pages as still images on a 2D
// canvas, turned by the same methods, keys, clicks, taps and swipes, with the same events and the same
// screen-reader support as Flipbook, so a page that embeds a book never shows an empty box.
import { actionForKey, createShell } from './book-shell.js';
import { createLinkLayer } from './link-layer.js';
import { checkFlipOptions, checkLiveOptions, pageEntries, validateOptions } from './options.js';
import { loadPage, pageFailure } from './page-loader.js';
import { BookEvents } from './book-events.js';
import { PageCache } from './page-residency.js';
import { listenForTapsAndSwipes, swipeDirection } from './tap-swipe.js';

const PAPER = 'rgb(250, 247, 240)';  // the renderer's placeholder paper (kPaper in book_renderer.cpp)
const DEFAULT_PAGE_WIDTH = 0.8;      // the engine's page, 0.8 wide for 1 along the spine
const FRAME_MARGIN = 1.3;            // room around the pages, as the WebGL book's camera leaves
const AUTO_DOUBLE_ASPECT = 1.2;      // as Flipbook: wider containers show two pages in 'auto'
const IMAGE_OVERSAMPLE = 1.5;        // the size a page function is asked for, per device pixel on screen
const MAX_ZOOM = 4;                  // Flipbook's range, checked the same way

// ---- where the book is: the engine Book's positions, in JS so the fallback needs no wasm -------------

/** Last position: a spread per leaf boundary (double), or the last page (single). As Book::lastPosition. */
export function lastPosition(pageCount, display) {
  return display === 'double' ? Math.ceil(pageCount / 2) : Math.max(0, pageCount - 1);
}

/** The position (spread or page) that shows `page`. As Book::positionOfPage. */
export function positionOfPage(page, pageCount, display) {
  const clamped = Math.min(Math.max(0, page), Math.max(0, pageCount - 1));
  return display === 'double' ? Math.floor((clamped + 1) / 2) : clamped;
}

/** First visible page at a position (at an odd book's last spread, its face-down last page). */
export function firstVisiblePage(position, pageCount, display) {
  if (display !== 'double') return position;
  return position === 0 ? 0 : Math.min(2 * position - 1, pageCount - 1);
}

/**
 * The pages lying open at a position: `turned` (the back of the last turned leaf: left in ltr) and
 * `unturned` (the front of the next leaf). Each is a page index, -1 for a leaf's blank back, or
 * undefined where no leaf lies. As the resting leaves of Book::frame().
 */
export function spreadAt(position, pageCount, display) {
  if (display !== 'double') return { unturned: position < pageCount ? position : undefined };
  const leaves = Math.ceil(pageCount / 2);
  const spread = {};
  if (position > 0) spread.turned = 2 * position - 1 < pageCount ? 2 * position - 1 : -1;
  if (position < leaves) spread.unturned = 2 * position;
  return spread;
}

export class StaticBook extends EventTarget {
  /**
   * Builds a static book in `container` with Flipbook's options (rejects with a TypeError naming a bad
   * one); resolves once the open pages have loaded or failed.
   */
  static async create(container, options) {
    if (!(container instanceof HTMLElement)) throw new TypeError('conecurl: container must be an HTMLElement');
    return this._fromSettings(container, validateOptions(options));
  }

  /** From options already checked (Flipbook's fallback); `pdf` is a PDF document the book now owns. */
  static async _fromSettings(container, settings, pdf = null) {
    const book = new this(container, settings);
    book._pdf = pdf;
    try {
      await book._build();
    } catch (error) {
      book.destroy();
      throw error;
    }
    book._events.releaseSoon();  // what happened while loading the first view is heard from now on
    return book;
  }

  constructor(container, settings) {
    super();
    this._settings = settings;
    this._events = new BookEvents(this, settings.on);  // `on` listeners first; events of create() held
    this._pages = pageEntries(settings.pages);
    this._images = new Map();       // page -> { image, owned } while kept
    this._cache = new PageCache(settings.loadWindow, this._pages.length);  // loads, and which images to keep
    this._abort = new AbortController();
    this._destroyed = false;
    this._shell = createShell(container, { label: settings.label, direction: settings.direction });
    this._canvas = this._shell.canvas;
    // The still pages do not zoom themselves: pinch-zoom stays the browser's.
    this._canvas.style.touchAction = settings.direction === 'vertical' ? 'pan-x pinch-zoom' : 'pan-y pinch-zoom';
    this._links = createLinkLayer(this._shell.root, (link, event) => this._onLink(link, event));
    this._display = 'double';
    this._position = 0;
  }

  get pageCount() { return this._pages.length; }
  /** Where page `index` stands: { state: 'idle' | 'loading' | 'loaded' | 'failed', reason?, error? }. */
  pageState(index) { return this._cache.pageState(index); }
  /** The first visible page. */
  get page() { return firstVisiblePage(this._position, this.pageCount, this._display); }
  get display() { return this._display; }
  /** The focusable element the book made in its container (holds the canvas). */
  get element() { return this._shell.root; }

  /**
   * Always 1: still pages are not magnified by the book (the browser's pinch-zoom works on them).
   * Setting it checks the value like Flipbook (RangeError outside 1..4) and changes nothing.
   */
  get zoom() { return 1; }
  /** Still pages never move: always false (the same member as Flipbook's). */
  get animating() { return false; }
  /** Pages whose images are loaded and kept, in page order. */
  get residentPages() { return [...this._images.keys()].sort((a, b) => a - b); }
  set zoom(scale) {
    this._alive();
    if (!(Number.isFinite(scale) && scale >= 1 && scale <= MAX_ZOOM)) {
      throw new RangeError(`conecurl: zoom must be a number from 1 to ${MAX_ZOOM}, got ${String(scale)}`);
    }
  }

  /** Shows the next spread at once (there is no curl to animate); false at the end. */
  next() { return this._turn('forward'); }
  prev() { return this._turn('backward'); }

  /** A static book draws no turn frames: checks its arguments like Flipbook's and returns false. */
  previewTurn(direction, t) {
    this._alive();
    if (direction !== 'forward' && direction !== 'backward') {
      throw new TypeError(`conecurl: previewTurn direction must be 'forward' or 'backward', got ${String(direction)}`);
    }
    if (!(Number.isFinite(t) && t >= 0 && t <= 1)) throw new RangeError(`conecurl: previewTurn t must be in [0, 1], got ${String(t)}`);
    return false;
  }

  async flip(index, options) {
    this._alive();
    checkFlipOptions(options);
    if (!Number.isInteger(index) || index < 0 || index >= this.pageCount) {
      throw new RangeError(`conecurl: page ${index} is not in 0..${this.pageCount - 1}`);
    }
    const target = positionOfPage(index, this.pageCount, this._display);
    if (target === this._position) return;
    this._position = target;
    this._show();
  }

  /** Takes lighting, shadows and gutter like Flipbook (checked the same way); a flat page shows none of them. */
  setOptions(options) {
    this._alive();
    Object.assign(this._settings, checkLiveOptions(options, this._settings.pages));
  }

  destroy() {
    if (this._destroyed) return;
    this._destroyed = true;
    this._events.drop();
    this._abort.abort();
    this._stopInput?.();
    this._resizeObserver?.disconnect();
    this._pdf?.destroy();
    this._pdf = null;
    for (const index of [...this._images.keys()]) this._drop(index);
    this._links.remove();
    this._shell.remove();
    this._cache.releaseWaiters();
  }

  /** Where the open pages lie on the canvas, in CSS pixels (both places of a spread in double). */
  restingRect() {
    const cssWidth = this._canvas.clientWidth;
    const cssHeight = this._canvas.clientHeight;
    const across = this._settings.pageAspect || DEFAULT_PAGE_WIDTH;
    const spread = this._display === 'double' ? 2 * across : across;
    const vertical = this._settings.direction === 'vertical';
    const width = vertical ? 1 : spread;
    const height = vertical ? spread : 1;
    const scale = Math.min(cssWidth / (width * FRAME_MARGIN), cssHeight / (height * FRAME_MARGIN));
    const w = width * scale;
    const h = height * scale;
    return { x: (cssWidth - w) / 2, y: (cssHeight - h) / 2, width: w, height: h };
  }

  async _build() {
    this._layoutSize = this._cssSize();
    this._display = this._displayFor(this._layoutSize);
    this._position = positionOfPage(this._settings.startPage, this.pageCount, this._display);
    this._listen();
    this._shell.showOpenPages(this._openPages(), this.pageCount, this._openPages().map((i) => this._pages[i].alt));
    this._updateResidency();
    this._draw();
    await this._cache.whenIdle();
    this._emit('ready', { page: this.page });
  }

  _alive() {
    if (this._destroyed) throw new Error('conecurl: this flipbook was destroyed');
  }

  _emit(type, detail) {
    if (!this._destroyed) this._events.dispatch(new CustomEvent(type, { detail }));
  }

  async _turn(direction) {
    this._alive();
    const target = this._position + (direction === 'forward' ? 1 : -1);
    if (target < 0 || target > lastPosition(this.pageCount, this._display)) return false;
    this._position = target;
    this._emit('turnstart', { direction, page: this.page });
    this._show();
    return true;
  }

  _turnQuietly(direction) {
    this._turn(direction).catch(() => {});
  }

  // The position changed: load what is now wanted, draw, and say so (live region, `turned`).
  _show() {
    this._updateResidency();
    this._draw();
    const pages = this._openPages();
    this._shell.showOpenPages(pages, this.pageCount, pages.map((i) => this._pages[i].alt));
    this._emit('turned', { page: this.page });
  }

  /** Pages open at the position: a spread's one or two pages, or the single page (as Flipbook). */
  _openPages() {
    const first = this.page;
    if (this._display !== 'double' || first === 0) return [first];
    return first + 1 < this.pageCount ? [first, first + 1] : [first];
  }

  _displayFor({ width, height }) {
    if (this._settings.display !== 'auto') return this._settings.display;
    return width / Math.max(1, height) > AUTO_DOUBLE_ASPECT ? 'double' : 'single';
  }

  _cssSize() {
    const { width, height } = this._shell.root.getBoundingClientRect();
    return { width, height };
  }

  // ---- drawing ----------------------------------------------------------------------------------

  /** Page slots on the canvas in CSS px: { page, x, y, width, height } for each leaf lying open. */
  _slots() {
    const rect = this.restingRect();
    const spread = spreadAt(this._position, this.pageCount, this._display);
    if (this._display !== 'double') return spread.unturned === undefined ? [] : [{ page: spread.unturned, ...rect }];
    const vertical = this._settings.direction === 'vertical';
    const half = vertical
      ? [{ ...rect, height: rect.height / 2 }, { ...rect, y: rect.y + rect.height / 2, height: rect.height / 2 }]
      : [{ ...rect, width: rect.width / 2 }, { ...rect, x: rect.x + rect.width / 2, width: rect.width / 2 }];
    // The turned side is where the spine's previous pages lie: left (ltr), right (rtl), top (vertical).
    const [turnedPlace, unturnedPlace] = this._settings.direction === 'rtl' ? [half[1], half[0]] : half;
    const slots = [];
    if (spread.turned !== undefined) slots.push({ page: spread.turned, ...turnedPlace });
    if (spread.unturned !== undefined) slots.push({ page: spread.unturned, ...unturnedPlace });
    return slots;
  }

  _draw() {
    if (this._destroyed) return;
    const canvas = this._canvas;
    const ratio = window.devicePixelRatio || 1;
    const width = Math.max(1, Math.round(canvas.clientWidth * ratio));
    const height = Math.max(1, Math.round(canvas.clientHeight * ratio));
    if (canvas.width !== width || canvas.height !== height) Object.assign(canvas, { width, height });
    const context = canvas.getContext('2d');
    context.setTransform(1, 0, 0, 1, 0, 0);
    context.clearRect(0, 0, width, height);
    context.setTransform(ratio, 0, 0, ratio, 0, 0);
    context.imageSmoothingQuality = 'high';
    for (const slot of this._slots()) {
      // Plain paper first: a page still loading, failed, or a blank back shows as paper.
      context.fillStyle = PAPER;
      context.fillRect(slot.x, slot.y, slot.width, slot.height);
      const kept = this._images.get(slot.page);
      if (kept) context.drawImage(kept.image, slot.x, slot.y, slot.width, slot.height);
    }
    // Links of the open pages, as anchors over them (the same layer as Flipbook's).
    const placed = this._slots().filter((slot) => slot.page >= 0 && this._pages[slot.page].links?.length)
      .map(({ page, x, y, width, height }) => ({ page, rect: { x, y, width, height }, links: this._pages[page].links }));
    if (placed.length > 0) this._links.show(placed);
    else this._links.hide();
  }

  _onLink(link, event) {
    const detail = { page: link.page, href: link.href, toPage: link.toPage };
    const proceed = this.dispatchEvent(new CustomEvent('link', { detail, cancelable: true }));
    if (link.toPage !== undefined || !proceed) event.preventDefault();
    if (proceed && link.toPage !== undefined) this.flip(link.toPage).catch(() => {});
  }

  // ---- loading: the open pages, then their neighbours, a bounded number kept ---------------------

  _updateResidency() {
    const open = this._openPages();
    const wanted = this._cache.want({
      onScreen: this._slots().map((slot) => slot.page),
      first: open[0],
      last: open[open.length - 1],
      loadWindow: this._settings.loadWindow,
      pageCount: this.pageCount,
    });
    for (const page of wanted) if (this._cache.stateOf(page) === 'idle') this._load(page);
    for (const page of this._cache.release([...this._images.keys()])) this._drop(page);
  }

  _drop(index) {
    const kept = this._images.get(index);
    if (kept?.owned && typeof kept.image.close === 'function') kept.image.close();  // an ImageBitmap made here
    this._images.delete(index);
    this._cache.setState(index, 'idle');
  }

  _pageSize() {
    const slot = this._slots()[0] || this.restingRect();
    const scale = (window.devicePixelRatio || 1) * IMAGE_OVERSAMPLE;
    return { width: Math.ceil(slot.width * scale), height: Math.ceil(slot.height * scale) };
  }

  async _load(index) {
    this._cache.startLoad(index);
    try {
      const loaded = await loadPage(this._pages[index].src, { index, size: this._pageSize(), signal: this._abort.signal });
      if (this._destroyed || this._cache.stateOf(index) !== 'loading') {
        if (loaded.owned) loaded.image.close?.();
        return;
      }
      this._images.set(index, loaded);
      this._cache.setState(index, 'loaded');
      if (this._slots().some((slot) => slot.page === index)) this._draw();
    } catch (error) {
      if (this._destroyed) return;
      const failure = pageFailure(error);
      this._cache.setState(index, 'failed', failure);
      this._emit('pageerror', { index, ...failure });
    } finally {
      const progress = this._cache.endLoad();
      if (!this._destroyed) this._emit('progress', progress);
    }
  }

  // ---- input and size ---------------------------------------------------------------------------

  _listen() {
    const root = this._shell.root;
    const stopTaps = listenForTapsAndSwipes(this._canvas, {
      tap: (x, y) => this._onTap(x, y),
      swipe: (dx, dy) => this._onSwipe(dx, dy),
    });
    const onKeyDown = (event) => this._onKeyDown(event);
    root.addEventListener('keydown', onKeyDown);
    this._stopInput = () => {
      stopTaps();
      root.removeEventListener('keydown', onKeyDown);
    };
    if (typeof ResizeObserver === 'function') {
      this._resizeObserver = new ResizeObserver(() => this._onResize());
      this._resizeObserver.observe(root);
    }
  }

  _onTap(clientX, clientY) {
    if (this._destroyed) return;
    const box = this._canvas.getBoundingClientRect();
    const rect = this.restingRect();
    const x = clientX - box.left - rect.x;
    const y = clientY - box.top - rect.y;
    if (x < 0 || y < 0 || x > rect.width || y > rect.height) return;
    const direction = this._settings.direction;
    const forward = direction === 'vertical' ? y >= rect.height / 2
      : direction === 'rtl' ? x < rect.width / 2 : x >= rect.width / 2;
    this._turnQuietly(forward ? 'forward' : 'backward');
  }

  _onSwipe(dx, dy) {
    if (this._destroyed) return;
    const turn = swipeDirection(dx, dy, this._settings.direction);
    if (turn) this._turnQuietly(turn);
  }

  _onKeyDown(event) {
    if (this._destroyed) return;
    const action = actionForKey(event, this._settings.direction);
    if (!action) return;
    event.preventDefault();
    if (action === 'first' || action === 'last') {
      this.flip(action === 'first' ? 0 : this.pageCount - 1).catch(() => {});
    } else {
      this._turnQuietly(action);
    }
  }

  _onResize() {
    if (this._destroyed) return;
    const size = this._cssSize();
    if (size.width === this._layoutSize.width && size.height === this._layoutSize.height) return;
    this._layoutSize = size;
    const display = this._displayFor(size);
    if (display !== this._display) {
      const page = this.page;
      this._display = display;
      this._position = positionOfPage(page, this.pageCount, display);
      const pages = this._openPages();
      this._shell.showOpenPages(pages, this.pageCount, pages.map((i) => this._pages[i].alt));
      this._updateResidency();
    }
    this._draw();
    this._emit('resize', { ...size, display: this._display });
  }
}
