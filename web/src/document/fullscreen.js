// Fullscreen (the Fullscreen API on the book's container, so a toolbar in it goes along). Loaded with the
// book, not on first use: a browser grants requestFullscreen() only within the press that asked for it, and
// a module fetched first could outlast that (a slow phone, a busy machine).

/** Whether `container` is the fullscreen element of its document (or shadow root). */
export function isFullscreen(container) {
  return (container.getRootNode().fullscreenElement ?? null) === container;
}

/**
 * Follows `container` in and out of fullscreen (by toggleFullscreen() or the browser: Escape), and
 * tells `changed(fullscreen)` each time it finds the container's state changed. It looks at the browser's
 * fullscreenchange events and when `look()` is called: Chrome changes the state at once (requestFullscreen()
 * resolves) but sends its event frames later, so a container that left before the event of its entry
 * came would be neither entered nor left by the events alone. Returns { look(), stop() }.
 */
export function followFullscreen(container, changed) {
  const doc = container.ownerDocument;
  let was = isFullscreen(container);
  const look = () => {
    const now = isFullscreen(container);
    if (now !== was) {
      was = now;
      changed(now);
    }
  };
  doc.addEventListener('fullscreenchange', look);
  return { look, stop: () => doc.removeEventListener('fullscreenchange', look) };
}

/** Enters (force true), leaves (false) or toggles fullscreen; resolves with whether the container is fullscreen. */
export async function toggleFullscreen(container, force) {
  if (force !== undefined && typeof force !== 'boolean') {
    throw new TypeError(`conecurl: toggleFullscreen() takes true, false or nothing; got ${String(force)}`);
  }
  const want = force ?? !isFullscreen(container);
  if (want && !isFullscreen(container)) {
    if (typeof container.requestFullscreen !== 'function') throw new Error('conecurl: this browser has no Fullscreen API');
    await container.requestFullscreen();
  } else if (!want && isFullscreen(container)) {
    await container.ownerDocument.exitFullscreen();
  }
  return isFullscreen(container);
}
