// `npm run fuzz`: the random-sequence test (tests/browser/fuzz.spec.js) with seeds drawn anew, for as
// long as asked, or one seed replayed. `npm test` runs only the fixed seeds of tests/browser/fuzz-seeds.mjs.
//
//   npm run fuzz                             new seeds for 10 minutes, 2000 sequences each
//   npm run fuzz -- --minutes 60             new seeds for an hour
//   npm run fuzz -- --seed 313494504         replay one seed (--sequences N: as many as it ran)
//
// Each failing seed is printed with the one command that replays it. Once the bug it found is fixed,
// add the seed to fuzz-seeds.mjs (and the bug to fuzz-regressions.spec.js as a test of its own).
import { spawnSync } from 'node:child_process';
import { randomInt } from 'node:crypto';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const usage = 'usage: node scripts/fuzz.mjs [--minutes M] [--seed S] [--sequences N]';

function parse(argv) {
  const options = { minutes: 10, seed: null, sequences: 2000 };
  for (let i = 0; i < argv.length; i++) {
    const [name, inline] = argv[i].split('=', 2);
    if (!['--minutes', '--seed', '--sequences'].includes(name)) throw new Error(`fuzz: unknown argument '${argv[i]}'\n${usage}`);
    const value = inline ?? argv[++i];
    const number = Number(value);
    if (value === undefined || !Number.isFinite(number) || number < 0) throw new Error(`fuzz: ${name} needs a number\n${usage}`);
    if (name !== '--minutes' && !Number.isInteger(number)) throw new Error(`fuzz: ${name} needs an integer\n${usage}`);
    options[name.slice(2)] = number;
  }
  if (options.sequences < 1) throw new Error(`fuzz: --sequences must be at least 1\n${usage}`);
  return options;
}

const replayCommand = (seed, sequences) => `npm run fuzz -- --seed ${seed} --sequences ${sequences}`;

/** Runs fuzz.spec.js for one seed; returns whether it passed. Playwright's own output goes through. */
function runSeed(seed, sequences) {
  const started = Date.now();
  console.log(`fuzz: seed ${seed}, ${sequences} sequences`);
  const result = spawnSync('npx', ['playwright', 'test', 'tests/browser/fuzz.spec.js', '--workers=1', '--reporter=line'], {
    cwd: root,
    stdio: 'inherit',
    env: { ...process.env, CONECURL_FUZZ_SEED: String(seed), CONECURL_FUZZ_SEQUENCES: String(sequences) },
  });
  const passed = result.status === 0;
  const seconds = ((Date.now() - started) / 1000).toFixed(0);
  console.log(passed ? `fuzz: seed ${seed} passed (${seconds} s)`
    : `fuzz: seed ${seed} FAILED (${seconds} s); replay it with:\n  ${replayCommand(seed, sequences)}`);
  return passed;
}

let options;
try {
  options = parse(process.argv.slice(2));
} catch (error) {
  console.error(error.message);
  process.exit(2);
}

const failed = [];
if (options.seed !== null) {
  if (!runSeed(options.seed, options.sequences)) failed.push(options.seed);
} else {
  // Seeds are drawn here, in this command only: the suite's own seeds are fixed.
  const deadline = Date.now() + options.minutes * 60_000;
  let tried = 0;
  do {
    const seed = randomInt(1, 2 ** 31);
    tried++;
    if (!runSeed(seed, options.sequences)) failed.push(seed);
  } while (Date.now() < deadline);
  console.log(`fuzz: ${tried} new seeds of ${options.sequences} sequences in ${options.minutes} min, ${failed.length} failed`);
}
for (const seed of failed) console.log(`fuzz: failing seed ${seed}: ${replayCommand(seed, options.sequences)}`);
process.exit(failed.length === 0 ? 0 : 1);
