// The engine's layout in plain JS (positions, page places, zoom) for the 2D fallback, which has no wasm,
// and the engine's constants for every JS module; tests/node/layout.test.mjs holds both to the engine.
import {
  BOARD_THICKNESS_OF_WIDTH, DEFAULT_LEAF_THICKNESS, MAX_PAPER_DEPTH_OF_WIDTH, DEFAULT_PAGE_HEIGHT, DEFAULT_PAGE_WIDTH, DEFAULT_SHOW_THROUGH, FRAME_MARGIN, MAX_LEAF_THICKNESS, MAX_PAGES, MAX_TURNS_IN_FLIGHT, MAX_ZOOM, PAPER_BLUE,
  PAPER_GREEN, PAPER_RED, SINGLE_FRAME_MARGIN, TURN_QUEUED, TURN_REFUSED, TURN_STARTED,
} from '../../../dist/engine-constants.js';
import { directionFacts } from './direction.js';

export { DEFAULT_SHOW_THROUGH, MAX_LEAF_THICKNESS, MAX_PAGES, MAX_TURNS_IN_FLIGHT, MAX_ZOOM, TURN_QUEUED, TURN_REFUSED, TURN_STARTED };
/** The renderer's placeholder paper, as a CSS colour. */
export const PAPER = `rgb(${PAPER_RED}, ${PAPER_GREEN}, ${PAPER_BLUE})`;
/** The engine's default page: width (spine to free edge) over height (along the spine). */
export const DEFAULT_PAGE_ASPECT = DEFAULT_PAGE_WIDTH / DEFAULT_PAGE_HEIGHT;
/** Whether a view magnification counts as zoomed in (above 1 by more than rounding). */
export const isZoomed = (scale) => scale > 1.001;
/**
 * Display 'auto' shows two pages only where each would be at least this many CSS px across the turn
 * (the `minPageWidth` option's default): narrower, a spread is unreadable and one page shows instead.
 */
export const AUTO_MIN_PAGE_WIDTH = 300;

/**
 * 'single' or 'double' for a display option ('single' | 'double' | 'auto') in a container of that size
 * (CSS px). 'auto' is 'double' where each page of a spread, laid as restingRect lays it, would be at
 * least `minPageWidth` CSS px wide across the turn (its height on screen for a vertical book), else
 * 'single'. `book`: { pageAspect, direction, minPageWidth } (defaults: the engine's page, 'ltr', 300).
 */
export function displayFor(option, size, book = {}) {
  if (option !== 'auto') return option;
  const { pageAspect = DEFAULT_PAGE_ASPECT, direction = 'ltr', minPageWidth = AUTO_MIN_PAGE_WIDTH } = book;
  return spreadPageWidth(size, { pageAspect, direction }) >= minPageWidth ? 'double' : 'single';
}

/** How wide (across the turn, in `size`'s unit) each page of a two-page spread lies in a view of `size`. */
export function spreadPageWidth(size, { pageAspect = DEFAULT_PAGE_ASPECT, direction = 'ltr' } = {}) {
  const rect = restingRect(size, { display: 'double', direction, pageAspect });
  return directionFacts(direction).vertical ? rect.height / 2 : rect.width / 2;
}

// ---- positions: spreads (double) or pages (single), as cpp/core/book.cpp ------------------------------

/** Last position: a spread per leaf boundary (double), or the last page (single). As Book::lastPosition. */
export function lastPosition(pageCount, display) {
  return display === 'double' ? Math.ceil(pageCount / 2) : Math.max(0, pageCount - 1);
}

/** The position that shows `page` (clamped to the book). As Book::positionOfPage. */
export function positionOfPage(page, pageCount, display) {
  const clamped = Math.min(Math.max(0, page), Math.max(0, pageCount - 1));
  return display === 'double' ? Math.floor((clamped + 1) / 2) : clamped;
}

/** First visible page at a position (at an odd book's blank last spread, its face-down last page); -1 without pages. */
export function firstVisiblePage(position, pageCount, display) {
  if (pageCount === 0) return -1;
  if (display !== 'double') return position;
  return position === 0 ? 0 : Math.min(2 * position - 1, pageCount - 1);
}

/** The pages the live region announces at a position: the first visible one, and its facing page in a spread. */
export function openPages(position, pageCount, display) {
  const first = firstVisiblePage(position, pageCount, display);
  if (first < 0) return [];
  if (display !== 'double' || first === 0) return [first];
  return first + 1 < pageCount ? [first, first + 1] : [first];
}

