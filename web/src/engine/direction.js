// What depends on a book's reading direction ('ltr', 'rtl', 'vertical'), in one place: the side the
// engine binds its spine on, the axis it turns along, which half and which swipe turn it forward, its
// keys, the free edge of each open page, and where the open pages lie. Every other module asks here.
import { BINDING_LEFT, BINDING_RIGHT, BINDING_TOP } from '../../../dist/engine-constants.js';

export const DIRECTIONS = Object.freeze(['ltr', 'rtl', 'vertical']);

const FACTS = {
  // binding: the engine's spine side (cpp/core/book_constants.hpp); forwardHalf: the half of the book
  // whose press turns forward (the next page's); forwardSign: the sign of a swipe along the turn that
  // turns forward (the finger moves the way the page turns); turnedFirst: the turned side comes first
  // along the axis (left or top); touchAction: the browser keeps the scroll across the turn.
  ltr: { binding: BINDING_LEFT, vertical: false, forwardHalf: 'right', forwardSign: -1, turnedFirst: true,
    keys: { ArrowRight: 'forward', ArrowLeft: 'backward' }, touchAction: 'pan-y' },
  rtl: { binding: BINDING_RIGHT, vertical: false, forwardHalf: 'left', forwardSign: 1, turnedFirst: false,
    keys: { ArrowLeft: 'forward', ArrowRight: 'backward' }, touchAction: 'pan-y' },
  vertical: { binding: BINDING_TOP, vertical: true, forwardHalf: 'bottom', forwardSign: -1, turnedFirst: true,
    keys: { ArrowDown: 'forward', ArrowUp: 'backward' }, touchAction: 'pan-x' },
};

/**
 * The facts of one direction: { binding, vertical, forwardHalf, forwardSign, turnedFirst, keys,
 * touchAction }. A TypeError names a direction that is not one of DIRECTIONS.
 */
export function directionFacts(direction) {
  const facts = Object.hasOwn(FACTS, direction) ? FACTS[direction] : null;
  if (!facts) throw new TypeError(`conecurl: direction must be 'ltr', 'rtl' or 'vertical', got ${String(direction)}`);
  return facts;
}

/** The free edge of an open page: 'left' | 'right' | 'top' | 'bottom'; `turned` for the turned side's page. */
export function freeEdge(direction, turned) {
  const { vertical, turnedFirst } = directionFacts(direction);
  if (vertical) return turned ? 'top' : 'bottom';
  return turned === turnedFirst ? 'left' : 'right';
}

/**
 * Which third of a box, along the turn, a point at (px, py) from its corner falls on: 'forward' (the
 * third on the forward half's side: a single page's free edge), 'backward' (the other end: its spine),
 * or 'middle' (edges included).
 */
export function thirdOf(direction, width, height, px, py) {
  const { vertical, forwardHalf } = directionFacts(direction);
  const [at, span] = vertical ? [py, height] : [px, width];
  if (at >= span / 3 && at <= (2 * span) / 3) return 'middle';
  return halfOf(direction, width, height, px, py) === forwardHalf ? 'forward' : 'backward';
}

/** Which half of a box a point at (px, py) from its corner falls on, as forwardHalf names halves. */
export function halfOf(direction, width, height, px, py) {
  if (directionFacts(direction).vertical) return py < height / 2 ? 'top' : 'bottom';
  return px < width / 2 ? 'left' : 'right';
}
