// Zoom and pan input for a book's canvas: Ctrl/⌘ + wheel (and trackpad pinch, which browsers send as
// Ctrl + wheel), two-finger pinch, double-click (a touch double tap is found by input-taps.js), and
// dragging to pan while zoomed. It only reads the DOM; what a zoom or a pan does is the book's
// (book/book-zoom.js, through its surface).
import { isZoomed } from '../engine/layout.js';
import { CLICK_AFTER_TOUCH_MS } from './tap-swipe.js';

const WHEEL_ZOOM_PER_PIXEL = 0.0025;  // zoom factor exp(-deltaY * this): a notch of 100 px is about 1.28x
const DOUBLE_CLICK_ZOOM = 2;

/** The scale a double-click or double tap asks for from `scale`: DOUBLE_CLICK_ZOOM, or back to 1 when zoomed. */
export const doubleTapScale = (scale) => (isZoomed(scale) ? 1 : DOUBLE_CLICK_ZOOM);

/**
 * @param {HTMLCanvasElement} canvas
 * @param {{ scale: () => number, zoomAbout: (scale: number, clientX: number, clientY: number) => void,
 *           panBy: (dxCss: number, dyCss: number) => void, doubleClicked?: () => void }} book
 * @returns {() => void} stops listening
 */
export function listenForZoom(canvas, book) {
  const touches = new Map();  // pointerId -> { x, y } for fingers down
  let pinch = null;           // { distance, scale } at the start of a two-finger pinch
  let pan = null;             // { id, x, y } while one pointer pans a zoomed view
  let lastTouch = -Infinity;  // timeStamp of the last touch or pen pointerup (its double taps are input-taps.js's)

  const onWheel = (event) => {
    if (!event.ctrlKey && !event.metaKey) return;  // a plain wheel scrolls the page as usual
    event.preventDefault();
    const lines = event.deltaMode === 1 ? 16 : event.deltaMode === 2 ? 400 : 1;
    book.zoomAbout(book.scale() * Math.exp(-event.deltaY * lines * WHEEL_ZOOM_PER_PIXEL), event.clientX, event.clientY);
  };
  const onDoubleClick = (event) => {
    event.preventDefault();
    // A double tap already zoomed (input-taps.js); the dblclick a browser may send after it must not undo it.
    if (event.sourceCapabilities?.firesTouchEvents || event.timeStamp - lastTouch < CLICK_AFTER_TOUCH_MS) return;
    book.doubleClicked?.();
    book.zoomAbout(doubleTapScale(book.scale()), event.clientX, event.clientY);
  };
  const onDown = (event) => {
    if (event.pointerType === 'touch') {
      touches.set(event.pointerId, { x: event.clientX, y: event.clientY });
      if (touches.size === 2) {
        const [a, b] = [...touches.values()];
        pinch = { distance: Math.max(1, Math.hypot(a.x - b.x, a.y - b.y)), scale: book.scale() };
        pan = null;
        return;
      }
    }
    if (isZoomed(book.scale()) && event.isPrimary && touches.size <= 1) {
      pan = { id: event.pointerId, x: event.clientX, y: event.clientY };
      canvas.setPointerCapture?.(event.pointerId);
    }
  };
  const onMove = (event) => {
    if (touches.has(event.pointerId)) touches.set(event.pointerId, { x: event.clientX, y: event.clientY });
    if (pinch && touches.size === 2) {
      const [a, b] = [...touches.values()];
      const distance = Math.max(1, Math.hypot(a.x - b.x, a.y - b.y));
      book.zoomAbout(pinch.scale * (distance / pinch.distance), (a.x + b.x) / 2, (a.y + b.y) / 2);
      return;
    }
    if (pan && event.pointerId === pan.id) {
      book.panBy(event.clientX - pan.x, event.clientY - pan.y);
      pan.x = event.clientX;
      pan.y = event.clientY;
    }
  };
  const onUp = (event) => {
    if (event.pointerType === 'touch' || event.pointerType === 'pen') lastTouch = event.timeStamp;
    touches.delete(event.pointerId);
    if (touches.size < 2) pinch = null;
    if (pan && event.pointerId === pan.id) pan = null;
  };
  const listeners = [
    ['wheel', onWheel, { passive: false }], ['dblclick', onDoubleClick], ['pointerdown', onDown],
    ['pointermove', onMove], ['pointerup', onUp], ['pointercancel', onUp],
  ];
  for (const [type, listener, options] of listeners) canvas.addEventListener(type, listener, options);
  return () => {
    for (const [type, listener, options] of listeners) canvas.removeEventListener(type, listener, options);
  };
}
