// A book's outline (its table of contents): the `outline` option as given, else a PDF's bookmarks
// (pages/pdf-outline.js, imported only then). Loaded by outline()'s first call.

const copy = (entries) => entries.map(({ title, page, children }) => ({ title, page, children: copy(children ?? []) }));

/**
 * `[{ title, page, children }]` (page from 0): the `outline` option, else the PDF's bookmarks, else `[]`.
 * @param {{ settings: object, pdfDocument: () => object|null }} book  the controller's port
 */
export async function bookOutline(book) {
  if (book.settings.outline) return copy(book.settings.outline);
  const pdf = book.pdfDocument();
  if (!pdf) return [];
  const { pdfOutline } = await import('../pages/pdf-outline.js');
  return pdfOutline(pdf);
}
