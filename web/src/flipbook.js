// The public entry point: a flipbook in a container element. Validates options, keeps a bounded
// cache of page textures around the open spread (placeholder and `pageerror` for failures), turns
// pages on clicks, taps, swipes and keys, speaks to screen readers, follows the container's size,
// and turns the engine's state into events. Drawing and animation stay in BookView over the wasm.
// Over 450 lines because it still holds input, loading, links and zoom as well: issue 13 splits it into
// a book controller over surfaces, with input modules and overlay layers in files of their own.
import { loadEngine } from './engine.js';
import { BookView, uploadSizeFor } from './book-view.js';
import { actionForKey, createShell } from './book-shell.js';
import { checkFlipOptions, checkLiveOptions, describeValue, pageEntries, validateOptions } from './options.js';
import { loadPage, pageFailure } from './page-loader.js';
import { PointerDrag } from './pointer-drag.js';
import { listenForTapsAndSwipes, swipeDirection } from './tap-swipe.js';
import { listenForZoom } from './zoom-input.js';
import { createLinkLayer } from './link-layer.js';
import { contextBudget } from './context-budget.js';
import { softwareWebGL } from './software-gl.js';
import { PageCache } from './page-residency.js';
import { BookEvents } from './book-events.js';

// Failures after which a book can still be shown, as still pages: Flipbook.create falls back on these.
const FALLBACK_CODES = ['webgl2-unavailable', 'engine-unavailable'];
const AUTO_DOUBLE_ASPECT = 1.2;  // containers wider than this show two pages in 'auto'
const TEXTURE_OVERSAMPLE = 1.5;  // textures up to this many texels per device pixel of the page on screen
const REFIT_DELAY_MS = 150;      // re-upload textures for a new size once a resize has come to rest
const REFIT_RATIO = 1.25;        // ... and only those this far off the size now wanted
const MAX_ZOOM = 4;              // the engine's kMaxZoom
const ZOOM_STEP = 1.25;          // the + and - keys
const CLICK_SERIES_MS = 300;     // clicks this close together are one series (a double-click, or rapid turning)

// `pdf` (a URL, ArrayBuffer or Uint8Array) instead of `pages`: pdf.js is imported only then.
async function openPdfOption(options) {
  if (options === null || typeof options !== 'object' || !('pdf' in options)) return null;
  const { pdf, pdfWorkerSrc } = options;
  if (!(typeof pdf === 'string' || pdf instanceof ArrayBuffer || pdf instanceof Uint8Array)) {
    throw new TypeError(`conecurl: option 'pdf' must be a URL string, an ArrayBuffer or a Uint8Array, got ${describeValue(pdf)}`);
  }
  if ('pages' in options) throw new TypeError("conecurl: option 'pages' cannot be given with 'pdf' (the PDF's pages are the book)");
  if (pdfWorkerSrc !== undefined && typeof pdfWorkerSrc !== 'string') {
    throw new TypeError(`conecurl: option 'pdfWorkerSrc' must be a URL string, got ${describeValue(pdfWorkerSrc)}`);
  }
  const { openPdf } = await import('./pdf-pages.js');
  return openPdf(pdf, { workerSrc: pdfWorkerSrc });
}

function withoutPdfOptions(options) {
  const rest = { ...options };
  delete rest.pdf;
  delete rest.pdfWorkerSrc;
  return rest;
}

export class Flipbook extends EventTarget {
  /** @param {HTMLElement} container @param {object} options  See flipbook.d.ts. */
  static async create(container, options) {
    if (!(container instanceof HTMLElement)) throw new TypeError('conecurl: container must be an HTMLElement');
    const pdf = await openPdfOption(options);
    let settings;
    try {
      settings = validateOptions(pdf ? { ...withoutPdfOptions(options), pages: pdf.pages } : options);
    } catch (error) {
      pdf?.destroy();
      throw error;
    }
    if (pdf) settings.pageAspect = pdf.aspect;  // page shape from the PDF's first page
    const book = new this(container, settings, null);  // `this`: subclasses get their own instances
    book._pdf = pdf;
    try {
      book._engine = await loadEngine(settings.wasmUrl ? { wasmUrl: settings.wasmUrl } : {});
      await book._build();
    } catch (error) {
      throw await book._fail(error);
    }
    book._events.releaseSoon();  // what happened while loading the first view is heard from now on
    return book;
  }

