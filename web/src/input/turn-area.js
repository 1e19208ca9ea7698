// Where a press may turn a page (the `turnArea` option): anywhere on it, a band along its free edge,
// its two free corners, or nowhere. One rule for presses on the canvas (input) and for the grips laid
// over an HTML page's live content that hand presses to the canvas (html-pages.js).
import { freeEdge } from '../engine/direction.js';

export const TURN_AREAS = ['page', 'edges', 'corners', 'none'];
const BAND = 0.15;       // the band's depth, as a fraction of the page across the turn
const MIN_BAND_PX = 24;  // ... and never less than a fingertip

function bandDepth(width, height, edge) {
  const across = edge === 'left' || edge === 'right' ? width : height;
  return Math.min(across / 2, Math.max(MIN_BAND_PX, BAND * across));
}

/**
 * Whether a press at (x, y) in the canvas's CSS px may turn a page: on the open page `places()` puts
 * there, within `turnArea` (places are only asked for when the area depends on them).
 */
export function turnsAt(turnArea, places, direction, x, y) {
  if (turnArea === 'page' || turnArea === 'none') return turnArea === 'page';
  const place = places().find((p) => x >= p.x && x <= p.x + p.width && y >= p.y && y <= p.y + p.height);
  return Boolean(place) && inTurnArea(turnArea, place, freeEdge(direction, place.turned), x, y);
}

/** Whether a point (in the units of `rect`) on an open page whose free edge is `edge` may start a turn. */
export function inTurnArea(turnArea, rect, edge, x, y) {
  if (turnArea === 'page') return true;
  if (turnArea === 'none') return false;
  const d = bandDepth(rect.width, rect.height, edge);
  const u = x - rect.x;
  const v = y - rect.y;
  const fromEdge = { left: u, right: rect.width - u, top: v, bottom: rect.height - v }[edge];
  if (fromEdge > d) return false;
  if (turnArea === 'edges') return true;
  const along = edge === 'left' || edge === 'right' ? [v, rect.height - v] : [u, rect.width - u];
  return Math.min(...along) <= d;
}

/**
 * The parts of a live page's content (width x height CSS px, from its top-left) where a press belongs
 * to the turn, not to the content: [{ x, y, width, height }]. Empty for 'page' (there presses pass by
 * CSS to the canvas wherever the content is not interactive) and for 'none'.
 */
export function turnGrips(turnArea, width, height, edge) {
  if (turnArea !== 'edges' && turnArea !== 'corners') return [];
  const d = bandDepth(width, height, edge);
  const strip = {
    left: { x: 0, y: 0, width: d, height }, right: { x: width - d, y: 0, width: d, height },
    top: { x: 0, y: 0, width, height: d }, bottom: { x: 0, y: height - d, width, height: d },
  }[edge];
  if (turnArea === 'edges') return [strip];
  const along = edge === 'left' || edge === 'right';
  return along
    ? [{ ...strip, height: d }, { ...strip, y: height - d, height: d }]
    : [{ ...strip, width: d }, { ...strip, x: width - d, width: d }];
}
