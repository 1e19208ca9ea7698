// How sharp a frame with moving leaves is drawn (the `resolution` option): at a device pixel ratio of 3
// a canvas has 9 times the pixels of ratio 1, so while leaves move the renderer may draw fewer and
// scale them up. 'auto' lowers the scale when frames come late and raises it when they come on time;
// a resting book is always drawn whole (the renderer's movingScale applies to moving frames only).

/** Device pixels per CSS pixel that 'auto' goes down to while leaves move (never above the screen's). */
export const RESOLUTION_FLOOR = 1.5;
const FRAME_MS = 1000 / 60;           // what a frame may take on a 60 Hz screen
const LATE_MS = FRAME_MS * 1.25;      // an interval this long missed the screen's frame
const ON_TIME_MS = FRAME_MS * 1.1;
const LATE_FRAMES = 2;                // late in a row before lowering: a turn's first frame draws the resting spread
const ON_TIME_FRAMES = 45;            // on time in a row before raising a step: about 3/4 s of moving frames
const RAISE = 1.2;                    // a step up, in scale
const LOWEST_CUT = 0.5;               // one step down at most halves the scale

/** The `resolution` option's values: 'auto', 'full', or device pixels per CSS pixel while leaves move. */
export function checkResolution(value) {
  return value === 'auto' || value === 'full' || (Number.isFinite(value) && value > 0)
    || "'auto', 'full' or a positive number of device pixels per CSS pixel";
}

export class MovingResolution {
  /** @param {'auto' | 'full' | number} setting */
  constructor(setting = 'auto') {
    this._setting = setting;
    this._scale = 1;       // the share of the drawing buffer's width and height a moving frame is drawn at
    this._last = null;     // the previous moving frame's time
    this._late = 0;        // late frames in a row
    this._onTime = 0;      // on-time frames in a row
  }

  get setting() { return this._setting; }
  set setting(value) {
    this._setting = value;
    this._late = this._onTime = 0;
  }

  /** The scale moving frames are drawn at now, in (0, 1]. */
  get scale() { return this._scale; }

  /**
   * Called at the start of each animation frame with its time, whether the frame before moved leaves,
   * and the device pixel ratio. Returns the scale to draw moving frames at when it changed, else null.
   */
  nextScale(now, moving, ratio) {
    const lowest = Math.min(1, RESOLUTION_FLOOR / ratio);
    const interval = moving && this._last !== null ? now - this._last : null;
    this._last = moving ? now : null;
    let next = this._scale;
    if (this._setting === 'full') next = 1;
    else if (this._setting !== 'auto') next = Math.min(1, this._setting / ratio);
    else if (lowest >= 1) next = 1;  // no pixels to spare: the floor is the screen's own ratio
    else if (interval !== null) next = this._adapt(interval, lowest);
    next = this._setting === 'auto' ? Math.max(lowest, next) : next;
    if (next === this._scale) return null;
    this._scale = next;
    return next;
  }

  // 'auto': one interval between two moving frames, judged against a 60 Hz screen.
  _adapt(interval, lowest) {
    if (interval > LATE_MS) {
      this._onTime = 0;
      if (++this._late < LATE_FRAMES) return this._scale;
      this._late = 0;
      // Pixels cost in proportion: the scale that would have fit the frame (a late one: below 0.9).
      const cut = Math.max(LOWEST_CUT, Math.sqrt(FRAME_MS / interval));
      return Math.max(lowest, this._scale * cut);
    }
    this._late = 0;
    if (interval > ON_TIME_MS || this._scale >= 1) return this._scale;
    if (++this._onTime < ON_TIME_FRAMES) return this._scale;
    this._onTime = 0;
    return Math.min(1, this._scale * RAISE);
  }
}
