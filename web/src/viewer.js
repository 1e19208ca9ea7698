// conecurl/viewer: the toolbar and its panels (thumbnails, contents, search) for a book you made, the
// same that the `controls` option shows, built on the book's public API alone.
export { attachControls } from './viewer/attach-controls.js';
export { DEFAULT_LABELS } from './viewer/viewer-labels.js';
export { CONTROL_PARTS } from './viewer/viewer-options.js';
