// Node tests of the rules that keep the suite's verdict independent of the machine (issue 21): no test
// draws a random number or a seed from the clock, the fuzz runs fixed seeds, and every sleep left in the
// browser tests says why a window of time is the thing it tests (review alone lets these slip back).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join, relative } from 'node:path';
import { FUZZ_SEEDS } from '../browser/fuzz-seeds.mjs';
import { filesUnder, root } from './source-files.mjs';

const testFiles = () => filesUnder(join(root, 'tests'), ['.js', '.mjs', '.html'])
  .filter((file) => !file.endsWith('test-rules.test.mjs'));  // this file names the patterns

test('node: no test draws a random number, and none takes a seed from the clock', () => {
  const files = testFiles();
  assert.ok(files.length > 40, `scanned ${files.length} files`);
  const found = [];
  for (const file of files) {
    readFileSync(file, 'utf8').split('\n').forEach((line, i) => {
      const where = `${relative(root, file)}:${i + 1}`;
      if (/Math\.random\s*\(|crypto\.(getRandomValues|randomInt|randomUUID)/.test(line)) found.push(`${where}: a random number`);
      if (/seed/i.test(line) && /Date\.now|performance\.now|new Date\(/.test(line)) found.push(`${where}: a seed from the clock`);
    });
  }
  assert.deepEqual(found, []);
});

test('node: the fuzz in npm test runs fixed seeds, 10 000 sequences in all, with the seeds that found bugs', () => {
  const seeds = FUZZ_SEEDS.map((entry) => entry.seed);
  for (const entry of FUZZ_SEEDS) {
    assert.ok(Number.isInteger(entry.seed) && entry.seed > 0 && entry.seed < 2 ** 31, `seed ${entry.seed}`);
    assert.ok(Number.isInteger(entry.sequences) && entry.sequences > 0, `sequences of seed ${entry.seed}`);
    assert.ok(typeof entry.found === 'string' && entry.found.length > 10, `seed ${entry.seed} says what it found`);
  }
  assert.equal(new Set(seeds).size, seeds.length, 'no seed twice');
  assert.ok(FUZZ_SEEDS.reduce((sum, entry) => sum + entry.sequences, 0) >= 10_000);
  // The seed a loaded machine failed on (a settle that raced real time), and every seed a regression
  // test names as the one that found its bug.
  const named = new Set([313494504]);
  for (const file of testFiles()) {
    for (const match of readFileSync(file, 'utf8').matchAll(/\bseed (\d{5,})/gi)) named.add(Number(match[1]));
  }
  assert.ok(named.size > 5, `found ${named.size} seeds named in tests`);
  for (const seed of named) assert.ok(seeds.includes(seed), `seed ${seed} found a bug (a test names it) but is not in fuzz-seeds.mjs`);
});

test('node: every sleep left in the browser tests says, in a comment beside it, why a window of time is what it tests', () => {
  const files = testFiles().filter((file) => relative(root, file).startsWith('tests/browser/'));
  assert.ok(files.length > 20, `scanned ${files.length} files`);
  const silent = [];
  for (const file of files) {
    const lines = readFileSync(file, 'utf8').split('\n');
    lines.forEach((line, i) => {
      // A fixed wait: Playwright's page.waitFor(Timeout)(ms), or a promise a timer resolves after some time (a
      // timer of 0, or none, only lets the tasks queued before it run: an order, not a wait).
      const sleeps = /\.waitFor(Timeout)\(/.test(line)
        || /setTimeout\(\s*(resolve|r|res|done)\s*,\s*(?!0\s*\))[^)]/.test(line);
      if (!sleeps) return;
      const nearby = lines.slice(Math.max(0, i - 3), i + 1);
      if (!nearby.some((l) => /\/\/|\/\*|^\s*\*/.test(l))) silent.push(`${relative(root, file)}:${i + 1}: ${line.trim()}`);
    });
  }
  assert.deepEqual(silent, []);
});
