// Node tests of the book's option checks (web/src/book/options.js): every option refuses NaN, negatives,
// wrong types and its neighbours' values with a TypeError that names it and says what is allowed;
// page entries, sparse page arrays and unknown keys too. No DOM is needed to check options.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { checkFlipOptions, checkLiveOptions, DEFAULTS, describeValue, pageEntries, validateOptions } from '../../web/src/book/options.js';

const pages = ['a.png', 'b.png', 'c.png'];

/** Asserts options are refused with a TypeError whose message is exactly "conecurl: <expected>". */
function refuses(options, expected) {
  assert.throws(() => validateOptions(options), (error) => {
    assert.ok(error instanceof TypeError, `${JSON.stringify(options)}: ${error}`);
    assert.equal(error.message, `conecurl: ${expected}`);
    return true;
  });
}

test('node: every option refuses NaN, negative, wrong-type values with a TypeError naming it and what it allows', () => {
  const allowed = {
    display: "'single', 'double' or 'auto'",
    minPageWidth: 'a positive number of CSS pixels',
    direction: "'ltr', 'rtl' or 'vertical'",
    startPage: 'a page index (a whole number from 0)',
    duration: 'a positive number of milliseconds',
    schedule: "'paper' or 'smooth'",
    center: 'true or false',
    hardCovers: 'true or false',
    lighting: 'true or false',
    shadows: 'true or false',
    gutter: 'true or false',
    showThrough: 'a number from 0 (none) to 1',
    thickness: "true, false or a leaf's thickness as a fraction of the page width (0 to 0.02)",
    loadWindow: 'a whole number of pages from 1',
    wasmUrl: 'a URL string',
    label: 'a non-empty string',
    fallback: 'true or false',
    hash: 'true or false',
    autoplay: 'true, false or { interval: milliseconds, loop: true or false }',
    sound: 'true or false',
    muted: 'true or false',
    rememberPage: 'a non-empty string (the key it is kept under)',
    antialias: "'auto', true or false",
    resolution: "'auto', 'full' or a positive number of device pixels per CSS pixel",
    on: 'an object of listeners by event name (ready, progress, pageerror, turnstart, turned, turncancel, resize, zoom, sharpened, link, pageschange, error, searchchange, fullscreenchange, download, print, passagelink, displaychange, middletap, readaloudstart, readaloudpage, readaloudword, readaloudsentence, readaloudvoices, readaloudpause, readaloudresume, readaloudend)',
    outline: 'an array of { title, page, children? }',
    download: 'a URL string',
    // viewer (issue 23): the shape here; the part and label names are the viewer's (viewer-options.test.mjs)
    controls: 'true, false or an object of parts to show or hide',
    labels: 'an object of texts by key',
    textLayer: 'true or false',
    readAloudMemory: 'false or a non-empty string (the localStorage key the voice and speed are kept under)',
  };
  const bad = {
    display: [NaN, 'triple', 2, null, ['double']],
    minPageWidth: [NaN, 0, -300, Infinity, '300', null, true],
    direction: ['LTR', -1, undefined, {}],
    startPage: [NaN, -1, 1.5, '1', Infinity, null],
    duration: [NaN, -1, 0, Infinity, '300', null],
    schedule: ['Smooth', 'eased', 1, null, true],
    center: ['yes', 1, null, NaN],
    hardCovers: ['true', 1, NaN, null],
    lighting: ['yes', 0, NaN],
    shadows: ['false', -1],
    gutter: [null, 'off'],
    showThrough: [NaN, -0.1, 1.01, Infinity, '0.1', null, true],
    thickness: [NaN, -0.001, 0.021, Infinity, '0.004', null],
    loadWindow: [NaN, -2, 0, 2.5, '4', Infinity],
    wasmUrl: [42, null, {}, NaN],
    label: ['', '   ', 42, null, NaN],
    fallback: ['no', 0, NaN],
    hash: ['true', 1, null],
    autoplay: ['yes', 3000, null, { interval: 0 }, { interval: NaN }, { loop: 'yes' }, { speed: 2 }],
    sound: ['on', 1, null, NaN],
    muted: ['true', 0, undefined],
    rememberPage: ['', '  ', 3, null, true],
    antialias: ['AUTO', 'on', 1, null, NaN],
    resolution: ['Auto', 'half', 0, -1.5, NaN, Infinity, '1.5', null, true],
    on: [null, [], () => {}, { turnd: () => {} }, { turned: 'log' }, { ready: null }],
    outline: [null, {}, 'toc', 3],
    download: ['', '  ', 3, null, true],
    controls: ['yes', 1, null, []],
    labels: [null, 'Suivant', [], { next: 3 }],
    textLayer: ['true', 1, null],
    readAloudMemory: ['', '  ', true, 0, null],
  };
  assert.deepEqual(Object.keys(bad).sort(), Object.keys(allowed).sort());
  for (const [option, values] of Object.entries(bad)) {
    for (const value of values) refuses({ pages, [option]: value }, `option '${option}' must be ${allowed[option]}, got ${describeValue(value)}`);
  }
  // Every option but `pages` has a default, so the table above covers them all.
  assert.deepEqual(Object.keys(DEFAULTS).sort(), Object.keys(allowed).filter((k) => !['wasmUrl', 'on', 'rememberPage', 'outline', 'download', 'labels'].includes(k)).sort());
});

