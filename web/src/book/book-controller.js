// The book controller: what a book is doing and what it tells its user, whichever surface draws it.
// It holds the options, the pages and their states (page-store.js), the turns asked for, zoom, size and
// events; input modules (book-input.js) and overlay layers attach to it; a surface (BookView over the
// wasm engine, or the 2D CanvasSurface) animates and draws. Flipbook and StaticBook are this class over
// each surface; the calls a surface answers are listed in docs/architecture.md.
// Over 350 lines because it is the whole public API of both book classes, each member documented;
// the work behind them is in the modules it imports.
import { followPage, openingPage } from './page-memory.js';
import { autoplaySettings, startAutoplay } from './autoplay.js';
import { startPageSound } from './page-sound.js';
import { createShell } from './book-shell.js';
import { BookEvents } from './book-events.js';
import { checkFlipOptions, checkLiveOptions, pageEntries } from './options.js';
import { LivePages } from './live-pages.js';
import { PageStore } from '../pages/page-store.js';
import { createLinkLayer } from '../layers/link-layer.js';
import { turnsAt } from '../input/turn-area.js';
import { attachInput } from '../input/book-input.js';
import { watchSize } from './size-watch.js';
import { MAX_ZOOM, displayFor, openPages } from '../engine/layout.js';
import { BookZoom } from './book-zoom.js';

const REFIT_DELAY_MS = 150;  // images are fitted to a new size or zoom once it has come to rest
const NEAR_LEAVES = 2;  // flip() turns this many leaves one by one; farther, it riffles

export class BookController extends EventTarget {
  /**
   * @param {HTMLElement} container
   * @param {object} settings  checked options with defaults (options.js validateOptions)
   * @param {object|null} pdf  an open PDF whose pages are the book's (pdf-pages.js): the book owns it
   */
  constructor(container, settings, pdf = null) {
    super();
    this._container = container;
    this._settings = settings;
    this._pdf = pdf;
    // Entries as given (a PDF's fill in their alt and links as their pages render), links in one form.
    this._pages = pageEntries(settings.pages, { copy: !pdf });
    this._events = new BookEvents(this, settings.on);  // `on` listeners first; events of create() held
    this._destroyed = false;
    this._flips = 0;  // counts flip() calls: a later one stops an earlier one's leaf-by-leaf turning
    this._surface = null;
    this._shell = createShell(container, { label: settings.label, direction: settings.direction });
    this._canvas = this._shell.canvas;
    this._zoom = new BookZoom(this._canvas, {
      surface: () => this._surface,
      moved: () => this._layoutLayers(),
      changed: (scale) => {
        this._refitSoon();  // sharp pages once it rests
        this._emit('zoom', { scale });
      },
    });
    this._store = new PageStore(this._pages, settings, {
      surface: () => this._surface,
      openPages: () => this.openPages,
      emit: (type, detail) => this._emit(type, detail),
      // A source may have learned its page's text and links while making it (a PDF page). Not while a
      // leaf moves or is lifted by a hover hint: the landing, or the hint's end, shows them again.
      onOpenPageLoaded: (index) => {
        if (!this._surface.animating && this.openPages.includes(index)) this._showOpenPages();
      },
    });
    this._html = null;  // HTML pages, once _build() has loaded their module
    this._layers = [createLinkLayer(this._shell.root, {
      linksOf: (page) => this._pages[page].links,
      onActivate: (link, event) => this._onLink(link, event),
    })];
    this._reducedMotion = typeof matchMedia === 'function' ? matchMedia('(prefers-reduced-motion: reduce)') : null;
  }

