// The book controller: what a book is doing and tells its user, whichever surface draws it; the public API
// of Flipbook and StaticBook. It holds the options, pages and their states (page-store.js), zoom, size, the
// open pages and events; turns are book-turns.js; its parts are wired to one port (`_makePort`) by
// book-wiring.js and document-wiring.js (document API, viewer). A surface's calls: docs/architecture.md.
// Over 350 lines because it is the whole public API of a book: each member a line or two here, its work in its parts.
import { createShell } from './book-shell.js';
import { BookEvents } from './book-events.js';
import { afterFirstFrame } from '../surfaces/after-first-frame.js';
import { checkFlipOptions, checkLiveOptions, pageEntries } from './options.js';
import { BookTurns } from './book-turns.js';
import {
  followSurface, loadCompanions, loadFirstView, loadLateParts, makeHtmlPages, makeLinkLayer, makeLivePages,
  makePageStore, makeZoom, openingPageOf, prefetchOpening, startCompanions, watchBookSize,
} from './book-wiring.js';
import { makeReadAloud } from './book-read-aloud.js';
import { makeDocumentApi, planViewer } from '../document/document-wiring.js';
import { DEFAULT_PAGE_ASPECT, MAX_ZOOM, displayFor, openPages } from '../engine/layout.js';
import { OpeningPoster } from './opening-poster.js';

const REFIT_DELAY_MS = 150;  // images are fitted to a new size or zoom once it has come to rest

export class BookController extends EventTarget {
  /**
   * @param {HTMLElement} container
   * @param {object} settings  checked options with defaults (options.js validateOptions)
   * @param {object|null} doc  an open document (document/pdf-pages.js, published-document.js) whose pages are the book's: it owns it
   */
  constructor(container, settings, doc = null) {
    super();
    this._container = container;
    this._settings = settings;
    this._document = doc;
    // Entries as given (a PDF's fill in their alt and links as their pages render), links in one form.
    this._pages = pageEntries(settings.pages, { copy: !doc });
    this._events = new BookEvents(this, settings.on);  // `on` listeners first; events of create() held
    this._destroyed = false;
    this._deferred = new Set();  // the cancels of tasks deferred (_defer), called by destroy()
    this._surface = null;
    this._shell = createShell(container, { label: settings.label, direction: settings.direction });
    this._canvas = this._shell.canvas;
    this._port = this._makePort();  // what the parts below may ask of the book (book-wiring.js)
    this._doc = makeDocumentApi(this, this._port);  // outline, search, thumbnails, fullscreen, download, print
    this._reading = makeReadAloud(this, this._port, (index) => this._doc.pageText(index));  // read-aloud, loaded on first use
    this._zoom = makeZoom(this._port);
    this._store = makePageStore(this._port);
    this._turns = new BookTurns(this._port);
    this._html = null;  // HTML pages, once _build() has loaded their module
    this._text = null;  // a PDF's selectable text, once _build() has loaded its module (text-layer.js)
    this._poster = new OpeningPoster((schedule, task) => this._defer(schedule, task));  // the first view's placeholders as images
    this._links = makeLinkLayer(this._port);
    this._layers = [this._links];
    this._reducedMotion = typeof matchMedia === 'function' ? matchMedia('(prefers-reduced-motion: reduce)') : null;
  }

