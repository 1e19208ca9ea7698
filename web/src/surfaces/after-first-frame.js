// What a book does once its first frame has reached the screen, not before: the browser presents a frame
// only after the task that drew it, so work started in that task (fetches, decodes, links) would hold it back.
// Each call returns its cancel: a book destroyed meanwhile is let go at once, not held until its tasks run.
const FRAMES = 2;         // the frame drawn is presented by the next animation frame; the second runs after it
const LATEST_MS = 250;    // a hidden tab runs no animation frames: the task runs after this at the latest
const IDLE_LATEST_MS = 1000;

/** Calls `task` once, after the next FRAMES animation frames (or LATEST_MS, whichever comes first). Returns its cancel. */
export function afterFirstFrame(task) {
  let frame = 0;
  const run = () => {
    cancel();
    task();
  };
  const timer = setTimeout(run, LATEST_MS);
  const cancel = () => {
    clearTimeout(timer);
    if (frame) cancelAnimationFrame(frame);
  };
  if (typeof requestAnimationFrame !== 'function') return cancel;
  let frames = 0;
  const step = () => {
    frame = 0;
    if (++frames < FRAMES) frame = requestAnimationFrame(step);
    else run();
  };
  frame = requestAnimationFrame(step);
  return cancel;
}

/** Calls `task` when the page is next idle (within IDLE_LATEST_MS), or soon where there is no requestIdleCallback. Returns its cancel. */
export function whenIdle(task) {
  if (typeof requestIdleCallback !== 'function') {
    const timer = setTimeout(task, 50);
    return () => clearTimeout(timer);
  }
  const id = requestIdleCallback(task, { timeout: IDLE_LATEST_MS });
  return () => cancelIdleCallback(id);
}

/** Calls `task` when the page is next idle after `ms` (a later look, not one each idle moment). Returns its cancel. */
export function whenIdleAfter(ms, task) {
  let cancel = null;
  const timer = setTimeout(() => { cancel = whenIdle(task); }, ms);
  return () => (cancel ? cancel() : clearTimeout(timer));
}

/**
 * Calls `task` once, after `count` animation frames have run, or at once when the page is or becomes hidden
 * (a hidden page runs none). Frames, not time: each one the browser renders is a chance to paint. Returns its cancel.
 */
export function afterFrames(count, task) {
  let frame = 0;
  let frames = 0;
  const cancel = () => {
    if (frame) cancelAnimationFrame(frame);
    frame = 0;
    document.removeEventListener('visibilitychange', onHidden);
  };
  const run = () => {
    cancel();
    task();
  };
  const onHidden = () => { if (document.visibilityState === 'hidden') run(); };
  if (typeof requestAnimationFrame !== 'function' || document.visibilityState === 'hidden') {
    task();
    return () => {};
  }
  const step = () => {
    frame = 0;
    if (++frames < count) frame = requestAnimationFrame(step);
    else run();
  };
  document.addEventListener('visibilitychange', onHidden);
  frame = requestAnimationFrame(step);
  return cancel;
}

/** Calls `task` when the page is next idle once the first frame is on screen (afterFirstFrame, then whenIdle). Returns its cancel. */
export function idleAfterFirstFrame(task) {
  let cancel = afterFirstFrame(() => { cancel = whenIdle(task); });
  return () => cancel();
}
