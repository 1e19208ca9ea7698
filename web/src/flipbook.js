// The public entry point: a flipbook in a container element. Validates options, keeps a bounded
// cache of page textures around the open spread (placeholder and `pageerror` for failures), turns
// pages on clicks, taps, swipes and keys, speaks to screen readers, follows the container's size,
// and turns the engine's state into events. Drawing and animation stay in BookView over the wasm.
import { loadEngine } from './engine.js';
import { BookView, uploadSizeFor } from './book-view.js';
import { createShell } from './book-shell.js';
import { PointerDrag } from './pointer-drag.js';
import { listenForTapsAndSwipes } from './tap-swipe.js';
import { contextBudget } from './context-budget.js';
import { pagesInFrame, pagesToRelease, textureCapacity, wantedPages } from './page-residency.js';

const OPTION_CHECKS = {
  pages: (v) => (Array.isArray(v) && v.length > 0) || 'a non-empty array of page sources',
  display: (v) => ['single', 'double', 'auto'].includes(v) || "'single', 'double' or 'auto'",
  direction: (v) => ['ltr', 'rtl', 'vertical'].includes(v) || "'ltr', 'rtl' or 'vertical'",
  startPage: (v) => (Number.isInteger(v) && v >= 0) || 'a page index (a whole number from 0)',
  duration: (v) => (Number.isFinite(v) && v > 0) || 'a positive number of milliseconds',
  hardCovers: (v) => typeof v === 'boolean' || 'true or false',
  lighting: (v) => typeof v === 'boolean' || 'true or false',
  shadows: (v) => typeof v === 'boolean' || 'true or false',
  gutter: (v) => typeof v === 'boolean' || 'true or false',
  loadWindow: (v) => (Number.isInteger(v) && v >= 1) || 'a whole number of pages from 1',
  wasmUrl: (v) => typeof v === 'string' || 'a URL string',
  label: (v) => (typeof v === 'string' && v.trim() !== '') || 'a non-empty string',
};
const DEFAULTS = {
  display: 'auto', direction: 'ltr', startPage: 0, duration: 1000, hardCovers: false,
  lighting: true, shadows: true, gutter: true, loadWindow: 4, label: 'Book',
};
const AUTO_DOUBLE_ASPECT = 1.2;  // containers wider than this show two pages in 'auto'
const TEXTURE_OVERSAMPLE = 1.5;  // textures up to this many texels per device pixel of the page on screen
const REFIT_DELAY_MS = 150;      // re-upload textures for a new size once a resize has come to rest
const REFIT_RATIO = 1.25;        // ... and only those this far off the size now wanted
const SWIPE_DOMINANCE = 1.5;     // a swipe travels this much further along the turn than across it

function validate(options) {
  if (options === null || typeof options !== 'object') throw new TypeError('conecurl: options must be an object');
  for (const [key, value] of Object.entries(options)) {
    const check = OPTION_CHECKS[key];
    if (!check) throw new TypeError(`conecurl: unknown option '${key}' (allowed: ${Object.keys(OPTION_CHECKS).join(', ')})`);
    const verdict = check(value);
    if (verdict !== true) throw new TypeError(`conecurl: option '${key}' must be ${verdict}, got ${String(value)}`);
  }
  options.pages.forEach((page, index) => {
    const src = page && typeof page === 'object' && 'src' in page ? page.src : page;
    const ok = typeof src === 'string' || src instanceof Blob
      || (typeof HTMLImageElement !== 'undefined' && src instanceof HTMLImageElement)
      || (typeof HTMLCanvasElement !== 'undefined' && src instanceof HTMLCanvasElement)
      || (typeof ImageBitmap !== 'undefined' && src instanceof ImageBitmap);
    if (!ok) {
      throw new TypeError(`conecurl: option 'pages[${index}]' must be a URL, HTMLImageElement, HTMLCanvasElement, `
        + 'ImageBitmap, Blob or { src, alt, hard }');
    }
  });
  if (options.startPage !== undefined && options.startPage >= options.pages.length) {
    throw new TypeError(`conecurl: option 'startPage' must be below the page count ${options.pages.length}`);
  }
  return { ...DEFAULTS, ...options };
}

