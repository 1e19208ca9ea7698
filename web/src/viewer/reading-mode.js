// Reading mode (a phone's Fullscreen, or "Read" where there is no Fullscreen API, as on iPhone Safari):
// the book's container fills the screen (fixed, 100dvw x 100dvh, above the host page), the toolbar
// becomes a bar over the page's foot that hides while reading and comes back with a tap in the middle
// of the page (the book's `middletap` event). Leaving (Escape, Exit, the browser leaving fullscreen)
// puts every style back as it was.

/** How long the bar stays up with nothing done on it, in ms. */
export const BAR_HIDES_AFTER_MS = 4000;

/** Whether the Fullscreen API can take `container` (false on iPhone Safari, or where it is off). */
export const canFullscreen = (container) => Boolean(container.ownerDocument.fullscreenEnabled)
  && typeof container.requestFullscreen === 'function';

const FILL = {
  position: 'fixed', top: '0', left: '0', right: 'auto', bottom: 'auto', width: '100dvw', height: '100dvh',
  maxWidth: 'none', maxHeight: 'none', minWidth: '0', minHeight: '0', margin: '0', padding: '0', border: '0',
  borderRadius: '0', aspectRatio: 'auto', transform: 'none', overflow: 'hidden', zIndex: '2147483000',
  background: 'var(--conecurl-reading-bg, #1f2023)', boxSizing: 'border-box',
};

/**
 * Reading mode for `book` in `container`. `viewer`: the viewer's element (it gets data-reading and
 * data-bar-hidden); `toolbar`: toolbar.js's object; `busy()`: a panel or the menu is open (the bar stays);
 * `changed()`: the mode changed (the caller lays the book out again).
 */
export function readingMode(book, { container, viewer, toolbar, busy, changed }) {
  let active = false;
  let viaFullscreen = false;
  let reachedFullscreen = false;
  let saved = null;
  let timer = 0;
  const doc = container.ownerDocument;

  const barHidden = () => viewer.hasAttribute('data-bar-hidden');
  function showBar() {
    if (!active) return;
    viewer.removeAttribute('data-bar-hidden');
    restartTimer();
  }
  function hideBar() {
    clearTimeout(timer);
    if (!active || busy()) return;
    if (viewer.contains(doc.activeElement)) book.element.focus({ preventScroll: true });
    viewer.setAttribute('data-bar-hidden', '');
  }
  function restartTimer() {
    clearTimeout(timer);
    timer = setTimeout(hideBar, BAR_HIDES_AFTER_MS);
  }

  const onMiddleTap = () => (barHidden() ? showBar() : hideBar());
  const onTurned = () => hideBar();
  const onUse = () => { if (!barHidden()) restartTimer(); };
  const onFocusIn = () => showBar();
  const onKey = (event) => {
    if (event.key === 'Escape' && !event.defaultPrevented) leave();
  };
  // The book's fullscreenchange: the browser leaving fullscreen (Escape, the host's exitFullscreen()) leaves reading mode.
  const onFullscreen = (event) => {
    if (event.detail.fullscreen) reachedFullscreen = true;
    else if (viaFullscreen && reachedFullscreen) leave();
  };

  // What reading mode listens to while it lasts: [target, type, listener].
  const listeners = [
    [book, 'middletap', onMiddleTap], [book, 'turned', onTurned], [book, 'fullscreenchange', onFullscreen],
    [viewer, 'pointerdown', onUse], [viewer, 'keydown', onUse],
    [viewer, 'focusin', onFocusIn], [doc, 'keydown', onKey],
  ];

  function enter() {
    if (active) return;
    active = true;
    const focusWasIn = viewer.contains(doc.activeElement);
    saved = { style: container.getAttribute('style'), rootOverflow: doc.documentElement.style.overflow };
    Object.assign(container.style, FILL);
    doc.documentElement.style.overflow = 'hidden';
    viewer.setAttribute('data-reading', '');
    toolbar.setReading(true);
    for (const [target, type, listener] of listeners) target.addEventListener(type, listener);
    viaFullscreen = canFullscreen(container);
    reachedFullscreen = false;
    if (viaFullscreen) {
      book.toggleFullscreen(true).then((now) => {
        if (now) reachedFullscreen = true;
        else if (active) leave();  // it left again before we heard it went
      }, () => { viaFullscreen = false; });
    }
    changed();
    showBar();
    if (focusWasIn) toolbar.buttons.exit.focus();
  }

  function leave() {
    if (!active) return;
    active = false;
    clearTimeout(timer);
    const focusWasIn = viewer.contains(doc.activeElement) || doc.activeElement === doc.body;
    for (const [target, type, listener] of listeners) target.removeEventListener(type, listener);
    if (saved.style === null) container.removeAttribute('style');
    else container.setAttribute('style', saved.style);
    doc.documentElement.style.overflow = saved.rootOverflow;
    viewer.removeAttribute('data-reading');
    viewer.removeAttribute('data-bar-hidden');
    toolbar.setReading(false);
    if (book.fullscreen) book.toggleFullscreen(false).catch(() => {});
    changed();
    if (focusWasIn) toolbar.focusTarget('fullscreen')?.focus();
  }

  return {
    enter,
    leave,
    toggle: () => (active ? leave() : enter()),
    active: () => active,
    /** The bar is hidden now (reading mode only). */
    barHidden,
    showBar,
    hideBar,
    remove: leave,
  };
}
