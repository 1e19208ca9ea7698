// The text of a book's pages for search: case and diacritics folded (with a map back to the original
// text), a document's pages (a PDF's, a published one's) indexed once in the background and kept, HTML
// pages read from their elements, and each hit's rectangles (one per line) as fractions of its page.
//
// What runs where: for a PDF, pdf.js parses each page's content stream and extracts its text in its
// worker; a published document's text files are fetched, a text group (many pages) a request. Only the
// folding, the matching and the geometry of the hits run here on the main thread, page by page in idle
// time, never inside a turn's frame.
import { emptyPageText } from './format.js';
import { measureText as measure } from '../layers/text-measure.js';

const MARKS = /\p{M}/gu;
const SNIPPET_SIDE = 20;  // characters of context on each side of a hit (~40 in all)

function foldChar(ch) {
  // NFKD also splits ligatures (ﬁ → fi) and compatibility forms; case folded, then marks stripped again.
  return ch.normalize('NFKD').replace(MARKS, '').toLowerCase().normalize('NFKD').replace(MARKS, '');
}

/**
 * `text` folded for search: lower case, no diacritics, whitespace runs as one space. `starts[k]` and
 * `ends[k]` are where folded character k came from in `text` (UTF-16 offsets).
 * @param {string} text
 * @returns {{ folded: string, starts: number[], ends: number[] }}
 */
export function foldText(text) {
  let folded = '';
  const starts = [];
  const ends = [];
  for (let i = 0; i < text.length;) {
    const code = text.charCodeAt(i);
    const ch = code < 0xd800 || code > 0xdbff ? text[i] : String.fromCodePoint(text.codePointAt(i));
    // ASCII, most of most text, without the normaliser: letters lower-cased, whitespace a space.
    let f;
    if (code < 128) f = code <= 32 ? ' ' : ch.toLowerCase();
    else f = /\s/u.test(ch) ? ' ' : foldChar(ch);
    if (f === ' ' && folded.endsWith(' ')) f = '';
    for (let k = 0; k < f.length; k++) {
      folded += f[k];
      starts.push(i);
      ends.push(i + ch.length);
    }
    i += ch.length;
  }
  return { folded, starts, ends };
}

/** A query as it is matched: folded and trimmed ('' matches nothing). */
export function foldQuery(text) {
  return foldText(text).folded.trim();
}

/** Original-text ranges [start, end) of every match of `query` (folded) in `text` (folded once: `fold`), in order. */
function matches(text, query, fold = foldText(text)) {
  const { folded, starts, ends } = fold;
  const found = [];
  for (let at = folded.indexOf(query); at >= 0; at = folded.indexOf(query, at + query.length)) {
    found.push([starts[at], ends[at + query.length - 1]]);
  }
  return found;
}

/** About 40 characters around [start, end) of `text`, with ellipses where it was cut. */
export function snippetOf(text, start, end) {
  const from = Math.max(0, start - SNIPPET_SIDE);
  const to = Math.min(text.length, end + SNIPPET_SIDE);
  const body = text.slice(from, to).replace(/\s+/g, ' ');
  return `${from > 0 ? '…' : ''}${from > 0 ? body.trimStart() : body}${to < text.length ? '…' : ''}`.trim();
}

/** Rectangles [x, y, w, h] on the same line (overlapping vertically) merged: one per line, top to bottom. */
export function rectsByLine(rects) {
  const lines = [];
  for (const [x, y, w, h] of rects) {
    if (!(w > 0 && h > 0)) continue;
    const line = lines.find((l) => y < l.y + l.h && y + h > l.y && Math.min(h, l.h) > 0.5 * Math.max(h, l.h));
    if (!line) {
      lines.push({ x, y, w, h });
      continue;
    }
    const right = Math.max(line.x + line.w, x + w);
    const bottom = Math.max(line.y + line.h, y + h);
    line.x = Math.min(line.x, x);
    line.y = Math.min(line.y, y);
    line.w = right - line.x;
    line.h = bottom - line.y;
  }
  return lines.sort((a, b) => a.y - b.y || a.x - b.x).map((l) => [l.x, l.y, l.w, l.h]);
}

// ---- a document's pages ----------------------------------------------------------------------------------

/** The rectangles (fractions of the page, one per line) of the original text range [start, end) of a page's record. */
export function recordRects(record, start, end) {
  const rects = [];
  for (const item of record.items) {
    if (item.end <= start || item.start >= end) continue;
    const a = Math.max(start, item.start) - item.start;
    const b = Math.min(end, item.end) - item.start;
    const whole = measure(item.str, item.family) || 1;
    const x0 = item.width * (measure(item.str.slice(0, a), item.family) / whole);
    const x1 = item.width * (measure(item.str.slice(0, b), item.family) / whole);
    const [tA, tB, tC, tD, tE, tF] = item.tx;
    const size = Math.hypot(tC, tD);
    const angle = Math.atan2(tB, tA);
    if (Math.abs(angle) < 1e-3) {
      rects.push([(tE + x0) / record.width, (tF - item.ascent * size) / record.height,
        (x1 - x0) / record.width, ((item.ascent - item.descent) * size) / record.height]);
    } else {
      // Rotated text: the box around the rotated run.
      const cos = Math.cos(angle);
      const sin = Math.sin(angle);
      const corners = [[x0, -item.ascent * size], [x1, -item.ascent * size], [x0, -item.descent * size], [x1, -item.descent * size]]
        .map(([u, v]) => [tE + u * cos - v * sin, tF + u * sin + v * cos]);
      const xs = corners.map((c) => c[0]);
      const ys = corners.map((c) => c[1]);
      rects.push([Math.min(...xs) / record.width, Math.min(...ys) / record.height,
        (Math.max(...xs) - Math.min(...xs)) / record.width, (Math.max(...ys) - Math.min(...ys)) / record.height]);
    }
  }
  return rectsByLine(rects);
}

