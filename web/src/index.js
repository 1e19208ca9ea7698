// The package's main entry ('conecurl'): the Flipbook class, and the lower layers for tools.
export { Flipbook } from './flipbook.js';
export { StaticBook } from './static-book.js';
export { PageLoadError } from './page-loader.js';
export { BookView } from './book-view.js';
export { loadEngine } from './engine.js';
