// Browser: random sequences of API calls, options and input (fast-check, property-based) against eight
// Flipbooks at once: no uncaught exception or unhandled rejection, bad arguments refused with an error
// naming them, and after each sequence every book settles with its invariants holding.
import { test, expect } from '@playwright/test';
import fc from 'fast-check';
import { openReady } from './helpers.js';
import { LANE_OPTIONS, batch } from './fuzz-sequences.mjs';

const FIXTURE = '/tests/browser/fixtures/fuzz-fixture.html';
const SEQUENCES = Number(process.env.CONECURL_FUZZ_SEQUENCES) || 10_000;
const SEED = Number(process.env.CONECURL_FUZZ_SEED) || Date.now() % 2 ** 31;

test(`browser: ${SEQUENCES} random sequences of calls, options and input leave no uncaught error and every book settled in range (fast-check)`, async ({ page }) => {
  test.setTimeout(600_000);
  const problems = await openReady(page, FIXTURE);
  const setup = await page.evaluate((options) => window.fuzz.init(options), LANE_OPTIONS);
  expect(setup).toEqual([]);
  const lanes = LANE_OPTIONS.length;
  const started = Date.now();
  let runs = 0;
  const outcome = await fc.check(fc.asyncProperty(batch(lanes), async (programs) => {
    runs++;
    if (process.env.CONECURL_FUZZ_PROGRESS && runs % 50 === 0) console.log(`fuzz: run ${runs}, ${((Date.now() - started) / 1000).toFixed(1)} s`);
    const failures = await page.evaluate((programs) => window.fuzz.run(programs), programs);
    if (failures.length > 0) throw new Error(failures.join('\n'));
  }), { numRuns: Math.ceil(SEQUENCES / lanes), seed: SEED, endOnFailure: false, markInterruptAsFailure: true });
  const seconds = (Date.now() - started) / 1000;
  const stats = await page.evaluate(() => window.fuzz.stats());
  const summary = `fuzz: seed ${SEED}, ${runs} runs of ${lanes} lanes: ${stats.sequences} sequences, ${stats.calls} calls `
    + `(${stats.expectedErrors} refused as expected), ${stats.turnsLanded} turns landed, ${stats.creates} books created, `
    + `${stats.framesStepped} frames, ${seconds.toFixed(1)} s; ${outcome.failed ? 'FAILED' : 'no failure'}`;
  console.log(summary);
  test.info().annotations.push({ type: 'fuzz', description: summary });
  const report = outcome.failed ? `${fc.defaultReportMessage(outcome)}\nFailures of the counterexample:\n${outcome.errorInstance?.message}` : '';
  expect(outcome.failed, report).toBe(false);
  expect(stats.sequences).toBeGreaterThanOrEqual(SEQUENCES);
  expect(problems).toEqual([]);
});