  // create() failed. Without WebGL2 or the engine the pages can still be shown: unless the option
  // `fallback` is false, a StaticBook takes the book's place in the container (error.fallback).
  // Then `error` is dispatched (subclasses such as <cone-flipbook> hear it) and create rejects.
  async _fail(error) {
    const canFallBack = this._settings.fallback && FALLBACK_CODES.includes(error && error.code);
    const pdf = canFallBack ? this._pdf : null;
    if (canFallBack) this._pdf = null;  // the fallback shows the same PDF
    this.destroy();
    if (canFallBack) {
      try {
        // Loaded only now: books that have WebGL2 never download the fallback.
        const { StaticBook } = await import('./static-book.js');
        error.fallback = await StaticBook._fromSettings(this._container, this._settings, pdf);
      } catch (fallbackError) {
        pdf?.destroy();
        error.fallbackError = fallbackError;
      }
    }
    this.dispatchEvent(new CustomEvent('error', { detail: { error } }));
    return error;
  }

  constructor(container, settings, engine) {
    super();
    this._container = container;
    this._settings = settings;
    this._engine = engine;
    // Entries as given (a PDF's fill in their alt and links as their pages render), with links in
    // one form: { rect, href, toPage, title }.
    this._pages = pageEntries(settings.pages);
    this._images = new Map();       // page -> decoded image, while its texture is resident
    this._cache = new PageCache(settings.loadWindow, this._pages.length);  // loads, and which textures to keep
    this._owned = new Set();        // images made here (ImageBitmaps from URLs and Blobs): closed when let go
    this._abort = new AbortController();  // page fetches still running when the book is destroyed stop
    this._destroyed = false;
    this._events = new BookEvents(this, settings.on);  // `on` listeners first; events of create() held
    this._flips = 0;       // counts flip() calls: a later one stops an earlier one's leaf-by-leaf turning
    this._shell = createShell(container, { label: settings.label, direction: settings.direction });
    this._canvas = this._shell.canvas;
    this._restingTouchAction = this._canvas.style.touchAction;
    this._links = createLinkLayer(this._shell.root, (link, event) => this._onLink(link, event));
    this._contextLease = contextBudget().lease(this._canvas);  // many books on a page share the WebGL contexts
    this._reducedMotion = typeof matchMedia === 'function' ? matchMedia('(prefers-reduced-motion: reduce)') : null;
  }

  get pageCount() { return this._pages.length; }
  /** Where page `index` stands: { state: 'idle' | 'loading' | 'loaded' | 'failed', reason?, error? }. */
  pageState(index) { return this._cache.pageState(index); }
  /** The first visible page at the settled position (after destroy(), where the book was left). */
  get page() { return this._view ? this._view.book.firstVisiblePage() : (this._finalPage ?? 0); }
  get display() {
    if (!this._view) return this._finalDisplay ?? (this._settings.display === 'single' ? 'single' : 'double');
    return this._view.book.isSingle() ? 'single' : 'double';
  }
  /** The focusable element the book made in its container (holds the canvas). */
  get element() { return this._shell.root; }
  /** A leaf is moving or waiting to (turns in flight, a held page); false after destroy(). */
  get animating() { return Boolean(this._view?.animating); }
  /** Pages whose images are loaded and kept (textures on the GPU), in page order. */
  get residentPages() { return [...this._images.keys()].sort((a, b) => a - b); }
  /** Where the open pages lie on the canvas, in CSS pixels (both places of a spread in double). */
  restingRect() { return this._view.restingRect(); }

  next() { return this._turn('forward'); }
  prev() { return this._turn('backward'); }

