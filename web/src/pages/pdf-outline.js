// A PDF's bookmarks as the book's outline: pdf.js's outline tree with each entry's destination
// resolved to a page index (from 0). Loaded only when a PDF book's outline() is first asked for.

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

/**
 * The outline of an open PDF (pdf-pages.js openPdf): `[{ title, page, children }]`, `[]` without bookmarks.
 * @param {{ doc: object }} pdf
 */
export async function pdfOutline(pdf) {
  return entriesOf(pdf.doc, await pdf.doc.getOutline());
}
