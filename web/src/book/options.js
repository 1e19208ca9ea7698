// The options of a book (Flipbook and its static fallback) checked in one place: every bad value is
// a TypeError that names the option and says what is allowed, before anything is built.
import { BOOK_EVENTS } from './book-events.js';
import { DIRECTIONS } from '../engine/direction.js';
import { AUTO_MIN_PAGE_WIDTH, DEFAULT_SHOW_THROUGH, MAX_LEAF_THICKNESS, MAX_PAGES } from '../engine/layout.js';
import { TURN_AREAS } from '../input/turn-area.js';
import { checkResolution } from '../surfaces/moving-resolution.js';
import { describeValue } from '../engine/describe-value.js';

export { describeValue };  // the options' errors show values so; other layers import it from engine/

const BOOLEAN = (v) => typeof v === 'boolean' || 'true or false';
export { MAX_PAGES };  // the engine's Book refuses more (cpp/core/book_constants.hpp)

const OPTION_CHECKS = {
  pages: (v) => (Array.isArray(v) && v.length > 0 && v.length <= MAX_PAGES)
    || `a non-empty array of at most ${MAX_PAGES} page sources`,
  display: (v) => ['single', 'double', 'auto'].includes(v) || "'single', 'double' or 'auto'",
  // phone (issue 28): display 'auto' shows two pages only where each is at least this wide (layout.js displayFor).
  minPageWidth: (v) => (Number.isFinite(v) && v > 0) || 'a positive number of CSS pixels',
  direction: (v) => DIRECTIONS.includes(v) || DIRECTIONS.map((d) => `'${d}'`).join(', ').replace(/, ([^,]+)$/, ' or $1'),
  startPage: (v) => (Number.isInteger(v) && v >= 0) || 'a page index (a whole number from 0)',
  duration: (v) => (Number.isFinite(v) && v > 0) || 'a positive number of milliseconds',
  schedule: (v) => ['paper', 'smooth'].includes(v) || "'paper' or 'smooth'",
  center: BOOLEAN,
  hardCovers: BOOLEAN,
  lighting: BOOLEAN,
  shadows: BOOLEAN,
  gutter: BOOLEAN,
  // phone turn (issue 40): the print seen through a blank back (single display), as thin paper shows it.
  showThrough: (v) => (Number.isFinite(v) && v >= 0 && v <= 1) || 'a number from 0 (none) to 1',
  thickness: (v) => typeof v === 'boolean' || (Number.isFinite(v) && v >= 0 && v <= MAX_LEAF_THICKNESS)
    || `true, false or a leaf's thickness as a fraction of the page width (0 to ${MAX_LEAF_THICKNESS})`,
  loadWindow: (v) => (Number.isInteger(v) && v >= 1) || 'a whole number of pages from 1',
  wasmUrl: (v) => typeof v === 'string' || 'a URL string',
  label: (v) => (typeof v === 'string' && v.trim() !== '') || 'a non-empty string',
  fallback: BOOLEAN,
  hash: BOOLEAN,
  autoplay: (v) => typeof v === 'boolean' || (isPlainEntry(v) && Object.keys(v).every((k) => k === 'interval' || k === 'loop')
    && (v.interval === undefined || (Number.isFinite(v.interval) && v.interval > 0))
    && (v.loop === undefined || typeof v.loop === 'boolean'))
    || 'true, false or { interval: milliseconds, loop: true or false }',
  sound: BOOLEAN,
  muted: BOOLEAN,
  rememberPage: (v) => (typeof v === 'string' && v.trim() !== '') || 'a non-empty string (the key it is kept under)',
  antialias: (v) => typeof v === 'boolean' || v === 'auto' || "'auto', true or false",
  // frame (issue 29): how sharp frames with moving leaves are drawn (surfaces/moving-resolution.js).
  resolution: checkResolution,
  turnArea: (v) => TURN_AREAS.includes(v) || TURN_AREAS.map((a) => `'${a}'`).join(', ').replace(/, ([^,]*)$/, ' or $1'),
  on: (v) => (isPlainEntry(v) && Object.entries(v).every(([type, f]) => BOOK_EVENTS.includes(type) && typeof f === 'function'))
    || `an object of listeners by event name (${BOOK_EVENTS.join(', ')})`,
  // docapi (issue 23): the document API's options; each outline entry is checked by checkOutline().
  outline: (v) => Array.isArray(v) || 'an array of { title, page, children? }',
  download: (v) => (typeof v === 'string' && v.trim() !== '') || 'a URL string',
  // edgemarks (issue 23)
  edgeMarks: BOOLEAN,
  // viewer (issue 23): the toolbar and its panels (web/src/viewer/)
  // Their shape here; the names of the parts and labels are checked by the viewer's attachControls when
  // the book is built (create() rejects with its TypeError), so a book without controls never loads them.
  controls: (v) => typeof v === 'boolean' || isPlainEntry(v) || 'true, false or an object of parts to show or hide',
  labels: (v) => (isPlainEntry(v) && Object.values(v).every((text) => typeof text === 'string')) || 'an object of texts by key',
  // textlayer (issue 23): a PDF book's selectable text over its flat pages.
  textLayer: BOOLEAN,
  // voice (issue 37): where read-aloud keeps the reader's voice and speed by language (engine/voice-choice.js).
  readAloudMemory: (v) => v === false || (typeof v === 'string' && v.trim() !== '')
    || 'false or a non-empty string (the localStorage key the voice and speed are kept under)',
};
/** Every option validateOptions() knows (Flipbook.create also takes a document in place of pages: DOCUMENT_OPTIONS). */
export const OPTION_NAMES = Object.keys(OPTION_CHECKS);
/**
 * The options of a book over a document, in place of `pages`: a PDF (`pdf`, `pdfWorkerSrc`) or a
 * published document (`document`). Flipbook.create checks them (flipbook.js) and opens the document.
 */