  get pageCount() { return this._pages.length; }
  /** Where page `index` stands: { state: 'idle' | 'loading' | 'loaded' | 'failed', reason?, error? }. */
  pageState(index) { return this._store.pageState(index); }
  /** The first visible page at the settled position (after destroy(), where the book was left). */
  get page() { return this._surface ? this._surface.firstVisiblePage() : (this._finalPage ?? 0); }
  get display() {
    return this._surface?.display ?? this._finalDisplay ?? (this._settings.display === 'single' ? 'single' : 'double');
  }
  /** The pages open at the settled position, as the live region announces them. */
  get openPages() {
    if (!this._surface) return [this.page];
    return openPages(this._surface.position, this.pageCount, this._surface.display);
  }
  /** The focusable element the book made in its container (holds the canvas). */
  get element() { return this._shell.root; }
  /** What draws the book: a BookView (WebGL2) or a CanvasSurface (still pages); null after destroy(). */
  get surface() { return this._surface; }
  /** A leaf is moving or waiting to (turns in flight, a held page); false after destroy(). */
  get animating() { return Boolean(this._surface?.animating); }
  /** Pages whose images are loaded and kept, in page order. */
  get residentPages() { return this._store.residentPages; }
  /** Pages loaded or failed so far, the page count, and loads running now (as the `progress` event says). */
  get progress() { return this._store.progress; }
  /** The options in effect, defaults filled in (a frozen copy; setOptions() changes the live ones). */
  get options() {
    const { pageAspect, ...options } = this._settings;  // pageAspect: the PDF's page shape, not an option
    return Object.freeze(options);
  }
  /** The page sound is muted (the `muted` option, live); the sound itself is the `sound` option. */
  get muted() { return this._settings.muted; }
  set muted(value) { this.setOptions({ muted: value }); }
  /** What the page sound is doing: { state, gain, target, speed, taps } (page-sound.js), for tools and tests. */
  get sound() { return this._sound?.status ?? null; }
  /** Where the open pages lie on the canvas, in CSS pixels (both places of a spread in double). */
  restingRect() { return this._surface.restingRect(); }
  /** The leaves lying open at the settled position: { page (-1: a blank back), x, y, width, height } in CSS px. */
  openPagePlaces() { return this._surface.openPagePlaces(); }
  /** Resolves once no page is loading (and no click waits to see if it is a double-click). */
  whenIdle() {
    if (this._input?.pendingClick) {
      return new Promise((resolve) => setTimeout(resolve, this._input.clickWaitMs + 20)).then(() => this.whenIdle());
    }
    return this._store.whenIdle();
  }

  next() { return this._turn('forward'); }
  prev() { return this._turn('backward'); }

  /** View magnification, 1 (the whole book) to MAX_ZOOM. Setting it zooms about the middle of the book. */
  get zoom() { return this._zoom.scale; }
  set zoom(scale) {
    this._alive();
    if (!(Number.isFinite(scale) && scale >= 1 && scale <= MAX_ZOOM)) {
      throw new RangeError(`conecurl: zoom must be a number from 1 to ${MAX_ZOOM}, got ${String(scale)}`);
    }
    this._zoom.aboutCentre(scale);
  }

  /**
   * Shows, frozen, the exact frame of the next ('forward') or previous ('backward') turn at progress
   * t in [0, 1]: for scrubbers and figures. Returns false at the end of the book (and on still pages).
   */
  previewTurn(direction, t) {
    this._alive();
    if (direction !== 'forward' && direction !== 'backward') {
      throw new TypeError(`conecurl: previewTurn direction must be 'forward' or 'backward', got ${String(direction)}`);
    }
    if (!(Number.isFinite(t) && t >= 0 && t <= 1)) throw new RangeError(`conecurl: previewTurn t must be in [0, 1], got ${String(t)}`);
    const shown = this._surface.showTurn(direction, t);
    if (shown) this._hideLayers();  // a posed leaf: live layers give way until the book next lands
    this._store.update();  // the pages the posed leaf shows
    return shown;
  }

  /**
   * Shows page `index`: animated (default), a near page leaf by leaf and a far one by a riffle (several
   * leaves at once, landing within RIFFLE_SPAN turns), else it jumps.
   */
  async flip(index, options) {
    this._alive();
    const { animate } = checkFlipOptions(options);
    if (!Number.isInteger(index) || index < 0 || index >= this.pageCount) {
      throw new RangeError(`conecurl: page ${index} is not in 0..${this.pageCount - 1}`);
    }
    // The latest flip wins: an animated flip still under way stops where it is (and resolves).
    const flip = ++this._flips;
    const surface = this._surface;
    if (!animate || !this._animates()) {
      const target = surface.positionOfPage(index);
      if (surface.position === target && !surface.animating) return;
      surface.jumpTo(target);
      this._store.update();
      this._landed();
      return;
    }
    for (;;) {
      if (index >= this.pageCount) return;  // pages removed meanwhile (removePages): that page is gone
      const target = this._surface.positionOfPage(index);  // again each leaf: the display may switch
      if (this._surface.position === target) return;
      const far = Math.abs(target - this._surface.position) > NEAR_LEAVES;
      const turned = await (far ? this._riffle(index, flip) : this._turn(target > this._surface.position ? 'forward' : 'backward'));
      if (!turned || this._destroyed || flip !== this._flips) return;
    }
  }

