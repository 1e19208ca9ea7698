// Issues 30 and 38's targets for the published reader's first spread, in one place: first-spread.mjs measures
// against them on a throttled phone, tests/node/reader-budget.test.mjs holds the JavaScript one as built.
/** The first spread in at most a third of pdf.js's time, after at most 300 KB, 8 requests and 45 KB of compressed JavaScript. */
export const FIRST_SPREAD_TARGETS = Object.freeze({ timeRatio: 1 / 3, bytes: 300 * 1024, requests: 8, scriptBytes: 45 * 1024 });
