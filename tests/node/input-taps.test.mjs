// Node tests of how taps make series (input-taps.js): a double tap whose second tap is delivered after the
// series closed on the clock, though its own stamp says it came in time, still zooms when the first tap did
// nothing (zoomed in), and never where the first tap already acted. Pointer events on a plain EventTarget,
// the series' timer on node's mock clock: no DOM, no engine.
import { test, mock } from 'node:test';
import assert from 'node:assert/strict';
import { listenForTaps } from '../../web/src/input/input-taps.js';

const RECT = { x: 0, y: 0, width: 300, height: 400 };

/** A canvas over RECT and a book port that records what the taps asked of it. */
function tapTarget({ zoomed }) {
  const canvas = new EventTarget();
  canvas.getBoundingClientRect = () => ({ left: 0, top: 0, width: RECT.width, height: RECT.height });
  const heard = [];
  const book = {
    direction: 'ltr',
    restingRect: () => RECT,
    turnsFrom: () => true,
    zoomed: () => zoomed,
    strokeWasDrag: () => false,
    turn: (direction) => heard.push(`turn ${direction}`),
    middleTapped: () => heard.push('middletap'),
    doubleTapped: () => heard.push('doubletap'),
  };
  return { canvas, book, heard };
}

/** A touch tap at (x, y): its pointerdown stamped `downAt`, its pointerup 60 ms later (event.timeStamp). */
function tap(canvas, x, y, downAt) {
  const send = (type, timeStamp) => {
    const event = new Event(type);
    Object.defineProperties(event, {
      pointerType: { value: 'touch' }, pointerId: { value: 1 }, button: { value: 0 },
      clientX: { value: x }, clientY: { value: y }, timeStamp: { value: timeStamp },
    });
    canvas.dispatchEvent(event);
  };
  send('pointerdown', downAt);
  send('pointerup', downAt + 60);
}

test('node: zoomed in, a double tap whose second tap is delivered after the series closed on the clock, but stamped 150 ms after the first, zooms', () => {
  mock.timers.enable({ apis: ['setTimeout'] });
  try {
    const { canvas, book, heard } = tapTarget({ zoomed: true });
    const taps = listenForTaps(canvas, book);
    tap(canvas, 250, 200, 1000);
    mock.timers.tick(taps.waitMs + 500);  // the second tap's events wait in a busy browser's queue
    assert.equal(taps.pending, false);
    tap(canvas, 252, 201, 1210);  // down 150 ms after the first's lift
    assert.deepEqual(heard, ['doubletap']);
    // Its series is spent: a third tap in time by its stamp is a tap of its own (zoomed in, it does nothing).
    tap(canvas, 252, 201, 1400);
    mock.timers.tick(taps.waitMs);
    assert.deepEqual(heard, ['doubletap']);
    taps.stop();
  } finally {
    mock.timers.reset();
  }
});

test('node: a late tap is no double tap when its stamp is past the series\' time, lies elsewhere, or follows a tap that turned', () => {
  mock.timers.enable({ apis: ['setTimeout'] });
  try {
    // Zoomed in, stamped 400 ms after the first's lift: two taps, and zoomed in neither does anything.
    let { canvas, book, heard } = tapTarget({ zoomed: true });
    let taps = listenForTaps(canvas, book);
    tap(canvas, 250, 200, 1000);
    mock.timers.tick(taps.waitMs);
    tap(canvas, 250, 200, 1460);
    mock.timers.tick(taps.waitMs);
    assert.deepEqual(heard, []);
    // Zoomed in, in time by its stamp but 60 px away.
    tap(canvas, 250, 200, 3000);
    mock.timers.tick(taps.waitMs);
    tap(canvas, 190, 200, 3210);
    mock.timers.tick(taps.waitMs);
    assert.deepEqual(heard, []);
    taps.stop();
    // At 1x the first tap (the outer third) turned when its series closed: the late one is a tap of its own and turns too.
    ({ canvas, book, heard } = tapTarget({ zoomed: false }));
    taps = listenForTaps(canvas, book);
    tap(canvas, 250, 200, 1000);
    mock.timers.tick(taps.waitMs);
    tap(canvas, 250, 200, 1210);
    mock.timers.tick(taps.waitMs);
    assert.deepEqual(heard, ['turn forward', 'turn forward']);
    taps.stop();
  } finally {
    mock.timers.reset();
  }
});

test('node: two taps delivered in time make one double tap at 1x too (no turn), as before', () => {
  mock.timers.enable({ apis: ['setTimeout'] });
  try {
    const { canvas, book, heard } = tapTarget({ zoomed: false });
    const taps = listenForTaps(canvas, book);
    tap(canvas, 250, 200, 1000);
    mock.timers.tick(100);
    tap(canvas, 250, 200, 1210);
    mock.timers.tick(taps.waitMs * 2);
    assert.deepEqual(heard, ['doubletap']);
    taps.stop();
  } finally {
    mock.timers.reset();
  }
});
