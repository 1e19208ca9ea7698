// The reader page: a book that fills the screen, with the toolbar. A published site's index.html (what
// `conecurl publish` writes) names its document in <main id="conecurl-reader" data-document="...">;
// reader.html (shipped in the package) opens a PDF at run time from its address: reader.html#file=book.pdf.
import { Flipbook } from '../src/index.js';

const main = document.getElementById('conecurl-reader');

/** The PDF the address names (#file=URL, as pdf.js's viewer takes it), or null. */
function fileFromHash() {
  const params = new URLSearchParams(location.hash.slice(1));
  const file = params.get('file');
  return file ? new URL(file, location.href).href : null;
}

function showProblem(text) {
  const message = document.createElement('p');
  message.className = 'conecurl-reader-problem';
  message.setAttribute('role', 'alert');
  message.textContent = text;
  main.replaceChildren(message);
}

async function open() {
  const published = main.dataset.document;
  const file = published ? null : fileFromHash();
  if (!published && !file) {
    showProblem('No document to show: open this page as reader.html#file=your.pdf');
    return null;
  }
  // A published book keeps its page in the address (#page=N, passage links #page=N&text=...); a PDF's
  // address is its #file=.
  const source = published ? { document: published } : { pdf: file };
  try {
    if (file) document.title = decodeURIComponent(new URL(file).pathname.split('/').pop() || document.title);
    // A page that fails shows plain paper; the reason goes to the console, for whoever runs the site.
    const pageerror = ({ detail }) => console.warn(`conecurl reader: page ${detail.index + 1} could not be shown (${detail.reason}): ${detail.error?.message ?? ''}`);
    return await Flipbook.create(main, { ...source, controls: true, hash: Boolean(published), on: { pageerror } });
  } catch (error) {
    if (error?.fallback) return error.fallback;  // no WebGL2: the pages still show, as still pages
    showProblem(`This book could not be opened. ${error?.message ?? error}`);
    return null;
  }
}

/** The book on the page, once open (null when it could not be opened): for the page's own scripts. */
export const book = open();
