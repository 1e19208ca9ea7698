// Keeps a BookView drawing across a lost WebGL context: the clock stops where it is, and once the context
// is back every GL object and page texture is made again. A context parked on purpose lets the clock run.

export class ContextKeeper {
  /**
   * @param {HTMLCanvasElement} canvas
   * @param {{ lease: () => object|null, stopClock: () => void, rebuild: () => void,
   *           uploadAgain: () => number[], redraw: () => void, imagesLost: (pages: number[]) => void }} view
   *   lease: the book's share of the page's contexts (context-budget.js); stopClock: no frame until the
   *   restore, whose first frame advances nothing; rebuild: every GL object made again; uploadAgain: the
   *   page textures made again, returning the pages whose image was closed; imagesLost: those pages
   */
  constructor(canvas, view) {
    this._canvas = canvas;
    this._view = view;
    this._lost = false;  // the GL context is lost: the clock and drawing wait for its restore
    this._onLost = (event) => this._lose(event);
    this._onRestored = () => this._restore();
    canvas.addEventListener('webglcontextlost', this._onLost);
    canvas.addEventListener('webglcontextrestored', this._onRestored);
  }

  /** The context is lost and not yet restored. */
  get lost() { return this._lost; }

  // The context was handed back on purpose (context-budget.js parks a book out of view): unlike an
  // accidental loss, the clock runs on, so turns land and resolve, and nothing is drawn.
  get parked() { return this._lost && this._view.lease()?.state === 'parked'; }

  /** Whether the clock may run: a live context, or a parked one. */
  get clockRuns() { return !this._lost || this.parked; }

  /** No more listening (the view is destroyed). */
  stop() {
    this._canvas.removeEventListener('webglcontextlost', this._onLost);
    this._canvas.removeEventListener('webglcontextrestored', this._onRestored);
  }

  // A lost context stops the clock where it is: turns in flight (and a held leaf) pause, and go on
  // from the same pose once it is restored. preventDefault() tells the browser we want it back.
  _lose(event) {
    event.preventDefault();
    this._lost = true;
    this._view.stopClock();
  }

  // Every GL object is rebuilt from CPU-side state; page images from the sources kept (page-textures.js).
  _restore() {
    this._lost = false;
    this._view.rebuild();
    const lost = this._view.uploadAgain();
    this._view.redraw();
    if (lost.length) this._view.imagesLost(lost);
  }
}
