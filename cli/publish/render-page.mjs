// One page of the PDF into its published files: drawn once by pdf.js into an @napi-rs/canvas canvas at
// the largest size needed (the zoom image), then scaled down for the reading image, the thumbnail and
// (page 1) the link-preview cover: drawing is the cheap part, encoding the images the dear one. Every
// image keeps within its format's largest side and PIXEL_BUDGET, whatever the page's shape or size.
import fs from 'node:fs';
import path from 'node:path';
import { encodePageText, pagePath } from '../../web/src/document/format.js';
import { pdfPageLinks, pdfPageText } from '../../web/src/document/pdf-document.js';
import { FORMATS } from './args.mjs';
import { COLORS, ICON_SIDES, iconFile } from './web-app.mjs';

const COVER = 'cover.jpg';
/** The most pixels a side each format takes: WebP's 14-bit sizes, AVIF kept to WebP's 16384 (what decoders take for sure), JPEG's 16 bits. */
export const MAX_SIDE = { webp: 16383, avif: 16384, jpeg: 65500 };
/**
 * The most pixels in any one image of a page (and so in the one canvas a page is drawn into): 24
 * megapixels, 96 MB as RGBA while drawn, so a worker's page stays far under the publisher's 1 GB.
 */
export const PIXEL_BUDGET = 24_000_000;
/**
 * The most pixels all workers together hold in their canvases at once (64 megapixels, 256 MB as RGBA):
 * a worker waits for its page's share (render-worker.js), so large pages do not pile up with many jobs.
 */
export const POOL_PIXELS = 64_000_000;
/** A zoom image that would be less than this much larger than the reading one is left out. */
export const MIN_ZOOM = 1.1;
/** How much of a page's text the main thread gets back (alt text and the noscript copy need less). */
const TEXT_BACK = 1000;
// The first spread's placeholder (page 1: a book opens at its cover, alone in either display): a WebP this
// small (about 3 KB) goes inline in book.json as a data: URL, so the reader draws it with no request of its
// own while the reading image loads (docs/publish.md). Always WebP: every browser with WebGL2 decodes it.
export const PLACEHOLDER = { pages: 1, width: 128, quality: 40 };

async function encode(canvas, format, quality) {
  return canvas.encode(format, format === 'avif' ? { quality } : quality);
}

/**
 * The largest scale, at most `wanted`, at which a `width` x `height` page (page units) is drawn within
 * `maxSide` pixels a side and `budget` pixels in all; `wanted` itself when that fits.
 */
export function fitScale(width, height, wanted, maxSide, budget = PIXEL_BUDGET) {
  const fits = (scale) => {
    const [w, h] = [Math.max(1, Math.round(width * scale)), Math.max(1, Math.round(height * scale))];
    return w <= maxSide && h <= maxSide && w * h <= budget;
  };
  if (fits(wanted)) return wanted;
  let scale = Math.min(wanted, maxSide / Math.max(width, height), Math.sqrt(budget / (width * height)));
  while (!fits(scale)) scale *= 0.999;  // the pixel sizes round: a step or two below the bound
  return scale;
}

/** Gives a canvas's pixels back at once (a worker's garbage collector does not see their size). */
function release(canvas) {
  canvas.width = 1;
  canvas.height = 1;
}

/**
 * A square `side` px PNG of `source` (page 1) for the web app's icons: the page kept whole, its shape
 * padded with the site's background colour, an eighth of the side free around it.
 */
function squareIcon(createCanvas, source, side) {
  const canvas = createCanvas(side, side);
  const context = canvas.getContext('2d');
  context.imageSmoothingQuality = 'high';
  context.fillStyle = COLORS.background;
  context.fillRect(0, 0, side, side);
  const fit = (side * 0.75) / Math.max(source.width, source.height);
  const [width, height] = [Math.max(1, Math.round(source.width * fit)), Math.max(1, Math.round(source.height * fit))];
  context.drawImage(source, Math.round((side - width) / 2), Math.round((side - height) / 2), width, height);
  return canvas;
}

/** A white canvas of `width` x `height` holding `source` scaled down to it. */
function scaled(createCanvas, source, width, height) {
  const canvas = createCanvas(Math.max(1, Math.round(width)), Math.max(1, Math.round(height)));
  const context = canvas.getContext('2d');
  context.imageSmoothingQuality = 'high';
  context.fillStyle = '#fff';
  context.fillRect(0, 0, canvas.width, canvas.height);
  context.drawImage(source, 0, 0, canvas.width, canvas.height);
  return canvas;
}

/**
 * Renders source page `number` (from 1) of `doc` as published page `index` (from 0) into `bookDir`, its
 * text read from `textDoc` (the same PDF opened with a browser's fonts: open-pdf.js);
 * `reserve(pixels)` resolves, once that many pixels may be drawn, to the function that gives them back;
 * returns what the manifest and index.html need: sizes, links, the start of its text, bytes written.
 */
