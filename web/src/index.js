// The package's main entry ('conecurl'): the Flipbook class, and the lower layers for tools.
export { Flipbook } from './book/flipbook.js';
export { StaticBook } from './book/static-book.js';
export { PageLoadError } from './pages/page-loader.js';
export { BookView } from './surfaces/book-view.js';
export { loadEngine } from './engine/load-engine.js';