const whenIdle = (callback) => (typeof requestIdleCallback === 'function'
  ? requestIdleCallback(callback, { timeout: 1000 })
  : setTimeout(callback, 16));
const cancelIdle = (id) => (typeof cancelIdleCallback === 'function' ? cancelIdleCallback(id) : clearTimeout(id));

/**
 * A document's text (a PDF's through pdf.js, or a published one's text files), each page's record
 * (format.js) read once and kept, for every later search.
 */
export class TextIndex {
  /**
   * @param {{ pageText: (index: number) => Promise<object>, readTextGroup?: (index: number) => Promise<void> }} doc
   *   the book's document @param {number} pageCount
   */
  constructor(doc, pageCount) {
    this._doc = doc;
    this._pages = new Array(pageCount);  // page -> Promise of its record
    this._next = 0;
    this._idle = 0;
    this._stopped = false;
  }

  /**
   * Page `index`'s record, read now if the background has not reached it yet (a page whose text cannot be
   * read has none). Where the document has text groups (a published one's `readTextGroup`), the page's
   * group is read first: one request for it and the pages beside it, which then need none.
   */
  page(index) {
    this._pages[index] ??= Promise.resolve(this._doc.readTextGroup?.(index)).then(() => this._doc.pageText(index)).catch(() => emptyPageText());
    return this._pages[index];
  }

  /** Reads the pages one by one in idle time, after the book opened, until all are read. */
  startBackground() {
    const step = () => {
      this._idle = 0;
      while (this._next < this._pages.length && this._pages[this._next]) this._next += 1;
      if (this._stopped || this._next >= this._pages.length) return;
      this.page(this._next).then(() => {
        if (!this._stopped) this._idle = whenIdle(step);
      });
    };
    this._idle = whenIdle(step);
  }

  /** Pages read so far. */
  get indexed() { return this._next; }

  /** The hits on page `index`: [{ page, snippet, rects }], in reading order. */
  async hits(index, query) {
    const record = await this.page(index);
    record.fold ??= foldText(record.text);  // folded once, kept with the page's text for later searches
    return matches(record.text, query, record.fold).map(([start, end]) => ({
      page: index, snippet: snippetOf(record.text, start, end), rects: recordRects(record, start, end),
    }));
  }

  stop() {
    this._stopped = true;
    cancelIdle(this._idle);
  }
}

// ---- HTML pages ---------------------------------------------------------------------------------

/** The box an HTML page's element lies in (its sheet's content area, through the slot it is given), or null while not laid in. */
export const htmlPageBox = (element) => (element.assignedSlot ?? element).parentElement;

/**
 * The hits of `query` (folded) in an HTML page's element, rects from a Range over each match relative
 * to `box` (the page's box: its sheet's content area). Read at the time of the search: the page is live.
 * @param {number} index @param {HTMLElement} element @param {Element} box @param {string} query
 */
export function htmlPageHits(index, element, box, query) {
  const page = htmlPageText(element);
  return matches(page.text, query).map(([start, end]) => ({
    page: index, snippet: snippetOf(page.text, start, end), rects: page.rects(start, end, box),
  }));
}

/**
 * An HTML page's text as read now (its text nodes joined; scripts and styles left out), and the
 * rectangles (fractions of `box`, one per line) of a range [start, end) of it, from a Range laid now.
 * @param {HTMLElement} element
 * @returns {{ text: string, rects: (start: number, end: number, box: Element) => number[][] }}
 */
export function htmlPageText(element) {
  const nodes = [];
  let text = '';
  const walker = document.createTreeWalker(element, NodeFilter.SHOW_TEXT, {
    acceptNode: (node) => (node.parentElement?.closest('script, style, template') ? NodeFilter.FILTER_REJECT : NodeFilter.FILTER_ACCEPT),
  });
  for (let node = walker.nextNode(); node; node = walker.nextNode()) {
    nodes.push({ node, start: text.length });
    text += node.data;
  }
  const at = (offset) => {
    let i = nodes.length - 1;
    while (i > 0 && nodes[i].start > offset) i -= 1;
    return [nodes[i].node, offset - nodes[i].start];
  };
  return {
    text,
    rects(start, end, box) {
      const frame = box.getBoundingClientRect();
      const range = document.createRange();
      range.setStart(...at(start));
      range.setEnd(...at(end - 1).map((v, k) => (k === 1 ? v + 1 : v)));
      return rectsByLine([...range.getClientRects()].map((r) => [(r.left - frame.left) / frame.width, (r.top - frame.top) / frame.height,
        r.width / frame.width, r.height / frame.height]));
    },
  };
}
