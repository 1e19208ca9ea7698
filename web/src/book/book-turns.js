// Turns as a book carries them out, whichever asked (next(), flip(), a key, a link): the lead-in before
// leaves move, the follow-through with its events, flip() leaf by leaf or by a riffle, and the cut
// that stands for a turn on still pages or under reduced motion. It sees the book through its port.

const NEAR_LEAVES = 2;  // flip() turns this many leaves one by one; farther, it riffles

export class BookTurns {
  /**
   * @param {{ surface: () => object, store: () => object, zoom: () => object, html: () => object|null,
   *           alive: () => void, destroyed: () => boolean, animates: () => boolean, page: () => number,
   *           pageCount: () => number, openPages: () => number[], emit: (type: string, detail: object) => void,
   *           hideLayers: () => void, showOpenPages: () => void }} book  the controller's port (book-controller.js)
   */
  constructor(book) {
    this._book = book;
    this._flips = 0;  // counts flip() calls: a later one stops an earlier one's leaf-by-leaf turning
  }

  /** One leaf 'forward' or 'backward'; resolves whether it landed (false at the end of the book). */
  async turn(direction) {
    const book = this._book;
    book.alive();
    const ready = this._readyToMove();
    if (ready !== true && !(await ready)) return false;  // no wait unless a page is drawn again: next() starts at once
    if (!book.animates()) return this._jumpOneLeaf(direction);
    return this._follow(book.surface().turn(direction), { direction });
  }

  /**
   * Shows page `index` (a page of the book): animated, a near page leaf by leaf and a far one by a
   * riffle, else it jumps. The latest flip wins: an animated flip still under way stops where it is.
   */
  async flip(index, animate) {
    const book = this._book;
    const flip = ++this._flips;
    const surface = book.surface();
    if (!animate || !book.animates()) {
      const target = surface.positionOfPage(index);
      if (surface.position === target && !surface.animating) return;
      surface.jumpTo(target);
      book.store().update();
      this.landed();
      return;
    }
    for (;;) {
      if (index >= book.pageCount()) return;  // pages removed meanwhile (removePages): that page is gone
      const target = book.surface().positionOfPage(index);  // again each leaf: the display may switch
      if (book.surface().position === target) return;
      const far = Math.abs(target - book.surface().position) > NEAR_LEAVES;
      const turned = await (far ? this._riffle(index, flip) : this.turn(target > book.surface().position ? 'forward' : 'backward'));
      if (!turned || book.destroyed() || flip !== this._flips) return;
    }
  }

  /** The book landed (a turn, a jump, a completed drag): the open pages shown again, then `turned`. */
  landed() {
    this._book.showOpenPages();
    this._book.emit('turned', { page: this._book.page() });
  }

  // A riffle to page `index`, once leaves in flight have landed (false if a later flip came first). The
  // position is found after the wait: the display may have switched meanwhile.
  async _riffle(index, flip) {
    const book = this._book;
    await book.surface().settle();
    if (book.destroyed() || flip !== this._flips) return false;
    const ready = this._readyToMove();
    if ((ready !== true && !(await ready)) || flip !== this._flips || index >= book.pageCount()) return false;
    const surface = book.surface();
    const target = surface.positionOfPage(index);
    if (target === surface.position) return true;
    const direction = target > surface.position ? 'forward' : 'backward';
    const riffling = surface.riffle(target);
    if (!surface.animating) return this.turn(direction);  // refused: leaf by leaf then
    return this._follow(riffling, { direction, riffle: true });
  }

  // Before leaves move: a turn asked for by code shows the whole book again, and open HTML pages whose
  // content changed since their textures were made are drawn again: true at once if none, else a
  // promise of whether the book is still alive once they are.
  _readyToMove() {
    const book = this._book;
    const zoom = book.zoom();
    if (zoom.zoomed) zoom.about(1, 0, 0);
    const stale = book.html()?.staleAmong(book.openPages()) ?? [];
    if (stale.length === 0) return true;
    return Promise.all(stale.map((index) => book.store().refresh(index))).then(() => !book.destroyed());
  }

  // Leaves set moving by the surface (`moving` resolves whether they landed): turnstart, the pages they
  // show, then turned.
  async _follow(moving, detail) {
    const book = this._book;
    if (book.surface().animating) {
      book.hideLayers();
      book.emit('turnstart', { ...detail, page: book.page() });
    }
    book.store().update();
    const landed = await moving;
    if (book.destroyed()) return false;
    book.store().update();
    if (landed) this.landed();
    return landed;
  }

  // Reduced motion, or still pages: a turn is a cut to the next spread, with the same events.
  _jumpOneLeaf(direction) {
    const book = this._book;
    const surface = book.surface();
    const target = surface.position + (direction === 'forward' ? 1 : -1);
    if (target < 0 || target > surface.lastPosition()) return false;
    surface.jumpTo(target);
    book.emit('turnstart', { direction, page: book.page() });
    book.store().update();
    this.landed();
    return true;
  }
}
