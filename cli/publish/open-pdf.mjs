// Opening the PDF, in the main thread and in each render worker alike: its bytes read once, pdf.js's
// failures (not a PDF, damaged, encrypted, wrong password) turned into one line that says what to do.
import fs from 'node:fs';
import path from 'node:path';
import { documentOptions, INSTALL_HINT, loadCanvas, loadPdfjs } from './pdfjs-node.mjs';
import { inputError } from './errors.mjs';

/** pdf.js and the canvas package, or an error that says how to install them. */
export async function loadRenderer() {
  try {
    const canvas = loadCanvas();
    const pdfjs = await loadPdfjs();
    return { pdfjs, canvas };
  } catch (error) {
    throw Object.assign(inputError(`publishing needs pdfjs-dist and @napi-rs/canvas, which are not installed here: ${INSTALL_HINT}`), { cause: error });
  }
}

/** The file's bytes; an error names the file when it is missing, a folder, or not a PDF at all. */
export function readPdf(file) {
  let bytes;
  try {
    bytes = fs.readFileSync(file);
  } catch (error) {
    const why = error.code === 'ENOENT' ? 'does not exist: check the path'
      : error.code === 'EISDIR' ? 'is a folder: give the PDF file inside it' : `cannot be read (${error.code ?? error.message})`;
    throw Object.assign(inputError(`${file} ${why}`), { cause: error });
  }
  if (bytes.length < 5 || bytes.subarray(0, 1024).indexOf('%PDF-') < 0) {
    throw inputError(`${file} is not a PDF (it does not start with %PDF-): give a .pdf file`);
  }
  return new Uint8Array(bytes.buffer, bytes.byteOffset, bytes.length);
}

/**
 * The pdf.js document of `bytes` (a copy is handed over: pdf.js detaches what it gets). `browserFonts`:
 * the 14 standard fonts a PDF may use without embedding them are taken as a browser's pdf.js takes them
 * (useSystemFonts, its default there: their metrics, not the font files'), for the page text records, so
 * the published text lies where a PDF opened in the browser puts it; pages are drawn with the files.
 */
export async function openPdf(pdfjs, bytes, file, password, { browserFonts = false } = {}) {
  const task = pdfjs.getDocument({ ...documentOptions(bytes.slice(), password), ...(browserFonts ? { useSystemFonts: true } : {}) });
  try {
    const doc = await task.promise;
    if (!(doc.numPages > 0)) throw new Error('no pages');
    return doc;
  } catch (error) {
    await task.destroy().catch(() => {});
    const name = path.basename(file);
    if (error?.name === 'PasswordException') {
      throw Object.assign(inputError(password === undefined
        ? `${file} is encrypted: give its password with --password`
        : `${file}: the password is wrong: check it (--password)`), { cause: error });
    }
    throw Object.assign(inputError(`${file} is damaged or not a PDF pdf.js can read (${String(error?.message ?? error).split('\n')[0]}): `
      + `re-save or repair ${name} (e.g. print it to PDF) and try again`), { cause: error });
  }
}
