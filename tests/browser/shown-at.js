// What a book shows where, read from its own pixels in the page: shared by the Chromium tests and the
// Firefox and WebKit journeys (tests/engines/), so that every engine is held to the same reading.

/**
 * In the page (pass it to page.evaluate / browser.evaluate): what window.book shows at `points` given as
 * fractions of its resting pages' rectangle: a page index (by its colour, pageAtColor of the fixture's
 * test-pages.js), 'paper' (the placeholder, or a blank back), 'none' (no page there) or 'other(r,g,b)'.
 * Works for the WebGL book (drawn and read in one task) and for the static fallback's 2D canvas.
 */
export function shownAtInPage(points) {
  const book = window.book;
  let pixels;
  let canvas;
  if (book.surface?.kind === 'webgl') {
    book.surface.drawNow();
    pixels = book.surface.readPixels();
    canvas = book.surface.canvas;
  } else {
    canvas = book.element.querySelector('canvas');
    pixels = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height);
  }
  const rect = book.restingRect();
  const ratio = pixels.width / canvas.clientWidth;
  return points.map(([fx, fy]) => {
    const x = Math.round((rect.x + fx * rect.width) * ratio);
    const y = Math.round((rect.y + fy * rect.height) * ratio);
    const i = (y * pixels.width + x) * 4;
    const [r, g, b, a] = Array.from(pixels.data.slice(i, i + 4));
    if (a < 16) return 'none';
    const index = window.pageAtColor([r, g, b], 12);  // the 12 distinct page hues
    if (index >= 0) return index;
    return Math.min(r, g, b) > 200 && Math.max(r, g, b) - Math.min(r, g, b) < 25 ? 'paper' : `other(${r},${g},${b})`;
  });
}
