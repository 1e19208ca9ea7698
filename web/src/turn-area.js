// Where a press may turn a page (the `turnArea` option): anywhere on it, a band along its free edge,
// its two free corners, or nowhere. One rule for presses on the canvas (input) and for the part of an
// HTML page's live content that lets presses through to the canvas (html-pages.js).

export const TURN_AREAS = ['page', 'edges', 'corners', 'none'];
const BAND = 0.15;       // the band's depth, as a fraction of the page across the turn
const MIN_BAND_PX = 24;  // ... and never less than a fingertip

/** The free edge of an open page: 'left' | 'right' | 'top' | 'bottom'; `turned` for the turned side's page. */
export function freeEdge(direction, turned) {
  if (direction === 'vertical') return turned ? 'top' : 'bottom';
  const left = direction === 'rtl' ? !turned : turned;
  return left ? 'left' : 'right';
}

function bandDepth(width, height, edge) {
  const across = edge === 'left' || edge === 'right' ? width : height;
  return Math.min(across / 2, Math.max(MIN_BAND_PX, BAND * across));
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
 * The CSS clip-path of a live page's content (width x height CSS px) that leaves its turn area to the
 * canvas beneath, where presses turn; '' where the content keeps every press ('none') or where presses
 * pass by CSS instead ('page': only its interactive elements take them).
 */
export function liveClipPath(turnArea, width, height, edge) {
  if (turnArea !== 'edges' && turnArea !== 'corners') return '';
  const d = bandDepth(width, height, edge);
  if (turnArea === 'edges') {
    const inset = { top: [d, 0, 0, 0], right: [0, d, 0, 0], bottom: [0, 0, d, 0], left: [0, 0, 0, d] }[edge];
    return `inset(${inset.map((n) => `${n}px`).join(' ')})`;
  }
  // The page less a d x d square at each end of the free edge, as a polygon (x, y in px).
  const [w, h] = [width, height];
  const points = {
    right: [[0, 0], [w - d, 0], [w - d, d], [w, d], [w, h - d], [w - d, h - d], [w - d, h], [0, h]],
    left: [[d, 0], [w, 0], [w, h], [d, h], [d, h - d], [0, h - d], [0, d], [d, d]],
    bottom: [[0, 0], [w, 0], [w, h - d], [w - d, h - d], [w - d, h], [d, h], [d, h - d], [0, h - d]],
    top: [[d, 0], [w - d, 0], [w - d, d], [w, d], [w, h], [0, h], [0, d], [d, d]],
  }[edge];
  return `polygon(${points.map(([x, y]) => `${x}px ${y}px`).join(', ')})`;
}
