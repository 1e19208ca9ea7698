// A page of fine strokes reduced below its size, read back from the book's own pixels: shared by the
// Chromium test (with a sampling browser stood in) and the Firefox and WebKit journeys (tests/engines/).

/**
 * In the page (pass it to page.evaluate / browser.evaluate, in the flipbook fixture): opens window.book on
 * two pages of 1-px black columns every `period` px on white, `width` x `height`, one a PNG Blob (decoded
 * at the size drawn) and one a canvas (scaled on a canvas). Resolves with
 * - `shown`: each open page's red across a row at its middle, { page, min, max, mean, faintest } (faintest:
 *   the lightest of the darkest pixels of each stroke's span), once the book rests with its mipmaps;
 * - `uploads`: the faintest stroke of each striped page's image as it was handed to WebGL;
 * - `anisotropy`: what the renderer's probe left its page textures (1: none).
 * Reduced 4x and more, a filtered pass shows 4-px strokes an even grey (a quarter black: about 191);
 * reduced 1.8x, every stroke still shows. A pass of one sample a pixel stripes the first and drops strokes
 * of the second.
 */
export async function fineStrokesInPage({ width = 1600, height = 2000, period = 4 } = {}) {
  const canvas = Object.assign(document.createElement('canvas'), { width, height });
  const g = canvas.getContext('2d');
  g.fillStyle = '#fff';
  g.fillRect(0, 0, width, height);
  g.fillStyle = '#000';
  for (let x = 1; x < width; x += period) g.fillRect(x, 0, 1, height);
  const blob = await new Promise((resolve) => canvas.toBlob(resolve, 'image/png'));
  // The faintest stroke of `reds`, a row that holds `across` source pixels.
  const faintestOf = (reds, across) => {
    const span = period * reds.length / across;
    let faintest = 0;
    for (let start = 0; start + span <= reds.length; start += span) {
      let darkest = 255;
      for (let x = Math.floor(start); x < Math.ceil(start + span); x++) darkest = Math.min(darkest, reds[x]);
      faintest = Math.max(faintest, darkest);
    }
    return faintest;
  };
  // Each striped page's image read as it is uploaded (grey, where the numbered pages are coloured).
  const uploads = [];
  const texImage2D = WebGL2RenderingContext.prototype.texImage2D;
  WebGL2RenderingContext.prototype.texImage2D = function readUpload(...args) {
    const source = args[args.length - 1];
    if (source && typeof source === 'object' && !ArrayBuffer.isView(source) && source.width > 2) {
      const copy = Object.assign(document.createElement('canvas'), { width: source.width, height: source.height }).getContext('2d');
      copy.drawImage(source, 0, 0);
      const row = copy.getImageData(0, Math.floor(source.height / 2), source.width, 1).data;
      const reds = Array.from({ length: source.width }, (_, x) => row[x * 4]);
      if (reds.every((r, x) => Math.abs(r - row[x * 4 + 2]) < 8)) uploads.push(faintestOf(reds, width));
    }
    return texImage2D.apply(this, args);
  };
  const pages = [window.makeNumberedPage(0), blob, canvas, window.makeNumberedPage(3)];
  try {
    await window.openBook({ pages, display: 'double', startPage: 1, lighting: false, shadows: false, gutter: false });
  } finally {
    WebGL2RenderingContext.prototype.texImage2D = texImage2D;
  }
  const book = window.book;
  // The page as a reader sees it once the book rests: the mipmaps idle time makes after the first view, made now,
  // and the turn's programs idle time readies, with the probe of anisotropic filtering (a poll: the driver may
  // still compile them, or a frame be coming).
  book.surface.renderer.finishFirstView();
  while (!book.surface.prepareTurn()) await new Promise((resolve) => setTimeout(resolve, 10));
  book.surface.drawNow();
  const pixels = book.surface.readPixels();
  const ratio = pixels.width / book.surface.canvas.clientWidth;
  const shown = book.openPagePlaces().map((place) => {
    const y = Math.round((place.y + place.height / 2) * ratio);  // readPixels rows run top to bottom
    const onPage = [];
    for (let x = Math.round(place.x * ratio); x < (place.x + place.width) * ratio; x++) onPage.push(pixels.data[(y * pixels.width + x) * 4]);
    const reds = onPage.slice(Math.round(0.2 * onPage.length), Math.round(0.8 * onPage.length));
    return {
      page: place.page, min: Math.min(...reds), max: Math.max(...reds),
      mean: Math.round(reds.reduce((a, b) => a + b, 0) / reds.length), faintest: faintestOf(reds, 0.6 * width),
    };
  });
  return { shown, uploads, anisotropy: book.surface.renderer.anisotropy() };
}

/** Strokes every 8 px on a page 680 px wide: in the fixture its texture is 370 wide, a 1.8x reduction. */
export const COARSE_STROKES = { width: 680, height: 850, period: 8 };
/** The faintest stroke of COARSE_STROKES, reduced by halves, reads 213 here; one sample a pixel drops one to 237. */
export const FAINTEST_STROKE = 222;
