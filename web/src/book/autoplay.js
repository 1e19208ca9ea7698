// autoplay: the book turns on its own every `interval` ms, and waits while a reader is busy with it:
// while the pointer is over it, while it (or something in it) has focus, and while the tab is hidden.
// At the last page it stops, unless `loop` takes it back to the first. A reader's own turn restarts
// the wait. Default interval 4000 ms.
export const AUTOPLAY_INTERVAL_MS = 4000;

/** The `autoplay` option as { interval, loop }, or null when off (false or absent). */
export function autoplaySettings(option) {
  if (!option) return null;
  return { interval: option === true ? AUTOPLAY_INTERVAL_MS : option.interval ?? AUTOPLAY_INTERVAL_MS, loop: option.loop === true };
}

/**
 * Starts turning `book` (next(), flip(), page, pageCount, animating, turned events) laid in `root`;
 * returns the stop.
 */
export function startAutoplay(book, root, { interval, loop }) {
  let timer = 0;
  let stopped = false;
  const busy = { hover: false, focus: false };
  const hidden = () => typeof document !== 'undefined' && document.visibilityState === 'hidden';
  const paused = () => busy.hover || busy.focus || hidden();

  const schedule = () => {
    clearTimeout(timer);
    if (!stopped && !paused()) timer = setTimeout(turn, interval);
  };
  const turn = async () => {
    if (stopped || paused() || book.animating) return schedule();
    const turned = await book.next().catch(() => false);
    if (turned || stopped) return undefined;  // the turned event schedules the next one
    if (!loop) return stop();  // the end of the book
    await book.flip(0).catch(() => {});
    return undefined;
  };
  const on = (target, type, handler) => {
    target.addEventListener(type, handler);
    return () => target.removeEventListener(type, handler);
  };
  const set = (key, value) => () => {
    busy[key] = value;
    schedule();
  };
  const listeners = [
    on(root, 'pointerenter', set('hover', true)),
    on(root, 'pointerleave', set('hover', false)),
    on(root, 'focusin', set('focus', true)),
    on(root, 'focusout', (event) => { if (!root.contains(event.relatedTarget)) set('focus', false)(); }),
    on(document, 'visibilitychange', schedule),
    on(book, 'turned', schedule),
  ];
  function stop() {
    stopped = true;
    clearTimeout(timer);
    for (const remove of listeners) remove();
  }
  schedule();
  return stop;
}
