// Types of BookView, the JS view of one book on a canvas. Kept beside book-view.js.
import type { Book, BookOptions, BookRenderer, ConeCurlEngine, LoadEngineOptions, RenderOptions } from '../engine/load-engine.js';

/** The engine Book's options (pageWidth, pageHeight, turnSeconds, hardPages, schedule, center, as load-engine.d.ts documents them), and the view's own. */
export interface BookViewOptions extends LoadEngineOptions, RenderOptions,
  Pick<BookOptions, 'pageWidth' | 'pageHeight' | 'turnSeconds' | 'hardPages' | 'schedule' | 'center'> {
  /** An engine already loaded with loadEngine(). */
  engine?: ConeCurlEngine;
  pageCount: number;
  /** Default 'double'. */
  display?: 'single' | 'double';
  /** 'ltr' (spine left, default), 'rtl' (spine right), 'vertical' (spine at the top, a calendar). */
  direction?: 'ltr' | 'rtl' | 'vertical';
  /** Multisampled edges (the WebGL context's antialias); default true. */
  antialias?: boolean;
  /** How sharp frames with moving leaves are drawn: 'auto' (default), 'full' or device px per CSS px (FlipbookOptions.resolution). */
  resolution?: 'auto' | 'full' | number;
}

/** The size setPageImage uploads a width x height image at (see its `cover`). */
export function uploadSizeFor(width: number, height: number,
  options: { cover?: { width: number; height: number }; maxTextureSize: number }): { width: number; height: number };