export const DOCUMENT_OPTIONS = ['pdf', 'pdfWorkerSrc', 'document'];
/** Every option Flipbook.create takes: FlipbookOptions in flipbook.d.ts (tests/node/typings.test.mjs checks it). */
export const CREATE_OPTIONS = [...OPTION_NAMES, ...DOCUMENT_OPTIONS];
export const DEFAULTS = {
  display: 'auto', minPageWidth: AUTO_MIN_PAGE_WIDTH, direction: 'ltr', startPage: 0, duration: 1000, schedule: 'paper', center: true, hardCovers: false,
  lighting: true, shadows: true, gutter: true, showThrough: DEFAULT_SHOW_THROUGH, thickness: true, loadWindow: 4, label: 'Book', fallback: true, hash: false,
  autoplay: false, sound: false, muted: false, antialias: 'auto', resolution: 'auto',
  controls: false,
  textLayer: true,
  readAloudMemory: 'conecurl-read-aloud',  // engine/voice-choice.js DEFAULT_MEMORY_KEY
};
/** Options a live book takes through setOptions(); the others need a new book. */
export const LIVE_OPTIONS = ['lighting', 'shadows', 'gutter', 'showThrough', 'thickness', 'resolution', 'display', 'minPageWidth', 'sound', 'muted'];
const PAGE_ENTRY_KEYS = ['src', 'html', 'alt', 'hard', 'zoomSrc', 'thumbSrc', 'placeholder', 'links', 'narration'];
const PAGE_SOURCES = 'a URL string, HTMLImageElement, HTMLCanvasElement, ImageBitmap, Blob, '
  + 'a function returning one of these (or a Promise of one), or an HTML element (an HTML page)';

function isPageImage(src) {
  return (typeof src === 'string' && src !== '') || src instanceof Blob
    || (typeof HTMLImageElement !== 'undefined' && src instanceof HTMLImageElement)
    || (typeof HTMLCanvasElement !== 'undefined' && src instanceof HTMLCanvasElement)
    || (typeof ImageBitmap !== 'undefined' && src instanceof ImageBitmap);
}

