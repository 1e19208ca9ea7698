// A BookView's page textures: each image uploaded at the size the GPU and the screen want, what each
// texture was made from (to make it again after a lost context), and the queue that, while leaves
// move, uploads one a frame so that pages arriving together mid-turn never stall the turn.
import { PageLoadError } from '../pages/page-loader.js';
import { atSize, naturalSize, uploadSizeFor } from '../pages/texture-upload.js';
import { splicePageMap, splicedPage } from '../engine/layout.js';

// A closed ImageBitmap reads 0 x 0 and cannot be uploaded again.
const isClosed = (source) => typeof ImageBitmap !== 'undefined' && source instanceof ImageBitmap && source.width === 0;

export class PageTextures {
  /**
   * @param {{ renderer: () => object, upload: (page: number, source: object, options: object) => void,
   *           moving: () => boolean, pagesOnScreen: () => number[], redraw: () => void }} view
   *   renderer: the BookRenderer; upload: the view's setPageImage (which comes here to set()), so that
   *   every upload, queued or made again, goes through it; moving: the last frame still moved (the next
   *   one comes anyway); pagesOnScreen: the pages drawn now; redraw: ask for a frame
   */
  constructor(view) {
    this._view = view;
    this._sources = new Map();  // page -> { source, cover }, to upload again after a context loss
    this._sizes = new Map();    // page -> { width, height } of its texture
    this._waiting = [];         // { page, source, options, resolve, reject }: images waiting for a frame
  }

  /** BookView.setPageImage: uploads now; a cross-origin image without CORS throws a PageLoadError. */
  set(page, source, { cover } = {}) {
    const renderer = this._view.renderer();
    const natural = source instanceof ImageData ? source : naturalSize(source);
    const size = uploadSizeFor(natural.width, natural.height, { cover, maxTextureSize: renderer.maxTextureSize() });
    try {
      renderer.setPageImage(page, atSize(source, natural, size), size.width, size.height);
    } catch (error) {
      if (error?.name !== 'SecurityError') throw error;
      throw new PageLoadError(`conecurl: page ${page}: its image is cross-origin without CORS, so its pixels cannot `
        + 'be read (load it with crossorigin="anonymous" from a server that sends Access-Control-Allow-Origin)',
      { reason: 'cors', cause: error });
    }
    this._sources.set(page, { source, cover });
    this._sizes.set(page, size);
    this._redrawIfShown(page);
  }

  /** BookView.queuePageImage: uploads now at rest; while leaves move, in a coming frame (drain()). */
  queue(page, source, options) {
    if (!this._view.moving()) {
      try {
        this._view.upload(page, source, options);
        return Promise.resolve();
      } catch (error) {
        return Promise.reject(error);
      }
    }
    return new Promise((resolve, reject) => {
      this._waiting.push({ page, source, options, resolve, reject });
      this._view.redraw();
    });
  }

  release(page) {
    this._view.renderer().releasePageImage(page);
    this._sources.delete(page);
    this._sizes.delete(page);
    this._redrawIfShown(page);
  }

  /** Pixel size of the page's texture as uploaded, or null without one. */
  sizeOf(page) {
    const size = this._sizes.get(page);
    return size ? { ...size } : null;
  }

  /** After a frame: one waiting image while leaves move (shown from the next frame), every one at rest. */
  drain(moving) {
    if (this._waiting.length > 0) this._uploadNext();
    while (!moving && this._waiting.length > 0) this._uploadNext();
  }

  /** The book's pages were spliced: textures, sources and waiting images follow their pages. */
  splice(at, removed, inserted) {
    this._sources = splicePageMap(this._sources, at, removed, inserted);
    this._sizes = splicePageMap(this._sizes, at, removed, inserted);
    for (const upload of this._waiting.splice(0)) {
      upload.page = splicedPage(upload.page, at, removed, inserted);
      if (upload.page >= 0) this._waiting.push(upload);
      else upload.reject(new Error('conecurl: the page was removed before its image was uploaded'));
    }
  }

  /**
   * After a context restore, every page again from the source kept; returns the pages whose image
   * was closed after upload by its owner (only the owner can make it again).
   */
  uploadAgain() {
    const closed = [];
    for (const [page, { source, cover }] of this._sources) {
      if (isClosed(source)) closed.push(page);
      else this._view.upload(page, source, { cover });
    }
    return closed;
  }

  /** The view is destroyed: nothing kept, waiting images rejected. */
  clear() {
    this._sources.clear();
    this._sizes.clear();
    for (const { reject } of this._waiting.splice(0)) reject(new Error('conecurl: the book view was destroyed'));
  }

  // A page's texture changed: a frame only if the page is drawn now. The pages loaded around the open
  // spread arrive one by one; each would otherwise cost a whole frame that shows nothing new. While
  // leaves move the next frame comes anyway: no call into the engine to ask (uploads land mid-turn).
  _redrawIfShown(page) {
    if (!this._view.moving() && this._view.pagesOnScreen().includes(page)) this._view.redraw();
  }

  _uploadNext() {
    const { page, source, options, resolve, reject } = this._waiting.shift();
    try {
      this._view.upload(page, source, options);
      resolve();
    } catch (error) {
      reject(error);
    }
  }
}