  /** View magnification, 1 (the whole book) to 4. Setting it zooms about the middle of the book. */
  get zoom() { return this._view ? this._view.book.zoom().scale : 1; }
  set zoom(scale) {
    this._alive();
    if (!(Number.isFinite(scale) && scale >= 1 && scale <= MAX_ZOOM)) {
      throw new RangeError(`conecurl: zoom must be a number from 1 to ${MAX_ZOOM}, got ${String(scale)}`);
    }
    const box = this._canvas.getBoundingClientRect();
    this._zoomAbout(scale, box.left + box.width / 2, box.top + box.height / 2);
  }

  /**
   * Shows, frozen, the exact frame of the next ('forward') or previous ('backward') turn at progress
   * t in [0, 1]: for scrubbers and figures. Returns false at the end of the book; the next turn,
   * flip or drag carries on from the open spread as usual.
   */
  previewTurn(direction, t) {
    this._alive();
    if (direction !== 'forward' && direction !== 'backward') {
      throw new TypeError(`conecurl: previewTurn direction must be 'forward' or 'backward', got ${String(direction)}`);
    }
    if (!(Number.isFinite(t) && t >= 0 && t <= 1)) throw new RangeError(`conecurl: previewTurn t must be in [0, 1], got ${String(t)}`);
    const shown = this._view.showTurn(direction, t);
    this._updateResidency();  // the pages the posed leaf shows
    return shown;
  }

  /** Shows page `index`; animated turns (default) go leaf by leaf, else it jumps. */
  async flip(index, options) {
    this._alive();
    const { animate } = checkFlipOptions(options);
    if (!Number.isInteger(index) || index < 0 || index >= this.pageCount) {
      throw new RangeError(`conecurl: page ${index} is not in 0..${this.pageCount - 1}`);
    }
    // The latest flip wins: an animated flip still under way stops where it is (and resolves), or two
    // would turn the book back and forth for ever.
    const flip = ++this._flips;
    if (!animate || this._prefersReducedMotion()) {
      const target = this._view.book.positionOfPage(index);
      if (this._view.position === target && !this._view.animating) return;
      this._view.jumpTo(target);
      this._updateResidency();
      this._landed();
      return;
    }
    for (;;) {
      const target = this._view.book.positionOfPage(index);  // again each leaf: the display may switch
      if (this._view.position === target) return;
      const turned = await this._turn(target > this._view.position ? 'forward' : 'backward');
      if (!turned || this._destroyed || flip !== this._flips) return;
    }
  }

  /** Switches lighting, shadows and gutter shading on a live book; other options need a new book. */
  setOptions(options) {
    this._alive();
    Object.assign(this._settings, checkLiveOptions(options, this._settings.pages));
    const { lighting, shadows, gutter } = this._settings;
    this._view.setOptions({ lighting, shadows, gutter });
  }

  destroy() {
    if (this._destroyed) return;
    if (this._view) {
      this._finalPage = this.page;  // page and display still answer after destroy()
      this._finalDisplay = this.display;
    }
    this._destroyed = true;
    this._events.drop();
    this._abort.abort();
    this._pointer?.destroy();
    this._pointer = null;
    this._pdf?.destroy();
    this._pdf = null;
    this._links.remove();
    this._stopInput?.();
    clearTimeout(this._clickSeries?.timer);
    this._resizeObserver?.disconnect();
    this._stopWatchingPixelRatio?.();
    clearTimeout(this._refitTimer);
    this._view?.destroy({ releaseContext: true });  // the canvas goes: give its WebGL context up now
    this._view = null;
    this._contextLease.dispose();
    for (const image of this._owned) image.close?.();
    this._owned.clear();
    this._images.clear();
    this._shell.remove();
    this._cache.releaseWaiters();
  }

  async _build() {
    this._view = this._makeView(this._displayFor(this._shell.root.getBoundingClientRect()));
    this._view.jumpTo(this._view.book.positionOfPage(this._settings.startPage));
    this._attachPointer();
    this._layoutSize = this._cssSize();
    this._listen();
    this._showOpenPages();
    this._updateResidency();
    await this._whenIdle();
    this._emit('ready', { page: this.page });
  }

