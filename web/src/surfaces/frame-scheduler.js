// A BookView's frames: one requestAnimationFrame chain that runs only while something moves or changes,
// and the promises of the frame in which every leaf has landed. What a frame does is the view's.

export class FrameScheduler {
  /**
   * @param {{ runs: () => boolean, tick: (now: number) => number, ticked: () => void, pagesChanged: () => void }} view
   *   runs: whether a frame may run now; tick: the frame's one step of the engine, returning its flags;
   *   ticked: after the step, once `moving` says whether the leaves still move; pagesChanged: the pages
   *   on screen changed in that step
   * @param {{ moving: number, settled: number, pagesChanged: number }} flags  the engine's tick flags
   */
  constructor(view, flags) {
    this._view = view;
    this._flags = flags;
    this._frame = 0;       // the animation frame asked for, 0 for none
    this._moving = false;  // the last frame still moved
    this._moved = false;   // some frame has moved
    this._settled = [];    // called once every leaf has landed
    this._run = (now) => this._tick(now);
  }

  /** The last frame still moved: the next one comes anyway. */
  get moving() { return this._moving; }
  /** Some frame so far has moved (drawn a leaf in flight or held). */
  get moved() { return this._moved; }
  /** A frame is asked for and not yet drawn. */
  get pending() { return this._frame !== 0; }

  /** Asks for a frame, unless one is asked for already or none may run now. */
  request() {
    if (!this._frame && this._view.runs()) this._frame = requestAnimationFrame(this._run);
  }

  /** Drops the frame asked for (a lost context, destroy). */
  cancel() {
    cancelAnimationFrame(this._frame);
    this._frame = 0;
  }

  /** Resolves to `value` in the frame that lands every turn in flight (or at settleAll()). */
  whenSettled(value) {
    return new Promise((resolve) => this._settled.push(() => resolve(value)));
  }

  /** Resolves every whenSettled() now. */
  settleAll() {
    for (const resolve of this._settled.splice(0)) resolve();
  }

  // One animation frame: the view's step, then the next frame while leaves move.
  _tick(now) {
    this._frame = 0;
    if (!this._view.runs()) return;
    const flags = this._view.tick(now);
    this._moving = Boolean(flags & this._flags.moving);
    this._moved ||= this._moving;
    this._view.ticked();
    // One frame chain only: an upload or a resize in the step may have asked for the next frame already.
    if (this._moving && !this._frame) this._frame = requestAnimationFrame(this._run);
    if (flags & this._flags.pagesChanged) this._view.pagesChanged();
    if (flags & this._flags.settled) this.settleAll();
  }
}
