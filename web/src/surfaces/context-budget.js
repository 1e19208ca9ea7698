// Browsers keep only about 16 live WebGL contexts per page and silently lose the oldest beyond that, so
// the books on a page share a budget: a book out of view hands its context back when another needs one
// (through WEBGL_lose_context) and takes it back, through BookView's restore path, when it scrolls in.

/** Live contexts the books on a page may hold at once: well below Chrome's 16, leaving room for others. */
export const MAX_LIVE_CONTEXTS = 8;
/** Books this close to the viewport (a fraction of it) count as visible: they get a context before they are seen. */
const VISIBLE_MARGIN = '25%';

/**
 * Which of the live books gives its context up for another, as an index into `candidates`
 * ({ visible, busy, lastUsed }), or -1 for none: a book out of view before one in view, a book at rest
 * before one with a leaf moving or held, then the one out of view longest (or, in view, used longest ago).
 */
export function chooseContextToRelease(candidates) {
  let best = -1;
  const rank = (c) => [c.visible ? 1 : 0, c.busy ? 1 : 0, c.lastUsed];
  for (let i = 0; i < candidates.length; i++) {
    if (best < 0) { best = i; continue; }
    const [a, b] = [rank(candidates[i]), rank(candidates[best])];
    const order = a[0] - b[0] || a[1] - b[1] || a[2] - b[2];
    if (order < 0) best = i;
  }
  return best;
}

/** The books of one page and their contexts; `contextBudget()` gives the page's one instance. */
export class ContextBudget {
  constructor({ maxLive = MAX_LIVE_CONTEXTS } = {}) {
    if (!(Number.isInteger(maxLive) && maxLive >= 1)) throw new RangeError('conecurl: maxLive must be a whole number from 1');
    this.maxLive = maxLive;
    this._leases = new Set();
    this._clock = 0;  // orders uses and departures from view; a counter, not wall time
  }

  /** Contexts held or being restored now. */
  get liveCount() { return [...this._leases].filter((lease) => lease.live).length; }

  /** A lease for a book drawing on `canvas`; call `admit()` before making its context. */
  lease(canvas) {
    const lease = new ContextLease(this, canvas);
    this._leases.add(lease);
    return lease;
  }

  _tick() { return ++this._clock; }

  _forget(lease) { this._leases.delete(lease); }

  // A book in view without a context takes one that is free or held by a book out of view, the book
  // used last first. Run whenever books come and go from view or let go: a book may have been parked
  // while it was in view, e.g. when newcomers still counted as visible before their first report.
  _rebalance() {
    for (;;) {
      // Only books known to be in view: a newcomer counts as visible before its first report, but
      // waking it on that guess would take a context for a book that may be far below.
      const waiting = [...this._leases].filter((lease) => lease.state === 'parked' && lease.visible && lease._visibilityReported);
      if (waiting.length === 0) return;
      const live = [...this._leases].filter((lease) => lease.live);
      if (live.length >= this.maxLive && live.every((lease) => lease.visible)) return;
      waiting.sort((a, b) => b._lastUsed - a._lastUsed)[0]._acquire();  // leaves 'parked': the loop ends
    }
  }

  // Parks live books (the policy's choice first) until `newcomer` fits within maxLive.
  _makeRoom(newcomer) {
    const others = [...this._leases].filter((lease) => lease !== newcomer && lease.live);
    while (others.length >= this.maxLive) {
      const index = chooseContextToRelease(others.map((lease) => lease._ranking()));
      const [victim] = others.splice(index, 1);
      victim._park();
    }
  }
}

const BUDGET_KEY = Symbol.for('conecurl.contextBudget');

/** The page's budget, shared by every copy of this module loaded on the page. */
export function contextBudget() {
  globalThis[BUDGET_KEY] ??= new ContextBudget();
  return globalThis[BUDGET_KEY];
}

/**
 * One book's claim on a context. States: 'new' (no context yet), 'live' (has one, or lost one by
 * accident and the browser restores it), 'parked' (handed back; the book keeps its state and its
 * clock runs, drawing nothing), 'restoring' (asked back, waiting for webglcontextrestored).
 * While parked the canvas shows a snapshot of its last frame as a CSS background.
 */
