// What a book does once its first frame has reached the screen, not before: the browser presents a frame
// only after the task that drew it, so work started in that task (fetches, decodes, links) would hold it back.
const FRAMES = 2;         // the frame drawn is presented by the next animation frame; the second runs after it
const LATEST_MS = 250;    // a hidden tab runs no animation frames: the task runs after this at the latest

/** Calls `task` once, after the next FRAMES animation frames (or LATEST_MS, whichever comes first). */
export function afterFirstFrame(task) {
  let done = false;
  const run = () => {
    if (done) return;
    done = true;
    task();
  };
  const timer = setTimeout(run, LATEST_MS);
  if (typeof requestAnimationFrame !== 'function') return;
  let frames = 0;
  const frame = () => {
    if (++frames < FRAMES) requestAnimationFrame(frame);
    else {
      clearTimeout(timer);
      run();
    }
  };
  requestAnimationFrame(frame);
}