/** Loads one page source into something BookView can draw. */
async function decode(source) {
  if (typeof source === 'string') {
    const image = new Image();
    image.crossOrigin = 'anonymous';  // a page without CORS fails to load instead of tainting the canvas
    image.src = source;
    try {
      await image.decode();
    } catch {
      throw new Error(`could not load or decode '${source}' (missing, not an image, or cross-origin without CORS)`);
    }
    return image;
  }
  if (source instanceof Blob) return createImageBitmap(source);
  if (typeof HTMLImageElement !== 'undefined' && source instanceof HTMLImageElement && !source.complete) await source.decode();
  return source;
}

export class Flipbook extends EventTarget {
  /** @param {HTMLElement} container @param {object} options  See flipbook.d.ts. */
  static async create(container, options) {
    if (!(container instanceof HTMLElement)) throw new TypeError('conecurl: container must be an HTMLElement');
    const settings = validate(options);
    const engine = await loadEngine(settings.wasmUrl ? { wasmUrl: settings.wasmUrl } : {});
    const book = new this(container, settings, engine);  // `this`: subclasses get their own instances
    try {
      await book._build();
    } catch (error) {
      book.destroy();
      throw error;
    }
    return book;
  }

  constructor(container, settings, engine) {
    super();
    this._container = container;
    this._settings = settings;
    this._engine = engine;
    this._pages = settings.pages.map((p) => (p && typeof p === 'object' && 'src' in p ? p : { src: p }));
    this._state = this._pages.map(() => 'idle');  // idle | loading | loaded | failed
    this._images = new Map();       // page -> decoded image, while its texture is resident
    this._lastWanted = new Map();   // page -> tick when it was last wanted (least recently wanted goes first)
    this._wanted = new Set();
    this._wantClock = 0;   // counts residency updates, to stamp _lastWanted
    this._capacity = textureCapacity(settings.loadWindow);
    this._loadsInFlight = 0;
    this._idleWaiters = [];
    this._destroyed = false;
    this._flips = 0;       // counts flip() calls: a later one stops an earlier one's leaf-by-leaf turning
    this._shell = createShell(container, { label: settings.label, direction: settings.direction });
    this._canvas = this._shell.canvas;
    this._contextLease = contextBudget().lease(this._canvas);  // many books on a page share the WebGL contexts
    this._reducedMotion = typeof matchMedia === 'function' ? matchMedia('(prefers-reduced-motion: reduce)') : null;
  }

  get pageCount() { return this._pages.length; }
  /** The first visible page at the settled position (after destroy(), where the book was left). */
  get page() { return this._view ? this._view.book.firstVisiblePage() : (this._left?.page ?? 0); }
  get display() {
    if (!this._view) return this._left?.display ?? (this._settings.display === 'single' ? 'single' : 'double');
    return this._view.book.isSingle() ? 'single' : 'double';
  }
  /** The focusable element the book made in its container (holds the canvas). */
  get element() { return this._shell.root; }

  next() { return this._turn('forward'); }
  prev() { return this._turn('backward'); }

  /** Shows page `index`; animated turns (default) go leaf by leaf, else it jumps. */
  async flip(index, { animate = true } = {}) {
    this._alive();
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
    if (options === null || typeof options !== 'object') throw new TypeError('conecurl: options must be an object');
    const checked = validate({ ...options, pages: this._settings.pages });  // a TypeError names a bad value
    const fixed = Object.keys(options).find((key) => !['lighting', 'shadows', 'gutter'].includes(key));
    if (fixed) throw new TypeError(`conecurl: option '${fixed}' cannot change on a live book (only lighting, shadows, gutter)`);
    for (const key of Object.keys(options)) this._settings[key] = checked[key];
    const { lighting, shadows, gutter } = this._settings;
    this._view.setOptions({ lighting, shadows, gutter });
  }

