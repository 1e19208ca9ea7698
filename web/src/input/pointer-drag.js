// Corner and edge dragging on a BookView's canvas: pointer events in, held turns out. The engine
// finds what the pointer holds and solves the cone pose that keeps it under the pointer (C++); this
// file only turns DOM events into canvas pixels, tracks velocity, and eases the hover hint in.

const DRAG_THRESHOLD_CSS_PX = 4;   // below this a press is a click, not a drag
export const VELOCITY_WINDOW_MS = 100;    // pointer samples this recent set the release velocity

const HINT_MS = 160;                // the hover hint eases in over this long

/**
 * Adds the pointer's place at the event's time to `samples`, keeping those within VELOCITY_WINDOW_MS and
 * the newest one before it, so the samples always span the window: where moves come far apart (a slow
 * frame rate coalescing them, or WebKit's driver, 85 ms), the window would otherwise hold only the last
 * move and the release at the same place, and a fling would read as a stop.
 */
function keepSample(samples, event, p) {
  const now = event.timeStamp || performance.now();
  samples.push({ t: now, x: p.x, y: p.y });
  while (samples.length > 2 && now - samples[1].t >= VELOCITY_WINDOW_MS) samples.shift();
}

export class PointerDrag {
  /**
   * @param {import('../surfaces/book-view.js').BookView} view
   * @param {{ onTurnStart?: (direction: 'forward'|'backward') => void,
   *           onTurnEnd?: (completed: boolean) => Promise<void>|void,
   *           onHintStart?: () => void, (a corner lifts as the mouse hovers it)
   *           onHintEnd?: () => void,   (a corner lifted by hovering fell back)
   *           enabled?: () => boolean,
   *           pressAllowed?: (clientX: number, clientY: number) => boolean }} [hooks]  (the turnArea option)
   */
  constructor(view, hooks = {}) {
    this.view = view;
    this.canvas = view.canvas;
    this._hooks = hooks;
    this._press = null;      // { id, grip, startX, startY } while a button is down on a leaf
    this._drag = null;       // { id, grip, samples } while dragging
    this._hint = null;       // { grip, start, frame } while a corner is lifted by hovering
    this._swallowClick = false;
    this.strokeWasDrag = false;  // the present (or last) stroke dragged a page: it is no tap or swipe
    this._listeners = {
      pointerdown: (e) => this._onDown(e),
      pointermove: (e) => this._onMove(e),
      pointerup: (e) => this._onUp(e, false),
      pointercancel: (e) => this._onUp(e, true),
      pointerleave: (e) => { if (!this._drag && !this._press) this._endHint(); },
      click: (e) => {
        // The click that ends a drag is not a click on the page.
        if (this._swallowClick) { e.stopImmediatePropagation(); e.preventDefault(); }
        this._swallowClick = false;
      },
    };
    for (const [type, listener] of Object.entries(this._listeners)) {
      this.canvas.addEventListener(type, listener, type === 'click' ? { capture: true } : undefined);
    }
    // touch-action stays as the book shell set it (pan-y, or pan-x when vertical): a stroke across the
    // turning direction still scrolls the page; one along it reaches us.
  }

  /** Whether a pointer holds a leaf (a drag in progress). */
  get dragging() { return this._drag !== null; }

  destroy() {
    for (const [type, listener] of Object.entries(this._listeners)) {
      this.canvas.removeEventListener(type, listener, type === 'click' ? { capture: true } : undefined);
    }
    if (this._hint) cancelAnimationFrame(this._hint.frame);
    this._hint = null;
    this._drag = null;
    this._press = null;
  }

  _enabled() { return this.view.renderer && (this._hooks.enabled ? this._hooks.enabled() : true); }

  /** Drawing-buffer pixel of a pointer event, and the buffer size (the engine's camera works in these). */
  _pixel(event) { return this.view.bufferPixel(event.clientX, event.clientY); }

  _onDown(event) {
    if (!this._enabled() || !event.isPrimary || event.button !== 0 || this._drag) return;
    if (this._hooks.pressAllowed && !this._hooks.pressAllowed(event.clientX, event.clientY)) return;
    this.strokeWasDrag = false;
    const p = this._pixel(event);
    const grip = this._hint ? this._hint.grip : this.view.book.gripAt(p.x, p.y, p.width, p.height);
    if (!grip) return;
    this._press = { id: event.pointerId, grip, startX: event.clientX, startY: event.clientY };
  }

  _onMove(event) {
    if (!this._enabled()) return;
    if (this._drag && event.pointerId === this._drag.id) {
      this._follow(event);
      return;
    }
    if (this._press && event.pointerId === this._press.id) {
      const moved = Math.hypot(event.clientX - this._press.startX, event.clientY - this._press.startY);
      if (moved >= DRAG_THRESHOLD_CSS_PX) this._beginDrag(event);
      return;
    }
    if (event.pointerType === 'mouse' && event.buttons === 0) this._hover(event);
  }