  /**
   * Switches lighting, shadows, gutter shading, thickness and display on a live book (same surface, same page);
   * other options need a new book.
   */
  setOptions(options) {
    this._alive();
    Object.assign(this._settings, checkLiveOptions(options, this._settings.pages));
    const { lighting, shadows, gutter, thickness } = this._settings;
    this._surface.setOptions({ lighting, shadows, gutter, thickness });
    if ('display' in options) this._relayout();
    this._sound.update();
  }

  /** Inserts `pages` before page `at` on the live book; resolves once applied (live-pages.js). */
  async insertPages(at, pages) { return this._live().insert(at, pages); }
  /** Removes `count` pages (default 1) from page `from` on; resolves once applied. */
  async removePages(from, count = 1) { return this._live().remove(from, count); }
  /** Puts `page` in the place of page `index`; resolves once applied. */
  async replacePage(index, page) { return this._live().replace(index, page); }

  _live() {
    this._alive();
    return (this._livePages ??= new LivePages({
      entries: this._pages, store: this._store, hardCovers: this._settings.hardCovers, surface: () => this._surface,
      html: () => this._html, attachHtml: (HtmlPages) => this._mountHtml(HtmlPages), page: () => this.page,
      pdf: () => Boolean(this._pdf), alive: () => this._alive(), shown: () => this._showOpenPages(),
      emit: (type, detail) => this._emit(type, detail), flushEvents: () => this._events.flush(),
    }));
  }

  destroy() {
    if (this._destroyed) return;
    if (this._surface) {
      this._finalPage = this.page;  // page and display still answer after destroy()
      this._finalDisplay = this.display;
    }
    this._destroyed = true;
    this._events.drop();
    this._store.close();
    this._pdf?.destroy();
    this._pdf = null;
    for (const layer of this._layers) layer.remove();
    this._input?.stop();
    this._stopWatchingSize?.();
    this._stopFollowingPage?.();
    this._stopAutoplay?.();
    this._sound?.stop();
    clearTimeout(this._refitTimer);
    this._surface?.destroy({ releaseContext: true });  // the canvas goes: give its WebGL context up now
    this._surface = null;
    this._shell.remove();
  }

  // ---- building: the subclass makes the surface ----------------------------------------------

  /** The surface for `display` on this._canvas (Flipbook: a BookView; StaticBook: a CanvasSurface). */
  _makeSurface() { throw new Error('conecurl: BookController is abstract: use Flipbook or StaticBook'); }

  /** Whether turns on this surface animate (a still surface cuts to the next spread). */
  _animates() { return this._surface.kind === 'webgl' && !this._reducedMotion?.matches; }

  async _build() {
    // HTML pages live over the canvas while they lie open (html-pages.js, loaded only for books that have them).
    const HtmlPages = this._pages.some((entry) => entry.html) ? (await import('../layers/html-pages.js')).HtmlPages : null;
    if (HtmlPages && !this._destroyed) this._mountHtml(HtmlPages);
    const { width, height } = this._shell.root.getBoundingClientRect();
    this._layoutSize = { width, height };
    this._surface = this._makeSurface(displayFor(this._settings.display, this._layoutSize));
    // While leaves move, the pages they show change (turns that waited start late): the surface says when.
    this._surface.onPagesChanged = () => { if (!this._destroyed) this._store.update(); };
    // After a lost context, pages whose images the store closed once uploaded are decoded again.
    this._surface.onImagesLost = (pages) => { if (!this._destroyed) this._store.reloadLost(pages); };
    this._surface.jumpTo(this._surface.positionOfPage(openingPage(this._settings, this.pageCount)));
    this._attachInput();
    this._stopWatchingSize = watchSize(this._shell.root, this._layoutSize, (size) => {
      if (this._destroyed) return;
      this._layoutSize = size;
      this._relayout();
    });
    this._showOpenPages();
    this._store.update();
    this._stopFollowingPage = followPage(this, this._settings);  // #page=N and the remembered page
    const autoplay = autoplaySettings(this._settings.autoplay);
    if (autoplay) this._stopAutoplay = startAutoplay(this, this._shell.root, autoplay);
    this._sound = startPageSound(this, this._shell.root, { animates: () => this._animates() });
    await this.whenIdle();
    this._emit('ready', { page: this.page });
  }

