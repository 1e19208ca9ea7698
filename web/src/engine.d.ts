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
}

export interface Vec3 { x: number; y: number; z: number; }

/** A curled page point and the analytic normal of the page's front there. */
export interface CurledPoint extends Vec3 { normal: Vec3; }

/** The WebGL2 renderer of one page. Call delete() (or CurlPageView.destroy()) to release it. */
export interface PageRenderer {
  setPageSize(width: number, height: number): void;
  pageWidth(): number;
  pageHeight(): number;
  setSchedule(schedule: CurlSchedule): void;
  schedule(): CurlSchedule;
  setShading(on: boolean): void;
  /** side 0: front, 1: back; pixels: width * height * 4 RGBA bytes, rows top to bottom. */
  setPageImage(side: 0 | 1, width: number, height: number, pixels: ArrayLike<number>): void;
  paramsAt(t: number): CurlParams;
  drawAt(t: number): void;
  draw(params: CurlParams): void;
  /** Pixels of the frame just drawn (same task), rows top to bottom. */
  readPixels(): { width: number; height: number; data: Uint8ClampedArray };
  /** Per grid vertex: x y z of the curled position, then the shader's normal nx ny nz. */
  captureCurledVertices(params: CurlParams): Float32Array;
  /** Flat page coordinates (x, y) of the grid vertices. */
  gridPoints(): Float32Array;
  gridColumns(): number;
  gridRows(): number;
  maxTextureSize(): number;
  delete(): void;
}

export interface ConeCurlEngine {
  defaultSchedule(): CurlSchedule;
  /** Schedule of the default constants for a page 1 unit tall; t is clamped to [0, 1]. */
  curlAt(t: number): CurlParams;
  curlAtWith(t: number, schedule: CurlSchedule, pageHeight: number): CurlParams;
  sanitizeCurlParams(params: CurlParams): CurlParams;
  curlPoint(x: number, y: number, params: CurlParams): CurledPoint;
  curlNormalFiniteDifference(x: number, y: number, params: CurlParams, delta: number): Vec3;
  coneBeta(x: number, y: number, params: CurlParams): number;
  PageRenderer: {
    /** Throws an Error ("conecurl: ...") if WebGL2 is unavailable on the target. */
    create(canvasTarget: string): PageRenderer;
  };
  /** Emscripten's map from target names to elements; CurlPageView registers canvases here. */
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
