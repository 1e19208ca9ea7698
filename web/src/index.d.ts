// Types of the package's main entry ('conecurl'), re-exported from the modules they describe.
export * from './flipbook.js';
export * from './static-book.js';
export * from './page-loader.js';
export * from './book-view.js';
export * from './engine.js';
