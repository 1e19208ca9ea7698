// One book on a canvas: JS ergonomics over the wasm Book (state, animation), BookRenderer (GL) and
// FrameLoop (the clock): canvas sizing, page uploads, and a render loop that runs only while something
// moves and costs one call into the engine per frame. It is the book controller's WebGL surface.
// Over 350 lines because it is also the public lower layer (README "Using the engine from JavaScript"),
// member by member a few lines over the engine, with the context-loss path that keeps it drawing.
import { loadEngine } from '../engine/load-engine.js';
import { PageLoadError } from '../pages/page-loader.js';
import { atSize, naturalSize, uploadSizeFor } from '../pages/texture-upload.js';
import { splicePageMap, splicedPage } from '../engine/layout.js';

export { uploadSizeFor };

const BINDING_OF_DIRECTION = { ltr: 'left', rtl: 'right', vertical: 'top' };
const TURN_REFUSED = 2;  // FrameLoop.requestTurn: 0 started, 1 queued, 2 refused

// A closed ImageBitmap reads 0 x 0 and cannot be uploaded again.
const isClosed = (source) => typeof ImageBitmap !== 'undefined' && source instanceof ImageBitmap && source.width === 0;
let nextTargetId = 1;

export class BookView {
  /**
   * @param {HTMLCanvasElement} canvas
   * @param {import('./book-view.js').BookViewOptions} options
   */
  static async create(canvas, options = {}) {
    if (!(canvas instanceof HTMLCanvasElement)) throw new TypeError('conecurl: canvas must be an HTMLCanvasElement');
    const engine = options.engine || (await loadEngine(options));
    return new BookView(engine, canvas, options);
  }

  constructor(engine, canvas, options) {
    const direction = options.direction ?? 'ltr';
    if (!(direction in BINDING_OF_DIRECTION)) {
      throw new TypeError(`conecurl: direction must be 'ltr', 'rtl' or 'vertical', got ${String(direction)}`);
    }
    this.engine = engine;
    this.canvas = canvas;
    this.book = engine.Book.create({
      pageCount: options.pageCount,
      display: options.display ?? 'double',
      binding: BINDING_OF_DIRECTION[direction],
      pageWidth: options.pageWidth,
      pageHeight: options.pageHeight,
      turnSeconds: options.turnSeconds,
      hardPages: options.hardPages,
      schedule: options.schedule,
      center: options.center,
      thickness: options.thickness ?? true,
    });
    this._target = `!conecurl-canvas-${nextTargetId++}`;
    engine.specialHTMLTargets[this._target] = canvas;
    try {
      this.renderer = engine.BookRenderer.create(this._target, options.antialias ?? true);
    } catch (error) {
      delete engine.specialHTMLTargets[this._target];
      this.book.delete();
      throw error;
    }
    this.renderer.setOptions({
      lighting: options.lighting ?? true, shadows: options.shadows ?? true, gutter: options.gutter ?? true,
    });
    this._loop = new engine.FrameLoop(this.book, this.renderer);
    this._ticks = { moving: engine.TICK_MOVING, settled: engine.TICK_SETTLED, pagesChanged: engine.TICK_PAGES_CHANGED };
    /** Called after a frame whose pages on screen changed (a leaf lifted or landed): residency follows. */
    this.onPagesChanged = null;
    this.onImagesLost = null;  // (pages) after a context restore, for pages whose image was closed
    /** Told each frame how the leaves moved ({ speed, hard, landings, landedHard }): set only by a page sound. */
    this.onMotion = null;
    /** The book's share of the page's WebGL contexts (context-budget.js), told when the view wants to draw. */
    this.contextLease = null;
    this._uploads = [];          // page images waiting for a frame while leaves move: one a frame
    this._moving = false;        // the last frame still moved
    this._sources = new Map();   // page -> { source, cover }, to upload again after a context loss
    this._uploaded = new Map();  // page -> { width, height } of its texture
    this._frame = 0;
    this._poseFrom = null;
    this._settled = [];
    this._lost = false;          // the GL context is lost: the clock and drawing wait for its restore
    this._sizeStale = true;      // the canvas's CSS size or pixel ratio changed since the buffer was sized
    this._onLost = (event) => this._loseContext(event);
    this._onRestored = () => this._restore();
    canvas.addEventListener('webglcontextlost', this._onLost);
    canvas.addEventListener('webglcontextrestored', this._onRestored);
    this._resizeObserver = typeof ResizeObserver === 'function' ? new ResizeObserver(() => this.sizeChanged()) : null;
    this._resizeObserver?.observe(canvas);
    this.requestRender();
  }

