// The modules the reader page (reader.js) imports on the way to a published book's first spread, beyond
// reader.js's static imports: the book imports them when its options ask (the document, the toolbar, the
// page in the address, the edge marks, the text layer, the voices its Read aloud button asks for).
// `conecurl publish` preloads them from index.html so they come in one round trip with the rest;
// publish.spec checks this list against what the page asks for.
export const FIRST_VIEW_MODULES = [
  'web/src/book/page-memory.js',
  'web/src/document/book-outline.js',
  'web/src/document/edge-marks.js',
  'web/src/document/format.js',
  'web/src/document/passage-address.js',
  'web/src/document/published-document.js',
  'web/src/engine/language.js',
  'web/src/engine/voice-choice.js',
  'web/src/layers/edge-tabs.js',
  'web/src/layers/text-layer.js',
  'web/src/layers/text-measure.js',
  'web/src/read-aloud/speech-engine.js',
  'web/src/viewer/attach-controls.js',
  'web/src/viewer/contents-panel.js',
  'web/src/viewer/more-menu.js',
  'web/src/viewer/panel.js',
  'web/src/viewer/read-aloud-menu.js',
  'web/src/viewer/reading-mode.js',
  'web/src/viewer/roving-focus.js',
  'web/src/viewer/search-panel.js',
  'web/src/viewer/thumbnails-panel.js',
  'web/src/viewer/toolbar.js',
  'web/src/viewer/viewer-icons.js',
  'web/src/viewer/viewer-labels.js',
  'web/src/viewer/viewer-options.js',
  'web/src/viewer/viewer-style.js',
];
