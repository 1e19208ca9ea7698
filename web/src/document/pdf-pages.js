// PDF books: opens a PDF with pdf.js (the optional dependency pdfjs-dist, imported only when a PDF is
// given) and turns each page into a page source the Flipbook calls when it wants that page, rendered
// at the size the canvas needs; the page's text becomes its accessible text. The open PDF is the book's
// document: its text records, outline and links come from document/pdf-document.js.
import { pdfOutline, pdfPageLinks, pdfPageText } from './pdf-document.js';
import { altText, emptyPageText } from './format.js';

/** Where a file of pdf.js's package is (its worker, its data folders), as the page resolves it; null if it cannot. */
function besidePdfjs(file) {
  try {
    return import.meta.resolve(`pdfjs-dist/${file}`);
  } catch {
    return null;
  }
}

// pdf.js's data, found beside it: the standard fonts' files (the 14 fonts a PDF may use without embedding
// them: their true metrics, so the text's places match a published document's, which Node drew with
// them), the character maps and the image decoders. Each only where the page can resolve it.
function pdfjsData() {
  const data = { standardFontDataUrl: besidePdfjs('standard_fonts/'), cMapUrl: besidePdfjs('cmaps/'), wasmUrl: besidePdfjs('wasm/') };
  for (const key of Object.keys(data)) if (!data[key]) delete data[key];
  if (data.cMapUrl) data.cMapPacked = true;
  return data;
}

async function importPdfjs() {
  try {
    return await import('pdfjs-dist');
  } catch (error) {
    throw new Error('conecurl: the \'pdf\' option needs the optional dependency pdfjs-dist (npm install pdfjs-dist); '
      + `it could not be loaded: ${error && error.message ? error.message : error}`);
  }
}

/**
 * @param {string|ArrayBuffer|Uint8Array} source  a URL, or the file's bytes
 * @param {{ workerSrc?: string }} [options]
 * @returns {Promise<{ pages: Array<{ src: Function, alt: string }>, aspect: number, pdfjs: object, doc: object,
 *   page: (index: number) => Promise<object>, textContent: (index: number) => Promise<object>, destroy: () => void }>}
 */
export async function openPdf(source, { workerSrc } = {}) {
  const pdfjs = await importPdfjs();
  if (!pdfjs.GlobalWorkerOptions.workerSrc) {
    const src = workerSrc || besidePdfjs('build/pdf.worker.min.mjs');
    if (!src) {
      throw new Error("conecurl: cannot find pdf.js's worker (pdfjs-dist/build/pdf.worker.min.mjs): "
        + "give its URL as the 'pdfWorkerSrc' option");
    }
    pdfjs.GlobalWorkerOptions.workerSrc = src;
  }
  const task = pdfjs.getDocument({
    ...pdfjsData(),
    ...(typeof source === 'string'
      ? { url: source }
      // pdf.js takes ownership of the bytes it is given: hand it a copy, the caller keeps theirs.
      : { data: source instanceof ArrayBuffer ? new Uint8Array(source.slice(0)) : source.slice() }),
  });
  let doc;
  try {
    doc = await task.promise;
  } catch (error) {
    throw new Error(`conecurl: could not open the PDF (${error && error.message ? error.message : error})`);
  }
  const first = (await doc.getPage(1)).getViewport({ scale: 1 });
  const pages = Array.from({ length: doc.numPages }, (_, i) => {
    const entry = { alt: '', src: (index, size) => renderPage(doc, i + 1, size, entry) };
    return entry;
  });
  const texts = new Map();  // page index → Promise of its text record, read once
  const opened = {
    pages,
    /** The PDF's language (its catalog's /Lang, as pdf.js reads it), '' until read or where it has none. */
    lang: '',
    aspect: first.width / first.height,
    /** pdf.js itself (for its TextLayer and the like) and the open document. */
    pdfjs,
    doc,
    /** The PDF's URL when it was given one (null for bytes): what download() fetches. */
    url: typeof source === 'string' ? source : null,
    /** Page `index` (from 0) as pdf.js's PDFPageProxy. */
    page: (index) => doc.getPage(index + 1),
    /** Page `index`'s text record (document/format.js), read once and kept: what search and the text layer read. */
    pageText(index) {
      if (!texts.has(index)) texts.set(index, doc.getPage(index + 1).then(pdfPageText).catch(() => emptyPageText()));
      return texts.get(index);
    },
    /** The PDF's bookmarks: [{ title, page, children }]. */
    outline: () => pdfOutline(doc),
    /** What download() fetches: the PDF's URL, else its bytes as a Blob URL (`made`: revoke it when done). */
    async downloadUrl() {
      if (typeof source === 'string') return { url: source, made: false };
      const bytes = await doc.getData();
      return { url: URL.createObjectURL(new Blob([bytes], { type: 'application/pdf' })), made: true };
    },
    destroy: () => task.destroy(),
  };
  doc.getMetadata().then(({ info }) => { opened.lang = String(info?.Language ?? '').trim(); }).catch(() => {});
  return opened;
}

/**
 * Renders page `number` into a canvas that covers `size` (device pixels the book wants for a page),
 * and fills the entry's alt text from the page's text once.
 */
async function renderPage(doc, number, size, entry) {
  const page = await doc.getPage(number);
  try {
    const base = page.getViewport({ scale: 1 });
    const want = size && size.width > 0 && size.height > 0 ? size : { width: base.width * 2, height: base.height * 2 };
    const viewport = page.getViewport({ scale: Math.max(want.width / base.width, want.height / base.height) });
    const canvas = document.createElement('canvas');
    canvas.width = Math.max(1, Math.ceil(viewport.width));
    canvas.height = Math.max(1, Math.ceil(viewport.height));
    await page.render({ canvas, viewport, background: '#ffffff' }).promise;
    if (!entry.alt) entry.alt = altText(number - 1, (await pdfPageText(page)).text);
    if (!entry.links) {
      try {
        // In the book's one form of a link (options.js pageEntries): { rect, href } or { rect, href: '#', toPage }.
        entry.links = (await pdfPageLinks(doc, page)).map(({ rect, href, page: toPage }) => (toPage === undefined ? { rect, href } : { rect, href: '#', toPage }));
      } catch {
        entry.links = [];  // links are a bonus: a page whose annotations pdf.js cannot read still shows
      }
    }
    return canvas;
  } finally {
    page.cleanup();
  }
}