test('node: pages must be a non-empty array of page sources; each entry is checked by index, src, alt, hard and key', () => {
  const sources = 'a URL string, HTMLImageElement, HTMLCanvasElement, ImageBitmap, Blob, a function returning one of these (or a Promise of one), or an HTML element (an HTML page)';
  const arrayRule = 'a non-empty array of at most 1000000 page sources';
  refuses({ pages: [] }, `option 'pages' must be ${arrayRule}, got an array of 0`);
  refuses({ pages: 'a.png' }, `option 'pages' must be ${arrayRule}, got "a.png"`);
  refuses({ pages: NaN }, `option 'pages' must be ${arrayRule}, got NaN`);
  refuses({ display: 'single' }, "option 'pages' is missing (a non-empty array of page sources)");
  refuses({ pages: ['a.png', 42] }, `option 'pages[1]' must be ${sources}, or { src, alt, hard }; got 42`);
  refuses({ pages: ['a.png', ''] }, `option 'pages[1]' must be ${sources}, or { src, alt, hard }; got ""`);
  refuses({ pages: ['a.png', null] }, `option 'pages[1]' must be ${sources}, or { src, alt, hard }; got null`);
  refuses({ pages: ['a.png', , 'c.png'] }, `option 'pages[1]' must be ${sources}, or { src, alt, hard }; got undefined`);  // eslint-disable-line no-sparse-arrays
  refuses({ pages: [{ src: 5 }] }, `option 'pages[0].src' must be ${sources}; got 5`);
  refuses({ pages: [{ alt: 'no source' }] }, `option 'pages[0].src' must be ${sources}; got undefined`);
  refuses({ pages: [{ src: 'a.png', alt: 5 }] }, "option 'pages[0].alt' must be a string (the page's text for screen readers); got 5");
  refuses({ pages: [{ src: 'a.png', hard: 'yes' }] }, "option 'pages[0].hard' must be true or false; got \"yes\"");
  refuses({ pages: [{ src: 'a.png', title: 'x' }] }, "option 'pages[0]' has an unknown key 'title' (allowed: src, html, alt, hard, zoomSrc, thumbSrc, placeholder, links, narration)");
  refuses({ pages: [{ src: 'a.png', zoomSrc: () => 'b.png' }] },
    "option 'pages[0].zoomSrc' must be a URL, HTMLImageElement, HTMLCanvasElement, ImageBitmap or Blob; got a function");
  refuses({ pages: [{ src: 'a.png', placeholder: 5 }] },
    "option 'pages[0].placeholder' must be a URL, HTMLImageElement, HTMLCanvasElement, ImageBitmap or Blob; got 5");
  refuses({ pages: [{ src: 'a.png', links: {} }] }, "option 'pages[0].links' must be an array of { rect, href } or { rect, page }; got an object");
  refuses({ pages: [{ src: 'a.png', links: [{ rect: [0, 0, 2, NaN], href: 'x' }] }] },
    "option 'pages[0].links[0].rect' must be [x, y, width, height] as fractions of the page (0 to 1); got an array of 4");
  refuses({ pages: ['a.png', { src: 'b.png', links: [{ rect: [0, 0, 1, 1], page: 2 }] }] },
    "option 'pages[1].links[0].page' must be a page index below 2; got 2");
  refuses({ pages: [['a.png']] }, `option 'pages[0]' must be ${sources}, or { src, alt, hard }; got an array of 1`);
  // Accepted: URLs, Blobs, functions and entries with them.
  const blob = new Blob(['x']);
  const fn = () => 'a.png';
  const settings = validateOptions({ pages: ['a.png', blob, fn, { src: 'b.png', alt: 'B', hard: true, links: [{ rect: [0, 0, 0.5, 0.5], page: 0 }] }] });
  assert.deepEqual(pageEntries(settings.pages), [{ src: 'a.png' }, { src: blob }, { src: fn },
    { src: 'b.png', alt: 'B', hard: true, links: [{ rect: [0, 0, 0.5, 0.5], href: '#', toPage: 0, title: undefined }] }]);
});

