// The demo's PDF example: a twelve-page brochure made in the browser with pdf-lib (a dev dependency),
// with headings, paragraphs, figures, a contents page whose entries link to their pages, a web link, and
// bookmarks (the viewer's Contents panel shows them).
import { PDFDocument, PDFHexString, PDFName, PDFNull, PDFString, StandardFonts, rgb } from '/node_modules/pdf-lib/dist/pdf-lib.esm.min.js';
import { wrapWords } from './book-pages.js';

const SECTIONS = ['Paper and grain', 'Folding the sheet', 'Sewing the book', 'The turning leaf', 'Cones, not cylinders',
  'Light on paper', 'Shadows in the gutter', 'Reading on screens', 'Zoom and detail'];
const WORDS = ('the leaf lifts at its corner and the curl runs along the page as the cone narrows toward the '
  + 'spine while light falls across the paper and the shadow gathers in the gutter of the book').split(' ');

function paragraph(seed, count) {
  return Array.from({ length: count }, (_, i) => WORDS[(seed * 7 + i * 3) % WORDS.length]).join(' ');
}

/** Lays `text` out in lines of at most `width` points; returns the lines. */
function wrap(text, font, size, width) {
  return wrapWords(text, width, (line) => font.widthOfTextAtSize(line, size));
}

export async function makeDemoPdf() {
  const pdf = await PDFDocument.create();
  pdf.setTitle('conecurl PDF example');
  const serif = await pdf.embedFont(StandardFonts.TimesRoman);
  const bold = await pdf.embedFont(StandardFonts.HelveticaBold);
  const [W, H] = [420, 560];
  const pages = Array.from({ length: SECTIONS.length + 3 }, () => pdf.addPage([W, H]));
  const link = (page, rect, action) => {
    const annotation = pdf.context.register(pdf.context.obj({ Type: 'Annot', Subtype: 'Link', Rect: rect, Border: [0, 0, 0], ...action }));
    const existing = page.node.lookup(PDFName.of('Annots'));
    if (existing) existing.push(annotation);
    else page.node.set(PDFName.of('Annots'), pdf.context.obj([annotation]));
  };
  // Cover.
  pages[0].drawRectangle({ x: 0, y: 0, width: W, height: H, color: rgb(0.12, 0.24, 0.3) });
  pages[0].drawText('Turning Pages', { x: 40, y: H - 160, size: 40, font: bold, color: rgb(0.85, 0.71, 0.42) });
  pages[0].drawText('a PDF shown with pdf.js, curled on a cone', { x: 40, y: H - 195, size: 14, font: serif, color: rgb(0.95, 0.92, 0.84) });
  // Contents, linking each entry to its page.
  pages[1].drawText('Contents', { x: 40, y: H - 70, size: 24, font: bold, color: rgb(0.2, 0.2, 0.2) });
  SECTIONS.forEach((title, i) => {
    const y = H - 120 - i * 30;
    pages[1].drawText(`${i + 1}. ${title}`, { x: 50, y, size: 14, font: serif, color: rgb(0.1, 0.25, 0.5) });
    pages[1].drawText(String(i + 3), { x: W - 60, y, size: 14, font: serif });
    link(pages[1], [45, y - 6, W - 45, y + 16], { Dest: [pages[i + 2].ref, PDFName.of('XYZ'), null, null, null] });
  });
  // Sections: heading, a figure, paragraphs, page number.
  SECTIONS.forEach((title, i) => {
    const page = pages[i + 2];
    page.drawText(title, { x: 40, y: H - 70, size: 22, font: bold, color: rgb(0.54, 0.23, 0.15) });
    const hue = i / SECTIONS.length;
    page.drawRectangle({ x: 40, y: H - 260, width: W - 80, height: 160, color: rgb(0.3 + 0.5 * hue, 0.55, 0.8 - 0.4 * hue) });
    page.drawCircle({ x: 40 + (W - 80) * (0.2 + 0.6 * hue), y: H - 180, size: 36, color: rgb(0.98, 0.85, 0.4) });
    let y = H - 290;
    for (let p = 0; p < 3; p++) {
      for (const line of wrap(paragraph(i * 3 + p, 40), serif, 11, W - 80)) {
        page.drawText(line, { x: 40, y, size: 11, font: serif, color: rgb(0.16, 0.15, 0.13) });
        y -= 15;
      }
      y -= 8;
    }
    page.drawText(String(i + 3), { x: W / 2 - 4, y: 24, size: 11, font: serif });
  });
  // Back page with a web link.
  const last = pages[pages.length - 1];
  last.drawText('Made with conecurl', { x: 40, y: H - 80, size: 22, font: bold });
  last.drawText('pdf.js: mozilla.github.io/pdf.js', { x: 40, y: H - 120, size: 13, font: serif, color: rgb(0.1, 0.25, 0.6) });
  link(last, [38, H - 126, 260, H - 104], { A: { Type: 'Action', S: 'URI', URI: PDFString.of('https://mozilla.github.io/pdf.js/') } });
  addBookmarks(pdf, [['Cover', 0], ['Contents', 1], ...SECTIONS.map((title, i) => [title, i + 2]), ['Made with conecurl', pages.length - 1]]
    .map(([title, index]) => ({ title, page: pages[index] })));
  return pdf.save();
}

// A flat /Outlines list: each bookmark's title and the page it opens.
function addBookmarks(pdf, marks) {
  const { context, catalog } = pdf;
  const outlines = context.nextRef();
  const refs = marks.map(() => context.nextRef());
  marks.forEach(({ title, page }, i) => {
    const entry = context.obj({ Parent: outlines, Dest: [page.ref, PDFName.of('XYZ'), PDFNull, PDFNull, PDFNull] });
    entry.set(PDFName.of('Title'), PDFHexString.fromText(title));
    if (i > 0) entry.set(PDFName.of('Prev'), refs[i - 1]);
    if (i < marks.length - 1) entry.set(PDFName.of('Next'), refs[i + 1]);
    context.assign(refs[i], entry);
  });
  context.assign(outlines, context.obj({ Type: 'Outlines', First: refs[0], Last: refs[refs.length - 1], Count: marks.length }));
  catalog.set(PDFName.of('Outlines'), outlines);
}
