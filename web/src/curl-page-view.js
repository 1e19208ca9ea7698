// One page curling on a canvas: JS ergonomics over the wasm PageRenderer (canvas sizing, image
// decoding, the real-time turn loop). The engine computes every frame; this only schedules them.
import { loadEngine } from './engine.js';

let nextTargetId = 1;

/** Reads any image source into RGBA pixels (rows top to bottom). */
function toPixels(source) {
  const width = source.naturalWidth || source.videoWidth || source.width;
  const height = source.naturalHeight || source.videoHeight || source.height;
  if (!(width > 0 && height > 0)) throw new TypeError('conecurl: page image has no size (not loaded yet?)');
  const canvas = typeof OffscreenCanvas === 'function'
    ? new OffscreenCanvas(width, height)
    : Object.assign(document.createElement('canvas'), { width, height });
  const context = canvas.getContext('2d', { willReadFrequently: true });
  context.drawImage(source, 0, 0);
  return context.getImageData(0, 0, width, height);
}

export class CurlPageView {
  /**
   * @param {HTMLCanvasElement} canvas
   * @param {{ pageWidth?: number, pageHeight?: number, engine?: object, wasmUrl?: string }} [options]
   */
  static async create(canvas, options = {}) {
    if (!(canvas instanceof HTMLCanvasElement)) throw new TypeError('conecurl: canvas must be an HTMLCanvasElement');
    const engine = options.engine || (await loadEngine(options));
    return new CurlPageView(engine, canvas, options);
  }

  constructor(engine, canvas, options) {
    this.engine = engine;
    this.canvas = canvas;
    this.t = 0;
    this._frame = 0;
    this._target = `!conecurl-canvas-${nextTargetId++}`;
    engine.specialHTMLTargets[this._target] = canvas;
    this.fitCanvas();
    try {
      this.renderer = engine.PageRenderer.create(this._target);
    } catch (error) {
      delete engine.specialHTMLTargets[this._target];
      throw error;
    }
    if (options.pageWidth || options.pageHeight) {
      this.renderer.setPageSize(options.pageWidth || 0.8, options.pageHeight || 1);
    }
  }

  /** Sizes the drawing buffer to the canvas's CSS size times devicePixelRatio. */
  fitCanvas() {
    const ratio = window.devicePixelRatio || 1;
    const width = Math.max(1, Math.round(this.canvas.clientWidth * ratio));
    const height = Math.max(1, Math.round(this.canvas.clientHeight * ratio));
    if (this.canvas.width !== width || this.canvas.height !== height) {
      this.canvas.width = width;
      this.canvas.height = height;
    }
  }

  /** @param {'front'|'back'} side  @param {CanvasImageSource|ImageData} source */
  setImage(side, source) {
    if (side !== 'front' && side !== 'back') throw new TypeError(`conecurl: side must be 'front' or 'back', got ${String(side)}`);
    const image = source instanceof ImageData ? source : toPixels(source);
    this.renderer.setPageImage(side === 'front' ? 0 : 1, image.width, image.height, image.data);
  }

  /** Draws the exact frame at turn time t in [0, 1]. */
  drawAt(t) {
    this.t = Math.min(1, Math.max(0, t));
    this.fitCanvas();
    this.renderer.drawAt(this.t);
  }

  /**
   * Animates from the current t to `to` (1: turned, 0: back); a full turn takes `duration` ms.
   * `onFrame(t)` runs after each frame is drawn. Resolves when the turn ends.
   */
  turnTo(to, { duration = 1200, onFrame } = {}) {
    cancelAnimationFrame(this._frame);
    const from = this.t;
    const span = Math.abs(to - from);
    if (span === 0 || duration <= 0) {
      this.drawAt(to);
      if (onFrame) onFrame(this.t);
      return Promise.resolve();
    }
    return new Promise((resolve) => {
      const start = performance.now();
      const step = (now) => {
        const f = Math.min(1, (now - start) / (duration * span));
        this.drawAt(from + (to - from) * f);
        if (onFrame) onFrame(this.t);
        if (f < 1) this._frame = requestAnimationFrame(step);
        else resolve();
      };
      this._frame = requestAnimationFrame(step);
    });
  }

  destroy() {
    cancelAnimationFrame(this._frame);
    if (this.renderer) {
      this.renderer.delete();
      this.renderer = null;
      delete this.engine.specialHTMLTargets[this._target];
    }
  }
}
