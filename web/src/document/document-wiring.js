// How the document API (outline, search and its marks, thumbnails, fullscreen, download, print) and
// the viewer (`controls`) are wired to a book from its port, each module imported on first use (but fullscreen's).
import { markedPageImage } from '../pages/marked-page.js';
import { followFullscreen, toggleFullscreen } from './fullscreen.js';

/**
 * The document API (issue 23): outline(), search() and its marks, pageThumbnail(), fullscreen,
 * download() and print(), each module imported on first use (fullscreen's is here already); a PDF's
 * text is indexed in the background once the book is open (indexInBackground). `controller` is the book, for its events.
 * @param {import('../book/book-wiring.js').BookPort} book
 */
export function makeDocumentApi(controller, book) {
  let search = null;
  let searchLoading = null;
  let textIndex = null;
  let thumbnails = null;
  let fullscreen = null;  // fullscreen.js followFullscreen(), from the first toggleFullscreen()
  let stopped = false;
  const documentModule = () => import('./book-document.js');
  const documentIndex = async () => {
    const doc = book.document();
    if (!doc) return null;
    const { TextIndex } = await import('./text-index.js');
    return (textIndex ??= new TextIndex(doc, book.pageCount()));
  };
  const searcher = () => (searchLoading ??= import('./book-search.js').then(({ BookSearch }) => {
    book.alive();
    return (search = new BookSearch(book, documentIndex));
  }));
  const drawer = async () => {
    const { PageThumbnails } = await import('./page-thumbnails.js');
    return (thumbnails ??= new PageThumbnails(book));
  };
  controller.addEventListener('pageschange', () => search?.pagesChanged());  // hits' page numbers no longer hold
  return {
    outline: async () => (await import('./book-outline.js')).bookOutline(book),
    search: async (text, options) => (await searcher()).search(text, options),
    showHit: async (hit) => (await searcher()).showHit(hit),
    clearSearch: () => search?.clear(),
    /** A document page's text record (null for other books): what search and read-aloud read. */
    pageText: async (index) => (await documentIndex())?.page(index) ?? null,
    /**
     * The image the surface gets for page `index` (the page store's `decorate` hook): the search's marks
     * and `extra` ones (the word read aloud, while its leaf turns) drawn in, or the image itself.
     */
    decorate: (index, image, extra = []) => {
      const marks = [...(search?.marksOn(index) ?? []), ...extra];
      return marks.length > 0 ? markedPageImage(image, marks) : image;
    },
    thumbnail: async (index, size) => (await drawer()).draw(index, size),
    // The request is made before anything is awaited: the browser grants it only within the press.
    toggleFullscreen: async (force) => {
      book.alive();
      fullscreen ??= followFullscreen(book.container, (now) => {
        book.emit('fullscreenchange', { fullscreen: now });
        book.refitSoon();  // the size watch lays the book out at its new size; sharp images once it rests
      });
      const now = await toggleFullscreen(book.container, force);
      if (!book.destroyed()) fullscreen.look();  // told as toggleFullscreen() resolves, not when the browser's event comes
      return now;
    },
    download: async () => {
      book.alive();
      return (await documentModule()).downloadDocument(controller, book.root, book.settings, book.document());
    },
    print: async () => {
      book.alive();
      const draw = (index, size) => drawer().then((t) => t.draw(index, size));
      return (await documentModule()).printDocument(controller, book.pageCount(), draw);
    },
    /** After the book opened: a document's text read page by page in idle time, for the first search. */
    indexInBackground: () => {
      if (book.document()) documentIndex().then((index) => { if (!stopped) index?.startBackground(); }).catch(() => {});
    },
    stop: () => {
      stopped = true;
      textIndex?.stop();
      fullscreen?.stop();
    },
  };
}

/**
 * The viewer (the `controls` option), in two steps: planViewer() checks its options and keeps the toolbar's
 * room before the first spread is laid out; its attach() imports the viewer (after the first spread is
 * drawn: none of it is needed to show it) and attaches it to `controller` through its public API, as
 * conecurl/viewer's attachControls is; null without `controls` or once destroyed. A bad `controls` or
 * `labels` rejects planViewer(), before anything is drawn.
 * @param {import('../book/book-wiring.js').BookPort} book
 */
export async function planViewer(controller, book) {
  const { controls, labels } = book.settings;
  if (!controls) return { attach: async () => null };
  // Small, and in the first spread's chunk when bundled; only a book with controls asks for them.
  const [{ checkViewerOptions }, { keepToolbarRoom }] = await Promise.all([import('../viewer/viewer-options.js'), import('../viewer/toolbar-room.js')]);
  checkViewerOptions(controls, labels);
  const giveBack = keepToolbarRoom(book.root);
  return {
    attach: async () => {
      const { attachControls } = await import('../viewer/attach-controls.js');
      if (book.destroyed()) return null;
      giveBack();  // in the same task: attachControls keeps the book's own height and sets the toolbar's room again
      return attachControls(controller, { controls, labels, pdf: book.isDocument() });
    },
  };
}