  /** Which surface this is (book-controller.js drives a 'webgl' or a 'canvas' one). */
  get kind() { return 'webgl'; }
  /** Textures are copies: a page's image may be closed once set (see onImagesLost). */
  get copiesImages() { return true; }
  get pageCount() { return this.book.pageCount(); }
  /** 'single' or 'double'. */
  get display() { return this.book.isSingle() ? 'single' : 'double'; }
  /** Where the book settles once turns in flight land: a spread (double) or a page (single). */
  get position() { return this.book.position(); }
  lastPosition() { return this.book.lastPosition(); }
  /** The position that shows page `page`. */
  positionOfPage(page) { return this.book.positionOfPage(page); }
  /** The first visible page at the settled position. */
  firstVisiblePage() { return this.book.firstVisiblePage(); }
  /** Pages drawn now: the resting ones and both sides of every leaf in flight. */
  pagesOnScreen() { return this.engine.pagesOnScreen(this.book); }
  /** View magnification, 1 to MAX_ZOOM. */
  get zoom() { return this.book.zoom().scale; }
  get maxTextureSize() { return this.renderer.maxTextureSize(); }
  get animating() { return this.book.animating(); }
  /** Frames drawn so far (the book draws only while something moves). */
  get framesDrawn() { return this.renderer.framesDrawn(); }
  /** Turns asked for that wait for a leaf still in flight. */
  get queuedTurns() { return this._loop.queuedTurns(); }
  /** The WebGL context is lost and not yet restored: turns in flight are paused. */
  get contextLost() { return this._lost; }

  /**
   * Uploads a page's image. It is scaled down (never up) to fit MAX_TEXTURE_SIZE and, given
   * `cover: { width, height }` in pixels, to the smallest size that still covers that box.
   */
  setPageImage(page, source, { cover } = {}) {
    const natural = source instanceof ImageData ? source : naturalSize(source);
    const size = uploadSizeFor(natural.width, natural.height, { cover, maxTextureSize: this.renderer.maxTextureSize() });
    try {
      this.renderer.setPageImage(page, atSize(source, natural, size), size.width, size.height);
    } catch (error) {
      if (error?.name !== 'SecurityError') throw error;
      throw new PageLoadError(`conecurl: page ${page}: its image is cross-origin without CORS, so its pixels cannot `
        + 'be read (load it with crossorigin="anonymous" from a server that sends Access-Control-Allow-Origin)',
      { reason: 'cors', cause: error });
    }
    this._sources.set(page, { source, cover });
    this._uploaded.set(page, size);
    this._redrawIfShown(page);
  }

  /**
   * Like setPageImage, but while leaves move the upload waits for the next frame, at most one a frame,
   * so pages that arrive together mid-turn never stall it. Resolves once uploaded; rejects with what
   * setPageImage throws (or an Error if the view is destroyed first).
   */
  queuePageImage(page, source, options = {}) {
    if (!this._moving) {
      try {
        this.setPageImage(page, source, options);
        return Promise.resolve();
      } catch (error) {
        return Promise.reject(error);
      }
    }
    return new Promise((resolve, reject) => {
      this._uploads.push({ page, source, options, resolve, reject });
      this.requestRender();
    });
  }

  _uploadNext() {
    const { page, source, options, resolve, reject } = this._uploads.shift();
    try {
      this.setPageImage(page, source, options);
      resolve();
    } catch (error) {
      reject(error);
    }
  }