  _makeView(display) {
    const hardPages = this._pages.map((p, i) => (p.hard || (this._settings.hardCovers
      && (i === 0 || i === this.pageCount - 1)) ? i : -1)).filter((i) => i >= 0);
    this._contextLease.admit();  // room in the page's context budget before the renderer makes one
    const view = new BookView(this._engine, this._canvas, {
      pageCount: this.pageCount,
      // A PDF's pages keep their shape; image books use the engine's default page (0.8 : 1).
      ...(this._settings.pageAspect ? { pageWidth: this._settings.pageAspect, pageHeight: 1 } : {}),
      display,
      direction: this._settings.direction,
      hardPages,
      turnSeconds: this._settings.duration / 1000,
      // 'auto': smooth edges unless WebGL runs in software, where multisampling costs ~30% a frame.
      antialias: this._settings.antialias === 'auto' ? !softwareWebGL() : this._settings.antialias,
      lighting: this._settings.lighting,
      shadows: this._settings.shadows,
      gutter: this._settings.gutter,
    });
    this._contextLease.attach(view);
    // While leaves move, the pages they show change (turns that waited start late): the engine says when.
    view.onPagesChanged = () => { if (!this._destroyed) this._updateResidency(); };
    return view;
  }

  // Dragging a corner or edge: a PointerDrag on each BookView (a display switch makes a new one).
  _attachPointer() {
    this._pointer?.destroy();
    this._pointer = new PointerDrag(this._view, {
      enabled: () => !this._zoomed(),
      onTurnStart: (direction) => {
        this._links.hide();
        this._emit('turnstart', { direction, page: this.page, drag: true });
        this._updateResidency();
      },
      onTurnEnd: (completed) => {
        if (this._destroyed) return;
        this._updateResidency();
        if (completed) {
          this._landed();
        } else {
          this._showOpenPages();
          this._emit('turncancel', { page: this.page });
        }
      },
      // A corner lifted by hovering fell back: the open pages are those from before it again.
      onHintEnd: () => { if (!this._destroyed) this._showOpenPages(); },
    });
  }

  _displayFor({ width, height }) {
    if (this._settings.display !== 'auto') return this._settings.display;
    return width / Math.max(1, height) > AUTO_DOUBLE_ASPECT ? 'double' : 'single';
  }

  // ---- input -------------------------------------------------------------------------------

  _listen() {
    const root = this._shell.root;
    const stopTaps = listenForTapsAndSwipes(this._canvas, {
      // A stroke that dragged a page is not also a tap or a swipe.
      tap: (x, y, kind) => {
        if (this._pointer?.strokeWasDrag) return;
        const half = this._pageHalfAt(x, y);
        if (kind === 'click') this._onMouseClick(half);
        else this._onClick(half);
      },
      swipe: (dx, dy) => { if (!this._pointer?.strokeWasDrag) this._onSwipe(dx, dy); },
    });
    const stopZoom = listenForZoom(this._canvas, {
      scale: () => this.zoom,
      zoomAbout: (scale, x, y) => this._zoomAbout(scale, x, y),
      doubleClicked: () => this._onDoubleClick(),
      panBy: (dx, dy) => this._panBy(dx, dy),
    });
    const onKeyDown = (event) => this._onKeyDown(event);
    root.addEventListener('keydown', onKeyDown);
    this._stopInput = () => {
      stopZoom();
      stopTaps();
      root.removeEventListener('keydown', onKeyDown);
    };
    if (typeof ResizeObserver === 'function') {
      this._resizeObserver = new ResizeObserver(() => this._onResize());
      this._resizeObserver.observe(root);
    }
    this._watchPixelRatio();
  }

  /**
   * Which half of the resting book a viewport point falls on: 'left'/'right' (ltr, rtl) or
   * 'top'/'bottom' (vertical) of the spread (double) or the page (single); null outside the pages.
   */
  _pageHalfAt(clientX, clientY) {
    const box = this._canvas.getBoundingClientRect();
    const rect = this._view.restingRect();
    const x = clientX - box.left - rect.x;
    const y = clientY - box.top - rect.y;
    if (x < 0 || y < 0 || x > rect.width || y > rect.height) return null;
    if (this._settings.direction === 'vertical') return y < rect.height / 2 ? 'top' : 'bottom';
    return x < rect.width / 2 ? 'left' : 'right';
  }