export async function renderPage({ doc, textDoc = doc, createCanvas, number, index, bookDir, options, reserve = async () => () => {} }) {
  // Where this page's time goes, in ms a step (the result's `steps`; publish-rate.mjs sums them).
  const steps = {};
  let mark = performance.now();
  const lap = (step) => {
    const now = performance.now();
    steps[step] = (steps[step] ?? 0) + (now - mark);
    mark = now;
  };
  const page = await doc.getPage(number);
  lap('page');
  try {
    const unit = page.getViewport({ scale: 1 });
    const asked = options.scale ?? options.height / unit.height;
    const maxSide = MAX_SIDE[options.format];
    const fit = (wanted, side = maxSide) => fitScale(unit.width, unit.height, wanted, side);
    const scale = fit(asked);
    const zoomScale = options.zoom > 0 ? fit(asked * options.zoom) : scale;
    const zoomed = options.zoom > 0 && zoomScale / scale >= MIN_ZOOM;
    // What the limits took from this page, for the manifest: the zoom factor given (0: none), the reading size's share.
    const limited = scale < asked || (options.zoom > 0 && zoomScale < asked * options.zoom) ? {
      ...(options.zoom > 0 ? { zoom: zoomed ? Math.floor((zoomScale / scale) * 100) / 100 : 0 } : {}),
      ...(scale < asked ? { reading: Math.floor((scale / asked) * 1000) / 1000 } : {}),
      by: limitName(unit, maxSide, options.format),
    } : null;
    const largest = zoomed ? zoomScale : scale;
    const pixels = (k) => Math.round(unit.width * k) * Math.round(unit.height * k);
    const ext = FORMATS[options.format];
    const files = [];
    // Written at once, not through the thread pool: this worker has nothing else to do meanwhile.
    const write = async (relative, data, kind) => {
      lap('encode');
      fs.writeFileSync(path.join(bookDir, relative), data);
      files.push({ path: relative, bytes: data.length, kind });
      lap('write');
    };
    let reading;
    let placeholder;  // a data: URL, for the first spread's pages
    const giveBack = await reserve(pixels(largest) + (zoomed ? pixels(scale) : 0));
    lap('wait');
    try {
      reading = await drawImages();
    } finally {
      giveBack();
    }

    const textPage = textDoc === doc ? page : await textDoc.getPage(number);
    const record = await pdfPageText(textPage);
    if (textPage !== page) textPage.cleanup();
    const textJson = Buffer.from(JSON.stringify(encodePageText(record)));
    lap('text');
    fs.writeFileSync(path.join(bookDir, pagePath('text', index, 'json')), textJson);
    files.push({ path: pagePath('text', index, 'json'), bytes: textJson.length, kind: 'text' });
    lap('write');
    const links = await pdfPageLinks(doc, page);
    lap('links');
    return {
      index, width: unit.width, height: unit.height, links, text: record.text.slice(0, TEXT_BACK),
      imageWidth: reading.width, imageHeight: reading.height, zoomed, ...(placeholder ? { placeholder } : {}), ...(limited ? { limited } : {}), files, steps,
    };

    /** Draws the page once at the largest size and writes its images; returns the reading image's size. */
    async function drawImages() {
      const viewport = page.getViewport({ scale: largest });
      const canvas = createCanvas(Math.max(1, Math.round(viewport.width)), Math.max(1, Math.round(viewport.height)));
      const context = canvas.getContext('2d');
      context.fillStyle = '#fff';
      context.fillRect(0, 0, canvas.width, canvas.height);
      await page.render({ canvas, canvasContext: context, viewport, background: '#fff' }).promise;
      lap('render');

      if (zoomed) await write(pagePath('zoom', index, ext), await encode(canvas, options.format, options.quality), 'image');
      const image = zoomed ? scaled(createCanvas, canvas, unit.width * scale, unit.height * scale) : canvas;
      lap('scale');
      await write(pagePath('pages', index, ext), await encode(image, options.format, options.quality), 'image');
      const size = { width: image.width, height: image.height };
      if (image !== canvas) release(image);
      const thumbScale = fit(options.thumbWidth / unit.width);
      const thumb = scaled(createCanvas, canvas, unit.width * thumbScale, unit.height * thumbScale);
      lap('scale');
      await write(pagePath('thumbs', index, ext), await encode(thumb, options.format, options.quality), 'image');
      release(thumb);
      if (index < PLACEHOLDER.pages) {
        const k = Math.min(PLACEHOLDER.width / unit.width, (2 * PLACEHOLDER.width) / unit.height);  // a tall page: 256 high at most
        const small = scaled(createCanvas, canvas, unit.width * k, unit.height * k);
        lap('scale');
        placeholder = `data:image/webp;base64,${(await encode(small, 'webp', PLACEHOLDER.quality)).toString('base64')}`;
        lap('encode');
        release(small);
      }
      if (index === 0) {
        const coverScale = fit(Math.min(options.coverWidth, canvas.width) / unit.width, MAX_SIDE.jpeg);
        const cover = scaled(createCanvas, canvas, unit.width * coverScale, unit.height * coverScale);
        lap('scale');
        await write(COVER, await cover.encode('jpeg', 85), 'image');
        release(cover);
        for (const side of ICON_SIDES) {
          const square = squareIcon(createCanvas, canvas, side);
          lap('scale');
          await write(iconFile(side), await square.encode('png'), 'image');
          release(square);
        }
      }
      release(canvas);
      return size;
    }
  } finally {
    page.cleanup();
  }
}

/** Which bound a page too large at some scale meets first: its format's largest side, or the pixel budget. */
function limitName(unit, maxSide, format) {
  const side = maxSide / Math.max(unit.width, unit.height);
  const area = Math.sqrt(PIXEL_BUDGET / (unit.width * unit.height));
  return side < area ? `${format}: ${maxSide} px a side` : `${PIXEL_BUDGET / 1e6} megapixels an image`;
}

export { COVER };
