// Types of CanvasSurface, the 2D-canvas surface of StaticBook (canvas-surface.js). Kept beside it.

/** Still pages on a 2D canvas, laid out by layout.js (no wasm). Driven by the book; read it for tests and tools. */
export class CanvasSurface {
  readonly kind: 'canvas';
  readonly canvas: HTMLCanvasElement;
  readonly pageCount: number;
  readonly display: 'single' | 'double';
  /** The spread (double) or page (single) shown. */
  readonly position: number;
  /** Always false: still pages never move. */
  readonly animating: false;
  readonly zoom: number;
  /** The size a page image is kept at for drawing, as a texture's would be; null without one. */
  pageImageSize(page: number): { width: number; height: number } | null;
  restingRect(): { x: number; y: number; width: number; height: number };
  /** Ignored: still pages draw no page blocks, so no marks on their edge (the `edgeMarks` option is the WebGL book's). */
  setEdgeMarks(marks: ReadonlyArray<{ page: number; kind: 'tab' | 'tick' }>): void;
  /** Always []. */
  edgeMarkPlaces(): never[];
}
