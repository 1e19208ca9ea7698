// A book's outline (its table of contents): the `outline` option as given, else its document's (a PDF's
// bookmarks, a published document's outline). Loaded by outline()'s first call.

const copy = (entries) => entries.map(({ title, page, children }) => ({ title, page, children: copy(children ?? []) }));

/**
 * `[{ title, page, children }]` (page from 0): the `outline` option, else the document's, else `[]`.
 * @param {{ settings: object, document: () => object|null }} book  the controller's port
 */
export async function bookOutline(book) {
  if (book.settings.outline) return copy(book.settings.outline);
  const doc = book.document();
  return doc ? doc.outline() : [];
}