  /** A click or tap on a half of the book: the half that holds the next page turns forward. */
  _onClick(half) {
    if (this._destroyed || !half || this._zoomed()) return;  // zoomed in, a press pans: no turning
    const forwardHalf = { ltr: 'right', rtl: 'left', vertical: 'bottom' }[this._settings.direction];
    this._turnQuietly(half === forwardHalf ? 'forward' : 'backward');
  }

  // Mouse clicks come in series. A series of exactly two is a double-click, which zooms: so the
  // first click of a series waits CLICK_SERIES_MS before it turns. A third click makes it rapid
  // turning: the clicks held back turn at once, and every further click of the series turns at once.
  _onMouseClick(half) {
    const series = this._clickSeries;
    if (series && !series.done) {
      clearTimeout(series.timer);
      if (series.turning) {
        this._onClick(half);
      } else {
        series.halves.push(half);
        if (series.halves.length >= 3) this._flushClicks(series, true);
      }
      if (!series.done) series.timer = setTimeout(() => this._flushClicks(series, false), CLICK_SERIES_MS);
      return;
    }
    const next = { halves: [half], turning: false, done: false, timer: 0 };
    next.timer = setTimeout(() => this._flushClicks(next, false), CLICK_SERIES_MS);
    this._clickSeries = next;
  }

  // Turns the clicks a series held back; `keepGoing`: the series stays open for more rapid clicks.
  _flushClicks(series, keepGoing) {
    for (const half of series.halves.splice(0)) this._onClick(half);
    series.turning = keepGoing;
    if (!keepGoing) series.done = true;
  }

  _onDoubleClick() {
    const series = this._clickSeries;
    if (series && !series.done && !series.turning && series.halves.length === 2) {
      clearTimeout(series.timer);
      series.halves.length = 0;  // the two clicks were a double-click: it zooms (zoom-input.js), no turn
      series.done = true;
    }
  }

  _onSwipe(dx, dy) {
    if (this._destroyed || this._zoomed()) return;
    const turn = swipeDirection(dx, dy, this._settings.direction);
    if (turn) this._turnQuietly(turn);
  }

  _onKeyDown(event) {
    if (this._destroyed || event.defaultPrevented || event.altKey || event.ctrlKey || event.metaKey) return;
    const zoomKey = { '+': ZOOM_STEP, '=': ZOOM_STEP, '-': 1 / ZOOM_STEP, 0: 0 }[event.key];
    if (zoomKey !== undefined) {
      event.preventDefault();
      const box = this._canvas.getBoundingClientRect();
      this._zoomAbout(zoomKey === 0 ? 1 : this.zoom * zoomKey, box.left + box.width / 2, box.top + box.height / 2);
      return;
    }
    const action = actionForKey(event, this._settings.direction);
    if (!action || this._zoomed()) return;  // zoomed in, the keys do not turn: 0 (or -) comes back first
    event.preventDefault();
    if (action === 'first' || action === 'last') {
      // Home and End jump: animating a whole book's leaves one by one would take minutes.
      this.flip(action === 'first' ? 0 : this.pageCount - 1, { animate: false }).catch(() => {});
      return;
    }
    // A held key repeats fast: it keeps at most one turn waiting instead of piling them up.
    if (event.repeat && this._view.queuedTurns > 0) return;
    this._turnQuietly(action);
  }

  _turnQuietly(direction) {
    this._turn(direction).catch(() => {});  // input after destroy() is dropped
  }

  // ---- turning -----------------------------------------------------------------------------

  _prefersReducedMotion() { return Boolean(this._reducedMotion?.matches); }

  async _turn(direction) {
    this._alive();
    if (this._zoomed()) this._zoomAbout(1, 0, 0);  // a turn asked for by code shows the whole book again
    if (this._prefersReducedMotion()) return this._jumpOneLeaf(direction);
    const turning = direction === 'forward' ? this._view.next() : this._view.prev();
    if (this._view.animating) {
      this._links.hide();
      this._emit('turnstart', { direction, page: this.page });
    }
    this._updateResidency();
    const turned = await turning;
    if (this._destroyed) return false;
    this._updateResidency();
    if (turned) this._landed();
    return turned;
  }

