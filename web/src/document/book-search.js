// A book's search: search() over its pages' text (text-index.js: a document's text indexed once,
// HTML pages read live), showHit() turning to a hit and marking it, clearSearch(), and the
// `searchchange` event. Marks are drawn into the pages' images (pages/marked-page.js, through the page
// store's `decorate` hook, document-wiring.js) and laid over the flat pages as elements (layers/search-hits.js).
// Made by the book's first search(), showHit() or clearSearch(); a document's index starts after the book opens.
import { foldQuery, htmlPageBox, htmlPageHits } from './text-index.js';
import { createSearchHitsLayer } from '../layers/search-hits.js';
import { describeValue } from '../engine/describe-value.js';

const sameHit = (a, b) => a.page === b.page && JSON.stringify(a.rects) === JSON.stringify(b.rects);
const abortError = () => new DOMException('conecurl: the search was aborted', 'AbortError');

/** Rejects with an AbortError when `signal` aborts; resolves never otherwise. */
function abortedBy(signal) {
  return new Promise((_, reject) => {
    if (!signal) return;
    if (signal.aborted) reject(abortError());
    signal.addEventListener('abort', () => reject(abortError()), { once: true });
  });
}

function checkHit(hit, pageCount) {
  if (hit === null || typeof hit !== 'object' || !Number.isInteger(hit.page) || hit.page < 0 || hit.page >= pageCount
      || !Array.isArray(hit.rects) || !hit.rects.every((r) => Array.isArray(r) && r.length === 4 && r.every(Number.isFinite))) {
    throw new TypeError(`conecurl: showHit() takes a hit from search(): { page (0 to ${pageCount - 1}), snippet, rects: [[x, y, width, height], ...] }, got ${describeValue(hit)}`);
  }
}

export class BookSearch {
  /**
   * @param {import('../book/book-wiring.js').BookPort} book  the controller's port
   * @param {() => Promise<object|null>} documentIndex  the document's text index (made once, shared with later searches)
   */
  constructor(book, documentIndex) {
    this._book = book;
    this._documentIndex = documentIndex;
    this._query = '';
    this._hits = [];
    this._current = null;
    this._marks = new Map();  // page -> [{ rect, current }] drawn now
    this._runs = 0;           // the latest search wins
    this._layer = createSearchHitsLayer(book.root, {
      marksOn: (page) => this._marks.get(page) ?? [],
      live: (page) => Boolean(book.entries[page]?.html),
    });
    book.addLayer(this._layer);
  }

  /** The marks page `index`'s image gets now (drawn in by document-wiring.js decorate): [{ rect, current }]. */
  marksOn(index) {
    return this._marks.get(index) ?? [];
  }

  /** The hits of `text` in reading order: [{ page, snippet, rects }]; rejects with an AbortError when `signal` aborts. */
  async search(text, { signal } = {}) {
    if (typeof text !== 'string') throw new TypeError(`conecurl: search() takes the text to find, a string; got ${describeValue(text)}`);
    if (signal !== undefined && !(signal instanceof AbortSignal)) {
      throw new TypeError(`conecurl: search()'s 'signal' must be an AbortSignal, got ${describeValue(signal)}`);
    }
    if (signal?.aborted) throw abortError();
    const run = ++this._runs;
    const query = foldQuery(text);
    const hits = [];
    if (query !== '') {
      const aborted = abortedBy(signal);
      aborted.catch(() => {});
      const { entries } = this._book;
      const index = await this._documentIndex();
      const pages = entries.length;
      // Pages not yet indexed are asked for all at once (pdf.js's worker reads them in turn, a published
      // document's text files are fetched) while the pages already read are matched here.
      if (index) for (let page = 0; page < pages; page++) index.page(page);
      for (let page = 0; page < pages; page++) {
        if (signal?.aborted) throw abortError();
        const entry = entries[page];
        if (entry.html) {
          const box = htmlPageBox(entry.html);
          if (box) hits.push(...htmlPageHits(page, entry.html, box, query));
        } else if (index) {
          hits.push(...await Promise.race([index.hits(page, query), aborted]));
        }
      }
    }
    if (run === this._runs && !this._book.destroyed()) {
      this._query = query === '' ? '' : text;
      this._hits = hits;
      this._current = null;
      this._remark();
      this._changed();
    }
    return hits;
  }

  /** Turns to `hit`'s page (riffling when far), marks it as the current hit; resolves once it lies open. */
  async showHit(hit) {
    checkHit(hit, this._book.pageCount());
    this._current = hit;
    this._remark();  // before the turn: the page's texture shows the marks as it comes
    this._changed();
    // Always flip, even when the hit's page looks open: a turn still under way (an earlier showHit())
    // would otherwise carry the book away from it; the latest flip wins, and an open page is no turn.
    await this._book.flip(hit.page);
    this._book.layoutLayers();
  }

  /** No more search: marks removed (the clean images handed back), `searchchange` with no hits. */
  clear() {
    this._runs += 1;  // a search still running no longer sets results
    const had = this._query !== '' || this._hits.length > 0 || this._current !== null;
    this._query = '';
    this._hits = [];
    this._current = null;
    this._remark();
    if (had) this._changed();
  }

  /**
   * Pages were spliced: the hits' page numbers no longer hold, and marked images moved with their
   * pages. The search ends and every kept page gets its clean image again.
   */
  pagesChanged() {
    const marked = this._marks.size > 0;
    this._marks.clear();
    this.clear();
    if (marked) for (const page of this._book.store().residentPages) this._book.store().remark(page).catch(() => {});
  }

  _changed() {
    this._book.emit('searchchange', { query: this._query, hits: this._hits.slice(), current: this._current });
  }

  // The marks now wanted, by page; pages whose marks changed get their image handed over again.
  _remark() {
    const marks = new Map();
    const add = (hit, current) => {
      if (!marks.has(hit.page)) marks.set(hit.page, []);
      for (const rect of hit.rects) marks.get(hit.page).push({ rect, current });
    };
    const current = this._current;
    for (const hit of this._hits) if (!current || !sameHit(hit, current)) add(hit, false);
    if (current) add(current, true);
    const before = this._marks;
    this._marks = marks;
    const pages = new Set([...before.keys(), ...marks.keys()]);
    for (const page of pages) {
      if (JSON.stringify(before.get(page) ?? []) !== JSON.stringify(marks.get(page) ?? [])) {
        this._book.store().remark(page).catch(() => {});
      }
    }
    this._book.layoutLayers();
  }
}
