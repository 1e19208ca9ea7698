// The first turn's frame costs several times a later one's (a software rasterizer builds its routines for
// each new draw state on first use; a GPU driver may too): one posed turning frame is drawn at rest, in idle
// time, and the resting frame over it in the same task, so only the resting frame ever reaches the screen.
const POSE = 0.5;  // the leaf half over: its curl, its shadow and both resting stacks all drawn

/**
 * Draws `book` (the engine's Book) once mid-turn and once as it rests now, with `renderer`, after `fit()`
 * sized the canvas; the book is left exactly where it was. Returns the frames drawn (0 when the book is not
 * at rest: a leaf in flight or held, zoomed in, or no leaf to turn).
 */
export function warmTurn(book, renderer, fit) {
  if (book.animating() || book.zoom().scale !== 1) return 0;
  const position = book.position();
  if (!book.startTurn('forward') && !book.startTurn('backward')) return 0;
  fit();
  try {
    book.setLatestTurnProgress(POSE);
    renderer.draw(book);
  } finally {
    book.jumpTo(position);
    renderer.draw(book);
  }
  return 2;
}