  // Reduced motion: a turn is a cut to the next spread, with the same events as an animated one.
  _jumpOneLeaf(direction) {
    const view = this._view;
    const target = view.position + (direction === 'forward' ? 1 : -1);
    if (target < 0 || target > view.book.lastPosition()) return false;
    view.jumpTo(target);
    this._emit('turnstart', { direction, page: this.page });
    this._updateResidency();
    this._landed();
    return true;
  }

  _landed() {
    this._showOpenPages();
    this._emit('turned', { page: this.page });
  }

  /** Pages open at the settled position: a spread's one or two pages, or the single page. */
  _openPages() {
    const first = this.page;
    if (this._view.book.isSingle() || first === 0) return [first];
    return first + 1 < this.pageCount ? [first, first + 1] : [first];
  }

  _showOpenPages() {
    this._layoutLinks();
    const pages = this._openPages();
    this._shell.showOpenPages(pages, this.pageCount, pages.map((i) => this._pages[i].alt));
  }

  // ---- the page cache ----------------------------------------------------------------------

  // Loads the pages wanted now (on screen, then the open spread's neighbours within loadWindow) and
  // releases the least recently wanted beyond the cache's capacity, which does not grow with the book.
  _updateResidency() {
    const open = this._openPages();
    const wanted = this._cache.want({
      onScreen: this._engine.pagesOnScreen(this._view.book),
      first: open[0],
      last: open[open.length - 1],
      loadWindow: this._settings.loadWindow,
      pageCount: this.pageCount,
    });
    for (const page of wanted) if (this._cache.stateOf(page) === 'idle') this._load(page);
    this._releaseExcess();
  }

  _releaseExcess() {
    for (const page of this._cache.release([...this._images.keys()])) {
      this._view.releasePageImage(page);
      this._closeIfOwned(this._images.get(page));
      this._images.delete(page);
      this._cache.setState(page, 'idle');
    }
  }

  async _load(index) {
    this._cache.startLoad(index);
    try {
      // A function makes its page only when the page is wanted (drawn, fetched or rendered on
      // demand), told the size in device pixels the page is drawn at.
      const { image, owned } = await loadPage(this._pages[index].src,
        { index, size: this._textureCover(), signal: this._abort.signal });
      if (owned) this._owned.add(image);
      if (this._destroyed || this._cache.stateOf(index) !== 'loading'
          || (!this._cache.wanted.has(index) && this._images.size >= this._cache.capacity)) {
        // Destroyed, or no longer wanted and no room: not worth a texture.
        this._closeIfOwned(image);
        if (!this._destroyed && this._cache.stateOf(index) === 'loading') this._cache.setState(index, 'idle');
        return;
      }
      await this._view.queuePageImage(index, image, { cover: this._textureCover() });  // mid-turn: one a frame
      if (this._destroyed) return;
      this._images.set(index, image);
      this._cache.setState(index, 'loaded');
      this._releaseExcess();
      // A source may have learned its page's text and links while making it (a PDF page).
      // (Not while a leaf moves or is lifted by a hover hint: the open pages are in flux, and the
      // landing, or the hint's end, shows them again.)
      if (!this._view.animating && this._openPages().includes(index)) this._showOpenPages();
    } catch (error) {
      if (this._destroyed) return;
      // The page keeps the plain paper placeholder; the book keeps working. `reason` says why:
      // 'http', 'network', 'cors' or 'decode' (PageLoadError), or 'upload' (the image would not upload).
      const failure = pageFailure(error);
      this._cache.setState(index, 'failed', failure);
      this._emit('pageerror', { index, ...failure });
    } finally {
      const progress = this._cache.endLoad();
      if (!this._destroyed) this._emit('progress', progress);
    }
  }

  _closeIfOwned(image) {
    if (image && this._owned.delete(image)) image.close?.();
  }

