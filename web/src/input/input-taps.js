// Turning by pointer without dragging: a click or tap on the book's outer thirds turns it (the third on
// the next page's side forward), one on its middle third turns nothing and says `middletap`; a swipe
// along the turn turns it. Clicks and taps come in series: a series of exactly two is a double-click or
// double tap, which zooms (zoom-input.js), so a first one waits a moment before it acts. A touch tap that
// comes after that moment, though its own stamp says it followed within it, still makes the double tap
// when the first did nothing (zoomed in): its events were delivered late, not tapped late.
import { thirdOf } from '../engine/direction.js';
import { listenForTapsAndSwipes, swipeDirection } from './tap-swipe.js';

/** Clicks or taps this close together are one series (a double, or rapid turning). */
export const CLICK_SERIES_MS = 300;
const DOUBLE_TAP_SLOP = 40;   // CSS px between a double tap's two taps (two taps farther apart are two taps)

/**
 * Which part of `rect` (CSS px of the canvas: the open page, or both pages of a spread) a point falls
 * on, in thirds along the turn: 'forward', 'backward' or 'middle' (direction.js thirdOf); null outside it.
 * In a spread the middle third is the band within a sixth of its width either side of the spine.
 */
export function zoneAt(rect, x, y, direction) {
  const px = x - rect.x;
  const py = y - rect.y;
  if (px < 0 || py < 0 || px > rect.width || py > rect.height) return null;
  return thirdOf(direction, rect.width, rect.height, px, py);
}

/**
 * Listens on `canvas`; `book` is the controller's input port (book/book-wiring.js, attachBookInput). Returns
 * { stop(), doubleClicked(), pending }: `doubleClicked` tells it the last two clicks were a
 * double-click (no turn); `pending` is true while a click or tap waits to see whether a second follows.
 * A touch or pen double tap is found here (book.doubleTapped zooms); a mouse double-click by its dblclick.
 */
export function listenForTaps(canvas, book) {
  // { taps: [{ zone, x, y, turns, time }], count, last, turning, done, idle, timer } of the present series;
  // idle: it closed having done nothing
  let series = null;

  const tapAt = (clientX, clientY, time) => {
    const box = canvas.getBoundingClientRect();
    return {
      zone: zoneAt(book.restingRect(), clientX - box.left, clientY - box.top, book.direction),
      x: clientX,
      y: clientY,
      turns: book.turnsFrom(clientX, clientY),  // the `turnArea` option limits turning (not middletap)
      time,
    };
  };
  // What a tap does once its series is known: an outer third turns (where turnArea lets it); the middle
  // third of a tap alone in its series says `middletap`. Zoomed in, a tap does nothing (a press pans).
  // Whether it did anything.
  const act = ({ zone, x, y, turns }, alone) => {
    if (!zone || book.zoomed()) return false;
    if (zone === 'middle') {
      if (alone) book.middleTapped(x, y);
      return alone;
    }
    if (turns) book.turn(zone);
    return turns;
  };
  // Acts on the taps a series held back; `keepGoing`: the series stays open for more rapid taps.
  const flush = (held, keepGoing) => {
    const alone = held.count === 1 && !keepGoing;
    let acted = false;
    for (const tap of held.taps.splice(0)) acted = act(tap, alone) || acted;
    held.turning = keepGoing;
    if (!keepGoing) {
      held.done = true;
      held.idle = !acted && held.count === 1;
    }
  };
  const open = () => Boolean(series && !series.done);
  const near = (tap, other) => Math.hypot(tap.x - other.x, tap.y - other.y) <= DOUBLE_TAP_SLOP;
  // A touch tap after a lone tap that did nothing, within the series' time by their own stamps: the double
  // tap whose second tap was delivered after the series had closed on the clock.
  const lateSecondTap = (tap, kind) => kind !== 'click' && series?.done && series.idle && near(tap, series.last)
    && tap.time - series.last.time <= CLICK_SERIES_MS;
  // A third click makes rapid turning: the clicks held back turn at once, and so does every further one.
  const onTap = (tap, kind) => {
    if (lateSecondTap(tap, kind)) {
      series.idle = false;
      book.doubleTapped(tap.x, tap.y);
      return;
    }
    if (kind !== 'click' && open() && !near(tap, series.last)) {
      clearTimeout(series.timer);
      flush(series, false);  // a tap somewhere else: the one before stands alone
    }
    if (open()) {
      clearTimeout(series.timer);
      series.count += 1;
      series.last = tap;
      if (kind !== 'click' && !series.turning && series.count === 2) {
        series.taps.length = 0;  // a double tap: it zooms, no turn, no middletap
        series.done = true;
        book.doubleTapped(tap.x, tap.y);
        return;
      }
      if (series.turning) {
        act(tap, false);
      } else {
        series.taps.push(tap);
        if (series.taps.length >= 3) flush(series, true);
      }
      const current = series;
      if (!current.done) current.timer = setTimeout(() => flush(current, false), CLICK_SERIES_MS);
      return;
    }
    const next = { taps: [tap], count: 1, last: tap, turning: false, done: false, idle: false, timer: 0 };
    next.timer = setTimeout(() => flush(next, false), CLICK_SERIES_MS);
    series = next;
  };

  const stop = listenForTapsAndSwipes(canvas, {
    // A stroke that dragged a page is not also a tap or a swipe.
    tap: (x, y, kind, time) => {
      if (!book.strokeWasDrag()) onTap(tapAt(x, y, time), kind);
    },
    swipe: (dx, dy, x, y) => {
      if (book.strokeWasDrag() || book.zoomed() || !book.turnsFrom(x, y)) return;
      const turn = swipeDirection(dx, dy, book.direction);
      if (turn) book.turn(turn);
    },
  });
  return {
    stop() {
      clearTimeout(series?.timer);
      stop();
    },
    doubleClicked() {
      if (series && !series.done && !series.turning && series.taps.length === 2) {
        clearTimeout(series.timer);
        series.taps.length = 0;  // the two clicks were a double-click: it zooms, no turn
        series.done = true;
      }
    },
    get pending() { return Boolean(series && !series.done); },
    waitMs: CLICK_SERIES_MS,
  };
}
