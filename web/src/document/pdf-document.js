// What a PDF gives the document features, read through pdf.js: its bookmarks as an outline, each page's
// links and its text record (format.js). The same code runs in the browser (a PDF book) and in Node
// (`conecurl publish`), so a published document holds exactly what a PDF opened at run time shows.
import { pageTextRecord } from './format.js';

/** The page index (from 0) of a destination as pdf.js gives it (a name or an explicit array), or null. */
async function destinationPage(doc, dest) {
  try {
    const explicit = typeof dest === 'string' ? await doc.getDestination(dest) : dest;
    if (!Array.isArray(explicit) || explicit[0] == null) return null;
    const target = explicit[0];
    // A page reference ({ num, gen }), or (in some files) a page number from 0.
    return Number.isInteger(target) ? target : await doc.getPageIndex(target);
  } catch {
    return null;  // a destination pdf.js cannot resolve is left out, not guessed
  }
}

async function entriesOf(doc, items) {
  const entries = [];
  for (const item of items ?? []) {
    const children = await entriesOf(doc, item.items);
    let page = item.dest ? await destinationPage(doc, item.dest) : null;
    // An entry without a destination of its own (a heading over its children) opens its first child's page.
    if (page === null && children.length > 0) page = children[0].page;
    if (page === null) continue;  // nothing to open (a web link, a broken destination)
    entries.push({ title: String(item.title ?? ''), page, children });
  }
  return entries;
}

/** The outline of a pdf.js document: `[{ title, page, children }]` (page from 0), `[]` without bookmarks. */
export async function pdfOutline(doc) {
  return entriesOf(doc, await doc.getOutline());
}

/**
 * A page's link annotations (`page`: pdf.js's PDFPageProxy of `doc`) as { rect (fractions of the page,
 * from its top-left), href } or { rect, page } (a page index, from 0).
 */
export async function pdfPageLinks(doc, page) {
  const viewport = page.getViewport({ scale: 1 });
  const links = [];
  for (const annotation of await page.getAnnotations()) {
    if (annotation.subtype !== 'Link' || !annotation.rect) continue;
    const [x1, y1] = viewport.convertToViewportPoint(annotation.rect[0], annotation.rect[1]);
    const [x2, y2] = viewport.convertToViewportPoint(annotation.rect[2], annotation.rect[3]);
    const clamp = (v) => Math.min(1, Math.max(0, v));
    const left = clamp(Math.min(x1, x2) / viewport.width);
    const top = clamp(Math.min(y1, y2) / viewport.height);
    const rect = [left, top, clamp(Math.abs(x2 - x1) / viewport.width + left) - left, clamp(Math.abs(y2 - y1) / viewport.height + top) - top];
    const href = annotation.url || annotation.unsafeUrl;
    if (href) {
      links.push({ rect, href });
      continue;
    }
    if (annotation.dest) {
      const target = await destinationPage(doc, annotation.dest);
      if (target !== null) links.push({ rect, page: target });
    }
  }
  return links;
}

/** Page `page`'s text record (format.js pageTextRecord) from pdf.js's text content. */
export async function pdfPageText(page) {
  return pageTextRecord(await page.getTextContent(), page.getViewport({ scale: 1 }));
}