// ---- where the pages lie: the camera's picture at the page plane, as cpp/core/book_camera.cpp ----------

/**
 * How deep a stack of `leaves` leaves lies, in page widths: a board for a hard top or bottom leaf (a
 * cover), the paper's `leafThickness` a leaf, approaching its cap smoothly. As stackDepth in book_stacks.cpp.
 */
export function stackDepthOfWidth(leaves, topHard, bottomHard, leafThickness) {
  if (leaves <= 0 || !(leafThickness > 0)) return 0;
  const top = topHard ? BOARD_THICKNESS_OF_WIDTH : 0;
  const bottom = bottomHard && leaves > (topHard ? 1 : 0) ? BOARD_THICKNESS_OF_WIDTH : 0;  // one leaf: its board counts once
  const paperLeaves = leaves - (top > 0 ? 1 : 0) - (bottom > 0 ? 1 : 0);
  const raw = paperLeaves * leafThickness;
  const paper = paperLeaves > 0 ? raw / Math.sqrt(1 + (raw / MAX_PAPER_DEPTH_OF_WIDTH) ** 2) : 0;
  return top + paper + bottom;
}

/** A `thickness` option (true, false or a leaf's thickness of the page width) as the leaf's thickness. As leafThicknessOf in book_bindings.cpp. */
export const leafThicknessOf = (thickness) => (thickness === true ? DEFAULT_LEAF_THICKNESS : thickness || 0);

/**
 * How far a book at rest at `position` sits from the middle, in page widths towards its unturned side:
 * half of a page and the edge band of its stack (as deep as the stack) with the front cover alone on that
 * side, as much the other way with the back cover alone, else 0 (and 0 in single display or with `center`
 * false). `book.leafThickness` (of the page width; default 0, no stacks) and `book.hardPages` (page
 * indices) give the stack. As Book::settledCenterShift.
 */
export function centerShift(position, { pageCount = 0, display = 'double', center = true, leafThickness = 0, hardPages = [] } = {}) {
  const leaves = Math.ceil(pageCount / 2);
  const side = (position < leaves ? 1 : 0) - (position > 0 ? 1 : 0);
  if (!center || display !== 'double' || side === 0) return 0;
  // One stack holds every leaf (leaf l holds pages 2l and 2l + 1); its top is the last leaf on the turned side.
  const hard = (leaf) => hardPages.includes(2 * leaf) || hardPages.includes(2 * leaf + 1);
  const [top, bottom] = side > 0 ? [0, leaves - 1] : [leaves - 1, 0];
  return 0.5 * (1 + stackDepthOfWidth(leaves, hard(top), hard(bottom), leafThickness)) * side;
}

/**
 * The rectangle both pages of a spread (or the one page) occupy in a view of `size` ({ width, height },
 * any pixel unit), unzoomed: the view frame times its margin (FRAME_MARGIN for a spread, the smaller
 * SINGLE_FRAME_MARGIN for a single page) fitted and centred, then moved by centerShift() when a
 * `position` is given. As the engine's restingRect.
 */
export function restingRect(size, book = {}, position = undefined) {
  const { display = 'double', direction = 'ltr', pageAspect = DEFAULT_PAGE_ASPECT } = book;
  const across = display === 'double' ? 2 * pageAspect : pageAspect;  // page widths, spine to free edge
  // A top spine (vertical) hangs the pages below it: the width runs down the canvas.
  const { vertical, turnedFirst } = directionFacts(direction);
  const [frameWidth, frameHeight] = vertical ? [1, across] : [across, 1];
  const margin = display === 'double' ? FRAME_MARGIN : SINGLE_FRAME_MARGIN;  // as frameMargin() in book_camera.cpp
  const scale = Math.min(size.width / (frameWidth * margin), size.height / (frameHeight * margin));
  const width = frameWidth * scale;
  const height = frameHeight * scale;
  // The camera moves towards the unturned side (right for ltr, left for rtl, down for vertical): the pages move the other way.
  const shift = position === undefined ? 0 : centerShift(position, book) * pageAspect * scale;
  const [dx, dy] = vertical ? [0, -shift] : [turnedFirst ? -shift : shift, 0];
  return { x: (size.width - width) / 2 + dx, y: (size.height - height) / 2 + dy, width, height };
}