  get pageCount() { return this._pages.length; }
  /** Where page `index` stands: { state: 'idle' | 'loading' | 'loaded' | 'failed', reason?, error? }. */
  pageState(index) { return this._store.pageState(index); }
  /** The first visible page at the settled position (after destroy(), where the book was left). */
  get page() { return this._surface ? this._surface.firstVisiblePage() : (this._finalPage ?? 0); }
  get display() { return this._surface?.display ?? this._finalDisplay ?? (this._settings.display === 'single' ? 'single' : 'double'); }
  /** The pages open at the settled position, as the live region announces them. */
  get openPages() { return this._surface ? openPages(this._surface.position, this.pageCount, this._surface.display) : [this.page]; }
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
    if (!this._input?.pendingClick) return this._store.whenIdle();
    return new Promise((resolve) => setTimeout(resolve, this._input.clickWaitMs + 20)).then(() => this.whenIdle());
  }

  next() { return this._turns.turn('forward'); }
  prev() { return this._turns.turn('backward'); }

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
    return this._turns.flip(index, animate);
  }

  /**
   * Switches lighting, shadows, gutter shading, show-through, thickness, resolution and display on a live book (same surface, same page);
   * other options need a new book.
   */
  setOptions(options) {
    this._alive();
    Object.assign(this._settings, checkLiveOptions(options, this._settings.pages));
    const { lighting, shadows, gutter, showThrough, thickness, resolution } = this._settings;
    this._surface.setOptions({ lighting, shadows, gutter, showThrough, thickness, resolution });
    if ('display' in options || 'minPageWidth' in options) this._relayout();
    this._sound.update();
  }

  /** Inserts `pages` before page `at` on the live book; resolves once applied (live-pages.js). */
  async insertPages(at, pages) { return (await this._live()).insert(at, pages); }
  /** Removes `count` pages (default 1) from page `from` on; resolves once applied. */
  async removePages(from, count = 1) { return (await this._live()).remove(from, count); }
  /** Puts `page` in the place of page `index`; resolves once applied. */
  async replacePage(index, page) { return (await this._live()).replace(index, page); }

  // ---- the document API (book-wiring.js makeDocumentApi: each part a module loaded on first use) ----
  /** The table of contents: [{ title, page, children }] (page from 0), from the `outline` option or a PDF's bookmarks. */
  async outline() { this._alive(); return this._doc.outline(); }
  /** The hits of `text` (case and diacritics folded): [{ page, snippet, rects }]; `signal` aborts it. */
  async search(text, options) { this._alive(); return this._doc.search(text, options); }
  /** Turns to a hit of search() and marks it. */
  async showHit(hit) { this._alive(); return this._doc.showHit(hit); }
  /** Ends the search: its marks go. */
  clearSearch() { this._doc.clearSearch(); }
  /** Page `index` drawn about `width` (x `height`) pixels, from its source: a canvas. */
  async pageThumbnail(index, size) { this._alive(); return this._doc.thumbnail(index, size); }
  /** The book's container is fullscreen. */
  get fullscreen() { return (this._container.getRootNode().fullscreenElement ?? null) === this._container; }
  /** Enters, leaves (force) or toggles fullscreen; resolves with whether it is fullscreen. */
  async toggleFullscreen(force) { this._alive(); return this._doc.toggleFullscreen(force); }
  /** Downloads the `download` URL or the PDF, unless a `download` listener prevents it; resolves whether it did. */
  async download() { this._alive(); return this._doc.download(); }
  /** Prints the pages, unless a `print` listener prevents it; resolves whether it did. */
  async print() { this._alive(); return this._doc.print(); }

  // ---- read-aloud (book-read-aloud.js: read-aloud/ loaded on first use) ----
  /** Reads aloud from the open page, word by word, turning at the end of the open pages; resolves with the reading. */
  async readAloud(options) { this._alive(); return this._reading.start(options); }
  /** The reading aloud now (what readAloud() resolved with), or null. */
  get readingAloud() { return this._reading.current(); }
  /** The browser's speech voices, in the order read-aloud chooses from for the open page's language ([] where it has none). */
  async readAloudVoices() { this._alive(); return this._reading.voices(this.pageLanguage()); }
  /** The language page `index` (default: the first open page) is read aloud in: an HTML page's, the document's, the book's. */
  pageLanguage(index) {
    this._alive();
    if (index !== undefined && !(Number.isInteger(index) && index >= 0 && index < this.pageCount)) {
      throw new RangeError(`conecurl: page ${index} is not in 0..${this.pageCount - 1}`);
    }
    return this._reading.lang(index ?? this.page);
  }
  /** Whether readAloud() can read this book: a page has recorded narration, or the browser has a voice. */
  async canReadAloud() { this._alive(); return this._reading.can(); }

  // live-pages.js, imported on the first change asked for.
  async _live() {
    this._alive();
    const live = await (this._livePages ??= makeLivePages(this._port));
    this._alive();
    return live;
  }

  destroy() {
    if (this._destroyed) return;
    this._reading.stop();  // `readaloudend` (reason 'destroyed') while listeners still hear it
    if (this._surface) {
      this._finalPage = this.page;  // page and display still answer after destroy()
      this._finalDisplay = this.display;
    }
    this._controls?.remove();  // before the book goes: closing a panel may end a search
    this._controls = null;
    this._destroyed = true;
    for (const cancel of this._deferred) cancel();
    this._deferred.clear();
    this._events.drop();
    this._store.close();
    this._doc.stop();
    this._document?.destroy();
    this._document = null;
    for (const layer of this._layers) layer.remove();
    this._poster.remove();
    this._input?.stop();
    this._stopWatchingSize?.();
    this._stopCompanions?.();  // page memory, autoplay, the page sound
    clearTimeout(this._refitTimer);
    this._surface?.destroy({ releaseContext: true });  // the canvas goes: give its WebGL context up now
    this._surface = null;
    this._shell.remove();
  }

  // ---- building: the subclass makes the surface ----------------------------------------------

  /** The surface for `display` on this._canvas, or a promise of it (Flipbook: a BookView; StaticBook: a CanvasSurface). */
  _makeSurface() { throw new Error('conecurl: BookController is abstract: use Flipbook or StaticBook'); }
  /** Readies the canvas before the layers over it are laid in (Flipbook: its WebGL context; it may _replaceCanvas()). */
  _prepareCanvas() {}

  /** Whether turns on this surface animate (a still surface cuts to the next spread). */
  _animates() { return this._surface.kind === 'webgl' && !this._reducedMotion?.matches; }

  // Builds the first view. destroy() meanwhile (a subclass holds the instance: <cone-flipbook> removed
  // from the document) stops it at its next step, with nothing made after it: _stopIfDestroyed().
  async _build() {
    this._stopIfDestroyed();
    // HTML pages live over the canvas while they lie open (html-pages.js, loaded only for books that have them).
    const htmlPages = this._pages.some((entry) => entry.html) ? import('../layers/html-pages.js') : null;
    // The toolbar's options checked and its room kept now (the toolbar itself comes after the first spread);
    // page memory says where the book opens.
    const [viewer, companionModules] = await Promise.all([planViewer(this, this._port), loadCompanions(this._settings)]);
    this._stopIfDestroyed();
    const { width, height } = this._shell.root.getBoundingClientRect();
    this._layoutSize = { width, height };
    const display = displayFor(this._settings.display, this._layoutSize, this._settings);
    const opening = openingPageOf(companionModules, this._settings, this.pageCount);
    // Fetched and decoded while the surface is made; the pages the poster shows once it has painted.
    prefetchOpening(this._port, display, opening, this._poster.placeholdersShown);
    // The opening pages' placeholders until the surface shows them, painted before the context is made.
    await this._poster.show(this._canvas, { entries: this._pages, ...this._layoutShape(display) }, this._layoutSize, opening);
    this._stopIfDestroyed();
    this._prepareCanvas();
    const HtmlPages = htmlPages && (await htmlPages).HtmlPages;
    this._stopIfDestroyed();
    if (HtmlPages) this._mountHtml(HtmlPages);
    const surface = await this._makeSurface(display);  // Flipbook's waits for the engine, and makes none once destroyed
    if (this._destroyed) surface.destroy({ releaseContext: true });  // made as destroy() ran
    this._stopIfDestroyed();
    this._surface = surface;
    this._poster.surfaceMade();
    followSurface(this._port);  // the pages a moving leaf shows, images lost with a context
    this._surface.jumpTo(this._surface.positionOfPage(opening));
    this._stopWatchingSize = watchBookSize(this._port, this._layoutSize);
    this._showOpenPages();
    this._store.update();
    const companions = startCompanions(this, this._port, companionModules);  // page memory, autoplay, the page sound
    this._sound = companions.sound;
    this._stopCompanions = companions.stop;
    // Its pages on screen, drawn; then their neighbours, and (once those on screen show) what they did not need.
    await loadFirstView(this._port, () => this._buildAfterFirstSpread(viewer));
    this._stopIfDestroyed();
    this._emit('ready', { page: this.page });
    this._doc.indexInBackground();  // a PDF's text, for search, in idle time from now on
  }

  // Once the first spread shows (each page on screen its placeholder or image): input, the toolbar (in the
  // room kept for it), a document's selectable text under the links, and the edge marks, imported only now;
  // then laid over the open pages.
  async _buildAfterFirstSpread(viewer) {
    this._port.afterFirstFrame(() => this._poster.retire());  // the surface's frame of those pages is on screen
    const parts = loadLateParts(this._port, this._links.element);
    const [input, controls, text, EdgeMarks] = await Promise.all([parts.input, viewer.attach(), parts.text, parts.edgeMarks]);
    if (this._destroyed) {  // made as destroy() ran: it found none to remove
      input?.stop();
      controls?.remove();
      text?.remove();
    }
    this._stopIfDestroyed();
    this._input = input;
    this._controls = controls;
    this._text = text;
    if (text) this._layers.splice(this._layers.indexOf(this._links), 0, text);
    if (EdgeMarks) this._layers.push(new EdgeMarks(this, this._port));  // tabs and ticks on the fore-edge
    this._showOpenPages();
  }

  // `task` run by `schedule` (after-first-frame.js: afterFirstFrame or whenIdle); cancelled if the book is destroyed first.
  _defer(schedule, task) {
    const cancel = schedule(() => {
      this._deferred.delete(cancel);
      task();
    });
    this._deferred.add(cancel);
  }

  // This book's shape in `display` as layout.js lays it out: what the poster and a still surface place pages by.
  _layoutShape(display) {
    return { pageCount: this.pageCount, display, direction: this._settings.direction,
      pageAspect: this._settings.pageAspect || DEFAULT_PAGE_ASPECT, center: this._settings.center, ...this._stackShape() };
  }

  // How the surface to come lays its stacks, for the poster: a still surface draws none (Flipbook's engine does).
  _stackShape() { return {}; }

  // The book draws on a fresh canvas in place of its own (Flipbook: the context its canvas was given is not the one wanted).
  _replaceCanvas() {
    this._port.canvas = this._canvas = this._shell.replaceCanvas();
    this._zoom = makeZoom(this._port);  // the only part that holds the canvas before the layers are laid in
  }

  // The HTML pages' layer, under the links.
  _mountHtml(HtmlPages) {
    this._html = makeHtmlPages(HtmlPages, this._port);
    this._layers.unshift(this._html);
  }

  // ---- the port: all that book-turns.js and book-wiring.js see of the book (book-wiring.js BookPort) --

  _makePort() {
    return {
      canvas: this._canvas,
      root: this._shell.root,
      entries: this._pages,
      settings: this._settings,
      surface: () => this._surface,
      store: () => this._store,
      zoom: () => this._zoom,
      turns: () => this._turns,
      html: () => this._html,
      destroyed: () => this._destroyed,
      alive: () => this._alive(),
      animates: () => this._animates(),
      page: () => this.page,
      pageCount: () => this.pageCount,
      openPages: () => this.openPages,
      emit: (type, detail) => this._emit(type, detail),
      afterFirstFrame: (task) => this._defer(afterFirstFrame, task),
      flip: (index) => this.flip(index),
      showOpenPages: () => this._showOpenPages(),
      layoutLayers: () => this._layoutLayers(),
      hideLayers: () => this._hideLayers(),
      refitSoon: () => this._refitSoon(),
      resized: (size) => { this._layoutSize = size; this._relayout(); },
      attachHtml: (HtmlPages) => this._mountHtml(HtmlPages),
      followLink: (link, event) => this._onLink(link, event),
      flushEvents: () => this._events.flush(),
      isDocument: () => Boolean(this._document),
      document: () => this._document,
      container: this._container,
      addLayer: (layer) => this._layers.push(layer),
      decorate: (index, image) => this._doc.decorate(index, image, this._reading.marksOn(index)),
      duckSound: (on) => this._sound?.duck(on),
    };
  }

  // ---- the open pages, the overlay layers, links ---------------------------------------------

  // The open pages are shown again: the overlay layers laid over them, the live region and alt text.
  _showOpenPages() {
    this._layoutLayers();
    const pages = this.openPages;
    // A page whose text layer is there is read from it, in order: its alt would say it all again.
    this._shell.showOpenPages(pages, this.pageCount, pages.map((i) => (this._text ? undefined : this._pages[i].alt)));
  }

  // Overlay layers: laid over the open pages while the book rests, hidden while a leaf moves.
  _layoutLayers() {
    if (this._destroyed || !this._surface) return;
    if (this._surface.animating) {
      this._hideLayers();
      return;
    }
    const places = this._surface.openPagePlaces().filter((place) => place.page >= 0);
    this._poster.fit(places);  // gone where the open pages lie elsewhere: zoomed, or other pages open
    for (const layer of this._layers) layer.place(places);
  }

  _hideLayers() {
    this._poster.remove();  // a moving leaf is the surface's alone
    for (const layer of this._layers) layer.hide();
  }

  _onLink(link, event) {
    const detail = { page: link.page, href: link.href, toPage: link.toPage };
    const proceed = this.dispatchEvent(new CustomEvent('link', { detail, cancelable: true }));
    if (link.toPage !== undefined || !proceed) event.preventDefault();
    if (proceed && link.toPage !== undefined) this.flip(link.toPage).catch(() => {});
  }

  // Size, pixel ratio or display options changed: 'auto' chooses again (layout.js displayFor, from the
  // settings' minPageWidth, direction, pageAspect); a switch keeps surface and page and says `displaychange`.
  _relayout() {
    this._poster.remove();  // laid for the first size
    const [display, previous] = [displayFor(this._settings.display, this._layoutSize, this._settings), this.display];
    if (display !== previous) {
      this._surface.setDisplay(display);
      this._store.update();
      this._showOpenPages();
      this._emit('displaychange', { display, previous });
    }
    this._surface.sizeChanged();  // drawn at the new size; the images refit once resizing rests
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

  // While create() builds the book: once destroy() has run, nothing more is made and create() rejects with an AbortError.
  _stopIfDestroyed() {
    if (this._destroyed) throw new DOMException('conecurl: the book was destroyed before create() finished', 'AbortError');
  }
}
