// The fixed seeds the random-sequence test (fuzz.spec.js) runs in `npm test`, so that every run of the
// suite tries the same sequences. New seeds are drawn by `npm run fuzz` (scripts/fuzz.mjs), never here.
//
// Every seed that ever found a bug stays in this list as a regression case, with what it found
// (tests/node/test-rules.test.mjs holds every seed a test names to this list). A
// seed draws the same sequences only while fuzz-sequences.mjs and LANE_OPTIONS stay as they were, so
// each bug also has a test of its own in fuzz-regressions.spec.js that does not depend on the seed.
// `sequences` is how many sequences the seed runs (the lanes carry their books from one run to the
// next, so a failure at sequence N needs the N before it); together they keep the suite's 10 000.

/** @type {{ seed: number, sequences: number, found: string }[]} */
export const FUZZ_SEEDS = [
  { seed: 313494504, sequences: 2000, found: 'a lane with inserted HTML pages did not settle in 600 frames while its loads ran on a loaded machine (the settle raced real time; now it waits for the loads)' },
  { seed: 279114954, sequences: 1000, found: 'nothing: the seed of the last clean 10 000-sequence run before the list was fixed' },
  { seed: 275849420, sequences: 1000, found: 'an animated flip whose page is removed while it turns asked the engine for a page past the end (RangeError)' },
  { seed: 274878860, sequences: 1000, found: 'destroy() between a riffle\'s two waits left it reading a null surface (TypeError)' },
  { seed: 273907716, sequences: 1000, found: 'a far flip riffled to a stale position after the display switched while it waited (RangeError)' },
  { seed: 265673574, sequences: 1000, found: 'an HTML page in a book squeezed to a few pixels got a snapshot canvas with no pixels (a pageerror)' },
  { seed: 99440867, sequences: 1000, found: 'a page loading under a hover hint left the live region announcing the spread under the hint' },
  { seed: 275635925, sequences: 1000, found: 'a page change asked for right after create() applied before the held create() events went out, so ready told of the changed book' },
  { seed: 7819076, sequences: 1000, found: 'a drag whose held turn was ended by a jumping flip() threw \'no held turn to drag\' on its next move' },
];
