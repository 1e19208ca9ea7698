// How sharp a frame with moving leaves is drawn (the `resolution` option): at a device pixel ratio of 3
// a canvas has 9 times the pixels of ratio 1, so while leaves move the renderer may draw fewer and
// scale them up. 'auto' lowers the scale when frames come late, keeps the lower scale only if frames
// then come sooner (where scaling up costs what the fewer pixels save, as on a software rasterizer,
// it goes back and waits before trying again), and raises it when they come on time; a resting book
// is always drawn whole (the renderer's movingScale applies to moving frames only).

/** Device pixels per CSS pixel that 'auto' goes down to while leaves move (never above the screen's). */
export const RESOLUTION_FLOOR = 1.5;
const FRAME_MS = 1000 / 60;           // what a frame may take on a 60 Hz screen
const LATE_MS = FRAME_MS * 1.25;      // an interval this long missed the screen's frame
const ON_TIME_MS = FRAME_MS * 1.1;
const LATE_FRAMES = 2;                // late in a row before lowering: a turn's first frame draws the resting spread
const ON_TIME_FRAMES = 45;            // on time in a row before raising a step: about 3/4 s of moving frames
const RAISE = 1.2;                    // a step up, in scale
const LOWEST_CUT = 0.5;               // one step down at most halves the scale
const TRIAL_FRAMES = 4;               // frames judged after a cut (the first one after it, which draws the spread again, is not)
const PAID = 0.9;                     // a cut is kept if those frames' median interval is at most this share of the late ones'
const HOLD_FRAMES = 300;              // moving frames without a cut after one that did not pay

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
    this._late = [];       // the intervals of the late frames in a row
    this._onTime = 0;      // on-time frames in a row
    this._trial = null;    // after a cut: { from: the scale before, baseline: the late median, intervals after it }
    this._hold = 0;        // moving frames left before another cut may be tried
  }

  get setting() { return this._setting; }
  set setting(value) {
    this._setting = value;
    this._onTime = this._hold = 0;
    this._late = [];
    this._trial = null;
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
    if (this._hold > 0) this._hold--;
    if (this._trial) return this._judge(interval);
    if (interval > LATE_MS) {
      this._onTime = 0;
      this._late.push(interval);
      if (this._late.length < LATE_FRAMES) return this._scale;
      const late = this._late;
      this._late = [];
      if (this._hold > 0 || this._scale <= lowest) return this._scale;
      // Pixels cost in proportion: the scale that would have fit the frame (a late one: below 0.9).
      const cut = Math.max(LOWEST_CUT, Math.sqrt(FRAME_MS / interval));
      this._trial = { from: this._scale, baseline: median(late), intervals: [] };
      return Math.max(lowest, this._scale * cut);
    }
    this._late = [];
    if (interval > ON_TIME_MS || this._scale >= 1) return this._scale;
    if (++this._onTime < ON_TIME_FRAMES) return this._scale;
    this._onTime = 0;
    return Math.min(1, this._scale * RAISE);
  }

  // After a cut: keep it if frames came sooner, else go back to the scale before and hold off.
  _judge(interval) {
    const trial = this._trial;
    trial.intervals.push(interval);
    if (trial.intervals.length <= TRIAL_FRAMES) return this._scale;
    this._trial = null;
    if (median(trial.intervals.slice(1)) <= PAID * trial.baseline) return this._scale;
    this._hold = HOLD_FRAMES;
    return trial.from;
  }
}

function median(values) {
  const sorted = [...values].sort((a, b) => a - b);
  const middle = sorted.length >> 1;
  return sorted.length % 2 ? sorted[middle] : (sorted[middle - 1] + sorted[middle]) / 2;
}
