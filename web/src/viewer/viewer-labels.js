// The texts of the toolbar and its panels, by key, so a book can be translated (the `labels` option):
// the defaults, the keys allowed, and the few texts made from numbers ("3 of 17", "Page 12").

/** Every label and its English default. `{n}`, `{total}`, `{size}` and `{percent}` are filled in where a number goes. */
export const DEFAULT_LABELS = Object.freeze({
  toolbar: 'Book controls',
  previous: 'Previous page',
  next: 'Next page',
  page: 'Page',
  pageOf: '{n} of {total}',
  zoomIn: 'Zoom in',
  zoomOut: 'Zoom out',
  fullscreen: 'Fullscreen',
  thumbnails: 'Thumbnails',
  contents: 'Contents',
  search: 'Search',
  download: 'Download',
  print: 'Print',
  close: 'Close',
  thumbnail: 'Page {n}',
  noContents: 'This book has no contents.',
  searchField: 'Search the book',
  previousHit: 'Previous result',
  nextHit: 'Next result',
  hitOf: '{n} of {total}',
  noHits: 'No results',
  searching: 'Searching\u2026',
  hitPage: 'Page {n}',
  more: 'More',
  read: 'Read',
  exitReading: 'Exit reading',
  readAloud: 'Read aloud',
  pauseReading: 'Pause reading',
  readAloudSettings: 'Voice and speed',
  voice: 'Voice',
  speed: 'Speed',
  defaultVoice: 'Browser\'s default',
  voiceLanguage: 'Language',
  keepOffline: 'Keep offline ({size})',
  keepingOffline: 'Keeping offline: {percent}% of {size}',
  keptOffline: 'Kept offline',
  keepOfflineFailed: 'Keeping offline stopped: the network failed. Try again online.',
});
export const LABEL_KEYS = Object.keys(DEFAULT_LABELS);

/** The labels in effect: the defaults with `given` over them. */
export function viewerLabels(given = {}) {
  return { ...DEFAULT_LABELS, ...given };
}

/** A label with its numbers filled in: fill('Page {n}', { n: 3 }) is "Page 3". */
export function fill(text, numbers) {
  return text.replace(/\{(\w+)\}/g, (whole, name) => (name in numbers ? String(numbers[name]) : whole));
}
