// Types of StaticBook, the book without WebGL2 (static-book.js). Kept beside static-book.js.
import type { BookController, FlipbookOptions } from './flipbook.js';

/**
 * The open pages as still images on a 2D canvas: what Flipbook.create leaves in the container when
 * WebGL2 or the engine is unavailable (the rejection's `fallback`), or a book of its own. The same book
 * controller as Flipbook: the same options, members, keys, clicks, taps, swipes, zoom and pan, links,
 * events (no `turncancel`: nothing is dragged) and screen-reader support; turns cut straight to the
 * next spread, `animating` is always false and previewTurn() returns false.
 */
export class StaticBook extends BookController {
  /**
   * Rejects with a TypeError naming a bad option, or an AbortError when the book was destroyed before it
   * finished; resolves once the open pages loaded or failed.
   */
  static create(container: HTMLElement, options: FlipbookOptions): Promise<StaticBook>;
}
