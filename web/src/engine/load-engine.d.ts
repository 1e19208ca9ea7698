// Types of the wasm engine as Embind exposes it, and of loadEngine(). Kept beside engine.js.

/** The cone at one instant: what the vertex shader receives as uniforms. */
export interface CurlParams {
  /** Cone half-angle in radians; pi/2 leaves the page flat. */
  theta: number;
  /** y of the cone apex on the spine line, in page units (negative: below the page). */
  apexY: number;
  /** Rotation about the spine in radians: 0 resting right, pi resting left. */
  rho: number;
}

/** Constants of the three-phase schedule (Nuon's by default, for a page 1 unit tall). */
export interface CurlSchedule {
  phase1End: number;
  phase2End: number;
  thetaRest: number;
  thetaPhase1: number;
  thetaPhase2: number;
  apexRest: number;
  apexPhase1: number;
  apexPhase2: number;
  thetaEasePhase1: number;
  apexEasePhase1: number;
  thetaEasePhase3: number;
  apexEasePhase3: number;
  /** The same key poses joined with continuous slopes (schedule: 'smooth') instead of the paper's phases. */
  smooth?: boolean;
}

export interface Vec3 { x: number; y: number; z: number; }

/** A curled page point and the analytic normal of the page's front there. */
export interface CurledPoint extends Vec3 { normal: Vec3; }

/** One leaf as Book.frame() lists it: its two pages (-1: blank) and its pose. */
export interface LeafDraw {
  leaf: number;
  frontPage: number;
  backPage: number;
  curl: CurlParams;
  /** A backward turn, posed as the mirror image of a forward one. */
  mirrored: boolean;
  hard: boolean;
  /** Flat in a stack (drawn first, receives shadows). */
  resting: boolean;
}

export interface BookOptions {
  pageCount: number;
  display?: 'single' | 'double';
  /** Where the spine is: 'left' (LTR books), 'right' (RTL), 'top' (calendars). */
  binding?: 'left' | 'right' | 'top';
  /** World units from the spine to the free edge; default 0.8. */
  pageWidth?: number;
  /** World units along the spine; default 1. */
  pageHeight?: number;
  /** Seconds per turn; default 1. */
  turnSeconds?: number;
  /** Indices of hard pages (covers): they turn rigidly. */
  hardPages?: number[];
  /** 'paper' (default, Nuon's three phases) or 'smooth' (the same key poses, C1 joins). */
  schedule?: 'paper' | 'smooth';
  /** A closed book (one cover alone) sits centred and slides open as the cover turns; default true. */
  center?: boolean;
  /** A leaf's thickness as a fraction of the page width (0 to 0.02) for the stacks' depth and edges; true: 0.004; false or 0: none. RangeError otherwise. */
  thickness?: boolean | number;
}

/** Book state and animation (C++). Invalid options throw a TypeError naming the option. Call delete(). */
export interface Book {
  pageCount(): number;
  binding(): 'left' | 'right' | 'top';
  isSingle(): boolean;
  pageWidth(): number;
  pageHeight(): number;
  leafCount(): number;
  /** Spread (double) or page (single) where the book settles once turns in flight land. */
  position(): number;
  lastPosition(): number;
  positionOfPage(page: number): number;
  firstVisiblePage(): number;
  /** False (nothing changes) at the end, if the leaf is already turning, or with 6 turns in flight. */
  startTurn(direction: 'forward' | 'backward'): boolean;
  /** Exact pose of the most recent turn, progress in [0, 1]. */
  setLatestTurnProgress(progress: number): void;
  /** Advances turns in flight; returns whether any is still moving. */
  advance(seconds: number): boolean;
  animating(): boolean;
  jumpTo(position: number): void;
  /**
   * Riffles to a far position: up to 6 leaves spread over the way, staggered, landing within
   * RIFFLE_SPAN turn durations. False (nothing changes) one leaf away or less, or while a leaf moves or is held.
   */
  riffleTo(position: number): boolean;
  /** The paper's thickness from now on, as the `thickness` option takes it (RangeError otherwise). */
  setThickness(thickness: boolean | number): void;
  /** One page or two from now on, keeping the first visible page; turns in flight land. TypeError for other values. */
  setDisplay(display: 'single' | 'double'): void;
  /**
   * The pages of a live book changed: `pageCount` pages, hard as `hardPages` (indices) says. Turns in
   * flight land; the first visible page's index stays in view, clamped. TypeError for bad values.
   */
  setPages(pageCount: number, hardPages: number[]): void;
  /** Test build only (dist/test/, never packed): undefined in the package's engine. */
  frame?(): LeafDraw[];
  /** Where the resting pages lie on a width x height drawing buffer (pixels), zoom included. */
  restingRect(width: number, height: number): { x: number; y: number; width: number; height: number };
  /**
   * The leaves lying open at the settled position, turned side first: the page each shows (-1 for a
   * blank back) and its rectangle in drawing-buffer pixels, zoom included.
   */
  openPagePlaces(width: number, height: number): Array<{ page: number; turned: boolean; x: number; y: number; width: number; height: number }>;
  /**
   * Where the marks on the page blocks' fore-edge that show lie (marks on leaves at rest in a drawn
   * block), ticks first, in drawing-buffer pixels: `mark` is the index into `marks`.
   */
  edgeMarkPlaces(marks: ReadonlyArray<{ page: number; kind: 'tab' | 'tick' }>, width: number, height: number):
    Array<{ mark: number; page: number; kind: 'tab' | 'tick'; turned: boolean; x: number; y: number; width: number; height: number }>;
  delete(): void;
}

