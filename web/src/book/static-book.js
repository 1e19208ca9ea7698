// The book without WebGL2 (or without the wasm engine): the same book controller as Flipbook over the
// 2D CanvasSurface, so a page that embeds a book never shows an empty box. Input, loading, links, zoom,
// events and screen-reader support are Flipbook's own; turns cut straight to the next spread.
import { BookController } from './book-controller.js';
import { CanvasSurface } from '../surfaces/canvas-surface.js';
import { validateOptions } from './options.js';

export class StaticBook extends BookController {
  /**
   * Builds a static book in `container` with Flipbook's options (rejects with a TypeError naming a bad
   * one); resolves once the open pages have loaded or failed.
   */
  static async create(container, options) {
    if (!(container instanceof HTMLElement)) throw new TypeError('conecurl: container must be an HTMLElement');
    return openStaticBook(container, validateOptions(options), null, this);
  }

  _makeSurface(display) {
    return new CanvasSurface(this._canvas, this._layoutShape(display));  // no stacks: a still surface draws none
  }

  // Builds the first view (BookController's _build, through `this`); resolves with the book once its
  // pages have loaded or failed, destroys it if that fails.
  async _open() {
    try {
      await this._build();
    } catch (error) {
      this._stopIfDestroyed();  // destroyed while it was built: an AbortError
      this.destroy();
      throw error;
    }
    this._events.releaseSoon();  // what happened while loading the first view is heard from now on
    return this;
  }
}

/**
 * A StaticBook from options already checked (Flipbook's fallback); `doc` is a document (a PDF, a
 * published one) the book now owns. Resolves once the open pages have loaded or failed.
 */
export async function openStaticBook(container, settings, doc = null, Class = StaticBook) {
  return new Class(container, settings, doc)._open();
}
