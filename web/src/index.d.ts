// Types of the package's main entry ('conecurl'), re-exported from the modules they describe.
export * from './book/flipbook.js';
export * from './book/static-book.js';
export * from './pages/page-loader.js';
export * from './surfaces/book-view.js';
export * from './engine/load-engine.js';