  /** Texture pixels a page needs: its size on screen in device pixels, times TEXTURE_OVERSAMPLE. */
  _textureCover({ zoomed = false } = {}) {
    // restingRect is the zoomed picture; textures are sized for the whole book unless asked for the
    // open pages while zoomed in (only those get the extra pixels: memory stays bounded).
    const unzoom = zoomed ? 1 : 1 / this.zoom;
    const full = this._view.restingRect();
    const rect = { width: full.width * unzoom, height: full.height * unzoom };
    const spread = this._view.book.isSingle() ? 1 : 2;
    const vertical = this._settings.direction === 'vertical';
    const scale = (window.devicePixelRatio || 1) * TEXTURE_OVERSAMPLE;
    return {
      width: Math.ceil((vertical ? rect.width : rect.width / spread) * scale),
      height: Math.ceil((vertical ? rect.height / spread : rect.height) * scale),
    };
  }

  /** Resolves once no page is loading (tests; `progress` with pending 0 says the same). */
  _whenIdle() {
    // Clicks held back to tell a double-click come first: wait them out (they may start a turn).
    if (this._clickSeries && !this._clickSeries.done) {
      return new Promise((resolve) => setTimeout(resolve, CLICK_SERIES_MS + 20)).then(() => this._whenIdle());
    }
    return this._cache.whenIdle();
  }

  // ---- size and pixel ratio ----------------------------------------------------------------

  _cssSize() {
    const { width, height } = this._shell.root.getBoundingClientRect();
    return { width, height };
  }

  _watchPixelRatio() {
    if (typeof matchMedia !== 'function') return;
    const query = matchMedia(`(resolution: ${window.devicePixelRatio || 1}dppx)`);
    const onChange = () => {
      query.removeEventListener('change', onChange);
      if (this._destroyed) return;
      this._watchPixelRatio();  // a new query for the new ratio
      this._relayout();
    };
    query.addEventListener('change', onChange);
    this._stopWatchingPixelRatio = () => query.removeEventListener('change', onChange);
  }

  _onResize() {
    const size = this._cssSize();
    if (size.width === this._layoutSize.width && size.height === this._layoutSize.height) return;
    this._layoutSize = size;
    this._relayout();
  }

  // The container or the pixel ratio changed: switch single/double for 'auto', redraw at the new
  // size, and (once resizing rests) bring textures to the size now wanted.
  _relayout() {
    const display = this._displayFor(this._layoutSize);
    if (display !== this.display) this._switchDisplay(display);
    this._view.sizeChanged();
    clearTimeout(this._refitTimer);
    this._refitTimer = setTimeout(() => this._refitTextures(), REFIT_DELAY_MS);
    this._layoutLinks();
    this._emit('resize', { ...this._layoutSize, display: this.display });
  }

  // Single or double pages for 'auto': the same Book, renderer and textures, showing the same page.
  _switchDisplay(display) {
    this._view.setDisplay(display);
    this._updateResidency();
    this._showOpenPages();
  }

  _refitTextures() {
    if (this._destroyed) return;
    const maxTextureSize = this._view.renderer.maxTextureSize();
    const open = new Set(this._openPages());
    for (const [index, image] of this._images) {
      const sharp = open.has(index) && this._zoomed();
      const cover = this._textureCover({ zoomed: sharp });
      const uploaded = this._view.pageImageSize(index);
      const natural = { width: image.naturalWidth || image.width, height: image.naturalHeight || image.height };
      const wanted = uploadSizeFor(natural.width, natural.height, { cover, maxTextureSize });
      const ratio = wanted.width / uploaded.width;
      if (ratio > REFIT_RATIO || ratio < 1 / REFIT_RATIO) this._view.setPageImage(index, image, { cover });
      // Zoomed in past what the image holds: a sharper source, where the page has one.
      if (sharp && wanted.width < cover.width / REFIT_RATIO && wanted.width < maxTextureSize) this._sharpen(index, cover);
    }
  }

