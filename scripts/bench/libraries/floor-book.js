// What the two floor contenders (floor-webgl.js, floor-2d.js) share and nothing more: where the pages
// lie, which pages a spread and a turn show, page images decoded ahead at the size drawn, and a turn's clock.
// Both floors are the smallest books that do the job (issue 24), so this holds no options, no input, no resize.

// The same page place as conecurl's at rest (web/src/engine/layout.js restingRect: the spread fitted
// in the view with FRAME_MARGIN around it, a single page with SINGLE_FRAME_MARGIN), so every contender
// shades the same number of page pixels. The margins are the engine's (cpp/core/book_constants.hpp).
import { FRAME_MARGIN, SINGLE_FRAME_MARGIN } from '../../../dist/engine-constants.js';

const PAGE_PIXELS = { width: 640, height: 800 };  // the bench's page images (scripts/bench/page-images.mjs)
const PAGE_ASPECT = PAGE_PIXELS.width / PAGE_PIXELS.height;
// Pages kept decoded (2D) or as textures (WebGL) around the open spread: behind it and ahead of it.
const KEEP_BEHIND = 2;
const KEEP_AHEAD = 5;

/** Where the book lies in a view of width x height px: { spineX, top, pageWidth, pageHeight } (px). */
export function bookPlace(width, height, display) {
  const across = display === 'double' ? 2 * PAGE_ASPECT : PAGE_ASPECT;
  const margin = display === 'double' ? FRAME_MARGIN : SINGLE_FRAME_MARGIN;
  const scale = Math.min(width / (across * margin), height / margin);
  const left = (width - across * scale) / 2;
  const pageWidth = PAGE_ASPECT * scale;
  return { spineX: display === 'double' ? left + pageWidth : left, top: (height - scale) / 2, pageWidth, pageHeight: scale };
}

/**
 * The pages to draw, back to front, as [{ page, angle }]: each page lies hinged at the spine, turned by
 * `angle` (0: flat on the right of the spine, PI: flat on the left). At rest `turn` is null; while a
 * leaf turns it is the leaf's angle, and the leaf shows its front while cos(angle) >= 0, else its back.
 * Double display, position p (p = 0: the cover alone on the right): pages 2p - 1 and 2p; a turn uncovers
 * 2p + 2 under the leaf (2p, its back 2p + 1). Single: page p, and a turn uncovers p + 1 under it.
 */
export function scene(position, pageCount, display, turn = null) {
  const quads = [];
  const add = (page, angle) => { if (page >= 0 && page < pageCount) quads.push({ page, angle }); };
  if (display === 'double') {
    add(2 * position - 1, Math.PI);
    if (turn === null) add(2 * position, 0);
    else {
      add(2 * position + 2, 0);
      add(Math.cos(turn) >= 0 ? 2 * position : 2 * position + 1, turn);
    }
  } else if (turn === null) add(position, 0);
  else {
    add(position + 1, 0);
    add(position, turn);  // a single page's leaf: the same image on its back, past the spine
  }
  return quads;
}

/** The last position: a spread per leaf (double) or a page (single), as the engine counts them. */
export const lastPosition = (pageCount, display) => (display === 'double' ? Math.ceil(pageCount / 2) : pageCount - 1);

/** Every page a turn forward from `position` draws. */
export const turnPages = (position, pageCount, display) => [
  ...new Set([0, Math.PI / 4, (3 * Math.PI) / 4, Math.PI].flatMap((angle) => scene(position, pageCount, display, angle).map((q) => q.page))),
];

/**
 * Page images decoded off the main thread (createImageBitmap) at the size they are drawn, in device pixels
 * (the page's CSS size x the device pixel ratio), but never larger than the image, as conecurl's page
 * loader (which never scales up): a phone at ratio 3 draws a page larger than the image, as does the
 * single page at 800x1100. Kept near the open spread.
 */
export class PageImages {
  constructor(urls, width, height) {
    this.urls = urls;
    this.size = width < PAGE_PIXELS.width
      ? { resizeWidth: Math.round(width), resizeHeight: Math.round(height), resizeQuality: 'high' }
      : {};  // drawn at the image's size or larger: decoded as it is
    this.decoded = new Map();  // page -> Promise<ImageBitmap>
  }

