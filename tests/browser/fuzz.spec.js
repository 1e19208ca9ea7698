// Browser: random sequences of API calls, options and input (fast-check, property-based) against eight
// Flipbooks at once: no uncaught exception or unhandled rejection, bad arguments refused with an error
// naming them, and after each sequence every book settles with its invariants holding.
// `npm test` runs the fixed seeds of fuzz-seeds.mjs; `npm run fuzz` (scripts/fuzz.mjs) draws new ones
// and replays one through CONECURL_FUZZ_SEED and CONECURL_FUZZ_SEQUENCES.
import { test, expect } from '@playwright/test';
import fc from 'fast-check';
import { openReady } from './helpers.js';
import { FUZZ_SEEDS } from './fuzz-seeds.mjs';
import { LANE_OPTIONS, batch } from './fuzz-sequences.mjs';

const FIXTURE = '/tests/browser/fixtures/fuzz-fixture.html';
const ONE_SEED = process.env.CONECURL_FUZZ_SEED;
const runs = ONE_SEED
  ? [{ seed: Number(ONE_SEED), sequences: Number(process.env.CONECURL_FUZZ_SEQUENCES) || 2000 }]
  : FUZZ_SEEDS;
if (runs.some(({ seed, sequences }) => !Number.isInteger(seed) || !Number.isInteger(sequences) || sequences < 1)) {
  throw new Error(`fuzz: a seed and a sequence count must be integers (CONECURL_FUZZ_SEED=${ONE_SEED})`);
}
// A sequence takes about 40 ms alone on a 2-core machine; the limit allows six times that and more.
const timeoutFor = (sequences) => 120_000 + 250 * sequences;
const replay = (seed, sequences) => `npm run fuzz -- --seed ${seed} --sequences ${sequences}`;

test.describe.configure({ mode: 'parallel' });  // the seeds are independent: one book page each

for (const { seed, sequences } of runs) {
  test(`browser: ${sequences} random sequences of calls, options and input (fast-check seed ${seed}) leave no uncaught error and every book settled in range`, async ({ page }) => {
    test.setTimeout(timeoutFor(sequences));
    const problems = await openReady(page, FIXTURE);
    const setup = await page.evaluate((options) => window.fuzz.init(options), LANE_OPTIONS);
    expect(setup).toEqual([]);
    const lanes = LANE_OPTIONS.length;
    let batches = 0;
    const outcome = await fc.check(fc.asyncProperty(batch(lanes), async (programs) => {
      batches++;
      if (process.env.CONECURL_FUZZ_PROGRESS && batches % 50 === 0) console.log(`fuzz: seed ${seed}, batch ${batches}`);
      const failures = await page.evaluate((programs) => window.fuzz.run(programs), programs);
      if (failures.length > 0) throw new Error(failures.join('\n'));
    }), { numRuns: Math.ceil(sequences / lanes), seed, endOnFailure: false, markInterruptAsFailure: true });
    const stats = await page.evaluate(() => window.fuzz.stats());
    const summary = `fuzz: seed ${seed}, ${batches} batches of ${lanes} lanes: ${stats.sequences} sequences, ${stats.calls} calls `
      + `(${stats.expectedErrors} refused as expected), ${stats.turnsLanded} turns landed, ${stats.creates} books created, `
      + `${stats.framesStepped} frames; ${outcome.failed ? 'FAILED' : 'no failure'}`;
    console.log(summary);
    test.info().annotations.push({ type: 'fuzz', description: summary });
    const report = outcome.failed
      ? `fuzz seed ${seed} failed; replay it with: ${replay(seed, sequences)}\n${fc.defaultReportMessage(outcome)}\n`
        + `Failures of the counterexample:\n${outcome.errorInstance?.message}`
      : '';
    expect(outcome.failed, report).toBe(false);
    expect(stats.sequences).toBeGreaterThanOrEqual(sequences);
    expect(problems).toEqual([]);
  });
}