/** An element shown as a live HTML page: any HTMLElement but an image, canvas or video. */
export function isHtmlPage(page) {
  return typeof HTMLElement !== 'undefined' && page instanceof HTMLElement && !isPageImage(page)
    && !(typeof HTMLVideoElement !== 'undefined' && page instanceof HTMLVideoElement);
}

function isPlainEntry(page) {
  return page !== null && typeof page === 'object' && !Array.isArray(page) && !isPageImage(page) && !isHtmlPage(page);
}

/**
 * Checks one page given as `name` (its place, as messages say it): a TypeError names what is wrong.
 * `kind` is what it was given to ('option', or a method such as 'insertPages').
 */
export function checkPage(page, name, pageCount, kind = 'option') {
  if (!isPlainEntry(page)) {
    if (isPageImage(page) || isHtmlPage(page) || typeof page === 'function') return;
    throw new TypeError(`conecurl: ${kind} '${name}' must be ${PAGE_SOURCES}, or { src, alt, hard }; got ${describeValue(page)}`);
  }
  const unknown = Object.keys(page).find((key) => !PAGE_ENTRY_KEYS.includes(key));
  if (unknown !== undefined) {
    throw new TypeError(`conecurl: ${kind} '${name}' has an unknown key '${unknown}' (allowed: ${PAGE_ENTRY_KEYS.join(', ')})`);
  }
  if (page.html !== undefined) {
    if (!isHtmlPage(page.html)) {
      throw new TypeError(`conecurl: ${kind} '${name}.html' must be an HTML element (not an image, canvas or video; `
        + `strings are never parsed as HTML); got ${describeValue(page.html)}`);
    }
    if (page.src !== undefined || page.zoomSrc !== undefined) {
      throw new TypeError(`conecurl: ${kind} '${name}' gives both 'html' and '${page.src !== undefined ? 'src' : 'zoomSrc'}': an HTML page is drawn from its element`);
    }
  } else if (!isPageImage(page.src) && typeof page.src !== 'function') {
    throw new TypeError(`conecurl: ${kind} '${name}.src' must be ${PAGE_SOURCES}; got ${describeValue(page.src)}`);
  }
  if (page.alt !== undefined && typeof page.alt !== 'string') {
    throw new TypeError(`conecurl: ${kind} '${name}.alt' must be a string (the page's text for screen readers); got ${describeValue(page.alt)}`);
  }
  if (page.hard !== undefined && typeof page.hard !== 'boolean') {
    throw new TypeError(`conecurl: ${kind} '${name}.hard' must be true or false; got ${describeValue(page.hard)}`);
  }
  for (const key of ['zoomSrc', 'thumbSrc', 'placeholder']) {
    if (page[key] !== undefined && !isPageImage(page[key])) {
      throw new TypeError(`conecurl: ${kind} '${name}.${key}' must be a URL, HTMLImageElement, HTMLCanvasElement, ImageBitmap or Blob; `
        + `got ${describeValue(page[key])}`);
    }
  }
  if (page.links !== undefined) checkLinks(page.links, `${name}.links`, pageCount, kind);
  if (page.narration !== undefined) checkNarration(page.narration, `${name}.narration`, kind);
}

// A page's recorded narration: { src (the audio's URL), words (its word times, or the URL of a WebVTT or
// JSON file of them) }; each word is checked when the page is read (read-aloud/word-times.js).
function checkNarration(narration, name, kind) {
  const { src, words } = narration ?? {};
  const ok = isPlainEntry(narration) && Object.keys(narration).every((key) => key === 'src' || key === 'words')
    && typeof src === 'string' && src !== '' && (Array.isArray(words) || (typeof words === 'string' && words !== ''));
  if (!ok) {
    throw new TypeError(`conecurl: ${kind} '${name}' must be { src: the audio's URL, words: [{ start, end, text, rect }] `
      + `or the URL of a WebVTT or JSON file of them }; got ${describeValue(narration)}`);
  }
}

