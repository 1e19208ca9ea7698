// Tells a book when its element's CSS size or the device pixel ratio changed (a ResizeObserver and a
// `resolution` media query), so that it lays out again; no layout is read per frame.

/**
 * Calls `onChange({ width, height })` when `element`'s CSS size changes from `initial`, or the pixel
 * ratio changes. Returns a function that stops watching.
 */
export function watchSize(element, initial, onChange) {
  let size = initial;
  let stopped = false;
  const measure = () => {
    const { width, height } = element.getBoundingClientRect();
    return { width, height };
  };
  const observer = typeof ResizeObserver === 'function' ? new ResizeObserver(() => {
    const now = measure();
    if (stopped || (now.width === size.width && now.height === size.height)) return;
    size = now;
    onChange(size);
  }) : null;
  observer?.observe(element);

  let stopRatio = () => {};
  const watchRatio = () => {
    if (typeof matchMedia !== 'function') return;
    const query = matchMedia(`(resolution: ${globalThis.devicePixelRatio || 1}dppx)`);
    const onRatio = () => {
      query.removeEventListener('change', onRatio);
      if (stopped) return;
      watchRatio();  // a new query for the new ratio
      onChange(size);
    };
    query.addEventListener('change', onRatio);
    stopRatio = () => query.removeEventListener('change', onRatio);
  };
  watchRatio();
  return () => {
    stopped = true;
    observer?.disconnect();
    stopRatio();
  };
}