  _beginDrag(event) {
    const { grip } = this._press;
    this._press = null;
    const book = this.view.book;
    const hinted = this._hint !== null;
    if (hinted) {
      cancelAnimationFrame(this._hint.frame);
      this._hint = null;  // the lifted leaf becomes the dragged one
    } else if (!book.startHeldTurn(grip)) {
      return;  // that leaf is still moving: the press stays a click
    }
    this._drag = { id: event.pointerId, grip, samples: [] };
    this.strokeWasDrag = true;
    try {
      this.canvas.setPointerCapture?.(event.pointerId);
    } catch {
      // No such active pointer (a synthetic event) or the canvas left the document: drag uncaptured.
    }
    this._hooks.onTurnStart?.(grip.backward ? 'backward' : 'forward');
    this._follow(event);
  }

  _follow(event) {
    // The held turn can end without the pointer (flip() jumping, a display rebuild): the drag ends
    // with it, and the pointer's later moves and release do nothing.
    if (!this.view.book.holding()) {
      this._drag = null;
      return;
    }
    const p = this._pixel(event);
    keepSample(this._drag.samples, event, p);
    this.view.book.dragHeldTurn(this._drag.grip, p.x, p.y, p.width, p.height);
    this.view.heldChanged();
  }

  _onUp(event, cancelled) {
    if (this._press && event.pointerId === this._press.id) {
      this._press = null;
      // A click on a corner lifted by hovering: the lifted leaf carries on into a full turn.
      if (this._hint && !cancelled) this._completeHint();
    }
    if (!this._drag || event.pointerId !== this._drag.id) return;
    const { grip, samples } = this._drag;
    this._drag = null;
    this._swallowClick = !cancelled;
    const p = this._pixel(event);
    // Where the pointer lifts, and when: a finger that stood still sends no moves, so without this
    // sample a drag that paused before lifting would be released at the speed it had before the pause.
    keepSample(samples, event, p);
    let vx = 0;
    let vy = 0;
    if (samples.length >= 2) {
      const first = samples[0];
      const last = samples[samples.length - 1];
      const seconds = Math.max(1e-3, (last.t - first.t) / 1000);
      vx = (last.x - first.x) / seconds;
      vy = (last.y - first.y) / seconds;
    }
    const book = this.view.book;
    const completed = cancelled ? (book.cancelHeldTurn(), false)
      : book.releaseHeldTurn(grip, p.x, p.y, vx, vy, p.width, p.height);
    const landed = this.view.settle();
    this.view.heldChanged();
    landed.then(() => this._hooks.onTurnEnd?.(completed));
  }

  _hover(event) {
    const book = this.view.book;
    const p = this._pixel(event);
    const grip = book.gripAt(p.x, p.y, p.width, p.height);
    const near = grip && grip.nearCorner;
    if (this._hint) {
      const same = near && grip.backward === this._hint.grip.backward && grip.flippedY === this._hint.grip.flippedY;
      if (!same) this._endHint();
      return;
    }
    if (!near || book.animating()) return;
    if (this._hooks.pressAllowed && !this._hooks.pressAllowed(event.clientX, event.clientY)) return;
    if (!book.startHeldTurn(grip)) return;
    this._hooks.onHintStart?.();
    const hint = { grip, start: performance.now(), frame: 0 };
    this._hint = hint;
    const step = (now) => {
      if (this._hint !== hint) return;
      book.hintHeldTurn(grip, Math.min(1, (now - hint.start) / HINT_MS));
      this.view.heldChanged();
      if (now - hint.start < HINT_MS) hint.frame = requestAnimationFrame(step);
    };
    hint.frame = requestAnimationFrame(step);
  }

  _completeHint() {
    cancelAnimationFrame(this._hint.frame);
    const { grip } = this._hint;
    this._hint = null;
    this.strokeWasDrag = true;   // this click is spent
    this._swallowClick = true;
    this._hooks.onTurnStart?.(grip.backward ? 'backward' : 'forward');
    this.view.book.completeHeldTurn();
    const landed = this.view.settle();
    this.view.heldChanged();
    landed.then(() => this._hooks.onTurnEnd?.(true));
  }

  _endHint() {
    if (!this._hint) return;
    cancelAnimationFrame(this._hint.frame);
    this._hint = null;
    if (this.view.book.holding()) this.view.book.cancelHeldTurn();  // it falls back flat
    this.view.heldChanged();
    this._hooks.onHintEnd?.();
  }
}