function checkLinks(links, where, pageCount, kind) {
  if (!Array.isArray(links)) {
    throw new TypeError(`conecurl: ${kind} '${where}' must be an array of { rect, href } or { rect, page }; got ${describeValue(links)}`);
  }
  links.forEach((link, i) => {
    const rect = link && link.rect;
    if (!Array.isArray(rect) || rect.length !== 4 || !rect.every((v) => Number.isFinite(v) && v >= 0 && v <= 1)) {
      throw new TypeError(`conecurl: ${kind} '${where}[${i}].rect' must be [x, y, width, height] as fractions of the page (0 to 1); `
        + `got ${describeValue(rect)}`);
    }
    const toPage = link.page;
    if (toPage !== undefined && !(Number.isInteger(toPage) && toPage >= 0 && toPage < pageCount)) {
      throw new TypeError(`conecurl: ${kind} '${where}[${i}].page' must be a page index below ${pageCount}; got ${describeValue(toPage)}`);
    }
    if (toPage === undefined && typeof link.href !== 'string') {
      throw new TypeError(`conecurl: ${kind} '${where}[${i}]' needs an href (a URL string) or a page (an index)`);
    }
  });
}

/**
 * Checks a book's options and returns them with the defaults filled in. Throws a TypeError naming
 * the first bad option (or page entry) and what it allows. `document`: the pages are a document's (a PDF
 * or a published one, Flipbook.create opened it), so its text layer is on unless `textLayer: false`.
 */
export function validateOptions(options, { document = false } = {}) {
  if (options === null || typeof options !== 'object') {
    throw new TypeError(`conecurl: options must be an object, got ${describeValue(options)}`);
  }
  for (const [key, value] of Object.entries(options)) {
    const check = OPTION_CHECKS[key];
    if (!check) throw new TypeError(`conecurl: unknown option '${key}' (allowed: ${Object.keys(OPTION_CHECKS).join(', ')})`);
    const verdict = check(value);
    if (verdict !== true) throw new TypeError(`conecurl: option '${key}' must be ${verdict}, got ${describeValue(value)}`);
  }
  if (!('pages' in options)) throw new TypeError("conecurl: option 'pages' is missing (a non-empty array of page sources)");
  // An index loop, not forEach: a hole in a sparse array is a missing page, not one to skip.
  for (let index = 0; index < options.pages.length; index++) checkPage(options.pages[index], `pages[${index}]`, options.pages.length);
  if (options.outline !== undefined) checkOutline(options.outline, 'outline', options.pages.length);
  if (options.startPage !== undefined && options.startPage >= options.pages.length) {
    throw new TypeError(`conecurl: option 'startPage' must be below the page count ${options.pages.length}, got ${options.startPage}`);
  }
  // A book with HTML pages, or a PDF's selectable text, turns from the pages' edges by default: a press
  // on their content is theirs. Not a PDF's text on a coarse pointer: a finger selects by a long press,
  // so a tap or a drag anywhere on the page may turn it (and a tap on a word reaches the book, text-layer.js).
  const hasHtml = Array.from(options.pages, (page) => isHtmlPage(page) || (isPlainEntry(page) && page.html !== undefined)).some(Boolean);
  const hasText = document && (options.textLayer ?? DEFAULTS.textLayer);
  // edgeMarks: on with the controls unless given.
  const coarse = Boolean(globalThis.matchMedia?.('(pointer: coarse)').matches);
  const settings = { ...DEFAULTS, turnArea: hasHtml || (hasText && !coarse) ? 'edges' : 'page', edgeMarks: Boolean(options.controls), ...options };
  if (settings.outline) settings.outline = copyOutline(settings.outline);  // the book's own: later changes to the caller's do not reach it
  return settings;
}

const copyOutline = (entries) => entries.map(({ title, page, children }) => ({ title, page, children: copyOutline(children ?? []) }));