export class BookView {
  /** Rejects with an Error if WebGL2 is unavailable, a TypeError naming a bad option. */
  static create(canvas: HTMLCanvasElement, options: BookViewOptions): Promise<BookView>;
  readonly engine: ConeCurlEngine;
  readonly canvas: HTMLCanvasElement;
  readonly book: Book;
  /** Null after destroy(). */
  readonly renderer: BookRenderer | null;
  /** The surface kind the book controller sees (a CanvasSurface is 'canvas'). */
  readonly kind: 'webgl';
  readonly pageCount: number;
  readonly display: 'single' | 'double';
  /** Where the book settles once turns in flight land: a spread (double) or a page (single). */
  readonly position: number;
  lastPosition(): number;
  positionOfPage(page: number): number;
  firstVisiblePage(): number;
  /** Pages drawn now: the resting ones and both sides of every leaf in flight. */
  pagesOnScreen(): number[];
  /** View magnification, 1 to 4. */
  readonly zoom: number;
  readonly maxTextureSize: number;
  /** The book's share of the page's WebGL contexts (context-budget.js), if it takes part in one. */
  contextLease: object | null;
  /** The leaves lying open at the settled position, as the engine's camera places them (CSS px, zoom included). */
  openPagePlaces(): Array<{ page: number; turned: boolean; x: number; y: number; width: number; height: number }>;
  /**
   * Marks on the page blocks' fore-edge, drawn by the engine at the leaves of their pages (with
   * `thickness` on): index tabs in slots down the edge, in page order, and ticks (thin lines across
   * the block). Replaces the marks before; [] removes them.
   */
  setEdgeMarks(marks: ReadonlyArray<{ page: number; kind: 'tab' | 'tick' }>): void;
  /**
   * Where the marks that show lie, in CSS pixels from the canvas's top-left, ticks first (marks on
   * leaves in flight, or on the turned side in single display, are left out).
   */
  edgeMarkPlaces(): Array<{ mark: number; page: number; kind: 'tab' | 'tick'; turned: boolean; x: number; y: number; width: number; height: number }>;
  readonly animating: boolean;
  /** Frames with a moving leaf are being drawn now (a turn, a riffle, a held leaf settling); read without a call into the engine. */
  readonly moving: boolean;
  /** Frames drawn so far: the book draws only while something moves or changes. */
  readonly framesDrawn: number;
  /** The share of the drawing buffer's width and height frames with moving leaves are drawn at now (the `resolution` option); 1 at rest too. */
  readonly movingScale: number;
  /**
   * Uploads a page image, scaled down (never up, aspect kept) to fit MAX_TEXTURE_SIZE and, with
   * `cover`, to the smallest size that still covers cover.width x cover.height pixels.
   */
  setPageImage(page: number, source: TexImageSource, options?: { cover?: { width: number; height: number } }): void;
  /**
   * setPageImage, but while leaves move (or a turn is asked for) the upload is spread over the coming
   * frames in bands of at most 512 KB a frame, so no frame of a turn carries a whole page. Resolves once
   * uploaded; rejects as setPageImage throws.
   */
  queuePageImage(page: number, source: TexImageSource, options?: { cover?: { width: number; height: number } }): Promise<void>;
  releasePageImage(page: number): void;
  /**
   * The book's pages were spliced: `removed` pages at `at` gave way to `inserted` new ones, hard as
   * `hardPages` (indices) says. Turns in flight land; the first visible page's index stays in view
   * (clamped); removed pages' textures go, later pages keep theirs, renumbered (no upload).
   */
  splicePages(at: number, removed: number, inserted: number, hardPages: number[]): void;
  /** Pixel size of the page's texture as uploaded; null without one. */
  pageImageSize(page: number): { width: number; height: number } | null;
  /** The resting pages' rectangle on the canvas in CSS px from its top-left (a whole spread in double). */
  restingRect(): { x: number; y: number; width: number; height: number };
  /** The drawing-buffer pixel under a viewport point, and the buffer size (the engine's camera works in these). */
  bufferPixel(clientX: number, clientY: number): { x: number; y: number; width: number; height: number };
  /** Magnifies the view to `scale` (1..4) about a viewport point, which keeps its table point. */
  zoomAbout(scale: number, clientX: number, clientY: number): void;
  /** Moves the zoomed view by CSS pixels, as far as the pages still fill it. */
  panBy(dxCss: number, dyCss: number): void;
  /** Turns asked for that wait for a leaf still in flight. */
  readonly queuedTurns: number;
  /** The WebGL context is lost and not yet restored: turns in flight and a held leaf are paused. */
  readonly contextLost: boolean;
  /** The renderer's effects, and the paper's thickness (the book's: Book.setThickness). */
  setOptions(options: RenderOptions & { thickness?: boolean | number }): void;
  /** Resolves true once every turn has landed, false if the book cannot turn that way. */
  next(): Promise<boolean>;
  prev(): Promise<boolean>;
  /** next() or prev() by name. */
  turn(direction: 'forward' | 'backward'): Promise<boolean>;
  /**
   * Riffles to a far position: several leaves fan over at once and it lands within RIFFLE_SPAN turn
   * durations. Resolves true once landed; false if it cannot now (a leaf in flight or held, or the
   * position one leaf away or less).
   */
  riffle(position: number): Promise<boolean>;
  jumpTo(position: number): void;
  /** 'single' or 'double' from now on, keeping the first visible page; the renderer and page textures stay. */
  setDisplay(display: 'single' | 'double'): void;
  /** The canvas's CSS size or the pixel ratio changed: the next frame sizes the drawing buffer. */
  sizeChanged(): void;
  /** Called after a frame whose pages on screen changed (a leaf lifted or landed). */
  onPagesChanged: (() => void) | null;
  /**
   * Told after each frame how the leaves moved (FrameLoop.motion: a second call into the engine a frame,
   * made only while this is set; the page sound sets it). Null by default.
   */
  onMotion: ((motion: import('../engine/load-engine.js').LeafMotion) => void) | null;
  /** True: textures are copies, so an ImageBitmap given to setPageImage may be closed once set. */
  readonly copiesImages: boolean;
  /** Called after a lost context is restored with the pages whose ImageBitmap was closed: set them again. */
  onImagesLost: ((pages: number[]) => void) | null;
  /** Exact frame of a turn from the settled position at progress t, with no clock running. */
  showTurn(direction: 'forward' | 'backward', t: number): boolean;
  /** Draws at once (same task as a following readPixels()). */
  drawNow(): void;
  readPixels(): { width: number; height: number; data: Uint8ClampedArray };
  /** Readies the programs a turn draws that a resting book does not, and at rest draws a posed turning frame under the resting one (a Flipbook does it in idle time once its first frame is on screen): true once done, or false while a frame is coming, a leaf moves (the renderer's check of anisotropic filtering waits for rest) or the driver still compiles the programs beside the page (KHR_parallel_shader_compile: ask again in a later idle task). */
  prepareTurn(): boolean;
  requestRender(): void;
  /**
   * Cancels animation, removes listeners, deletes every GL object and the wasm objects. With
   * `releaseContext: true` the canvas's WebGL context is released too (WEBGL_lose_context) rather than
   * when the canvas is garbage-collected; leave it false to make another BookView on the same canvas.
   */
  destroy(options?: { releaseContext?: boolean }): void;
}
