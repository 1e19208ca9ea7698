// Turning by pointer without dragging: a click or tap on the book's outer thirds turns it (the third on
// the next page's side forward), one on its middle third turns nothing and says `middletap`; a swipe
// along the turn turns it. Clicks and taps come in series: a series of exactly two is a double-click or
// double tap, which zooms (zoom-input.js), so a first one waits a moment before it acts.
import { thirdOf } from '../engine/direction.js';
import { listenForTapsAndSwipes, swipeDirection } from './tap-swipe.js';

const CLICK_SERIES_MS = 300;  // clicks or taps this close together are one series (a double, or rapid turning)
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
  let series = null;  // { taps: [{ zone, x, y, turns }], count, turning, done, timer } of the present series

  const tapAt = (clientX, clientY) => {
    const box = canvas.getBoundingClientRect();
    return {
      zone: zoneAt(book.restingRect(), clientX - box.left, clientY - box.top, book.direction),
      x: clientX,
      y: clientY,
      turns: book.turnsFrom(clientX, clientY),  // the `turnArea` option limits turning (not middletap)
    };
  };
  // What a tap does once its series is known: an outer third turns (where turnArea lets it); the middle
  // third of a tap alone in its series says `middletap`. Zoomed in, a tap does nothing (a press pans).
  const act = ({ zone, x, y, turns }, alone) => {
    if (!zone || book.zoomed()) return;
    if (zone === 'middle') {
      if (alone) book.middleTapped(x, y);
    } else if (turns) {
      book.turn(zone);
    }
  };
  // Acts on the taps a series held back; `keepGoing`: the series stays open for more rapid taps.
  const flush = (held, keepGoing) => {
    const alone = held.count === 1 && !keepGoing;
    for (const tap of held.taps.splice(0)) act(tap, alone);
    held.turning = keepGoing;
    if (!keepGoing) held.done = true;
  };
  const open = () => Boolean(series && !series.done);
  // A third click makes rapid turning: the clicks held back turn at once, and so does every further one.
  const onTap = (tap, kind) => {
    if (kind !== 'click' && open() && Math.hypot(tap.x - series.last.x, tap.y - series.last.y) > DOUBLE_TAP_SLOP) {
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
    const next = { taps: [tap], count: 1, last: tap, turning: false, done: false, timer: 0 };
    next.timer = setTimeout(() => flush(next, false), CLICK_SERIES_MS);
    series = next;
  };

  const stop = listenForTapsAndSwipes(canvas, {
    // A stroke that dragged a page is not also a tap or a swipe.
    tap: (x, y, kind) => {
      if (!book.strokeWasDrag()) onTap(tapAt(x, y), kind);
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
