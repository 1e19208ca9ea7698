// The test PDF of the document API's browser tests (search.spec.js, document.spec.js): made in
// tests/fixtures/document-pdf.mjs (shared with the Node publish tests) and opened in a book here.
import { openReady } from './helpers.js';

export { BOOKMARKS, PAGES, PAGE_SIZE, lineAt, makeDocumentPdf } from '../fixtures/document-pdf.mjs';

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
