// Turning by pointer without dragging: a click or tap on a half of the book turns it (the half that
// holds the next page turns forward), a swipe along the turn turns it. Mouse clicks come in series: a
// series of exactly two is a double-click, which zooms (zoom-input.js), so a first click waits a moment.
import { directionFacts, halfOf as halfOfBox } from '../engine/direction.js';
import { listenForTapsAndSwipes, swipeDirection } from './tap-swipe.js';

const CLICK_SERIES_MS = 300;  // clicks this close together are one series (a double-click, or rapid turning)

/**
 * Which half of `rect` (CSS px of the canvas) a point falls on: 'left'/'right' (ltr, rtl) or
 * 'top'/'bottom' (vertical); null outside it.
 */
export function halfAt(rect, x, y, direction) {
  const px = x - rect.x;
  const py = y - rect.y;
  if (px < 0 || py < 0 || px > rect.width || py > rect.height) return null;
  return halfOfBox(direction, rect.width, rect.height, px, py);
}

/**
 * Listens on `canvas`; `book` is the controller's input port (book/book-wiring.js, attachBookInput). Returns
 * { stop(), doubleClicked(), pending }: `doubleClicked` tells it the last two clicks were a
 * double-click (no turn); `pending` is true while a click waits to see whether a second follows.
 */
export function listenForTaps(canvas, book) {
  let series = null;  // { halves, turning, done, timer } of the present click series

  const halfOf = (clientX, clientY) => {
    const box = canvas.getBoundingClientRect();
    return halfAt(book.restingRect(), clientX - box.left, clientY - box.top, book.direction);
  };
  const turnTo = (half) => {
    if (!half || book.zoomed()) return;  // zoomed in, a press pans: no turning
    book.turn(half === directionFacts(book.direction).forwardHalf ? 'forward' : 'backward');
  };
  // Turns the clicks a series held back; `keepGoing`: the series stays open for more rapid clicks.
  const flush = (held, keepGoing) => {
    for (const half of held.halves.splice(0)) turnTo(half);
    held.turning = keepGoing;
    if (!keepGoing) held.done = true;
  };
  // A third click makes rapid turning: the clicks held back turn at once, and so does every further one.
  const onMouseClick = (half) => {
    if (series && !series.done) {
      clearTimeout(series.timer);
      if (series.turning) {
        turnTo(half);
      } else {
        series.halves.push(half);
        if (series.halves.length >= 3) flush(series, true);
      }
      const current = series;
      if (!current.done) current.timer = setTimeout(() => flush(current, false), CLICK_SERIES_MS);
      return;
    }
    const next = { halves: [half], turning: false, done: false, timer: 0 };
    next.timer = setTimeout(() => flush(next, false), CLICK_SERIES_MS);
    series = next;
  };

  const stop = listenForTapsAndSwipes(canvas, {
    // A stroke that dragged a page is not also a tap or a swipe.
    tap: (x, y, kind) => {
      if (book.strokeWasDrag() || !book.turnsFrom(x, y)) return;
      if (kind === 'click') onMouseClick(halfOf(x, y));
      else turnTo(halfOf(x, y));
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
      if (series && !series.done && !series.turning && series.halves.length === 2) {
        clearTimeout(series.timer);
        series.halves.length = 0;  // the two clicks were a double-click: it zooms, no turn
        series.done = true;
      }
    },
    get pending() { return Boolean(series && !series.done); },
    waitMs: CLICK_SERIES_MS,
  };
}