/**
 * The pages lying open at `position` and where: [{ page, turned, x, y, width, height }] in `size`'s unit, the
 * turned side first (left for ltr, right for rtl, top for vertical), page -1 for a leaf's blank back,
 * under `zoom` if given. As the engine's openPagePlaces.
 */
export function openPagePlaces(position, book, size, zoom) {
  const { pageCount, display = 'double', direction = 'ltr' } = book;
  const rect = restingRect(size, book, position);
  const places = [];
  if (display !== 'double') {
    if (position < pageCount) places.push({ page: position, turned: false, ...rect });
  } else {
    const { vertical, turnedFirst } = directionFacts(direction);
    const half = vertical
      ? [{ ...rect, height: rect.height / 2 }, { ...rect, y: rect.y + rect.height / 2, height: rect.height / 2 }]
      : [{ ...rect, width: rect.width / 2 }, { ...rect, x: rect.x + rect.width / 2, width: rect.width / 2 }];
    const [turned, unturned] = turnedFirst ? half : [half[1], half[0]];
    // The turned leaf shows its back page, the unturned one its front (a leaf holds pages 2l and 2l + 1).
    if (position > 0) places.push({ page: 2 * position - 1 < pageCount ? 2 * position - 1 : -1, turned: true, ...turned });
    if (position < Math.ceil(pageCount / 2)) places.push({ page: 2 * position, turned: false, ...unturned });
  }
  return zoom ? places.map(({ page, turned, ...place }) => ({ page, turned, ...zoomRect(place, zoom, size.width, size.height) })) : places;
}

// ---- zoom: { scale, offsetX, offsetY }, the picture scaled about the centre then moved (NDC, -1..1) ----

/** `zoom` kept so the pages still fill the view: scale in [1, MAX_ZOOM], offsets within scale - 1. As clampZoom. */
export function clampZoom({ scale, offsetX, offsetY }) {
  const s = Math.min(Math.max(Number.isFinite(scale) ? scale : 1, 1), MAX_ZOOM);
  const reach = s - 1;
  const clamp = (v) => Math.min(Math.max(Number.isFinite(v) ? v : 0, -reach), reach);
  return { scale: s, offsetX: clamp(offsetX), offsetY: clamp(offsetY) };
}

/** `zoom` changed to `scale` keeping the point under pixel (x, y) of a width x height view there. As zoomAbout. */
export function zoomAbout(zoom, scale, x, y, width, height) {
  const ndcX = (2 * x) / Math.max(1, width) - 1;
  const ndcY = 1 - (2 * y) / Math.max(1, height);
  const s = clampZoom({ scale }).scale;
  // The unzoomed picture point under the pixel, then the offset that puts it back there.
  const px = (ndcX - zoom.offsetX) / zoom.scale;
  const py = (ndcY - zoom.offsetY) / zoom.scale;
  return clampZoom({ scale: s, offsetX: ndcX - s * px, offsetY: ndcY - s * py });
}

/** `zoom` moved by (dx, dy) pixels of a width x height view, as far as the pages still fill it. As panBy. */
export function panBy(zoom, dx, dy, width, height) {
  return clampZoom({
    scale: zoom.scale,
    offsetX: zoom.offsetX + (2 * dx) / Math.max(1, width),
    offsetY: zoom.offsetY - (2 * dy) / Math.max(1, height),
  });
}

/** Where the zoomed picture shows an unzoomed rect ({ x, y, width, height }) of a width x height view. */
export function zoomRect(rect, { scale, offsetX, offsetY }, width, height) {
  // ndc' = scale * ndc + offset, with ndc x = 2x / width - 1 and ndc y = 1 - 2y / height.
  return {
    x: scale * rect.x + ((1 - scale + offsetX) * width) / 2,
    y: scale * rect.y + ((1 - scale - offsetY) * height) / 2,
    width: scale * rect.width,
    height: scale * rect.height,
  };
}

// ---- pages spliced on a live book (insertPages, removePages): one renumbering rule for every index map ----

/** Where page `page` goes when `removed` pages at `at` give way to `inserted` new ones: its new index, or -1 if removed. */
export function splicedPage(page, at, removed, inserted) {
  if (page < at) return page;
  return page < at + removed ? -1 : page + inserted - removed;
}

/** A Map keyed by page index, renumbered for such a splice (the removed pages' entries dropped). */
export function splicePageMap(map, at, removed, inserted) {
  const out = new Map();
  for (const [page, value] of map) {
    const moved = splicedPage(page, at, removed, inserted);
    if (moved >= 0) out.set(moved, value);
  }
  return out;
}
