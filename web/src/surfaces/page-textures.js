// A BookView's page textures: each image uploaded at the size the GPU and the screen want, what each
// texture was made from (to make it again after a lost context), and the queue that, while leaves
// move, uploads in horizontal bands of at most UPLOAD_BAND_BYTES a frame, so that no frame of a turn
// carries a whole page upload (pages arriving mid-turn never stall it). At rest images go up whole.
import { PageLoadError } from '../pages/page-loader.js';
import { atSize, naturalSize, uploadSizeFor } from '../pages/texture-upload.js';
import { splicePageMap, splicedPage } from '../engine/layout.js';

/**
 * The most bytes of page pixels uploaded in one frame while leaves move: 512 KB, about 5 ms on
 * software WebGL (SwiftShader), a quarter of a 640 x 800 page. A page takes ceil(bytes / this) frames.
 */
export const UPLOAD_BAND_BYTES = 512 * 1024;

// A closed ImageBitmap reads 0 x 0 and cannot be uploaded again.
const isClosed = (source) => typeof ImageBitmap !== 'undefined' && source instanceof ImageBitmap && source.width === 0;

// What the browser throws for an upload becomes a PageLoadError when the image is cross-origin.
function uploadError(page, error) {
  if (error?.name !== 'SecurityError') return error;
  return new PageLoadError(`conecurl: page ${page}: its image is cross-origin without CORS, so its pixels cannot `
    + 'be read (load it with crossorigin="anonymous" from a server that sends Access-Control-Allow-Origin)',
  { reason: 'cors', cause: error });
}

export class PageTextures {
  /**
   * @param {{ renderer: () => object, upload: (page: number, source: object, options: object) => void,
   *           moving: () => boolean, turning: () => boolean, pagesOnScreen: () => number[], redraw: () => void }} view
   *   renderer: the BookRenderer; upload: the view's setPageImage (which comes here to set()), so that
   *   every upload, queued or made again, goes through it; moving: the last frame still moved (the next
   *   one comes anyway); turning: turns are in flight or a leaf is held (the first frame of a turn may
   *   not have run yet); pagesOnScreen: the pages drawn now; redraw: ask for a frame
   */
  constructor(view) {
    this._view = view;
    this._sources = new Map();  // page -> { source, cover }, to upload again after a context loss
    this._sizes = new Map();    // page -> { width, height } of its texture
    this._waiting = [];         // { page, source, options, resolve, reject, row?, prepared? }: images waiting for frames
  }

  /** BookView.setPageImage: uploads now; a cross-origin image without CORS throws a PageLoadError. */
  set(page, source, { cover } = {}) {
    const renderer = this._view.renderer();
    const { pixels, size } = this._prepare(renderer, source, cover, false);
    try {
      renderer.setPageImage(page, pixels, size.width, size.height);
    } catch (error) {
      throw uploadError(page, error);
    }
    this._restartBands(page);
    this._uploaded(page, source, cover, size);
  }

  /** BookView.queuePageImage: uploads now at rest; while leaves move or a turn is asked for, in bands over the coming frames (drain()). */
  queue(page, source, options) {
    if (!this._view.moving() && !this._view.turning()) {
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
    this._restartBands(page);
    this._sources.delete(page);
    this._sizes.delete(page);
    this._redrawIfShown(page);
  }

  /** Pixel size of the page's texture as uploaded, or null without one. */
  sizeOf(page) {
    const size = this._sizes.get(page);
    return size ? { ...size } : null;
  }

  /**
   * After a frame: while leaves move, one band of the first waiting image (whole once its last band is
   * in, shown from the next frame); at rest every waiting image, whole.
   */
  drain(moving) {
    if (moving) {
      if (this._waiting.length > 0) this._uploadBand(this._waiting[0]);
      return;
    }
    while (this._waiting.length > 0) this._uploadNext();
  }

  /** The book's pages were spliced: textures, sources and waiting images follow their pages. */
  splice(at, removed, inserted) {
    this._sources = splicePageMap(this._sources, at, removed, inserted);
    this._sizes = splicePageMap(this._sizes, at, removed, inserted);
    for (const upload of this._waiting.splice(0)) {
      upload.page = splicedPage(upload.page, at, removed, inserted);
      upload.row = 0;  // the renderer gave up the bands under way: they start over
      if (upload.page >= 0) this._waiting.push(upload);
      else upload.reject(new Error('conecurl: the page was removed before its image was uploaded'));
    }
  }

  /**
   * After a context restore, every page again from the source kept; returns the pages whose image
   * was closed after upload by its owner (only the owner can make it again).
   */
  uploadAgain() {
    for (const upload of this._waiting) upload.row = 0;  // bands under way died with the context
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

  // One band of a waiting image: rows from where the last band ended, UPLOAD_BAND_BYTES at most. The
  // pixels are prepared once (scaled on a canvas of its own: the shared scratch canvas may be redrawn
  // between two bands) and the texture takes the page's place with the last band.
  _uploadBand(upload) {
    const renderer = this._view.renderer();
    try {
      upload.prepared ??= this._prepare(renderer, upload.source, upload.options.cover, true);
      const { pixels, size } = upload.prepared;
      upload.row ??= 0;
      const rows = Math.max(1, Math.min(size.height - upload.row, Math.floor(UPLOAD_BAND_BYTES / (size.width * 4))));
      try {
        renderer.setPageImageRows(upload.page, pixels, size.width, size.height, upload.row, rows);
      } catch (error) {
        throw uploadError(upload.page, error);
      }
      upload.row += rows;
      if (upload.row < size.height) return;
      this._waiting.shift();
      this._uploaded(upload.page, upload.source, upload.options.cover, size);
      upload.resolve();
    } catch (error) {
      this._waiting.shift();
      upload.reject(error);
    }
  }

  // The pixels to upload a source from and the texture's size: scaled down to what the GPU and `cover` want.
  _prepare(renderer, source, cover, own) {
    const natural = source instanceof ImageData ? source : naturalSize(source);
    const size = uploadSizeFor(natural.width, natural.height, { cover, maxTextureSize: renderer.maxTextureSize() });
    return { pixels: atSize(source, natural, size, { own }), size };
  }

  // The renderer gave up the bands under way for `page` (a whole upload or a release): they start over.
  _restartBands(page) {
    for (const upload of this._waiting) if (upload.page === page) upload.row = 0;
  }

  // A page's texture is in: what it was made from is kept (to make it again), and it is shown.
  _uploaded(page, source, cover, size) {
    this._sources.set(page, { source, cover });
    this._sizes.set(page, size);
    this._redrawIfShown(page);
  }
}