  releasePageImage(page) {
    this.renderer.releasePageImage(page);
    this._sources.delete(page);
    this._uploaded.delete(page);
    this._redrawIfShown(page);
  }

  // A page's texture changed: a frame only if the page is drawn now. The pages loaded around the open
  // spread arrive one by one; each would otherwise cost a whole frame that shows nothing new. While
  // leaves move the next frame comes anyway: no call into the engine to ask (uploads land mid-turn).
  _redrawIfShown(page) {
    if (!this._moving && this.pagesOnScreen().includes(page)) this.requestRender();
  }

  /** Pixel size of page `page`'s texture as uploaded, or null without one. */
  pageImageSize(page) {
    const size = this._uploaded.get(page);
    return size ? { ...size } : null;
  }

  /**
   * Where the resting pages lie on the canvas, in CSS pixels from its top-left: both page places of
   * a spread (double) or the one page (single). The same framing as the renderer's camera.
   */
  restingRect() {
    const { width, height } = this.fitCanvas();
    const r = this.book.restingRect(width, height);  // drawing-buffer pixels, from the engine's camera
    const toCss = this.canvas.clientWidth / width;
    return { x: r.x * toCss, y: r.y * toCss, width: r.width * toCss, height: r.height * toCss };
  }

  /**
   * The leaves lying open at the settled position, as the engine's camera places them: for each, its
   * visible page (-1 for a blank back) and its rectangle in CSS pixels from the canvas's top-left,
   * turned side first, zoom included.
   */
  openPagePlaces() {
    const { width, height } = this.fitCanvas();
    const toCss = this.canvas.clientWidth / width;
    return this.book.openPagePlaces(width, height).map(({ page, turned, x, y, width: w, height: h }) => (
      { page, turned, x: x * toCss, y: y * toCss, width: w * toCss, height: h * toCss }));
  }

  /**
   * The drawing-buffer pixel under a viewport point, and the buffer's size: the engine's camera (drag
   * solve, zoom) works in these, the DOM in CSS pixels.
   */
  bufferPixel(clientX, clientY) {
    const box = this.canvas.getBoundingClientRect();
    const { width, height } = this.fitCanvas();
    return {
      x: ((clientX - box.left) * width) / Math.max(1, box.width),
      y: ((clientY - box.top) * height) / Math.max(1, box.height),
      width,
      height,
    };
  }

  /** Magnifies the view to `scale` keeping the table point under the viewport point where it is. */
  zoomAbout(scale, clientX, clientY) {
    const p = this.bufferPixel(clientX, clientY);
    this.book.zoomAbout(scale, p.x, p.y, p.width, p.height);
    this.requestRender();
  }

  /** Moves the zoomed view by CSS pixels, as far as the pages still fill it. */
  panBy(dxCss, dyCss) {
    const origin = this.bufferPixel(0, 0);
    const moved = this.bufferPixel(dxCss, dyCss);
    this.book.panBy(moved.x - origin.x, moved.y - origin.y, origin.width, origin.height);
    this.requestRender();
  }

  /** { lighting, shadows, gutter } (the renderer's) and thickness (the book's: its stacks' depth, hence its layout). */
  setOptions({ thickness, ...effects }) {
    if (thickness !== undefined) this.book.setThickness(thickness);
    this.renderer.setOptions(effects);
    this.requestRender();
  }

  /**
   * Turns one leaf forward; resolves true when every turn in flight has landed, false if the book
   * cannot turn that way. A turn asked for while the leaf it needs is still moving waits its turn.
   */
  next() { return this.turn('forward'); }
  prev() { return this.turn('backward'); }

  /**
   * Shows 'single' or 'double' pages from now on, keeping the first visible page in view; turns in
   * flight land at once. The renderer, its shaders and the page textures stay as they are.
   */
  setDisplay(display) {
    this._poseFrom = null;
    this._loop.clearQueue();
    this.book.setDisplay(display);
    this.requestRender();
  }