test('node: options that are not an object, unknown keys, and a start page past the end are refused by name', () => {
  refuses(null, 'options must be an object, got null');
  refuses('pages', 'options must be an object, got "pages"');
  refuses({ pages, colour: 'red' }, "unknown option 'colour' (allowed: pages, display, minPageWidth, direction, startPage, duration, schedule, center, hardCovers, "
    + 'lighting, shadows, gutter, showThrough, thickness, loadWindow, wasmUrl, label, fallback, hash, autoplay, sound, muted, rememberPage, antialias, resolution, turnArea, on, outline, download, edgeMarks, controls, labels, textLayer, readAloudMemory)');
  refuses({ pages, antialias: 'yes' }, "option 'antialias' must be 'auto', true or false, got \"yes\"");
  refuses({ pages, startPage: 3 }, "option 'startPage' must be below the page count 3, got 3");
  // A value whose own toString throws or is huge is described, not called.
  const hostile = { toString() { throw new Error('gotcha'); } };
  refuses({ pages, display: hostile }, "option 'display' must be 'single', 'double' or 'auto', got an object");
  refuses({ pages, label: Symbol('x') }, "option 'label' must be a non-empty string, got a symbol");
  refuses({ pages, display: 'x'.repeat(500) }, `option 'display' must be 'single', 'double' or 'auto', got "${'x'.repeat(57)}..."`);
});

