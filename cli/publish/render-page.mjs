// One page of the PDF into its published files: drawn once by pdf.js into an @napi-rs/canvas canvas at
// the largest size needed (the zoom image), then scaled down for the reading image, the thumbnail and
// (page 1) the link-preview cover: drawing is the cheap part, encoding the images the dear one.
import fs from 'node:fs/promises';
import path from 'node:path';
import { encodePageText, pagePath } from '../../web/src/document/format.js';
import { pdfPageLinks, pdfPageText } from '../../web/src/document/pdf-document.js';
import { FORMATS } from './args.mjs';

const COVER = 'cover.jpg';
/** How much of a page's text the main thread gets back (alt text and the noscript copy need less). */
const TEXT_BACK = 1000;

async function encode(canvas, format, quality) {
  return canvas.encode(format, format === 'avif' ? { quality } : quality);
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
 * returns what the manifest and index.html need: sizes, links, the start of its text, bytes written.
 */
export async function renderPage({ doc, textDoc = doc, createCanvas, number, index, bookDir, options }) {
  const page = await doc.getPage(number);
  try {
    const unit = page.getViewport({ scale: 1 });
    const scale = options.scale ?? options.height / unit.height;
    const largest = scale * Math.max(1, options.zoom);
    const viewport = page.getViewport({ scale: largest });
    const canvas = createCanvas(Math.max(1, Math.round(viewport.width)), Math.max(1, Math.round(viewport.height)));
    const context = canvas.getContext('2d');
    context.fillStyle = '#fff';
    context.fillRect(0, 0, canvas.width, canvas.height);
    await page.render({ canvas, canvasContext: context, viewport, background: '#fff' }).promise;

    const ext = FORMATS[options.format];
    const files = [];
    const write = async (relative, data, kind) => {
      await fs.writeFile(path.join(bookDir, relative), data);
      files.push({ path: relative, bytes: data.length, kind });
    };
    const reading = options.zoom > 0 ? scaled(createCanvas, canvas, unit.width * scale, unit.height * scale) : canvas;
    await write(pagePath('pages', index, ext), await encode(reading, options.format, options.quality), 'image');
    if (options.zoom > 0) await write(pagePath('zoom', index, ext), await encode(canvas, options.format, options.quality), 'image');
    const thumb = scaled(createCanvas, canvas, options.thumbWidth, options.thumbWidth * unit.height / unit.width);
    await write(pagePath('thumbs', index, ext), await encode(thumb, options.format, options.quality), 'image');
    if (index === 0) {
      const width = Math.min(options.coverWidth, canvas.width);
      const cover = scaled(createCanvas, canvas, width, width * unit.height / unit.width);
      await write(COVER, await cover.encode('jpeg', 85), 'image');
    }

    const textPage = textDoc === doc ? page : await textDoc.getPage(number);
    const record = await pdfPageText(textPage);
    if (textPage !== page) textPage.cleanup();
    await write(pagePath('text', index, 'json'), Buffer.from(JSON.stringify(encodePageText(record))), 'text');
    const links = await pdfPageLinks(doc, page);
    return {
      index, width: unit.width, height: unit.height, links, text: record.text.slice(0, TEXT_BACK),
      imageWidth: reading.width, imageHeight: reading.height, files,
    };
  } finally {
    page.cleanup();
  }
}

export { COVER };
