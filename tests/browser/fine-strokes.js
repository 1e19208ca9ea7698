// A page of fine strokes reduced far below its size, read back from the book's own pixels: shared by the
// Chromium test (with a sampling browser stood in) and the Firefox and WebKit journeys (tests/engines/).

/**
 * In the page (pass it to page.evaluate / browser.evaluate, in the flipbook fixture): opens window.book on
 * two pages of 1-px black columns every 4 px on white, 1600 x 2000, one a PNG Blob (decoded at the size
 * drawn) and one a canvas (scaled on a canvas), drawn about 300 px wide. A filtered reduction shows them
 * an even grey (a quarter black: about 191); one sampled once a pixel drops the strokes or stripes them.
 * Resolves with each open page's { page, min, max, mean } red across a row at its middle.
 */
export async function fineStrokesInPage() {
  const canvas = Object.assign(document.createElement('canvas'), { width: 1600, height: 2000 });
  const g = canvas.getContext('2d');
  g.fillStyle = '#fff';
  g.fillRect(0, 0, canvas.width, canvas.height);
  g.fillStyle = '#000';
  for (let x = 1; x < canvas.width; x += 4) g.fillRect(x, 0, 1, canvas.height);
  const blob = await new Promise((resolve) => canvas.toBlob(resolve, 'image/png'));
  const pages = [window.makeNumberedPage(0), blob, canvas, window.makeNumberedPage(3)];
  await window.openBook({ pages, display: 'double', startPage: 1, lighting: false, shadows: false, gutter: false });
  const book = window.book;
  book.surface.drawNow();
  const pixels = book.surface.readPixels();
  const ratio = pixels.width / book.surface.canvas.clientWidth;
  return book.openPagePlaces().map((place) => {
    const y = Math.round((place.y + place.height / 2) * ratio);  // readPixels rows run top to bottom
    const reds = [];
    for (let x = Math.round((place.x + 0.2 * place.width) * ratio); x < (place.x + 0.8 * place.width) * ratio; x++) {
      reds.push(pixels.data[(y * pixels.width + x) * 4]);
    }
    return { page: place.page, min: Math.min(...reds), max: Math.max(...reds), mean: Math.round(reds.reduce((a, b) => a + b, 0) / reds.length) };
  });
}
