// The public entry point: a flipbook in a container element. Validates options, loads pages lazily
// around the open spread (placeholder and `pageerror` for failures), and turns the engine's
// state into events. Drawing and animation stay in the engine (BookView over the wasm).
import { loadEngine } from './engine.js';
import { BookView } from './book-view.js';
import { PointerDrag } from './pointer-drag.js';

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
};
const DEFAULTS = {
  display: 'auto', direction: 'ltr', startPage: 0, duration: 1000, hardCovers: false,
  lighting: true, shadows: true, gutter: true, loadWindow: 4,
};
const AUTO_DOUBLE_ASPECT = 1.2;  // containers wider than this show two pages in 'auto'

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
    await book._build();
    return book;
  }

  constructor(container, settings, engine) {
    super();
    this._container = container;
    this._settings = settings;
    this._engine = engine;
    this._pages = settings.pages.map((p) => (p && typeof p === 'object' && 'src' in p ? p : { src: p }));
    this._state = this._pages.map(() => 'idle');  // idle | loading | loaded | failed
    this._destroyed = false;
    this._canvas = document.createElement('canvas');
    this._canvas.style.cssText = 'display:block;width:100%;height:100%';
    container.append(this._canvas);
  }

  get pageCount() { return this._pages.length; }
  /** The first visible page at the settled position. */
  get page() { return this._view ? this._view.book.firstVisiblePage() : 0; }
  get display() { return this._view.book.isSingle() ? 'single' : 'double'; }

  next() { return this._turn('forward'); }
  prev() { return this._turn('backward'); }

  /** Shows page `index`; animated turns (default) go leaf by leaf, else it jumps. */
  async flip(index, { animate = true } = {}) {
    this._alive();
    if (!Number.isInteger(index) || index < 0 || index >= this.pageCount) {
      throw new RangeError(`conecurl: page ${index} is not in 0..${this.pageCount - 1}`);
    }
    const target = this._view.book.positionOfPage(index);
    if (!animate) {
      this._view.jumpTo(target);
      this._loadAround();
      this._emit('turned', { page: this.page });
      return;
    }
    while (this._view.position !== target) {
      const turned = await this._turn(target > this._view.position ? 'forward' : 'backward');
      if (!turned || this._destroyed) return;
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
    this._view?.destroy();
    this._view = null;
    this._canvas.remove();
  }

  async _build() {
    const { width, height } = this._container.getBoundingClientRect();
    const display = this._settings.display === 'auto'
      ? (width / Math.max(1, height) > AUTO_DOUBLE_ASPECT ? 'double' : 'single')
      : this._settings.display;
    const hardPages = this._pages.map((p, i) => (p.hard || (this._settings.hardCovers
      && (i === 0 || i === this.pageCount - 1)) ? i : -1)).filter((i) => i >= 0);
    this._view = await BookView.create(this._canvas, {
      engine: this._engine,
      pageCount: this.pageCount,
      display,
      direction: this._settings.direction,
      hardPages,
      turnSeconds: this._settings.duration / 1000,
      lighting: this._settings.lighting,
      shadows: this._settings.shadows,
      gutter: this._settings.gutter,
    });
    this._view.jumpTo(this._view.book.positionOfPage(this._settings.startPage));
    this._pointer = new PointerDrag(this._view, {
      onTurnStart: (direction) => {
        this._emit('turnstart', { direction, page: this.page, drag: true });
        this._loadAround();
      },
      onTurnEnd: (completed) => {
        if (this._destroyed) return;
        this._loadAround();
        this._emit(completed ? 'turned' : 'turncancel', { page: this.page });
      },
    });
    await this._loadAround();
    this._emit('ready', { page: this.page });
  }

  async _turn(direction) {
    this._alive();
    const turning = direction === 'forward' ? this._view.next() : this._view.prev();
    if (this._view.animating) this._emit('turnstart', { direction, page: this.page });
    this._loadAround();
    const turned = await turning;
    if (this._destroyed) return false;
    this._loadAround();
    if (turned) this._emit('turned', { page: this.page });
    return turned;
  }

  // Loads pages within loadWindow of the open spread and releases the rest, so memory does not grow
  // with the book. Resolves when the pages it started have settled (loaded or failed).
  _loadAround() {
    const first = this.page;
    const reach = this._settings.loadWindow + (this._view.book.isSingle() ? 0 : 1);
    const started = [];
    this._pages.forEach((page, index) => {
      const near = index >= first - this._settings.loadWindow && index <= first + reach;
      if (near && this._state[index] === 'idle') started.push(this._load(index));
      if (!near && this._state[index] === 'loaded') {
        this._view.releasePageImage(index);
        this._state[index] = 'idle';
      }
    });
    return Promise.all(started);
  }

  async _load(index) {
    this._state[index] = 'loading';
    try {
      const image = await decode(this._pages[index].src);
      if (this._destroyed || this._state[index] !== 'loading') return;
      this._view.setPageImage(index, image);
      this._state[index] = 'loaded';
    } catch (error) {
      if (this._destroyed) return;
      // The page keeps the plain paper placeholder; the book keeps working.
      this._state[index] = 'failed';
      this._emit('pageerror', { index, error: error instanceof Error ? error : new Error(String(error)) });
    }
    const loaded = this._state.filter((s) => s === 'loaded' || s === 'failed').length;
    this._emit('progress', { loaded, total: this.pageCount });
  }

  _emit(type, detail) {
    if (!this._destroyed) this.dispatchEvent(new CustomEvent(type, { detail }));
  }

  _alive() {
    if (this._destroyed) throw new Error('conecurl: this flipbook was destroyed');
  }
}
