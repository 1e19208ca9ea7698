// Wires a book's input modules to its controller: keys, clicks and taps and swipes, zoom gestures, and
// corner dragging where the surface has leaves to hold. Each module asks for what it wants through one
// small port, the same for either surface; none of them reaches into the controller.
import { listenForKeys } from './input-keys.js';
import { listenForTaps } from './input-taps.js';
import { doubleTapScale, listenForZoom } from './zoom-input.js';
import { PointerDrag } from './pointer-drag.js';

/**
 * @param {{ canvas: HTMLCanvasElement, element: HTMLElement, surface: object, direction: string }} where
 * @param {{ zoom: () => number, zoomed: () => boolean, zoomAbout: (scale: number, x: number, y: number) => void,
 *           zoomAboutCentre: (scale: number) => void, panBy: (dx: number, dy: number) => void,
 *           turn: (direction: string) => void, jump: (end: 'first'|'last') => void,
 *           turnsFrom: (clientX: number, clientY: number) => boolean,
 *           dragStarted: (direction: string) => void, dragEnded: (completed: boolean) => void,
 *           hintStarted: () => void, hintEnded: () => void,
 *           middleTapped: (clientX: number, clientY: number) => void }} book  what the controller lets input do
 * @returns {{ stop: () => void, readonly pendingClick: boolean, clickWaitMs: number }}
 */
export function attachInput({ canvas, element, surface, direction }, book) {
  // First: a press on a corner is a drag, not a tap. Only the engine can solve a held leaf's pose.
  const drag = surface.kind === 'webgl' ? new PointerDrag(surface, {
    enabled: () => !book.zoomed(),
    pressAllowed: book.turnsFrom,
    onTurnStart: book.dragStarted,
    onTurnEnd: book.dragEnded,
    onHintStart: book.hintStarted,
    onHintEnd: book.hintEnded,
  }) : null;
  const port = {
    direction,
    get zoom() { return book.zoom(); },
    zoomed: book.zoomed,
    zoomAboutCentre: book.zoomAboutCentre,
    turn: book.turn,
    jump: book.jump,
    queuedTurns: () => surface.queuedTurns,
    restingRect: () => surface.restingRect(),
    strokeWasDrag: () => Boolean(drag?.strokeWasDrag),
    turnsFrom: book.turnsFrom,
    middleTapped: book.middleTapped,
    // A touch double tap zooms in about the point, or back out, as a double-click does.
    doubleTapped: (x, y) => book.zoomAbout(doubleTapScale(book.zoom()), x, y),
  };
  const taps = listenForTaps(canvas, port);
  const stopZoom = listenForZoom(canvas, {
    scale: book.zoom,
    zoomAbout: book.zoomAbout,
    doubleClicked: () => taps.doubleClicked(),
    panBy: book.panBy,
  });
  const stopKeys = listenForKeys(element, port);
  return {
    stop() {
      drag?.destroy();
      stopZoom();
      taps.stop();
      stopKeys();
    },
    get pendingClick() { return taps.pending; },
    clickWaitMs: taps.waitMs,
  };
}
