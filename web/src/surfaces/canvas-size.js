// A BookView's canvas sizes: the drawing buffer fitted to the CSS size x devicePixelRatio when a frame
// needs it (no layout read otherwise), and buffer pixels to CSS pixels and back.

export class CanvasSize {
  /**
   * @param {HTMLCanvasElement} canvas
   * @param {{ changed: () => void, cleared: () => void }} view  changed: the canvas's CSS size changed
   *   (a ResizeObserver); cleared: the buffer was resized, which cleared it
   */
  constructor(canvas, view) {
    this._canvas = canvas;
    this._view = view;
    this._stale = true;  // the canvas's CSS size or pixel ratio changed since the buffer was sized
    this._observer = typeof ResizeObserver === 'function' ? new ResizeObserver(() => view.changed()) : null;
    this._observer?.observe(canvas);
  }

  /** The CSS size or the pixel ratio changed: fitIfStale() sizes the buffer anew. */
  markStale() { this._stale = true; }

  fitIfStale() {
    if (this._stale) this.fit();
  }

  /** Sizes the drawing buffer to the canvas's CSS size x devicePixelRatio; returns that size. */
  fit() {
    this._stale = false;
    const canvas = this._canvas;
    const ratio = window.devicePixelRatio || 1;
    const width = Math.max(1, Math.round(canvas.clientWidth * ratio));
    const height = Math.max(1, Math.round(canvas.clientHeight * ratio));
    if (canvas.width !== width || canvas.height !== height) {
      canvas.width = width;
      canvas.height = height;
      this._view.cleared();  // resizing cleared the buffer
    }
    return { width, height };
  }

  /** CSS pixels per pixel of a drawing buffer `bufferWidth` wide. */
  cssPerPixel(bufferWidth) { return this._canvas.clientWidth / bufferWidth; }

  /** `rect` ({ x, y, width, height, ...others }) in a buffer `bufferWidth` wide, in CSS pixels (others kept). */
  toCss(rect, bufferWidth) {
    const k = this.cssPerPixel(bufferWidth);
    return { ...rect, x: rect.x * k, y: rect.y * k, width: rect.width * k, height: rect.height * k };
  }

  /** The drawing-buffer pixel under a viewport point, and the buffer's size (fitted first). */
  bufferPixel(clientX, clientY) {
    const box = this._canvas.getBoundingClientRect();
    const { width, height } = this.fit();
    return {
      x: ((clientX - box.left) * width) / Math.max(1, box.width),
      y: ((clientY - box.top) * height) / Math.max(1, box.height),
      width,
      height,
    };
  }

  stop() { this._observer?.disconnect(); }
}
