// One book on a canvas: JS ergonomics over the wasm Book (state, animation), BookRenderer (GL) and
// FrameLoop (the clock), one call into the engine per frame. It is the book controller's WebGL surface
// and the public lower layer (docs/engine.md): member by member a few lines over the engine's objects
// (engine-objects.js) and the view's parts: the frames (frame-scheduler.js), the page textures
// (page-textures.js), the lost context (context-keeper.js), the canvas's sizes (canvas-size.js), the
// sharpness of moving frames (moving-resolution.js).
// Over 350 lines because it is BookView's whole public API (docs/engine.md): each member a few lines over its parts.
import { loadEngine } from '../engine/load-engine.js';
import { TURN_REFUSED } from '../engine/layout.js';
import { uploadSizeFor } from '../pages/texture-upload.js';
import { createEngineObjects } from './engine-objects.js';
import { FrameScheduler } from './frame-scheduler.js';
import { PageTextures } from './page-textures.js';
import { ContextKeeper } from './context-keeper.js';
import { CanvasSize } from './canvas-size.js';
import { MovingResolution } from './moving-resolution.js';
import { warmTurn } from './warm-turn.js';
import { idleAfterFirstFrame } from './after-first-frame.js';

export { uploadSizeFor };

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
    const made = createEngineObjects(engine, canvas, options);  // a TypeError names a bad direction
    this.engine = engine;
    this.canvas = canvas;
    this.book = made.book;
    this.renderer = made.renderer;
    this._loop = made.loop;       // the clock: one call into the engine a frame
    this._target = made.target;   // the canvas's name in engine.specialHTMLTargets
    /** Called after a frame whose pages on screen changed (a leaf lifted or landed): residency follows. */
    this.onPagesChanged = null;
    this.onImagesLost = null;  // (pages) after a context restore, for pages whose image was closed
    /** Told each frame how the leaves moved ({ speed, hard, landings, landedHard }): set only by a page sound. */
    this.onMotion = null;
    /** The book's share of the page's WebGL contexts (context-budget.js), told when the view wants to draw. */
    this.contextLease = null;
    this._poseFrom = null;  // the settled position showTurn() poses from
    this._warmDraws = 0;  // frames drawn by prepareTurn() that never reached the screen
    this._cancelFirstViewFinish = null;  // set once the first frame is drawn: cancels the first view's finish to come (see _drawn)
    this._resolution = new MovingResolution(options.resolution ?? 'auto');
    this._frames = new FrameScheduler({
      runs: () => Boolean(this.renderer) && this._context.clockRuns,
      tick: (now) => this._tick(now),
      ticked: () => this._ticked(),
      pagesChanged: () => this.onPagesChanged?.(),
    }, { moving: engine.TICK_MOVING, settled: engine.TICK_SETTLED, pagesChanged: engine.TICK_PAGES_CHANGED });
    this._textures = new PageTextures({
      renderer: () => this.renderer,
      upload: (page, source, options) => this.setPageImage(page, source, options),
      moving: () => this._frames.moving,
      turning: () => this.book.animating(),
      pagesOnScreen: () => this.pagesOnScreen(),
      redraw: () => this.requestRender(),
    });
    this._context = new ContextKeeper(canvas, {
      lease: () => this.contextLease,
      stopClock: () => {
        this._frames.cancel();
        this._loop.forgetLastTick();  // the first frame after the restore advances nothing
      },
      rebuild: () => this.renderer.recreateGpuObjects(),
      uploadAgain: () => this._textures.uploadAgain(),
      redraw: () => this.requestRender(),
      imagesLost: (pages) => this.onImagesLost?.(pages),
    });
    this._size = new CanvasSize(canvas, {
      changed: () => this.sizeChanged(),
      cleared: () => this.requestRender(),
    });
    this.requestRender();
  }

  /** Which surface this is (book-controller.js drives a 'webgl' or a 'canvas' one). */
  get kind() { return 'webgl'; }
  /** Textures are copies: a page's image may be closed once set (see onImagesLost). */
  get copiesImages() { return true; }
  get pageCount() { return this.book.pageCount(); }
  get display() { return this.book.isSingle() ? 'single' : 'double'; }  // 'single' or 'double'
  get position() { return this.book.position(); }  // where it settles once turns land: a spread (double) or a page (single)
  lastPosition() { return this.book.lastPosition(); }
  positionOfPage(page) { return this.book.positionOfPage(page); }  // the position that shows page `page`
  firstVisiblePage() { return this.book.firstVisiblePage(); }  // at the settled position
  /** Pages drawn now: the resting ones and both sides of every leaf in flight. */
  pagesOnScreen() { return this.engine.pagesOnScreen(this.book); }
  get zoom() { return this.book.zoom().scale; }  // view magnification, 1 to MAX_ZOOM
  get maxTextureSize() { return this.renderer.maxTextureSize(); }
  get animating() { return this.book.animating(); }
  get moving() { return this._frames.moving; }  // frames with a moving leaf are being drawn (no call into the engine)
  get framesDrawn() { return this.renderer.framesDrawn() - this._warmDraws; }  // so far: the book draws only while something moves
  get movingScale() { return this._resolution.scale; }  // of the buffer's size, frames with moving leaves are drawn at
  /** Turns asked for that wait for a leaf still in flight. */
  get queuedTurns() { return this._loop.queuedTurns(); }
  /** The WebGL context is lost and not yet restored: turns in flight are paused. */
  get contextLost() { return this._context.lost; }

  /** Uploads a page's image, scaled down (never up) to fit MAX_TEXTURE_SIZE and, given `cover: { width, height }`
   * in pixels, to the smallest size that still covers that box. */
  setPageImage(page, source, options) { this._textures.set(page, source, options); }

  /**
   * Like setPageImage, but while leaves move (or a turn is asked for) in bands of at most UPLOAD_BAND_BYTES a
   * frame (page-textures.js). Resolves once uploaded; rejects as setPageImage throws (or if destroyed first).
   */
  queuePageImage(page, source, options = {}) { return this._textures.queue(page, source, options); }

  /** Deletes the page's texture (a frame only if the page is drawn now). */
  releasePageImage(page) { this._textures.release(page); }

  /** Pixel size of page `page`'s texture as uploaded, or null without one. */
  pageImageSize(page) { return this._textures.sizeOf(page); }

  /** Where the resting pages lie on the canvas, in CSS pixels from its top-left: both page places of a spread
   * (double) or the one page (single). The same framing as the renderer's camera. */
  restingRect() {
    const { width, height } = this.fitCanvas();
    return this._size.toCss(this.book.restingRect(width, height), width);  // from the engine's camera
  }

  /**
   * The leaves lying open at the settled position, as the engine's camera places them: for each, its
   * visible page (-1 for a blank back) and its rectangle in CSS pixels from the canvas's top-left,
   * turned side first, zoom included.
   */
  openPagePlaces() {
    const { width, height } = this.fitCanvas();
    return this.book.openPagePlaces(width, height).map((place) => this._size.toCss(place, width));
  }

  /**
   * Marks on the page blocks' fore-edge, drawn by the engine at the leaves of their pages: `tab`s (index
   * tabs in slots down the edge, in page order) and `tick`s (a thin line on the block). Replaces the
   * marks before; [] removes them. A TypeError names a bad mark.
   * @param {Array<{ page: number, kind: 'tab' | 'tick' }>} marks
   */
  setEdgeMarks(marks) {
    const list = Array.isArray(marks) ? marks.map((mark) => ({ page: mark?.page, kind: mark?.kind })) : marks;
    this.renderer.setEdgeMarks(list);  // checks each mark
    this._edgeMarks = list;
    this.requestRender();
  }

  /**
   * Where the marks given to setEdgeMarks() lie now that show (on leaves at rest in a drawn block), in
   * CSS pixels from the canvas's top-left, ticks first: { mark (its index), page, kind, turned, x, y,
   * width, height }, the engine's camera as openPagePlaces() uses it.
   */
  edgeMarkPlaces() {
    if (!this._edgeMarks?.length) return [];
    const { width, height } = this.fitCanvas();
    return this.book.edgeMarkPlaces(this._edgeMarks, width, height).map((place) => this._size.toCss(place, width));
  }

  /** The drawing-buffer pixel under a viewport point, and the buffer's size: the engine's camera (drag solve, zoom) works in these. */
  bufferPixel(clientX, clientY) { return this._size.bufferPixel(clientX, clientY); }

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

  /** lighting, shadows, gutter, showThrough (the renderer's), thickness (the book's stacks), resolution (moving-resolution.js). */
  setOptions({ thickness, resolution, ...effects }) {
    if (thickness !== undefined) this.book.setThickness(thickness);
    if (resolution !== undefined) this._resolution.setting = resolution;
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
    this._textures.splice(at, removed, inserted);
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
    return this._frames.whenSettled();
  }

  /** Draws the current state at once (same task), e.g. before readPixels(); sizes the canvas first. */
  drawNow() {
    this.fitCanvas();
    this.renderer.draw(this.book);
    this._drawn();
  }

  // After a drawn frame: what the first view left out, each a wait on the GL (the mipmaps, the drawing buffer's
  // size: BookRenderer::finishFirstView), asked for once, in idle time after its first frame. A frame drawn with a
  // leaf still moving did it first (BookRenderer::draw): the idle call, a wasted call into the engine in the middle
  // of a turn, is cancelled.
  _drawn() {
    if (this._frames.moving) {
      this._cancelFirstViewFinish?.();
      this._cancelFirstViewFinish = () => {};
      return;
    }
    this._cancelFirstViewFinish ??= idleAfterFirstFrame(() => {
      if (this.renderer && !this._context.lost && this.renderer.finishFirstView()) this.requestRender();
    });
  }

  readPixels() { return this.renderer.readPixels(); }
  /** Readies a turn's programs and draws a posed turning frame under the resting one (warm-turn.js): true
   * once done, false to be called again in a later idle task (a frame is coming, or the driver still
   * compiles the programs beside the page: BookRenderer::prepareTurn). A turn under way links its own, but
   * the renderer's page-wide checks (its anisotropic filtering probe) wait for rest: asked again after it. */
  prepareTurn() {
    if (this._context.lost || !this.renderer) return true;
    if (this._frames.moving || this._frames.pending || !this.renderer.prepareTurn()) return false;
    // A frame that moved drew the turn's draw states already: no posed frame is needed then.
    if (this._poseFrom === null && !this._frames.moved) this._warmDraws += warmTurn(this.book, this.renderer, () => this.fitCanvas());
    return true;
  }

  /** Asks for a frame (none while the context is lost, unless parked: context-keeper.js). */
  requestRender() {
    this.contextLease?.demand();  // Flipbook's share of the page's WebGL contexts (context-budget.js)
    this._frames.request();
  }

  /**
   * Cancels animation, removes listeners, deletes every GL object and the wasm objects. With
   * `releaseContext` the canvas's WebGL context is given up too (WEBGL_lose_context), instead of
   * whenever the canvas is garbage-collected; leave it false to make a new BookView on the same canvas.
   */
  destroy({ releaseContext = false } = {}) {
    if (!this.renderer) return;
    this._frames.cancel();
    this._cancelFirstViewFinish?.();
    this._size.stop();
    this._context.stop();
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
    this._textures.clear();
    this._frames.settleAll();
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
    return this._frames.whenSettled(true);
  }

  /** next() or prev() by name: 'forward' or 'backward'. */
  turn(direction) {
    this._poseFrom = null;
    // performance.now() and animation frames share a clock: the turn runs from now, not from its first frame.
    if (this._loop.requestTurn(direction, performance.now()) === TURN_REFUSED) return Promise.resolve(false);
    this.requestRender();
    return this._frames.whenSettled(true);
  }

  // A frame's step (frame-scheduler.js): a single call into the engine advances, starts queued turns
  // and draws (nothing while a parked context is away: the clock runs on). Returns its flags.
  _tick(now) {
    const drawing = !this._context.lost;
    if (drawing) this._size.fitIfStale();
    const scale = drawing ? this._resolution.nextScale(now, this._frames.moving, window.devicePixelRatio || 1) : null;
    if (scale !== null) this.renderer.setOptions({ movingScale: scale });  // only when it changes
    return this._loop.tick(now, drawing);
  }

  // After the step: the leaves' motion to the page sound, and page images that arrived: one band a
  // frame while leaves move (a page shown from the frame after its last band), all at once at rest.
  _ticked() {
    if (!this._context.lost) this._drawn();
    if (this.onMotion) this.onMotion(this._loop.motion());  // a second call into the engine, only with sound on
    this._textures.drain(this._frames.moving);
  }

  /** After the held leaf's pose changed (dragged, hinted, released): draw and run the clock until it rests. */
  heldChanged() {
    this._poseFrom = null;
    this._loop.run(performance.now());
    this.requestRender();
  }

  /** The canvas's CSS size or the device pixel ratio changed: the next frame sizes the buffer anew. */
  sizeChanged() {
    this._size.markStale();
    this.requestRender();
  }

  /** Sizes the drawing buffer to the canvas's CSS size x devicePixelRatio; returns that size. */
  fitCanvas() { return this._size.fit(); }
}