export class ContextLease {
  constructor(budget, canvas) {
    this._budget = budget;
    this.canvas = canvas;
    this.state = 'new';
    this.view = null;             // the BookView drawing on the canvas now
    this._visible = true;         // until the observer says otherwise, a new book is taken to be in view
    this._visibilityReported = false;
    this._lastUsed = budget._tick();
    this._lostEventSeen = false;  // a restore is allowed only after the lost event was dispatched
    this._restoreTimer = 0;
    this._restoreCalled = false;
    this._parkedAt = null;        // position and motion when parked: a change asks for the context back
    this._snapshotUrl = null;
    this._snapshotHolder = null;  // the element whose background shows the snapshot
    this._gl = null;
    this._loseContext = null;  // WEBGL_lose_context of the canvas's context
    this._onLost = () => {
      this._lostEventSeen = true;
      // After BookView's own handler (context-keeper.js, which stops its frames) has run, whatever the listener order.
      setTimeout(() => this._afterLost());
    };
    this._onRestored = () => {
      this._lostEventSeen = false;
      this._restoreCalled = false;
      if (this.state === 'restoring') {
        this.state = 'live';
        requestAnimationFrame(() => this._showLiveFrame());
      } else if (this.state === 'parked') {
        setTimeout(() => this._reparkAfterRestore());  // restored by someone else while parked
      }
    };
    canvas.addEventListener('webglcontextlost', this._onLost);
    canvas.addEventListener('webglcontextrestored', this._onRestored);
    this._observer = typeof IntersectionObserver === 'function'
      ? new IntersectionObserver((entries) => this._onVisibility(entries[entries.length - 1].isIntersecting),
        { rootMargin: VISIBLE_MARGIN })
      : null;
    this._observer?.observe(canvas);
  }

  /** Holds a context or is getting one back (what the budget counts). */
  get live() { return this.state === 'live' || this.state === 'restoring'; }
  get visible() { return this._visible; }

  /** Makes room in the budget before the book's first context is made on the canvas. */
  admit() {
    if (this.state === 'parked' || this.state === 'restoring') {
      throw new Error('conecurl: a renderer cannot be made while the canvas has handed its context back');
    }
    this._lastUsed = this._budget._tick();
    this._budget._makeRoom(this);
    this.state = 'live';
  }

  /** The BookView now drawing on the canvas (a new one after a display switch). */
  attach(view) {
    this.view = view;
    view.contextLease = this;
    if (!this._gl) {
      this._gl = this.canvas.getContext('webgl2');  // the renderer's context: made already
      // Kept: a lost context gives out no extensions, and this one must restore it.
      this._loseContext = this._gl?.getExtension('WEBGL_lose_context') ?? null;
    }
  }

  /**
   * BookView asks to draw. A live book counts as used; a parked one in view takes a context back when
   * its picture changed (a turn, a drag, a jump), not merely because a page image arrived.
   */
  demand() {
    if (this.state === 'live') {
      this._lastUsed = this._budget._tick();
      return;
    }
    if (this.state !== 'parked' || !this._visible || !this.view) return;
    const { position, animating } = this._parkedAt ?? {};
    if (this.view.animating || animating || this.view.position !== position) this._acquire();
  }

  /** Stops taking part and frees the context now (the canvas is going away). */
  dispose() {
    if (this.state === 'disposed') return;
    this.state = 'disposed';
    clearTimeout(this._restoreTimer);
    this._observer?.disconnect();
    this.canvas.removeEventListener('webglcontextlost', this._onLost);
    this.canvas.removeEventListener('webglcontextrestored', this._onRestored);
    this._budget._forget(this);
    this._clearSnapshot();
    if (this.view) this.view.contextLease = null;
    this.view = null;
    // A canvas's context otherwise lives until the canvas is garbage collected, and counts until then.
    if (this._gl && !this._gl.isContextLost()) this._loseContext?.loseContext();
    this._budget._rebalance();  // the context freed may go to a book in view without one
  }

  _ranking() {
    return { visible: this._visible, busy: Boolean(this.view?.animating), lastUsed: this._lastUsed };
  }