/** How the leaves moved in a frame loop's last tick. */
export interface LeafMotion {
  /** |d rho / dt| of the fastest leaf in flight since the previous tick, rad/s (a leaf counts from its second tick in flight). */
  speed: number;
  /** That leaf turns rigidly (a hard page). */
  hard: boolean;
  /** Leaves that landed (or fell back flat) in the tick. */
  landings: number;
  /** One of them is a hard leaf. */
  landedHard: boolean;
}

/**
 * A book's frame loop: one call per animation frame advances the clock (capped at 0.25 s a frame),
 * starts turns waiting for a leaf in flight, composes the frame and draws it. Delete it before the
 * Book and BookRenderer it drives.
 */
export interface FrameLoop {
  /** `nowMs`: the animation frame's timestamp; `draw` false advances without drawing. Returns TICK_* bits. */
  tick(nowMs: number, draw: boolean): number;
  /**
   * 0: started; 1: waits behind a leaf in flight; 2: refused (end of the book, or 16 already waiting).
   * `nowMs`: performance.now() when asked; the first frame after it advances by the time since then.
   */
  requestTurn(direction: 'forward' | 'backward', nowMs: number): 0 | 1 | 2;
  queuedTurns(): number;
  clearQueue(): void;
  /** The clock runs (a held pose changed), from `nowMs` unless it was running already. */
  run(nowMs: number): void;
  /** An exact pose is shown: time stops changing the frame until run(). */
  stop(): void;
  running(): boolean;
  /** The next tick advances nothing (after frames were paused). */
  forgetLastTick(): void;
  /** How the leaves moved in the last tick (a second call a frame: BookView makes it only for a page sound). */
  motion(): LeafMotion;
  delete(): void;
}

export interface RenderOptions {
  lighting?: boolean;
  shadows?: boolean;
  gutter?: boolean;
  /**
   * How much of the other side's print shows through a blank side of a soft leaf (single display's
   * back), in [0, 1] (default 0.1): 0 none. RangeError outside [0, 1].
   */
  showThrough?: number;
  /**
   * The share of the drawing buffer's width and height a frame with moving leaves is drawn at, in
   * (0, 1] (default 1): below 1 it is drawn offscreen at that scale and scaled up to the canvas (fewer
   * pixels shaded while a leaf moves). Resting frames are always drawn whole. RangeError outside (0, 1].
   */
  movingScale?: number;
}

