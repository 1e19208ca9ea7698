// PDF books: opens a PDF with pdf.js (the optional dependency pdfjs-dist, imported only when a PDF is
// given) and turns each page into a page source the Flipbook calls when it wants that page, rendered
// at the size the canvas needs; the page's text becomes its accessible text.

/** Where pdf.js's worker module is, when the caller did not say: next to pdf.js, as the page resolves it. */
function defaultWorkerSrc() {
  try {
    return import.meta.resolve('pdfjs-dist/build/pdf.worker.min.mjs');
  } catch {
    return null;
  }
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
    const src = workerSrc || defaultWorkerSrc();
    if (!src) {
      throw new Error("conecurl: cannot find pdf.js's worker (pdfjs-dist/build/pdf.worker.min.mjs): "
        + "give its URL as the 'pdfWorkerSrc' option");
    }
    pdfjs.GlobalWorkerOptions.workerSrc = src;
  }
  const task = pdfjs.getDocument(typeof source === 'string'
    ? { url: source }
    // pdf.js takes ownership of the bytes it is given: hand it a copy, the caller keeps theirs.
    : { data: source instanceof ArrayBuffer ? new Uint8Array(source.slice(0)) : source.slice() });
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
  const texts = new Map();  // page index → Promise of its text content, read once
  return {
    pages,
    aspect: first.width / first.height,
    /** pdf.js itself (for its TextLayer and the like) and the open document. */
    pdfjs,
    doc,
    /** The PDF's URL when it was given one (null for bytes): what download() fetches. */
    url: typeof source === 'string' ? source : null,
    /** Page `index` (from 0) as pdf.js's PDFPageProxy. */
    page: (index) => doc.getPage(index + 1),
    /**
     * Page `index`'s text as pdf.js gives it ({ items, styles }), with the page's size in PDF units
     * at scale 1 ({ width, height }): read once and kept, for search and the text layer alike.
     */
    textContent(index) {
      if (!texts.has(index)) {
        texts.set(index, doc.getPage(index + 1).then(async (page) => {
          const { width, height } = page.getViewport({ scale: 1 });
          return { content: await page.getTextContent(), width, height };
        }));
      }
      return texts.get(index);
    },
    destroy: () => task.destroy(),
  };
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
    if (!entry.alt) {
      const text = await page.getTextContent();
      const words = text.items.map((item) => item.str || '').join(' ').replace(/\s+/g, ' ').trim();
      entry.alt = words ? `Page ${number}: ${words}` : `Page ${number}`;
    }
    if (!entry.links) {
      try {
        entry.links = await pageLinks(doc, page, base);
      } catch {
        entry.links = [];  // links are a bonus: a page whose annotations pdf.js cannot read still shows
      }
    }
    return canvas;
  } finally {
    page.cleanup();
  }
}

/** The page's link annotations as { rect (fractions of the page, from its top-left), href | toPage }. */
async function pageLinks(doc, page, viewport) {
  const links = [];
  for (const annotation of await page.getAnnotations()) {
    if (annotation.subtype !== 'Link' || !annotation.rect) continue;
    const [x1, y1] = viewport.convertToViewportPoint(annotation.rect[0], annotation.rect[1]);
    const [x2, y2] = viewport.convertToViewportPoint(annotation.rect[2], annotation.rect[3]);
    const rect = [Math.min(x1, x2) / viewport.width, Math.min(y1, y2) / viewport.height,
      Math.abs(x2 - x1) / viewport.width, Math.abs(y2 - y1) / viewport.height];
    const href = annotation.url || annotation.unsafeUrl;
    if (href) {
      links.push({ rect, href });
      continue;
    }
    try {
      const dest = typeof annotation.dest === 'string' ? await doc.getDestination(annotation.dest) : annotation.dest;
      if (Array.isArray(dest) && dest[0]) {
        const toPage = typeof dest[0] === 'number' ? dest[0] : await doc.getPageIndex(dest[0]);
        links.push({ rect, href: '#', toPage });
      }
    } catch {
      // A destination pdf.js cannot resolve is left out, not guessed.
    }
  }
  return links;
}
