// Read-aloud as the controller holds it before anything is read: read-aloud/book-reader.js imported
// at the first call, and the word read aloud handed to the page images (`marksOn`) once it is.

/**
 * Read-aloud (read-aloud/book-reader.js, imported at the first call): readAloud(), readingAloud,
 * readAloudVoices(), canReadAloud(); `pageText(index)` is a document page's text record.
 * @param {BookPort} book
 */
export function makeReadAloud(controller, book, pageText) {
  let reader = null;
  let loading = null;
  const load = () => (loading ??= import('../read-aloud/book-reader.js').then(({ BookReader }) => {
    book.alive();
    return (reader ??= new BookReader(controller, book, pageText));
  }));
  return {
    start: async (options) => (await load()).start(options),
    current: () => reader?.current ?? null,
    voices: async () => (await load()).voices(),
    can: async () => (await load()).can(),
    /** The word read aloud, drawn into its page's image while its leaf turns: the marks of page `index`. */
    marksOn: (index) => reader?.marksOn(index) ?? [],
    stop: () => reader?.stop(),
  };
}
