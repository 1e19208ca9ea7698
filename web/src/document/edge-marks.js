// The marks on the book's edge (the `edgeMarks` option): index tabs from the outline's top-level entries
// (`outline()`) and ticks from the search's hits (the `searchchange` event), handed to the surface, which
// draws them on the page blocks at their leaves, and to the overlay buttons (layers/edge-tabs.js) that
// name them and riffle there. It is one of the controller's overlay layers (place, hide, remove).
import { createEdgeTabs } from '../layers/edge-tabs.js';

export class EdgeMarks {
  /**
   * @param {EventTarget & { outline?: () => Promise<Array<{ title: string, page: number }>>, showHit?: (hit: object) => Promise<void> }} controller
   *   the book, through its public API
   * @param {import('../book/book-wiring.js').BookPort} book
   */
  constructor(controller, book) {
    this._controller = controller;
    this._book = book;
    this._tabs = [];
    this._ticks = [];
    this._marks = [];
    this._layer = createEdgeTabs(book.root, {
      marks: () => this._marks,
      placesOf: () => book.surface()?.edgeMarkPlaces() ?? [],
      onActivate: (mark) => this._activate(mark),
    });
    this._onSearch = (event) => this.setHits(event.detail?.hits ?? []);
    this._onPages = () => { this.refreshTabs(); };  // pages moved: the outline's pages with them
    controller.addEventListener('searchchange', this._onSearch);
    controller.addEventListener('pageschange', this._onPages);
    this.refreshTabs();
  }

  /** The marks shown: tabs (with their titles as labels), then ticks. */
  get marks() { return this._marks; }

  /** Reads the outline again: a tab per top-level entry with a page in the book. */
  async refreshTabs() {
    let outline = [];
    try {
      outline = typeof this._controller.outline === 'function' ? await this._controller.outline() : [];
    } catch {
      outline = [];  // a PDF whose outline cannot be read has no tabs; the book reads on
    }
    if (this._book.destroyed()) return;
    this._tabs = (Array.isArray(outline) ? outline : [])
      .filter((entry) => Number.isInteger(entry?.page) && entry.page >= 0)
      .map((entry) => ({ page: entry.page, kind: 'tab', label: String(entry.title ?? '') }));
    this._apply();
  }

  /** Search hits ([{ page, snippet, rects }]): a tick per page with a hit, the first hit kept for a click. */
  setHits(hits) {
    const byPage = new Map();
    for (const hit of Array.isArray(hits) ? hits : []) {
      if (Number.isInteger(hit?.page) && hit.page >= 0 && !byPage.has(hit.page)) byPage.set(hit.page, hit);
    }
    this._ticks = [...byPage.values()].map((hit) => ({ page: hit.page, kind: 'tick', label: hit.snippet || undefined, hit }));
    this._apply();
  }

  _apply() {
    const pageCount = this._book.pageCount();
    this._marks = [...this._tabs, ...this._ticks].filter((mark) => mark.page < pageCount);
    this._book.surface()?.setEdgeMarks(this._marks.map(({ page, kind }) => ({ page, kind })));
    this._layer.hide();  // laid out again from the new places
    this._book.layoutLayers();
  }

  _activate(mark) {
    // A tick's hit is shown (and marked) where the book can; else, like a tab, its page (riffling when far).
    const go = mark.hit && typeof this._controller.showHit === 'function'
      ? this._controller.showHit(mark.hit) : this._book.flip(mark.page);
    Promise.resolve(go).catch(() => {});  // a later flip won: nothing to report
  }

  // ---- an overlay layer (book-controller.js) ----
  place() { this._layer.place(); }
  hide() { this._layer.hide(); }
  get buttons() { return this._layer.buttons; }
  remove() {
    this._controller.removeEventListener('searchchange', this._onSearch);
    this._controller.removeEventListener('pageschange', this._onPages);
    this._layer.remove();
  }
}