  destroy() {
    if (this._destroyed) return;
    this._destroyed = true;
    this._pointer?.destroy();
    this._pointer = null;
    this._stopInput?.();
    this._resizeObserver?.disconnect();
    this._stopWatchingPixelRatio?.();
    clearTimeout(this._refitTimer);
    cancelAnimationFrame(this._followFrame);
    if (this._view) this._left = { page: this.page, display: this.display };  // reads stay answered after destroy
    this._view?.destroy();
    this._view = null;
    this._contextLease.dispose();
    this._images.clear();
    this._shell.remove();
    for (const resolve of this._idleWaiters.splice(0)) resolve();
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
      display,
      direction: this._settings.direction,
      hardPages,
      turnSeconds: this._settings.duration / 1000,
      lighting: this._settings.lighting,
      shadows: this._settings.shadows,
      gutter: this._settings.gutter,
    });
    this._contextLease.attach(view);
    return view;
  }

  // Dragging a corner or edge: a PointerDrag on each BookView (a display switch makes a new one).
  _attachPointer() {
    this._pointer?.destroy();
    this._pointer = new PointerDrag(this._view, {
      onTurnStart: (direction) => {
        this._emit('turnstart', { direction, page: this.page, drag: true });
        this._followTurns();
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
      tap: (x, y) => { if (!this._pointer?.strokeWasDrag) this._onClick(this._pageHalfAt(x, y)); },
      swipe: (dx, dy) => { if (!this._pointer?.strokeWasDrag) this._onSwipe(dx, dy); },
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
    if (this._destroyed || !half) return;
    const forwardHalf = { ltr: 'right', rtl: 'left', vertical: 'bottom' }[this._settings.direction];
    this._turnQuietly(half === forwardHalf ? 'forward' : 'backward');
  }

  _onSwipe(dx, dy) {
    if (this._destroyed) return;
    const vertical = this._settings.direction === 'vertical';
    const along = vertical ? dy : dx;
    const across = vertical ? dx : dy;
    if (Math.abs(along) < SWIPE_DOMINANCE * Math.abs(across)) return;
    // The finger moves the way the page turns: toward the spine side of the next page's place.
    const forwardSign = this._settings.direction === 'rtl' ? 1 : -1;
    this._turnQuietly(Math.sign(along) === forwardSign ? 'forward' : 'backward');
  }

  _onKeyDown(event) {
    if (this._destroyed || event.defaultPrevented || event.altKey || event.ctrlKey || event.metaKey) return;
    const keys = {
      ltr: { ArrowRight: 'forward', ArrowLeft: 'backward' },
      rtl: { ArrowLeft: 'forward', ArrowRight: 'backward' },
      vertical: { ArrowDown: 'forward', ArrowUp: 'backward' },
    }[this._settings.direction];
    const action = keys[event.key] || { PageDown: 'forward', PageUp: 'backward', Home: 'first', End: 'last' }[event.key];
    if (!action) return;
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
    if (this._prefersReducedMotion()) return this._jumpOneLeaf(direction);
    const turning = direction === 'forward' ? this._view.next() : this._view.prev();
    if (this._view.animating) {
      this._emit('turnstart', { direction, page: this.page });
      this._followTurns();
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

  // While leaves move, the pages they show change every frame (turns that waited start late).
  _followTurns() {
    if (this._followFrame) return;
    const step = () => {
      this._followFrame = 0;
      if (this._destroyed || !this._view.animating) return;
      this._updateResidency();
      this._followFrame = requestAnimationFrame(step);
    };
    this._followFrame = requestAnimationFrame(step);
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
    const pages = this._openPages();
    this._shell.showOpenPages(pages, this.pageCount, pages.map((i) => this._pages[i].alt));
  }

  // ---- the page cache ----------------------------------------------------------------------

  // Loads the pages wanted now (on screen, then the open spread's neighbours within loadWindow) and
  // releases the least recently wanted beyond the cache's capacity, which does not grow with the book.
  _updateResidency() {
    const open = this._openPages();
    const wanted = wantedPages({
      onScreen: pagesInFrame(this._view.book.frame()),
      first: open[0],
      last: open[open.length - 1],
      loadWindow: this._settings.loadWindow,
      pageCount: this.pageCount,
      capacity: this._capacity,
    });
    this._wantClock++;
    this._wanted = new Set(wanted);
    for (const page of wanted) {
      this._lastWanted.set(page, this._wantClock);
      if (this._state[page] === 'idle') this._load(page);
    }
    this._releaseExcess();
  }

  _releaseExcess() {
    const resident = [...this._images.keys()];
    const release = pagesToRelease({ resident, wanted: this._wanted, lastWanted: this._lastWanted, capacity: this._capacity });
    for (const page of release) {
      this._view.releasePageImage(page);
      this._images.delete(page);
      this._lastWanted.delete(page);
      this._state[page] = 'idle';
    }
  }

  async _load(index) {
    this._state[index] = 'loading';
    this._loadsInFlight++;
    try {
      const image = await decode(this._pages[index].src);
      if (this._destroyed || this._state[index] !== 'loading') return;
      if (!this._wanted.has(index) && this._images.size >= this._capacity) {
        this._state[index] = 'idle';  // no longer wanted and no room: not worth a texture
        return;
      }
      this._upload(index, image);
      this._state[index] = 'loaded';
      this._releaseExcess();
    } catch (error) {
      if (this._destroyed) return;
      // The page keeps the plain paper placeholder; the book keeps working.
      this._state[index] = 'failed';
      this._emit('pageerror', { index, error: error instanceof Error ? error : new Error(String(error)) });
    } finally {
      this._loadsInFlight--;
      if (!this._destroyed) {
        const loaded = this._state.filter((s) => s === 'loaded' || s === 'failed').length;
        this._emit('progress', { loaded, total: this.pageCount, pending: this._loadsInFlight });
      }
      if (this._loadsInFlight === 0) for (const resolve of this._idleWaiters.splice(0)) resolve();
    }
  }

  _upload(index, image) {
    this._view.setPageImage(index, image, { cover: this._textureCover() });
    this._images.set(index, image);
  }

  /** Texture pixels a page needs: its size on screen in device pixels, times TEXTURE_OVERSAMPLE. */
  _textureCover() {
    const rect = this._view.restingRect();
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
    if (this._loadsInFlight === 0) return Promise.resolve();
    return new Promise((resolve) => this._idleWaiters.push(resolve));
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
    if (display !== this.display) this._rebuildView(display);
    this._view.requestRender();
    clearTimeout(this._refitTimer);
    this._refitTimer = setTimeout(() => this._refitTextures(), REFIT_DELAY_MS);
    this._emit('resize', { ...this._layoutSize, display: this.display });
  }

  // The C++ Book takes its display at creation: a new BookView on the same canvas, at the same page,
  // with the textures uploaded again from the images in the cache. Turns in flight land at once.
  _rebuildView(display) {
    // A canvas that handed its context back (out of view, see context-budget.js) cannot take a new
    // renderer: switch once it has its context again.
    if (this._contextLease.state !== 'live') {
      if (!this._relayoutWhenLive) {
        this._relayoutWhenLive = true;
        this._contextLease.whenLive(() => {
          this._relayoutWhenLive = false;
          if (!this._destroyed) this._relayout();
        });
      }
      return;
    }
    const page = this.page;
    this._view.destroy();
    this._view = this._makeView(display);
    this._view.jumpTo(this._view.book.positionOfPage(page));
    this._attachPointer();
    for (const [index, image] of this._images) this._view.setPageImage(index, image, { cover: this._textureCover() });
    this._updateResidency();
    this._showOpenPages();
  }

  _refitTextures() {
    if (this._destroyed) return;
    const cover = this._textureCover();
    const maxTextureSize = this._view.renderer.maxTextureSize();
    for (const [index, image] of this._images) {
      const uploaded = this._view.pageImageSize(index);
      const natural = { width: image.naturalWidth || image.width, height: image.naturalHeight || image.height };
      const wanted = uploadSizeFor(natural.width, natural.height, { cover, maxTextureSize });
      const ratio = wanted.width / uploaded.width;
      if (ratio > REFIT_RATIO || ratio < 1 / REFIT_RATIO) this._view.setPageImage(index, image, { cover });
    }
  }

  _emit(type, detail) {
    if (!this._destroyed) this.dispatchEvent(new CustomEvent(type, { detail }));
  }

  _alive() {
    if (this._destroyed) throw new Error('conecurl: this flipbook was destroyed');
  }
}
