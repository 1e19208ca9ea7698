// The book's zoom and pan as the controller asks for them: magnify about a viewport point or the
// middle, pan, and what follows each (layers laid again, touch-action, sharper pages, the `zoom` event).
import { MAX_ZOOM, isZoomed } from '../engine/layout.js';

export class BookZoom {
  /**
   * @param {HTMLCanvasElement} canvas
   * @param {{ surface: () => object|null, moved: () => void, changed: (scale: number) => void }} book
   *   moved: the view moved (lay the layers again); changed: the scale changed (refit, event)
   */
  constructor(canvas, book) {
    this._canvas = canvas;
    this._book = book;
    this._restingTouchAction = canvas.style.touchAction;
  }

  /** View magnification, 1 to MAX_ZOOM (1 without a surface). */
  get scale() { return this._book.surface()?.zoom ?? 1; }
  get zoomed() { return isZoomed(this.scale); }

  aboutCentre(scale) {
    const box = this._canvas.getBoundingClientRect();
    this.about(scale, box.left + box.width / 2, box.top + box.height / 2);
  }

  /** Zooms to `scale` about a viewport point (the table point under it stays there). */
  about(scale, clientX, clientY) {
    const surface = this._book.surface();
    if (!surface) return;
    const before = this.scale;
    surface.zoomAbout(Math.min(MAX_ZOOM, Math.max(1, scale)), clientX, clientY);
    const after = this.scale;
    this._book.moved();
    // Zoomed in, a finger pans the view; at 1x the browser may scroll the page across the turn again.
    this._canvas.style.touchAction = isZoomed(after) ? 'none' : this._restingTouchAction;
    if (after !== before) this._book.changed(after);
  }

  /** Moves the zoomed view by CSS pixels (a pan), as far as the pages still fill it. */
  panBy(dxCss, dyCss) {
    this._book.surface()?.panBy(dxCss, dyCss);
    this._book.moved();
  }
}
