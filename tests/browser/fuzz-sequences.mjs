// Random command lists for the random-sequence test (fuzz.spec.js, scripts/fuzz.mjs): fast-check
// arbitraries of the calls, options and DOM input a page can throw at a Flipbook, valid and invalid,
// in the form the fixture's window.fuzz.run() executes. Invalid values carry the option they break.
import fc from 'fast-check';

/** Lane books at the start: the layouts a fuzz run begins from (turns of 1-20 ms). */
export const LANE_OPTIONS = [
  { pages: 6, duration: 8 },
  { pages: 1, display: 'double', duration: 3 },
  { pages: 2, display: 'single', direction: 'rtl', duration: 12 },
  { pages: 5, display: 'double', direction: 'vertical', duration: 5 },
  { pages: 12, loadWindow: 1, hardCovers: true, duration: 1 },
  { pages: 3, display: 'auto', direction: 'rtl', startPage: 2, duration: 20 },
  { pages: 7, display: 'single', direction: 'vertical', lighting: false, duration: 6 },
  { pages: 9, display: 'auto', hardCovers: true, loadWindow: 2, shadows: false, duration: 15 },
];

const flag = fc.boolean();

// ---- Flipbook.create options -----------------------------------------------------------------

const validCreate = fc.record({
  pages: fc.integer({ min: 1, max: 12 }),
  display: fc.constantFrom('single', 'double', 'auto'),
  direction: fc.constantFrom('ltr', 'rtl', 'vertical'),
  startPage: fc.nat(11),
  duration: fc.integer({ min: 1, max: 20 }),
  hardCovers: flag,
  lighting: flag,
  shadows: flag,
  gutter: flag,
  loadWindow: fc.integer({ min: 1, max: 3 }),
  label: fc.constantFrom('Book', 'Catalogue <img src=x onerror=alert(1)>'),
  antialias: fc.constantFrom('auto', true, false),
  turnArea: fc.constantFrom('page', 'edges', 'corners', 'none'),
  htmlPages: flag,  // not an option: the fixture makes every fourth page a live HTML page
}, { requiredKeys: ['pages', 'duration'] }).map((options) => {
  if (options.startPage !== undefined) options.startPage %= options.pages;
  return options;
});

// option -> values it must refuse with a TypeError naming it.
const BAD_CREATE_VALUES = {
  pages: [0, 'bad-entry', null, 'pages.png'],
  display: ['triple', 2, null],
  direction: ['up', ''],
  startPage: [-1, 1.5, Number.NaN, '0', 99],
  duration: [0, -5, Number.NaN, Number.POSITIVE_INFINITY, '10'],
  hardCovers: ['yes', 1],
  lighting: [1, 'false'],
  shadows: [null],
  gutter: [0],
  loadWindow: [0, 2.5, -1, Number.NaN],
  label: ['', '   ', 7],
  wasmUrl: [5],
  antialias: ['on', 1, null],
  colour: ['red'],
};

const invalidCreate = fc.tuple(validCreate, fc.constantFrom(...Object.keys(BAD_CREATE_VALUES)), fc.nat())
  .map(([options, culprit, pick]) => {
    const bad = BAD_CREATE_VALUES[culprit];
    const value = bad[pick % bad.length];
    const out = { ...options, [culprit]: value };
    // A startPage past the end must be past this book's end; the message names 'startPage'.
    if (culprit === 'startPage' && value === 99) out.pages = Math.min(out.pages, 12);
    return { options: out, culprit };
  });

export const createCommand = fc.oneof(
  { weight: 3, arbitrary: validCreate.map((options) => ({ options, culprit: null })) },
  { weight: 2, arbitrary: invalidCreate },
).map((spec) => ['create', spec]);

// ---- setOptions ---------------------------------------------------------------------------------

