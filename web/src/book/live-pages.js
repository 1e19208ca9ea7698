// Pages that change on a live book (insertPages, removePages, replacePage): no rebuild. A change waits
// for the leaves in flight to land, then splices the page entries, the page store, the HTML pages and
// the surface's textures in one go (untouched pages keep theirs, renumbered), keeps the page the reader
// had in view, and says what changed in a `pageschange` event. For Flipbook and StaticBook alike.
import { MAX_PAGES, checkPage, describeValue, hardPageIndices, pageEntries } from './options.js';

export class LivePages {
  /**
   * @param {{ entries: object[], store: object, surface: () => object, html: () => object|null,
   *           attachHtml: (HtmlPages: Function) => void, page: () => number, hardCovers: boolean, isDocument: () => boolean,
   *           alive: () => void, shown: () => void, emit: (type: string, detail: object) => void,
   *           flushEvents: () => void }} book
   */
  constructor(book) {
    this._book = book;
    this._pending = 0;                 // changes waiting for the book to rest, applied in the order asked
    this._last = Promise.resolve();
  }

  /** Inserts `pages` before page `at` (at === pageCount: after the last). */
  insert(at, pages) {
    const entries = this._entries('insertPages', pages, 'pages', this._count() + (Array.isArray(pages) ? pages.length : 0));
    return this._enqueue(entries, (HtmlPages) => {
      this._check('insertPages', 'at', at, this._count());
      return this._splice('insert', at, 0, entries, HtmlPages);  // the first HTML pages of a book bring their layer
    });
  }

  /** Removes `count` pages from page `from` on. */
  remove(from, count) {
    this._changeable('removePages');
    this._whole('removePages', 'from', from);
    this._whole('removePages', 'count', count);
    return this._enqueue([], () => {
      const pageCount = this._count();
      this._check('removePages', 'from', from, pageCount - 1);
      if (count < 1 || from + count > pageCount) {
        throw new RangeError(`conecurl: removePages count must be from 1 to ${pageCount - from} (the pages from ${from} on), got ${count}`);
      }
      if (count === pageCount) throw new RangeError(`conecurl: removePages cannot remove all ${pageCount} pages: a book keeps at least one`);
      return this._splice('remove', from, count, []);
    });
  }

  /** Puts `page` in the place of page `index`. */
  replace(index, page) {
    this._changeable('replacePage');
    this._whole('replacePage', 'index', index);
    const [entry] = this._entries('replacePage', [page], 'page', this._count());
    return this._enqueue([entry], (HtmlPages) => {
      this._check('replacePage', 'index', index, this._count() - 1);
      const book = this._book;
      const old = book.entries[index];
      book.entries[index] = entry;
      if (old.html || entry.html) this._html(index, 1, [entry], HtmlPages);
      book.store.replace(index);
      book.surface().splicePages(index, 0, 0, hardPageIndices(book.entries, book.hardCovers));
      return this._done('replace', index, 1);
    });
  }

  _count() { return this._book.entries.length; }

  // Checked page entries for a method: each page as the options check it (links to pages below
  // `pageCount`), none an HTML element shown already.
  _changeable(method) {
    this._book.alive();
    if (this._book.isDocument()) throw new Error(`conecurl: ${method}: a PDF book's pages are its PDF's; they cannot change on a live book`);
  }

  _entries(method, pages, name, pageCount) {
    this._changeable(method);
    if (name === 'pages' && !(Array.isArray(pages) && pages.length > 0)) {
      throw new TypeError(`conecurl: ${method} pages must be a non-empty array of page sources, got ${describeValue(pages)}`);
    }
    pages.forEach((page, i) => checkPage(page, name === 'pages' ? `pages[${i}]` : name, pageCount, method));
    const shown = new Set(this._book.entries.map((entry) => entry.html).filter(Boolean));
    const entries = pageEntries(pages, { copy: true });
    entries.forEach((entry, i) => {
      if (entry.html && shown.has(entry.html)) throw new TypeError(`conecurl: ${method} ${name === 'pages' ? `pages[${i}]` : name} is an HTML element the book shows already`);
      if (entry.html) shown.add(entry.html);
    });
    return entries;
  }

  _whole(method, name, value) {
    this._book.alive();
    if (!Number.isInteger(value)) throw new TypeError(`conecurl: ${method} ${name} must be a whole number, got ${describeValue(value)}`);
  }

  _check(method, name, value, max) {
    this._whole(method, name, value);
    if (value < 0 || value > max) throw new RangeError(`conecurl: ${method} ${name} must be from 0 to ${max}, got ${value}`);
  }

  // Applies a change now if nothing waits and no leaf moves, else once the changes before it are applied
  // and the book rests. HTML pages coming into a book without any first load their module.
  async _enqueue(entries, apply) {
    const needsHtml = entries.some((entry) => entry.html) && !this._book.html();
    // Events held from create() tell of the book before the change: they go out first.
    const applyNow = (HtmlPages) => {
      this._book.flushEvents();
      return apply(HtmlPages);
    };
    if (this._pending === 0 && !needsHtml && !this._book.surface().animating) return applyNow(null);
    this._pending++;
    const previous = this._last;
    const run = (async () => {
      await previous.catch(() => {});
      const HtmlPages = needsHtml ? (await import('../layers/html-pages.js')).HtmlPages : null;
      for (;;) {
        this._book.alive();
        const surface = this._book.surface();
        if (!surface.animating) break;
        await surface.settle();  // turns in flight land (and a held leaf is let go) before the pages change
      }
      return applyNow(HtmlPages);
    })();
    this._last = run;
    try {
      return await run;
    } finally {
      this._pending--;
    }
  }

  // `removed` pages at `at` give way to `entries`; the first page in view stays in view where it went
  // (a removed one: the page that took its place).
  _splice(change, at, removed, entries, HtmlPages) {
    const book = this._book;
    const pageCount = this._count() - removed + entries.length;
    if (pageCount > MAX_PAGES) throw new RangeError(`conecurl: insertPages would make ${pageCount} pages; a book holds at most ${MAX_PAGES}`);
    const before = book.page();
    let after = before;
    if (before >= at + removed) after = before - removed + entries.length;
    else if (before >= at && removed > 0) after = Math.min(at, pageCount - 1);
    else if (before >= at) after = before + entries.length;
    const list = book.entries;
    const tail = list.slice(at + removed);  // in place (the store and the layers hold this array), without spread arguments
    list.length = at;
    for (const entry of entries) list.push(entry);
    for (const entry of tail) list.push(entry);
    book.store.splice(at, removed, entries.length);
    this._html(at, removed, entries, HtmlPages);
    const surface = book.surface();
    surface.splicePages(at, removed, entries.length, hardPageIndices(list, book.hardCovers));
    surface.jumpTo(surface.positionOfPage(after));
    return this._done(change, at, change === 'insert' ? entries.length : removed);
  }

  _html(at, removed, entries, HtmlPages) {
    const html = this._book.html();
    if (html) html.splice(at, removed, entries);
    else if (HtmlPages) this._book.attachHtml(HtmlPages);  // mounts every HTML entry, these among them
  }

  _done(change, at, count) {
    const book = this._book;
    book.store.update();
    book.shown();
    const detail = { change, at, count, pageCount: this._count(), page: book.page() };
    book.emit('pageschange', detail);
    return detail;
  }
}
