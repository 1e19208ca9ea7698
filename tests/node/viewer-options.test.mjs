// Node tests of the viewer's option tables (web/src/viewer/viewer-options.js, viewer-labels.js): which
// toolbar parts a `controls` value shows (Download and Print by the book's kind unless given), the
// label texts filled in with numbers, and attachControls' TypeError for a bad option. No DOM needed.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { CONTROL_PARTS, checkControls, checkLabels, shownParts } from '../../web/src/viewer/viewer-options.js';
import { DEFAULT_LABELS, LABEL_KEYS, fill, viewerLabels } from '../../web/src/viewer/viewer-labels.js';
import { attachControls } from '../../web/src/viewer.js';

const on = (parts) => CONTROL_PARTS.filter((part) => parts[part]);

test('node: controls: true shows every part but Download, Print and Keep offline on an image book; a PDF shows Download and Print, a download URL shows Download; { keepOffline: true } shows Keep offline', () => {
  const shown = CONTROL_PARTS.filter((part) => part !== 'keepOffline');
  const all = shown.filter((part) => part !== 'download' && part !== 'print');
  assert.deepEqual(on(shownParts(true, { pdf: false, downloadUrl: false })), all);
  assert.deepEqual(on(shownParts(true, { pdf: true, downloadUrl: false })), shown);
  assert.deepEqual(on(shownParts(true, { pdf: false, downloadUrl: true })), shown.filter((part) => part !== 'print'));
  assert.deepEqual(on(shownParts({ keepOffline: true }, { pdf: false, downloadUrl: false })), [...all, 'keepOffline']);
});

test('node: an object of parts hides those set false and shows Download or Print when set true, whatever the book', () => {
  const parts = shownParts({ thumbnails: false, zoom: false, print: true }, { pdf: false, downloadUrl: false });
  assert.equal(parts.thumbnails, false);
  assert.equal(parts.zoom, false);
  assert.equal(parts.print, true);
  assert.equal(parts.download, false);
  assert.equal(parts.search, true);
  assert.equal(shownParts({ download: false }, { pdf: true, downloadUrl: true }).download, false);
});

test('node: the option checks say what is allowed; labels fill their numbers and keep the defaults under what is given', () => {
  assert.equal(checkControls(true), true);
  assert.equal(checkControls({ search: false }), true);
  assert.match(checkControls({ share: false }), /previous, next, page, zoom, fullscreen, thumbnails, contents, search, download, print/);
  assert.equal(checkLabels({ next: 'Suivant' }), true);
  assert.match(checkLabels({ next: '' }), /non-empty string/);
  assert.deepEqual(Object.keys(DEFAULT_LABELS), LABEL_KEYS);
  const labels = viewerLabels({ next: 'Suivant', pageOf: '{n} sur {total}' });
  assert.equal(labels.next, 'Suivant');
  assert.equal(labels.previous, 'Previous page');
  assert.equal(fill(labels.pageOf, { n: '6\u20137', total: 12 }), '6\u20137 sur 12');
  assert.equal(fill('Page {n} of {missing}', { n: 3 }), 'Page 3 of {missing}');
});

test('node: attachControls refuses a bad option with a TypeError naming it, before touching the book', () => {
  const book = new Proxy({}, { get() { throw new Error('the book was touched'); } });
  assert.throws(() => attachControls(book, { controls: { share: false } }), (error) => error instanceof TypeError
    && /attachControls option 'controls' must be/.test(error.message));
  assert.throws(() => attachControls(book, { labels: { nextPage: 'Suivant' } }), (error) => error instanceof TypeError
    && /attachControls option 'labels' must be/.test(error.message));
});

test('node: Keep offline says sizes as people read them: KB under a megabyte (at least 1), MB with one decimal under 100 MB (needs nothing)', async () => {
  const { sizeText } = await import('../../web/src/viewer/keep-offline.js');
  assert.deepEqual([120, 90_400, 999_000, 4_250_000, 12_500_000, 340_000_000].map(sizeText), ['1 KB', '90 KB', '999 KB', '4.3 MB', '12.5 MB', '340 MB']);
});