const effectOption = fc.constantFrom('lighting', 'shadows', 'gutter');
const validSetOptions = fc.record({
  effects: fc.dictionary(effectOption, flag, { maxKeys: 3 }),
  display: fc.option(fc.constantFrom('single', 'double', 'auto'), { nil: undefined }),
}).map(({ effects, display }) => ({ options: display === undefined ? effects : { ...effects, display }, culprit: null }));
const invalidSetOptions = fc.oneof(
  fc.tuple(effectOption, fc.constantFrom('yes', 1, null, 0, Number.NaN)).map(([key, value]) => ({ options: { [key]: value }, culprit: key })),
  fc.constantFrom('triple', 2, null).map((value) => ({ options: { display: value }, culprit: 'display' })),
  // Options fixed for a book's life: valid values, refused because the book is live.
  fc.constantFrom(['duration', 500], ['direction', 'rtl'], ['startPage', 0], ['loadWindow', 2],
    ['label', 'New'], ['hardCovers', true]).map(([key, value]) => ({ options: { [key]: value, lighting: true }, culprit: key })),
  fc.constant({ options: { colour: 'red' }, culprit: 'colour' }),
  fc.constantFrom(null, 'lighting', 42).map((options) => ({ options, culprit: 'options' })),
);
const setOptionsCommand = fc.oneof(validSetOptions, invalidSetOptions).map((spec) => ['setOptions', spec]);

// ---- input ----------------------------------------------------------------------------------------

// Fractions of the resting pages' rectangle: corners and edges often, anywhere (and a little outside) too.
const fraction = fc.oneof(
  fc.constantFrom(0, 0.01, 0.04, 0.25, 0.5, 0.75, 0.96, 0.99, 1, -0.05, 1.05),
  fc.double({ min: -0.2, max: 1.2, noNaN: true }),
);
const pointerKind = fc.constantFrom('mouse', 'mouse', 'touch');
const key = fc.constantFrom('ArrowRight', 'ArrowLeft', 'ArrowDown', 'ArrowUp', 'PageDown', 'PageUp', 'Home', 'End', 'a', ' ', 'Enter');
const keyOptions = fc.record({ repeat: flag, ctrlKey: flag, shiftKey: flag }, { requiredKeys: [] });
const flipIndex = fc.oneof(
  { weight: 6, arbitrary: fc.integer({ min: 0, max: 12 }) },
  { weight: 1, arbitrary: fc.constantFrom(-1, 1.5, Number.NaN, Number.POSITIVE_INFINITY, '3', null, undefined, 1e9) },
);

// Where a live page change acts: mostly in or just past the book, sometimes not a page index at all.
const spliceIndex = fc.oneof(
  { weight: 6, arbitrary: fc.integer({ min: 0, max: 14 }) },
  { weight: 1, arbitrary: fc.constantFrom(-1, 1.5, Number.NaN, '2', null) },
);

/** One call or event. Weights keep the costly ones (a new WebGL context, real frames) rare. */
export const command = fc.oneof(
  { weight: 40, arbitrary: fc.constant(['next']) },
  { weight: 25, arbitrary: fc.constant(['prev']) },
  { weight: 20, arbitrary: fc.tuple(fc.constant('flip'), flipIndex, fc.option(flag, { nil: undefined })) },
  { weight: 15, arbitrary: fc.tuple(fc.constant('frames'), fc.integer({ min: 1, max: 3 })) },
  { weight: 10, arbitrary: setOptionsCommand },
  { weight: 15, arbitrary: fc.constant(['read']) },
  { weight: 15, arbitrary: fc.tuple(fc.constant('click'), fraction, fraction) },
  { weight: 20, arbitrary: fc.tuple(fc.constant('key'), key, keyOptions) },
  { weight: 35, arbitrary: fc.tuple(fc.constant('pointer'), fc.constantFrom('down', 'move', 'move', 'move', 'up', 'cancel'), pointerKind, fraction, fraction) },
  { weight: 4, arbitrary: fc.constant(['leave']) },
  { weight: 1, arbitrary: fc.tuple(fc.constant('resize'), fc.integer({ min: 0, max: 320 }), fc.integer({ min: 0, max: 200 })) },
  { weight: 5, arbitrary: fc.tuple(fc.constant('insert'), spliceIndex, fc.integer({ min: 1, max: 3 }), flag) },
  { weight: 4, arbitrary: fc.tuple(fc.constant('remove'), spliceIndex, fc.oneof(fc.integer({ min: 1, max: 3 }), fc.constantFrom(0, -1, 2.5))) },
  { weight: 4, arbitrary: fc.tuple(fc.constant('replace'), spliceIndex, flag) },
  { weight: 1, arbitrary: fc.constant(['destroy']) },
  { weight: 1, arbitrary: createCommand },
);

/** One sequence: a short command list for one book. */
export const sequence = fc.array(command, { minLength: 1, maxLength: 8 });

/** One run: a sequence per lane, run side by side on the lanes' books. */
export const batch = (lanes) => fc.tuple(...Array.from({ length: lanes }, () => sequence));