test('node: setOptions takes only lighting, shadows, gutter, showThrough, thickness, resolution, display, minPageWidth, sound and muted, checked; flip options are { animate: boolean }', () => {
  assert.deepEqual(checkLiveOptions({ lighting: false }, pages), { lighting: false });
  assert.deepEqual(checkLiveOptions({ minPageWidth: 150 }, pages), { minPageWidth: 150 });
  assert.throws(() => checkLiveOptions({ minPageWidth: -1 }, pages), /option 'minPageWidth' must be a positive number of CSS pixels, got -1/);
  assert.deepEqual(checkLiveOptions({ display: 'single' }, pages), { display: 'single' });
  assert.throws(() => checkLiveOptions({ display: 'triple' }, pages), /option 'display' must be 'single', 'double' or 'auto'/);
  assert.throws(() => checkLiveOptions({ direction: 'rtl' }, pages), /option 'direction' cannot change on a live book \(only lighting, shadows, gutter, showThrough, thickness, resolution, display, minPageWidth, sound, muted\)/);
  assert.deepEqual(checkLiveOptions({ showThrough: 0 }, pages), { showThrough: 0 });
  assert.throws(() => checkLiveOptions({ showThrough: 1.5 }, pages), /option 'showThrough' must be a number from 0 \(none\) to 1, got 1.5/);
  assert.deepEqual(checkLiveOptions({ resolution: 1.5 }, pages), { resolution: 1.5 });
  assert.deepEqual(checkLiveOptions({ resolution: 'full' }, pages), { resolution: 'full' });
  assert.throws(() => checkLiveOptions({ resolution: 0 }, pages), /option 'resolution' must be 'auto', 'full' or a positive number of device pixels per CSS pixel, got 0/);
  assert.deepEqual(checkLiveOptions({ sound: true, muted: true }, pages), { sound: true, muted: true });
  assert.throws(() => checkLiveOptions({ muted: 'yes' }, pages), /option 'muted' must be true or false, got "yes"/);
  assert.deepEqual(checkLiveOptions({ thickness: 0.01 }, pages), { thickness: 0.01 });
  assert.deepEqual(checkLiveOptions({ thickness: false }, pages), { thickness: false });
  assert.throws(() => checkLiveOptions({ thickness: 0.5 }, pages), /option 'thickness' must be true, false or a leaf's thickness/);
  assert.throws(() => checkLiveOptions({ shadows: NaN }, pages), /option 'shadows' must be true or false, got NaN/);
  assert.throws(() => checkLiveOptions(undefined, pages), /options must be an object, got undefined/);
  assert.deepEqual(checkFlipOptions(undefined), { animate: true });
  assert.deepEqual(checkFlipOptions({ animate: false }), { animate: false });
  assert.throws(() => checkFlipOptions({ animate: 0 }), (e) => e instanceof TypeError && /flip option 'animate' must be true or false, got 0/.test(e.message));
  assert.throws(() => checkFlipOptions({ speed: 2 }), /unknown flip option 'speed' \(allowed: animate\)/);
  assert.throws(() => checkFlipOptions(null), /flip options must be an object like \{ animate: false \}, got null/);
});

test('node: turnArea is one of page, edges, corners, none; its default is edges for a book with HTML pages, else page', () => {
  assert.equal(validateOptions({ pages: ['a.jpg'] }).turnArea, 'page');
  assert.equal(validateOptions({ pages: ['a.jpg'], turnArea: 'corners' }).turnArea, 'corners');
  assert.throws(() => validateOptions({ pages: ['a.jpg'], turnArea: 'middle' }),
    { name: 'TypeError', message: "conecurl: option 'turnArea' must be 'page', 'edges', 'corners' or 'none', got \"middle\"" });
  assert.throws(() => validateOptions({ pages: [{ html: 'a <b>string</b>' }] }),
    { name: 'TypeError', message: /option 'pages\[0\]\.html' must be an HTML element .*strings are never parsed as HTML/ });
});

test('node: a PDF book (validateOptions told pdf) turns from the edges by default while its text layer is on; textLayer is a boolean, default true', () => {
  assert.equal(validateOptions({ pages: ['a.jpg'] }, { document: true }).turnArea, 'edges');
  assert.equal(validateOptions({ pages: ['a.jpg'] }, { document: true }).textLayer, true);
  assert.equal(validateOptions({ pages: ['a.jpg'], textLayer: false }, { document: true }).turnArea, 'page');
  assert.equal(validateOptions({ pages: ['a.jpg'], turnArea: 'page' }, { document: true }).turnArea, 'page');
  assert.equal(validateOptions({ pages: ['a.jpg'] }).turnArea, 'page');  // an image book has no text layer
  assert.throws(() => validateOptions({ pages: ['a.jpg'], textLayer: 'yes' }),
    { name: 'TypeError', message: 'conecurl: option \'textLayer\' must be true or false, got "yes"' });
});

test('node: schedule is \'paper\' (default) or \'smooth\'', () => {
  assert.equal(validateOptions({ pages: ['a.jpg'] }).schedule, 'paper');
  assert.equal(validateOptions({ pages: ['a.jpg'], schedule: 'smooth' }).schedule, 'smooth');
  assert.throws(() => validateOptions({ pages: ['a.jpg'], schedule: 'bouncy' }),
    { name: 'TypeError', message: "conecurl: option 'schedule' must be 'paper' or 'smooth', got \"bouncy\"" });
});

test('node: edgeMarks is true or false, off by default without controls', () => {
  assert.equal(validateOptions({ pages: ['a.jpg'] }).edgeMarks, false);
  assert.equal(validateOptions({ pages: ['a.jpg'], edgeMarks: true }).edgeMarks, true);
  assert.throws(() => validateOptions({ pages: ['a.jpg'], edgeMarks: 'yes' }),
    { name: 'TypeError', message: "conecurl: option 'edgeMarks' must be true or false, got \"yes\"" });
});
