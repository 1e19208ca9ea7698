// Page thumbnails (pageThumbnail()): a page drawn small from its own source, for a thumbnails panel:
// its small image (`thumbSrc`, a published document has one) or an image decoded at about the size
// asked (pages/page-loader.js), a PDF page rendered by pdf.js at that
// size (its entry's source function), a live HTML page as a numbered placeholder. Never through the
// page store: the book's textures and kept images are not touched. A few at a time, so a panel asking
// for forty does not hold up the pages the book itself is loading.
import { loadPage } from '../pages/page-loader.js';
import { PAPER } from '../engine/layout.js';
import { describeValue } from '../engine/describe-value.js';

const AT_ONCE = 3;          // thumbnails drawn at the same time
const MAX_SIDE = 4096;      // the largest thumbnail side taken
const FROM_THUMB = 512;     // a thumbnail at most this wide is drawn from the page's thumbSrc, when it has one

export class PageThumbnails {
  /** @param {{ entries: object[], pageCount: () => number, alive: () => void }} book  the controller's port */
  constructor(book) {
    this._book = book;
    this._running = 0;
    this._waiting = [];  // resolves of calls waiting for a slot
  }

  /** Page `index` drawn `width` pixels wide (and `height` high, else in its own shape): a new canvas. */
  async draw(index, size) {
    this._book.alive();
    const count = this._book.pageCount();
    if (!Number.isInteger(index) || index < 0 || index >= count) {
      throw new RangeError(`conecurl: pageThumbnail() page ${describeValue(index)} is not in 0..${count - 1}`);
    }
    const { width, height } = size ?? {};
    const isSide = (v) => Number.isFinite(v) && v >= 1 && v <= MAX_SIDE;
    if (!isSide(width) || (height !== undefined && !isSide(height))) {
      throw new TypeError(`conecurl: pageThumbnail() takes { width, height? } in pixels (1 to ${MAX_SIDE}); got ${describeValue(size)}`);
    }
    await this._slot();
    try {
      return await this._drawNow(index, Math.round(width), height === undefined ? undefined : Math.round(height));
    } finally {
      this._running -= 1;
      this._waiting.shift()?.();
    }
  }

  _slot() {
    if (this._running < AT_ONCE) {
      this._running += 1;
      return Promise.resolve();
    }
    return new Promise((resolve) => this._waiting.push(() => {
      this._running += 1;
      resolve();
    }));
  }

  async _drawNow(index, width, height) {
    const entry = this._book.entries[index];
    if (entry.html) return placeholder(index, width, height ?? Math.round(width * Math.SQRT2));
    let loaded;
    try {
      // A source function (a PDF page) is told the size wanted and renders at it; an encoded image is
      // decoded at about that size. Height 1 when not given: the width decides.
      const src = entry.thumbSrc && width <= FROM_THUMB ? entry.thumbSrc : entry.src;
      loaded = await loadPage(src, { index, size: { width, height: height ?? 1 } });
    } catch (error) {
      throw new Error(`conecurl: pageThumbnail(${index}): the page could not be drawn (${error?.message ?? error})`, { cause: error });
    }
    const { image, owned } = loaded;
    try {
      const iw = image.naturalWidth || image.width;
      const ih = image.naturalHeight || image.height;
      const canvas = document.createElement('canvas');
      canvas.width = width;
      canvas.height = height ?? Math.max(1, Math.round(width * (ih / iw)));
      const g = canvas.getContext('2d');
      g.fillStyle = PAPER;
      g.fillRect(0, 0, canvas.width, canvas.height);
      g.imageSmoothingQuality = 'high';
      g.drawImage(image, 0, 0, canvas.width, canvas.height);
      return canvas;
    } finally {
      if (owned) image.close?.();
    }
  }
}

/** A live HTML page's thumbnail: paper with its page number (drawing the live page small would cost a snapshot). */
function placeholder(index, width, height) {
  const canvas = document.createElement('canvas');
  canvas.width = width;
  canvas.height = height;
  const g = canvas.getContext('2d');
  g.fillStyle = PAPER;
  g.fillRect(0, 0, width, height);
  g.fillStyle = '#555';
  g.font = `${Math.max(8, Math.round(width / 4))}px sans-serif`;
  g.textAlign = 'center';
  g.textBaseline = 'middle';
  g.fillText(String(index + 1), width / 2, height / 2);
  return canvas;
}