  /**
   * The book's pages were spliced (insertPages, removePages): `removed` pages at `at` gave way to
   * `inserted` new ones, hard as `hardPages` (indices) says. Turns in flight land at once and the first
   * visible page's index stays in view (clamped); the removed pages' textures go, the others are kept
   * and renumbered (no upload).
   */
  splicePages(at, removed, inserted, hardPages) {
    this._poseFrom = null;
    this._loop.clearQueue();
    this.renderer.splicePageImages(at, removed, inserted);
    this.book.setPages(this.book.pageCount() - removed + inserted, hardPages);
    this._sources = splicePageMap(this._sources, at, removed, inserted);
    this._uploaded = splicePageMap(this._uploaded, at, removed, inserted);
    for (const upload of this._uploads.splice(0)) {
      upload.page = splicedPage(upload.page, at, removed, inserted);
      if (upload.page >= 0) this._uploads.push(upload);
      else upload.reject(new Error('conecurl: the page was removed before its image was uploaded'));
    }
    this.requestRender();
  }

  jumpTo(position) {
    this._poseFrom = null;
    this._loop.clearQueue();
    this.book.jumpTo(position);
    this.requestRender();
  }

  /**
   * Shows the exact frame of a turn from the settled position at progress t in [0, 1], with no
   * clock running (tests, scrubbing). Calling it again re-poses from the same position.
   */
  showTurn(direction, t) {
    if (this._poseFrom === null) this._poseFrom = this.book.position();
    this._loop.stop();
    this.book.jumpTo(this._poseFrom);
    const started = this.book.startTurn(direction);
    if (started) this.book.setLatestTurnProgress(t);
    this.drawNow();
    return started;
  }

  /** Resolves when every turn in flight has landed and no leaf is held. */
  settle() {
    if (!this.book.animating()) return Promise.resolve();
    return new Promise((resolve) => this._settled.push(resolve));
  }

  /** Draws the current state at once (same task), e.g. before readPixels(); sizes the canvas first. */
  drawNow() {
    this.fitCanvas();
    this.renderer.draw(this.book);
  }

  readPixels() { return this.renderer.readPixels(); }

  requestRender() {
    this.contextLease?.demand();  // Flipbook's share of the page's WebGL contexts (context-budget.js)
    if (!this._frame && this.renderer && (!this._lost || this._parked)) this._frame = requestAnimationFrame((now) => this._tick(now));
  }

  // The context was handed back on purpose (context-budget.js parks a book out of view): unlike an
  // accidental loss, the clock runs on, so turns land and resolve, and nothing is drawn.
  get _parked() { return this._lost && this.contextLease?.state === 'parked'; }

  /**
   * Cancels animation, removes listeners, deletes every GL object and the wasm objects. With
   * `releaseContext` the canvas's WebGL context is given up too (WEBGL_lose_context), instead of
   * whenever the canvas is garbage-collected; leave it false to make a new BookView on the same canvas.
   */
  destroy({ releaseContext = false } = {}) {
    if (!this.renderer) return;
    cancelAnimationFrame(this._frame);
    this._frame = 0;
    this._resizeObserver?.disconnect();
    this.canvas.removeEventListener('webglcontextlost', this._onLost);
    this.canvas.removeEventListener('webglcontextrestored', this._onRestored);
    // The canvas has its WebGL2 context already: getContext hands back that one, it makes no new one.
    const gl = releaseContext ? this.canvas.getContext('webgl2') : null;
    this.onPagesChanged = null;
    this.onImagesLost = null;
    this.onMotion = null;
    this._loop.delete();  // it points at the book and the renderer: it goes first
    this.renderer.delete();
    this.book.delete();
    gl?.getExtension('WEBGL_lose_context')?.loseContext();
    this.renderer = null;
    delete this.engine.specialHTMLTargets[this._target];
    this._sources.clear();
    this._uploaded.clear();
    for (const { reject } of this._uploads.splice(0)) reject(new Error('conecurl: the book view was destroyed'));
    for (const resolve of this._settled.splice(0)) resolve();
  }