  // Loads a sharper image of an open page for the zoomed view: `zoomSrc`, or the page's function
  // called again for the larger size (a PDF page rendered anew). The page keeps its present texture
  // until the sharper one is ready.
  async _sharpen(index, cover) {
    const entry = this._pages[index];
    const source = typeof entry.src === 'function' ? entry.src : entry.zoomSrc;  // a function is told `cover`
    if (!source || this._sharpening?.has(index)) return;
    (this._sharpening ??= new Set()).add(index);
    try {
      const { image, owned } = await loadPage(source, { index, size: cover, signal: this._abort.signal });
      if (owned) this._owned.add(image);
      if (this._destroyed || !this._images.has(index)) {
        this._closeIfOwned(image);
        return;
      }
      const previous = this._images.get(index);
      this._view.setPageImage(index, image, { cover });
      this._images.set(index, image);
      if (previous !== image) this._closeIfOwned(previous);
      this._emit('sharpened', { index, width: this._view.pageImageSize(index).width });
    } catch (error) {
      if (!this._destroyed) {
        this._emit('pageerror', { index, ...pageFailure(error) });
      }
    } finally {
      this._sharpening.delete(index);
    }
  }


  // ---- links ---------------------------------------------------------------------------------

  // Lays the open pages' links over them while the book rests; a moving leaf hides them.
  _layoutLinks() {
    if (this._destroyed || !this._view) return;
    const open = this._openPages();
    if (this._view.animating || !open.some((page) => this._pages[page].links?.length)) {
      this._links.hide();
      return;
    }
    const spread = this._view.restingRect();
    const vertical = this._settings.direction === 'vertical';
    const placed = open.map((page) => {
      let rect = spread;
      if (!this._view.book.isSingle()) {
        // Even pages lie on the half the book turns forward to: right (ltr), left (rtl), bottom (vertical).
        const forwardHalf = page % 2 === 0;
        const second = this._settings.direction === 'rtl' ? !forwardHalf : forwardHalf;  // right, or bottom
        rect = vertical
          ? { x: spread.x, y: spread.y + (second ? spread.height / 2 : 0), width: spread.width, height: spread.height / 2 }
          : { x: spread.x + (second ? spread.width / 2 : 0), y: spread.y, width: spread.width / 2, height: spread.height };
      }
      return { page, rect, links: this._pages[page].links ?? [] };
    });
    this._links.show(placed);
  }

  _onLink(link, event) {
    const detail = { page: link.page, href: link.href, toPage: link.toPage };
    const proceed = this.dispatchEvent(new CustomEvent('link', { detail, cancelable: true }));
    if (link.toPage !== undefined || !proceed) event.preventDefault();
    if (proceed && link.toPage !== undefined) this.flip(link.toPage).catch(() => {});
  }

  // ---- zoom ------------------------------------------------------------------------------------

  _zoomed() { return this.zoom > 1.001; }

  /** Zooms to `scale` about a viewport point (the engine keeps the table point under it). */
  _zoomAbout(scale, clientX, clientY) {
    if (this._destroyed) return;
    const before = this.zoom;
    this._view.zoomAbout(Math.min(MAX_ZOOM, Math.max(1, scale)), clientX, clientY);
    this._afterZoom(before);
  }

  /** Moves the zoomed view by CSS pixels (a pan), as far as the pages still fill it. */
  _panBy(dxCss, dyCss) {
    this._view.panBy(dxCss, dyCss);
    this._layoutLinks();
  }

  _afterZoom(before) {
    const scale = this.zoom;
    this._layoutLinks();
    // Zoomed in, a finger pans the view; at 1x the browser may scroll the page across the turn again.
    this._canvas.style.touchAction = scale > 1.001 ? 'none' : this._restingTouchAction;
    if (scale === before) return;
    clearTimeout(this._refitTimer);
    this._refitTimer = setTimeout(() => this._refitTextures(), REFIT_DELAY_MS);  // sharp pages once it rests
    this._emit('zoom', { scale });
  }

  _emit(type, detail) {
    if (!this._destroyed) this._events.dispatch(new CustomEvent(type, { detail }));
  }

  _alive() {
    if (this._destroyed) throw new Error('conecurl: this flipbook was destroyed');
  }
}
