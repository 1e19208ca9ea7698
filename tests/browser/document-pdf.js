// The test PDF of the document API's browser tests (search.spec.js, document.spec.js), made with
// pdf-lib: pages with a heading (Helvetica-Bold) and lines of body text (Helvetica), and a bookmarks
// tree (/Outlines) whose entries point at pages by explicit and by named destinations. It also says
// where each line of text was drawn, so a test can check a hit's rectangle against the glyphs' place.
import { PDFDocument, PDFHexString, PDFName, PDFNull, PDFNumber, StandardFonts, rgb } from 'pdf-lib';
import { openReady } from './helpers.js';

export const PAGE_SIZE = [420, 560];  // points, portrait
const MARGIN = 40;
const BODY_SIZE = 14;
const HEADING_SIZE = 24;

/** Page texts: a heading and body lines. Words to look for: zebra (pages 1 and 4), café/CAFE/cafe, naïve. */
export const PAGES = [
  { heading: 'Contents', lines: ['A book about animals and drinks.', 'Read it in any order.'] },
  { heading: 'Chapter One: Zebras', lines: ['The zebra has stripes.', 'Stripes confuse flies, it is said.', 'A naïve reader may doubt it.'] },
  { heading: 'Section 1.1', lines: ['Horses are relatives of the', 'striped animals of Africa.'] },
  { heading: 'Chapter Two: Coffee', lines: ['In a Café in Paris the coffee', 'comes with a glass of water.'] },
  { heading: 'Section 2.1', lines: ['THE CAFE OF THE ZEBRA', 'is a real place, or a dream.', 'A NAIVE question: which?'] },
  { heading: 'Chapter Three: Tea', lines: ['Tea is not coffee; a cafe', 'serves both, and cake.'] },
  { heading: 'Appendix', lines: ['Nothing more here.'] },
  { heading: 'Index', lines: ['animals 1, coffee 3, tea 5'] },
];

/** The bookmarks: titles and target pages (index from 0); `named` ones use a named destination. */
export const BOOKMARKS = [
  { title: 'Contents', page: 0 },
  { title: 'Chapter One: Zebras', page: 1, children: [{ title: 'Section 1.1', page: 2, named: 'sec-1-1' }] },
  { title: 'Chapter Two: Coffee', page: 3, children: [{ title: 'Section 2.1', page: 4 }] },
  { title: 'Chapter Three: Tea', page: 5 },
  { title: 'Appendix', page: 6, children: [{ title: 'Index', page: 7, named: 'index' }] },
];

/** Where line `line` of page `page` was drawn: { x, baseline (from the top), size, font: 'body' | 'heading' }. */
export function lineAt(page, line) {
  if (line < 0) return { x: MARGIN, baseline: MARGIN + HEADING_SIZE, size: HEADING_SIZE, font: 'heading' };
  return { x: MARGIN, baseline: MARGIN + HEADING_SIZE + 30 + line * (BODY_SIZE * 1.6), size: BODY_SIZE, font: 'body' };
}

/**
 * The PDF's bytes (base64) and, for the geometry checks, a function measuring text as drawn:
 * widthOf(text, font) in points.
 */
export async function makeDocumentPdf() {
  const pdf = await PDFDocument.create();
  const body = await pdf.embedFont(StandardFonts.Helvetica);
  const heading = await pdf.embedFont(StandardFonts.HelveticaBold);
  const pages = PAGES.map(({ heading: title, lines }, index) => {
    const page = pdf.addPage(PAGE_SIZE);
    const h = lineAt(index, -1);
    page.drawText(title, { x: h.x, y: PAGE_SIZE[1] - h.baseline, size: h.size, font: heading, color: rgb(0, 0, 0) });
    lines.forEach((text, line) => {
      const at = lineAt(index, line);
      page.drawText(text, { x: at.x, y: PAGE_SIZE[1] - at.baseline, size: at.size, font: body, color: rgb(0, 0, 0) });
    });
    page.drawText(`${index + 1}`, { x: PAGE_SIZE[0] / 2, y: 20, size: 10, font: body, color: rgb(0.3, 0.3, 0.3) });
    return page;
  });
  addOutline(pdf, pages);
  const bytes = await pdf.save();
  return {
    base64: Buffer.from(bytes).toString('base64'),
    widthOf: (text, font) => (font === 'heading' ? heading : body).widthOfTextAtSize(text, font === 'heading' ? HEADING_SIZE : BODY_SIZE),
  };
}

// The /Outlines tree and the /Dests of the named destinations, written with pdf-lib's low-level objects.
function addOutline(pdf, pages) {
  const { context, catalog } = pdf;
  const dests = {};
  const destOf = (page) => context.obj([pages[page].ref, PDFName.of('XYZ'), PDFNull, PDFNull, PDFNull]);
  const build = (entries, parentRef) => {
    const refs = entries.map(() => context.nextRef());
    let count = 0;
    entries.forEach((entry, i) => {
      const dict = context.obj({});
      dict.set(PDFName.of('Title'), PDFHexString.fromText(entry.title));
      dict.set(PDFName.of('Parent'), parentRef);
      if (entry.named) {
        dests[entry.named] = destOf(entry.page);
        dict.set(PDFName.of('Dest'), PDFName.of(entry.named));
      } else {
        dict.set(PDFName.of('Dest'), destOf(entry.page));
      }
      if (i > 0) dict.set(PDFName.of('Prev'), refs[i - 1]);
      if (i < entries.length - 1) dict.set(PDFName.of('Next'), refs[i + 1]);
      count += 1;
      if (entry.children) {
        const child = build(entry.children, refs[i]);
        dict.set(PDFName.of('First'), child.first);
        dict.set(PDFName.of('Last'), child.last);
        dict.set(PDFName.of('Count'), PDFNumber.of(child.count));
        count += child.count;
      }
      context.assign(refs[i], dict);
    });
    return { first: refs[0], last: refs[refs.length - 1], count };
  };
  const outlinesRef = context.nextRef();
  const top = build(BOOKMARKS, outlinesRef);
  context.assign(outlinesRef, context.obj({ Type: 'Outlines', First: top.first, Last: top.last, Count: top.count }));
  catalog.set(PDFName.of('Outlines'), outlinesRef);
  const destsDict = context.obj({});
  for (const [name, dest] of Object.entries(dests)) destsDict.set(PDFName.of(name), dest);
  catalog.set(PDFName.of('Dests'), destsDict);
}

/**
 * Opens the PDF fixture page with a book of `made` (makeDocumentPdf's result) in `window.book` (options
 * merged over a double spread turning in 300 ms), and beside it, to compare with, pdf.js itself as the
 * page has it (`window.pdfjs`, the module the book imported) and the same PDF opened by it (`window.refDoc`).
 */
export async function openPdfBook(page, made, options = {}) {
  await openReady(page, '/tests/browser/fixtures/pdf-fixture.html');
  await page.evaluate(async ({ base64, options }) => {
    window.pdfBytes = window.bytesFromBase64(base64);
    window.book = await window.Flipbook.create(window.container, {
      pdf: window.pdfBytes, display: 'double', duration: 300, ...options,
    });
    await window.book.whenIdle();
    window.pdfjs = await import('pdfjs-dist');
    window.refDoc = await window.pdfjs.getDocument({ data: window.pdfBytes.slice() }).promise;
  }, { base64: made.base64, options });
}