  /**
   * Riffles to a far `position`: several leaves fan over at once and the book lands there within
   * RIFFLE_SPAN turn durations (the engine's Book.riffleTo). Resolves true once it lands; false if
   * it cannot riffle now (a leaf in flight or held, or the position one leaf away or less).
   */
  riffle(position) {
    this._poseFrom = null;
    if (this._loop.queuedTurns() > 0 || !this.book.riffleTo(position)) return Promise.resolve(false);
    this._loop.run(performance.now());
    this.requestRender();
    return new Promise((resolve) => this._settled.push(() => resolve(true)));
  }

  /** next() or prev() by name: 'forward' or 'backward'. */
  turn(direction) {
    this._poseFrom = null;
    // performance.now() and animation frames share a clock: the turn runs from now, not from its first frame.
    if (this._loop.requestTurn(direction, performance.now()) === TURN_REFUSED) return Promise.resolve(false);
    this.requestRender();
    return new Promise((resolve) => this._settled.push(() => resolve(true)));
  }

  // One animation frame: a single call into the engine advances, starts queued turns and draws.
  _tick(now) {
    this._frame = 0;
    if (!this.renderer || (this._lost && !this._parked)) return;
    if (!this._lost) this._fitIfStale();
    const flags = this._loop.tick(now, !this._lost);
    this._moving = Boolean(flags & this._ticks.moving);
    if (this.onMotion) this.onMotion(this._loop.motion());  // a second call into the engine, only with sound on
    // Pages that arrived while leaves move: one a frame (shown from the next); all at once at rest.
    if (this._uploads.length > 0) this._uploadNext();
    while (!this._moving && this._uploads.length > 0) this._uploadNext();
    // One frame chain only: an upload or a resize above may have asked for the next frame already.
    if (this._moving && !this._frame) this._frame = requestAnimationFrame((t) => this._tick(t));
    if (flags & this._ticks.pagesChanged) this.onPagesChanged?.();
    if (flags & this._ticks.settled) for (const resolve of this._settled.splice(0)) resolve();
  }

  /** After the held leaf's pose changed (dragged, hinted, released): draw and run the clock until it rests. */
  heldChanged() {
    this._poseFrom = null;
    this._loop.run(performance.now());
    this.requestRender();
  }

  /** The canvas's CSS size or the device pixel ratio changed: the next frame sizes the buffer anew. */
  sizeChanged() {
    this._sizeStale = true;
    this.requestRender();
  }

  _fitIfStale() {
    if (this._sizeStale) this.fitCanvas();
  }

  /** Sizes the drawing buffer to the canvas's CSS size x devicePixelRatio; returns that size. */
  fitCanvas() {
    this._sizeStale = false;
    const ratio = window.devicePixelRatio || 1;
    const width = Math.max(1, Math.round(this.canvas.clientWidth * ratio));
    const height = Math.max(1, Math.round(this.canvas.clientHeight * ratio));
    if (this.canvas.width !== width || this.canvas.height !== height) {
      this.canvas.width = width;
      this.canvas.height = height;
      this.requestRender();  // resizing cleared the buffer
    }
    return { width, height };
  }

  // A lost context stops the clock where it is: turns in flight (and a held leaf) pause, and go on
  // from the same pose once it is restored. preventDefault() tells the browser we want it back.
  _loseContext(event) {
    event.preventDefault();
    this._lost = true;
    cancelAnimationFrame(this._frame);
    this._frame = 0;
    this._loop.forgetLastTick();  // the first frame after the restore advances nothing
  }

  _restore() {
    this._lost = false;
    // Every GL object is rebuilt from CPU-side state; page images from the sources kept here.
    this.renderer.recreateGpuObjects();
    const lost = [];
    for (const [page, { source, cover }] of this._sources) {
      if (isClosed(source)) lost.push(page);  // closed after upload by its owner: only the owner can make it again
      else this.setPageImage(page, source, { cover });
    }
    this.requestRender();
    if (lost.length) this.onImagesLost?.(lost);
  }
}