  // The HTML pages' layer, under the links.
  _mountHtml(HtmlPages) {
    this._html = new HtmlPages(this._shell.root, this._pages, {
      direction: this._settings.direction,
      turnArea: this._settings.turnArea,
      canvas: this._canvas,
      zoom: () => this.zoom,
      pageSize: () => this._store.pageCssSize(),
      changed: (index) => this._store.refresh(index),
      pagesOnScreen: () => this._surface?.pagesOnScreen() ?? [],
      // A video's new frame drawn into the page's image: upload it again, if the page is still kept.
      // (The snapshot already has the page's texture size: no cover to work out, no layout read a frame.)
      redrawn: (index, canvas) => { if (this._store.holds(index, canvas)) this._surface.setPageImage(index, canvas); },
    });
    this._layers.unshift(this._html);
  }

  // ---- input: each module in its own file (book-input.js), told what it may do --------------

  _attachInput() {
    this._input = attachInput({
      canvas: this._canvas, element: this._shell.root, surface: this._surface, direction: this._settings.direction,
    }, {
      zoom: () => this.zoom,
      zoomed: () => this._zoom.zoomed,
      zoomAbout: (scale, x, y) => { if (!this._destroyed) this._zoom.about(scale, x, y); },
      zoomAboutCentre: (scale) => { if (!this._destroyed) this._zoom.aboutCentre(scale); },
      panBy: (dx, dy) => this._zoom.panBy(dx, dy),
      turn: (direction) => { if (!this._destroyed) this._turn(direction).catch(() => {}); },  // input after destroy() is dropped
      jump: (end) => { this.flip(end === 'first' ? 0 : this.pageCount - 1).catch(() => {}); },  // Home, End: a riffle
      turnsFrom: (clientX, clientY) => this._turnsFrom(clientX, clientY),
      dragStarted: (direction) => {
        this._hideLayers();
        this._emit('turnstart', { direction, page: this.page, drag: true });
        this._store.update();
      },
      dragEnded: (completed) => {
        if (this._destroyed) return;
        this._store.update();
        if (completed) {
          this._landed();
        } else {
          this._showOpenPages();
          this._emit('turncancel', { page: this.page });
        }
      },
      // A corner lifts as the mouse hovers it: the live layers give way to the page's texture.
      hintStarted: () => this._hideLayers(),
      // A corner lifted by hovering fell back: the open pages are those from before it again.
      hintEnded: () => { if (!this._destroyed) this._showOpenPages(); },
    });
  }

  // ---- turning -------------------------------------------------------------------------------

  async _turn(direction) {
    this._alive();
    const ready = this._readyToMove();
    if (ready !== true && !(await ready)) return false;  // no wait unless a page is drawn again: next() starts at once
    if (!this._animates()) return this._jumpOneLeaf(direction);
    return this._follow(this._surface.turn(direction), { direction });
  }

  // A riffle to page `index`, once leaves in flight have landed (false if a later flip came first). The
  // position is found after the wait: the display may have switched meanwhile.
  async _riffle(index, flip) {
    await this._surface.settle();
    if (this._destroyed || flip !== this._flips) return false;
    const ready = this._readyToMove();
    if ((ready !== true && !(await ready)) || flip !== this._flips || index >= this.pageCount) return false;
    const target = this._surface.positionOfPage(index);
    if (target === this._surface.position) return true;
    const direction = target > this._surface.position ? 'forward' : 'backward';
    const riffling = this._surface.riffle(target);
    if (!this._surface.animating) return this._turn(direction);  // refused: leaf by leaf then
    return this._follow(riffling, { direction, riffle: true });
  }

