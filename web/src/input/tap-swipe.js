// Pointer input that turns pages without dragging: a mouse click or a touch/pen tap names a point,
// a touch/pen stroke is a swipe. One small place, so the corner-drag module can share it.
import { directionFacts } from '../engine/direction.js';

const TAP_SLOP = 10;          // CSS px a finger may wander and still tap
const TAP_MAX_MS = 500;
const SWIPE_MIN = 40;         // CSS px of travel that make a stroke a swipe, slow or fast
/** A click or dblclick this soon after a touch is the browser's compatibility echo of it, not a new press. */
export const CLICK_AFTER_TOUCH_MS = 800;
const SWIPE_DOMINANCE = 1.5;  // a swipe travels this much further along the turn than across it

/**
 * Which way a swipe of (dx, dy) CSS px turns a book of `direction`: 'forward', 'backward', or null
 * when it runs more across the turn than along it. The finger moves the way the page turns: toward
 * the spine side of the next page's place.
 */
export function swipeDirection(dx, dy, direction) {
  const { vertical, forwardSign } = directionFacts(direction);
  const along = vertical ? dy : dx;
  const across = vertical ? dx : dy;
  if (Math.abs(along) < SWIPE_DOMINANCE * Math.abs(across)) return null;
  return Math.sign(along) === forwardSign ? 'forward' : 'backward';
}

/**
 * Calls `tap(clientX, clientY, kind, time)` for a primary mouse click (kind 'click') or a touch/pen tap
 * ('touch', pen included) on `element` (`time`: the click's or the lift's own event stamp, ms), and
 * `swipe(dx, dy, x, y)` (CSS px, end minus start; where it started) for a touch/pen stroke of SWIPE_MIN or more. A second
 * finger cancels the stroke (pinch-zoom is not a swipe). Returns a function that stops listening.
 */
export function listenForTapsAndSwipes(element, { tap, swipe }) {
  let stroke = null;
  let lastTouchUp = -Infinity;

  const onPointerDown = (event) => {
    if (event.pointerType === 'mouse') return;
    if (stroke) {
      stroke.cancelled = true;
      return;
    }
    stroke = { id: event.pointerId, x: event.clientX, y: event.clientY, time: event.timeStamp, cancelled: false };
  };
  const onPointerUp = (event) => {
    if (!stroke || event.pointerId !== stroke.id) return;
    const { x, y, time, cancelled } = stroke;
    stroke = null;
    lastTouchUp = event.timeStamp;
    if (cancelled) return;
    const dx = event.clientX - x;
    const dy = event.clientY - y;
    const elapsed = event.timeStamp - time;
    if (Math.hypot(dx, dy) <= TAP_SLOP && elapsed <= TAP_MAX_MS) tap(x, y, 'touch', event.timeStamp);
    else if (Math.max(Math.abs(dx), Math.abs(dy)) >= SWIPE_MIN) swipe(dx, dy, x, y);
  };
  const onPointerCancel = (event) => {
    if (stroke && event.pointerId === stroke.id) stroke = null;
  };
  const onClick = (event) => {
    if (event.button !== 0) return;
    // Touch and pen taps were handled at pointerup; their click follows (Safari's without a pointerType).
    if (event.pointerType === 'touch' || event.pointerType === 'pen') return;
    if (event.timeStamp - lastTouchUp < CLICK_AFTER_TOUCH_MS) return;
    tap(event.clientX, event.clientY, 'click', event.timeStamp);
  };

  element.addEventListener('pointerdown', onPointerDown);
  element.addEventListener('pointerup', onPointerUp);
  element.addEventListener('pointercancel', onPointerCancel);
  element.addEventListener('click', onClick);
  return () => {
    element.removeEventListener('pointerdown', onPointerDown);
    element.removeEventListener('pointerup', onPointerUp);
    element.removeEventListener('pointercancel', onPointerCancel);
    element.removeEventListener('click', onClick);
  };
}