  _onVisibility(visible) {
    if (this.state === 'disposed') return;
    if (visible !== this._visible) this._lastUsed = this._budget._tick();  // out of view: from now; in view: used now
    this._visible = visible;
    this._visibilityReported = true;
    if (visible && this.state === 'parked') this._acquire();
    this._budget._rebalance();
  }

  // Hands the context back: the last frame becomes the canvas's background, then WEBGL_lose_context.
  _park() {
    if (this.state === 'restoring' && !this._restoreCalled) {
      clearTimeout(this._restoreTimer);  // asked back but not yet restored: simply stay parked
      this.state = 'parked';
      return;
    }
    if (this.state === 'restoring') {  // restoreContext() is under way: park again once it lands
      this.state = 'parked';
      return;
    }
    if (this.state !== 'live') return;
    this.state = 'parked';
    const view = this.view;
    this._parkedAt = view ? { position: view.position, animating: view.animating } : null;
    if (this._gl && !this._gl.isContextLost()) {
      this._snapshot();
      this._loseContext?.loseContext();
    }
    // Chrome paints a canvas without its context as a broken image: hide it (it still takes pointer
    // events and stays observed) and let the snapshot behind it show.
    this.canvas.style.opacity = '0';
  }

  _acquire() {
    if (this.state !== 'parked') return;
    this._lastUsed = this._budget._tick();
    this._budget._makeRoom(this);
    this.state = 'restoring';
    if (this._lostEventSeen) this._scheduleRestore();  // else the lost event, when it comes, restores
  }

  _scheduleRestore() {
    clearTimeout(this._restoreTimer);
    // Chrome refuses a restore from the task that dispatched the lost event.
    this._restoreTimer = setTimeout(() => {
      if (this.state !== 'restoring' || !this._gl?.isContextLost()) return;
      this._restoreCalled = true;
      this._loseContext?.restoreContext();
    });
  }

  _afterLost() {
    if (this.state === 'restoring' && !this._restoreCalled) {
      this._scheduleRestore();
    } else if (this.state === 'parked' && this.view?.animating) {
      this.view.requestRender();  // a parked book's turns go on landing (drawing nothing) and resolve
    }
  }

  _reparkAfterRestore() {
    if (this.state !== 'parked' || !this._gl || this._gl.isContextLost()) return;
    this.state = 'live';
    this._park();
  }

  // Draws the current frame and keeps it as the background of the canvas's box (the book's element)
  // while the canvas has no context.
  _snapshot() {
    const view = this.view;
    if (!view?.renderer || typeof this.canvas.toBlob !== 'function') return;
    try {
      view.drawNow();
    } catch {
      return;  // nothing fit to show: the canvas stays blank while parked
    }
    // toBlob copies the drawing buffer now, in this task, and encodes it later.
    this.canvas.toBlob((blob) => {
      if (!blob || this.state !== 'parked') return;
      if (this._snapshotUrl) URL.revokeObjectURL(this._snapshotUrl);
      this._snapshotUrl = URL.createObjectURL(blob);
      this._snapshotHolder = this.canvas.parentElement;
      const style = this._snapshotHolder?.style;
      if (!style) return;
      style.backgroundImage = `url("${this._snapshotUrl}")`;
      style.backgroundSize = '100% 100%';
      style.backgroundRepeat = 'no-repeat';
    });
  }

  /** Whether the book shows a snapshot of its last frame instead of its canvas (tests). */
  get showingSnapshot() { return this._snapshotUrl !== null; }

  _showLiveFrame() {
    if (this.state !== 'live') return;
    if (this.view?.renderer) this.view.drawNow();  // same task as showing the canvas again: no blank frame
    this._clearSnapshot();
  }

  _clearSnapshot() {
    this.canvas.style.opacity = '';
    if (!this._snapshotUrl) return;
    URL.revokeObjectURL(this._snapshotUrl);
    this._snapshotUrl = null;
    if (this._snapshotHolder) {
      const style = this._snapshotHolder.style;
      style.backgroundImage = style.backgroundSize = style.backgroundRepeat = '';
    }
    this._snapshotHolder = null;
  }
}
