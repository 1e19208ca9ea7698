// Types of CurlPageView, the JS view of one curling page. Kept beside curl-page-view.js.
import type { ConeCurlEngine, LoadEngineOptions, PageRenderer } from './engine.js';

export interface CurlPageViewOptions extends LoadEngineOptions {
  /** An engine already loaded with loadEngine(). */
  engine?: ConeCurlEngine;
  /** Page size in world units; default 0.8 x 1 (Nuon's page). */
  pageWidth?: number;
  pageHeight?: number;
}

export interface TurnOptions {
  /** Milliseconds for a full turn (t from 0 to 1); default 1200. */
  duration?: number;
  /** Runs after each frame is drawn, with its t. */
  onFrame?: (t: number) => void;
}

export class CurlPageView {
  /** Creates the WebGL2 renderer on the canvas; rejects with an Error if WebGL2 is unavailable. */
  static create(canvas: HTMLCanvasElement, options?: CurlPageViewOptions): Promise<CurlPageView>;
  readonly engine: ConeCurlEngine;
  readonly canvas: HTMLCanvasElement;
  /** The underlying renderer; null after destroy(). */
  readonly renderer: PageRenderer | null;
  /** Turn time of the frame on screen, in [0, 1]. */
  readonly t: number;
  /** Sizes the drawing buffer to the canvas's CSS size x devicePixelRatio. */
  fitCanvas(): void;
  setImage(side: 'front' | 'back', source: CanvasImageSource | ImageData): void;
  /** Draws the exact frame at turn time t (clamped to [0, 1]). */
  drawAt(t: number): void;
  /** Animates to t = `to`; resolves when the turn ends. */
  turnTo(to: number, options?: TurnOptions): Promise<void>;
  /** Cancels any animation and releases the GL context and the wasm object. */
  destroy(): void;
}
