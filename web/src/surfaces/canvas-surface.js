// The 2D-canvas surface: the open pages as still images, for browsers without WebGL2 or the engine.
// It answers the same surface calls as BookView (see docs/architecture.md, the surface table) with layout.js's layout, the
// engine's own rules in plain JS, so it needs no wasm; a turn cuts straight to the next spread.
import * as layout from '../engine/layout.js';
import { MAX_IMAGE_SIZE, naturalSize, uploadSizeFor } from '../pages/texture-upload.js';

export class CanvasSurface {
  /**
   * @param {HTMLCanvasElement} canvas
   * @param {{ pageCount: number, display: 'single'|'double', direction: string, pageAspect?: number, center?: boolean }} book
   */
  constructor(canvas, { pageCount, display, direction, pageAspect, center = true }) {
    this.canvas = canvas;
    this._context = canvas.getContext('2d');
    if (!this._context) throw new Error('conecurl: the canvas gives no 2D context');
    this._book = { pageCount, display, direction, pageAspect: pageAspect || layout.DEFAULT_PAGE_ASPECT, center };
    this._position = 0;
    this._zoom = { scale: 1, offsetX: 0, offsetY: 0 };
    this._images = new Map();  // page -> { image, size } to draw; the controller's page store owns them
    this._destroyed = false;
    /** Called when the pages on screen changed without a turn the controller asked for (never here). */
    this.onPagesChanged = null;
  }

  get kind() { return 'canvas'; }
  /** It draws from the images themselves: they must stay open while set. */
  get copiesImages() { return false; }
  get pageCount() { return this._book.pageCount; }
  get display() { return this._book.display; }
  get position() { return this._position; }
  /** Still pages never move. */
  get animating() { return false; }
  get queuedTurns() { return 0; }
  get zoom() { return this._zoom.scale; }
  get maxTextureSize() { return MAX_IMAGE_SIZE; }

  lastPosition() { return layout.lastPosition(this.pageCount, this.display); }
  positionOfPage(page) { return layout.positionOfPage(page, this.pageCount, this.display); }
  firstVisiblePage() { return layout.firstVisiblePage(this._position, this.pageCount, this.display); }
  pagesOnScreen() { return this.openPagePlaces().map((place) => place.page).filter((page) => page >= 0); }

  /** Shows the next or previous spread at once; false at the end of the book. */
  turn(direction) {
    const target = this._position + (direction === 'forward' ? 1 : -1);
    if (target < 0 || target > this.lastPosition()) return Promise.resolve(false);
    this.jumpTo(target);
    return Promise.resolve(true);
  }

  jumpTo(position) {
    this._position = Math.min(Math.max(0, position), this.lastPosition());
    this._draw();
  }

  setDisplay(display) {
    const page = Math.max(0, this.firstVisiblePage());
    this._book.display = display;
    this.jumpTo(this.positionOfPage(page));
  }

  /** The book's pages were spliced: as BookView.splicePages (hard pages do not show on still pages). */
  splicePages(at, removed, inserted) {
    const page = Math.max(0, this.firstVisiblePage());
    this._images = layout.splicePageMap(this._images, at, removed, inserted);
    this._book.pageCount += inserted - removed;
    this.jumpTo(this.positionOfPage(page));
  }

  /** No turn frames to show: false. */
  showTurn() { return false; }

  /** Where the open pages lie on the canvas, in CSS px (both places of a spread in double), zoom included. */
  restingRect() {
    const size = this._cssSize();
    return layout.zoomRect(layout.restingRect(size, this._book, this._position), this._zoom, size.width, size.height);
  }

  /** Still pages draw no page blocks, so no marks on their edge: edge marks are a WebGL surface's (book-view.js). */
  setEdgeMarks() {}
  edgeMarkPlaces() { return []; }

  openPagePlaces() {
    const size = this._cssSize();
    return layout.openPagePlaces(this._position, this._book, size, this._zoom);
  }

  zoomAbout(scale, clientX, clientY) {
    const box = this.canvas.getBoundingClientRect();
    this._zoom = layout.zoomAbout(this._zoom, scale, clientX - box.left, clientY - box.top, box.width, box.height);
    this._draw();
  }

  panBy(dxCss, dyCss) {
    const { width, height } = this._cssSize();
    this._zoom = layout.panBy(this._zoom, dxCss, dyCss, width, height);
    this._draw();
  }

  setPageImage(page, image, { cover } = {}) {
    const natural = naturalSize(image);
    const size = uploadSizeFor(natural.width, natural.height, { cover, maxTextureSize: MAX_IMAGE_SIZE });
    this._images.set(page, { image, size });
    if (this.pagesOnScreen().includes(page)) this._draw();
  }

  queuePageImage(page, image, options) {
    try {
      this.setPageImage(page, image, options);
      return Promise.resolve();
    } catch (error) {
      return Promise.reject(error);
    }
  }

  releasePageImage(page) {
    this._images.delete(page);
  }

  pageImageSize(page) {
    const kept = this._images.get(page);
    return kept ? { ...kept.size } : null;
  }

  sizeChanged() { this._draw(); }
  /** Lighting, shadows, gutter shading, show-through, thickness and resolution: flat still pages show none of them. */
  setOptions() {}

  destroy() {
    this._destroyed = true;
    this._images.clear();
  }

  _cssSize() { return { width: this.canvas.clientWidth, height: this.canvas.clientHeight }; }

  _draw() {
    if (this._destroyed) return;
    const canvas = this.canvas;
    const ratio = globalThis.devicePixelRatio || 1;
    const width = Math.max(1, Math.round(canvas.clientWidth * ratio));
    const height = Math.max(1, Math.round(canvas.clientHeight * ratio));
    if (canvas.width !== width || canvas.height !== height) Object.assign(canvas, { width, height });
    const context = this._context;
    context.setTransform(1, 0, 0, 1, 0, 0);
    context.clearRect(0, 0, width, height);
    context.setTransform(ratio, 0, 0, ratio, 0, 0);
    context.imageSmoothingQuality = 'high';
    for (const place of this.openPagePlaces()) {
      // Plain paper first: a page still loading, failed, or a blank back shows as paper.
      context.fillStyle = layout.PAPER;
      context.fillRect(place.x, place.y, place.width, place.height);
      const kept = this._images.get(place.page);
      if (kept) context.drawImage(kept.image, place.x, place.y, place.width, place.height);
    }
  }
}