// The `outline` option's entries, each { title: non-empty string, page: index in the book, children?: entries }.
function checkOutline(entries, where, pageCount) {
  entries.forEach((entry, i) => {
    const name = `${where}[${i}]`;
    if (!isPlainEntry(entry)) throw new TypeError(`conecurl: option '${name}' must be { title, page, children? }, got ${describeValue(entry)}`);
    const extra = Object.keys(entry).find((key) => !['title', 'page', 'children'].includes(key));
    if (extra) throw new TypeError(`conecurl: option '${name}' has an unknown key '${extra}' (allowed: title, page, children)`);
    if (typeof entry.title !== 'string' || entry.title.trim() === '') {
      throw new TypeError(`conecurl: option '${name}.title' must be a non-empty string, got ${describeValue(entry.title)}`);
    }
    if (!Number.isInteger(entry.page) || entry.page < 0 || entry.page >= pageCount) {
      throw new TypeError(`conecurl: option '${name}.page' must be a page index from 0 to ${pageCount - 1}, got ${describeValue(entry.page)}`);
    }
    if (entry.children === undefined) return;
    if (!Array.isArray(entry.children)) {
      throw new TypeError(`conecurl: option '${name}.children' must be an array of { title, page, children? }, got ${describeValue(entry.children)}`);
    }
    checkOutline(entry.children, `${name}.children`, pageCount);
  });
}

const oneLinkForm = (l) => ({ rect: l.rect, href: l.href ?? '#', toPage: l.page, title: l.title });

/**
 * The page entries of checked options: every page as { src, alt?, hard?, zoomSrc?, thumbSrc?, placeholder?, links? } (or { html, ... }), links
 * in one form { rect, href, toPage, title }. Entries without links stay the objects given (a PDF's
 * fill in their alt and links as their pages render) unless `copy`: each entry its own object, so the
 * same page given twice is two entries (pages spliced on a live book are followed by their entries).
 */
export function pageEntries(pages, { copy = false } = {}) {
  return pages.map((page) => {
    if (isHtmlPage(page)) return { html: page, alt: page.getAttribute('aria-label') ?? undefined };
    if (!isPlainEntry(page)) return { src: page };
    if (page.html) return { ...page, links: page.links?.map(oneLinkForm) };  // a copy: the book adds its `src`
    if (!page.links) return copy ? { ...page } : page;
    return { ...page, links: page.links.map(oneLinkForm) };
  });
}

/** The hard pages' indices: pages marked `hard`, and with `hardCovers` the first and the last. */
export function hardPageIndices(entries, hardCovers) {
  const last = entries.length - 1;
  return entries.flatMap((entry, i) => (entry.hard || (hardCovers && (i === 0 || i === last)) ? [i] : []));
}

/** `flip(index, options)`'s second argument: nothing, or { animate: boolean }. */
export function checkFlipOptions(options) {
  if (options === undefined) return { animate: true };
  if (options === null || typeof options !== 'object') {
    throw new TypeError(`conecurl: flip options must be an object like { animate: false }, got ${describeValue(options)}`);
  }
  const unknown = Object.keys(options).find((key) => key !== 'animate');
  if (unknown !== undefined) throw new TypeError(`conecurl: unknown flip option '${unknown}' (allowed: animate)`);
  if (options.animate !== undefined && typeof options.animate !== 'boolean') {
    throw new TypeError(`conecurl: flip option 'animate' must be true or false, got ${describeValue(options.animate)}`);
  }
  return { animate: options.animate ?? true };
}

/** setOptions()'s argument on a live book: only LIVE_OPTIONS, each checked like at create. */
export function checkLiveOptions(options, pages) {
  if (options === null || typeof options !== 'object') {
    throw new TypeError(`conecurl: options must be an object, got ${describeValue(options)}`);
  }
  const checked = validateOptions({ ...options, pages });  // a TypeError names a bad value
  const fixed = Object.keys(options).find((key) => !LIVE_OPTIONS.includes(key));
  if (fixed) throw new TypeError(`conecurl: option '${fixed}' cannot change on a live book (only ${LIVE_OPTIONS.join(', ')})`);
  return Object.fromEntries(Object.keys(options).map((key) => [key, checked[key]]));
}