  // Before leaves move: a turn asked for by code shows the whole book again, and open HTML pages whose
  // content changed since their textures were made are drawn again: true at once if none, else a
  // promise of whether the book is still alive once they are.
  _readyToMove() {
    if (this._zoom.zoomed) this._zoom.about(1, 0, 0);
    const stale = this._html?.staleAmong(this.openPages) ?? [];
    if (stale.length === 0) return true;
    return Promise.all(stale.map((index) => this._store.refresh(index))).then(() => !this._destroyed);
  }

  // Leaves set moving by the surface (`moving` resolves whether they landed): turnstart, the pages they
  // show, then turned.
  async _follow(moving, detail) {
    if (this._surface.animating) {
      this._hideLayers();
      this._emit('turnstart', { ...detail, page: this.page });
    }
    this._store.update();
    const landed = await moving;
    if (this._destroyed) return false;
    this._store.update();
    if (landed) this._landed();
    return landed;
  }

  /** Whether a press at a viewport point may turn a page there (the `turnArea` option). */
  _turnsFrom(clientX, clientY) {
    const box = this._canvas.getBoundingClientRect();
    const { turnArea, direction } = this._settings;
    return turnsAt(turnArea, () => this._surface.openPagePlaces(), direction, clientX - box.left, clientY - box.top);
  }

  // Reduced motion, or still pages: a turn is a cut to the next spread, with the same events.
  _jumpOneLeaf(direction) {
    const surface = this._surface;
    const target = surface.position + (direction === 'forward' ? 1 : -1);
    if (target < 0 || target > surface.lastPosition()) return false;
    surface.jumpTo(target);
    this._emit('turnstart', { direction, page: this.page });
    this._store.update();
    this._landed();
    return true;
  }

  _landed() {
    this._showOpenPages();
    this._emit('turned', { page: this.page });
  }

  // The open pages are shown again: the overlay layers laid over them, the live region and alt text.
  _showOpenPages() {
    this._layoutLayers();
    const pages = this.openPages;
    this._shell.showOpenPages(pages, this.pageCount, pages.map((i) => this._pages[i].alt));
  }

  // ---- overlay layers: laid over the open pages while the book rests, hidden while a leaf moves --
  _layoutLayers() {
    if (this._destroyed || !this._surface) return;
    if (this._surface.animating) {
      this._hideLayers();
      return;
    }
    const places = this._surface.openPagePlaces().filter((place) => place.page >= 0);
    for (const layer of this._layers) layer.place(places);
  }

  _hideLayers() {
    for (const layer of this._layers) layer.hide();
  }

  _onLink(link, event) {
    const detail = { page: link.page, href: link.href, toPage: link.toPage };
    const proceed = this.dispatchEvent(new CustomEvent('link', { detail, cancelable: true }));
    if (link.toPage !== undefined || !proceed) event.preventDefault();
    if (proceed && link.toPage !== undefined) this.flip(link.toPage).catch(() => {});
  }

  // ---- size and pixel ratio ------------------------------------------------------------------
  // The container or the pixel ratio changed: switch single/double for 'auto' (same surface, same
  // page), draw at the new size, and once resizing rests bring the images to the size now wanted.
  _relayout() {
    const display = displayFor(this._settings.display, this._layoutSize);
    if (display !== this.display) {
      this._surface.setDisplay(display);
      this._store.update();
      this._showOpenPages();
    }
    this._surface.sizeChanged();
    this._refitSoon();
    this._layoutLayers();
    this._emit('resize', { ...this._layoutSize, display: this.display });
  }

  _refitSoon() {
    clearTimeout(this._refitTimer);
    this._refitTimer = setTimeout(() => this._store.refit(), REFIT_DELAY_MS);
  }

  _emit(type, detail) {
    if (!this._destroyed) this._events.dispatch(new CustomEvent(type, { detail }));
  }

  _alive() {
    if (this._destroyed) throw new Error('conecurl: this flipbook was destroyed');
  }
}