/** The WebGL2 renderer of a book. Call delete() to release its context. */
export interface BookRenderer {
  setOptions(options: RenderOptions): void;
  /**
   * Uploads `source` (width x height pixels) straight into the page's texture: the browser copies it,
   * nothing passes through the wasm heap. RangeError for a page, width or height that is not a whole
   * number in range, TypeError for a source that is not an object, Error if too large for the GPU or
   * not an image the browser can upload, a SecurityError DOMException for a cross-origin image without CORS.
   */
  setPageImage(page: number, source: TexImageSource, width: number, height: number): void;
  /**
   * The same upload in horizontal bands, one call a band: rows `y` to `y + rows` of the source into a
   * texture of their own, which becomes the page's once its last row is in (the page shows its old
   * image until then). Bands go from y = 0 down, one page at a time; y = 0 starts over. Thrown as setPageImage.
   */
  setPageImageRows(page: number, source: TexImageSource, width: number, height: number, y: number, rows: number): void;
  releasePageImage(page: number): void;
  /** `removed` pages at `at` gave way to `inserted`: their textures released, later pages' renumbered (no upload). */
  splicePageImages(at: number, removed: number, inserted: number): void;
  hasPageImage(page: number): boolean;
  residentPageImages(): number;
  draw(book: Book): void;
  framesDrawn(): number;
  /** The scale the last frame was drawn at: movingScale's (to whole pixels) while leaves moved, 1 at rest. */
  lastFrameScale(): number;
  /**
   * How many times the resting spread (stacks, resting pages, their light) was drawn into its cache:
   * once as a turn starts, then only when what rests changes (a page image, a leaf landing or lifting,
   * size, camera, options). Frames in between lay the cache down with one blit or draw.
   */
  restingSpreadDraws(): number;
  /** Pixels of the frame just drawn (same task), rows top to bottom. */
  readPixels(): { width: number; height: number; data: Uint8ClampedArray };
  /**
   * Per grid vertex of frame leaf `index`: world x y z, then the shader's normal nx ny nz. RangeError
   * unless `index` is a leaf of book.frame(). Test build only (dist/test/, never packed).
   */
  captureLeaf?(book: Book, index: number): Float32Array;
  /** Flat page coordinates (x, y) of the grid vertices. Test build only. */
  gridPoints?(): Float32Array;
  gridColumns(): number;
  gridRows(): number;
  /** Verified mesh error of the chosen grid, in pixels at the current canvas (NaN with fixed rows). */
  gridErrorPixels(): number;
  /** Fixed grid rows; 0 (default) chooses them from the canvas size for < 0.5 px error. */
  setGridRows(rows: number): void;
  maxTextureSize(): number;
  /** The anisotropic filtering page textures get: 1 (none) until prepareTurn() has found, once a page, that this GPU filters a page at rest with it as trilinear does (Mesa's llvmpipe does not), then up to 8. */
  anisotropy(): number;
  /** Readies the programs a turning frame draws that resting frames do not (each is otherwise linked at its first draw), and with them asks once a page whether anisotropic filtering is right here (anisotropy()): true once they are linked; false (ask again in a later idle task) while the driver still compiles them beside the page, where the browser has KHR_parallel_shader_compile (the first call asks for them, later ones ask whether they are done). */
  prepareTurn(): boolean;
  /** Ends the first view: until then page textures go up without their mipmaps and frames take the drawing buffer's size from the canvas (neither waits on the GL). Makes the mipmaps and asks the buffer's size; true if that is not the size the last frame was drawn at (draw again). The first frame with a moving leaf calls it itself; later calls do nothing. A BookView calls it in idle time once its first frame is on screen. */
  finishFirstView(): boolean;
  /** After a context restore: rebuild every GL object (page images must be set again). */
  recreateGpuObjects(): void;
  /** Marks drawn on the page blocks' fore-edge from the next frame on: index tabs and search ticks at their pages' leaves; [] none. */
  setEdgeMarks(marks: ReadonlyArray<{ page: number; kind: 'tab' | 'tick' }>): void;
  delete(): void;
}

export interface ConeCurlEngine {
  defaultSchedule(): CurlSchedule;
  /** Schedule of the default constants for a page 1 unit tall; t is clamped to [0, 1]. */
  curlAt(t: number): CurlParams;
  curlAtWith(t: number, schedule: CurlSchedule, pageHeight: number): CurlParams;
  sanitizeCurlParams(params: CurlParams): CurlParams;
  curlPoint(x: number, y: number, params: CurlParams): CurledPoint;
  /** Test build only (dist/test/, never packed): undefined in the package's engine. */
  curlNormalFiniteDifference?(x: number, y: number, params: CurlParams, delta: number): Vec3;
  coneBeta?(x: number, y: number, params: CurlParams): number;
  /** C++ reference of where the shader puts page point (x, y) of a leaf, and its +z side's normal (test build only). */
  leafPointToWorld?(draw: LeafDraw, binding: 'left' | 'right' | 'top', pageHeight: number, x: number, y: number): Vec3;
  leafNormalToWorld?(draw: LeafDraw, binding: 'left' | 'right' | 'top', pageHeight: number, x: number, y: number): Vec3;
  Book: { create(options: BookOptions): Book };
  FrameLoop: new (book: Book, renderer: BookRenderer) => FrameLoop;
  /** FrameLoop.tick bits: time still changes the frame; nothing moves and no leaf is held; the pages on screen changed; a frame was drawn. */
  TICK_MOVING: number;
  TICK_SETTLED: number;
  TICK_PAGES_CHANGED: number;
  TICK_DREW: number;
  /** The pages the book's frame shows (resting sides facing up, both sides of leaves in flight), no blanks. */
  pagesOnScreen(book: Book): number[];
  BookRenderer: {
    /**
     * Throws an Error ("conecurl: ...") if the renderer cannot be made: with `code`
     * 'webgl2-unavailable' when the canvas gives no WebGL2 context at all. `antialias` (default true)
     * asks for a multisampled drawing buffer; anything but a boolean is a TypeError.
     */
    create(canvasTarget: string, antialias?: boolean): BookRenderer;
  };
  /** Bytes of the wasm heap allocated and not freed (malloc's in-use count): for leak tests (test build only). */
  heapBytesInUse?(): number;
  /** Emscripten's map from target names to elements; BookView registers canvases here. */
  specialHTMLTargets: Record<string, EventTarget>;
}

export interface LoadEngineOptions {
  /** Where the .wasm is served, if not next to conecurl-engine.mjs. */
  wasmUrl?: string;
  /** The .wasm bytes themselves (Node, or a bundler that inlines them). */
  wasmBinary?: ArrayBuffer | Uint8Array;
  /** Full control over how Emscripten resolves its files. */
  locateFile?: (file: string) => string;
}

/** Loads the engine; without options the module is shared by all callers on the page. */
export function loadEngine(options?: LoadEngineOptions): Promise<ConeCurlEngine>;