  /** The page's bitmap (decoding starts now if it has not). */
  get(page) {
    if (!this.decoded.has(page)) {
      this.decoded.set(page, fetch(this.urls[page]).then((response) => {
        if (!response.ok) throw new Error(`floor: page ${page} answered ${response.status}`);
        return response.blob();
      }).then((blob) => createImageBitmap(blob, this.size)));
    }
    return this.decoded.get(page);
  }

  /** Forgets a page, closing its bitmap (WebGL, once uploaded; both, when it leaves the window). */
  drop(page) {
    const bitmap = this.decoded.get(page);
    this.decoded.delete(page);
    if (bitmap) bitmap.then((b) => b.close(), () => {});
  }

  /** Drops what lies outside the pages kept around `page`; returns the kept range [from, to]. */
  keepAround(page) {
    const from = page - KEEP_BEHIND;
    const to = page + KEEP_AHEAD;
    for (const kept of [...this.decoded.keys()]) if (kept < from || kept > to) this.drop(kept);
    return [from, to];
  }
}

/**
 * Plays one turn of `duration` ms from the time of the call: draw(angle) on every animation frame,
 * angle eased from 0 to PI (slow at both ends, as a hand turns a page); resolves after the frame
 * that reaches PI.
 */
export function playTurn(duration, draw) {
  const start = performance.now();
  return new Promise((resolve) => {
    const frame = () => {
      const t = Math.min(1, Math.max(0, (performance.now() - start) / duration));
      if (t >= 1) { resolve(); return; }
      draw(Math.PI * (0.5 - 0.5 * Math.cos(Math.PI * t)));
      requestAnimationFrame(frame);
    };
    requestAnimationFrame(frame);
  });
}

/** A canvas over the whole container at the device's pixel ratio: both floors draw into one. */
export function viewportCanvas(container) {
  const { width, height } = container.getBoundingClientRect();
  const ratio = window.devicePixelRatio || 1;
  const canvas = document.createElement('canvas');
  canvas.width = Math.round(width * ratio);
  canvas.height = Math.round(height * ratio);
  canvas.style.cssText = 'position:absolute;inset:0;width:100%;height:100%';
  container.append(canvas);
  return { canvas, width, height, ratio };
}

/**
 * The bench adapter both floors give the harness. `surface` draws scene() quads (draw), gets each page's
 * image before it is drawn (prepare(page, bitmap, images), awaited before a turn's first frame: WebGL
 * uploads there), says which pages it holds (has) and lets go of those outside a range (keep).
 */
export async function floorBook({ urls, display, duration, width, height, ratio, surface }) {
  const pageCount = urls.length;
  const place = bookPlace(width, height, display);
  const images = new PageImages(urls, place.pageWidth * ratio, place.pageHeight * ratio);
  let position = 0;
  const restingPages = () => scene(position, pageCount, display).map((q) => q.page);
  const missing = (pages) => pages.filter((page) => !surface.has(page));
  const prepare = (pages) => Promise.all(missing(pages).map(async (page) => surface.prepare(page, await images.get(page), images)));
  // The next two turns' pages, so a turn asked right after another does not wait for a decode.
  const decodeAhead = () => {
    for (const at of [position, position + 1]) {
      if (at < lastPosition(pageCount, display)) for (const page of missing(turnPages(at, pageCount, display))) images.get(page);
    }
  };
  await prepare(restingPages());
  surface.draw(scene(position, pageCount, display), place);
  decodeAhead();
  return {
    async turn() {
      if (position >= lastPosition(pageCount, display)) throw new Error(`floor: no page to turn to from position ${position}`);
      await prepare(turnPages(position, pageCount, display));
      await playTurn(duration, (angle) => surface.draw(scene(position, pageCount, display, angle), place));
      position += 1;
      surface.draw(scene(position, pageCount, display), place);
      const first = Math.min(...restingPages());
      const [from, to] = images.keepAround(first);
      surface.keep(from, to);
      decodeAhead();
    },
    stats() {
      return { page: Math.min(...restingPages()) };
    },
  };
}
