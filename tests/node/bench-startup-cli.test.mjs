// Node: scripts/bench/startup.mjs, a developer's command, says what is wrong with what it was given in one line
// and exits 2, before it serves, bundles or writes anything (no stack trace).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import path from 'node:path';

const SCRIPT = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../../scripts/bench/startup.mjs');
const run = (...args) => spawnSync(process.execPath, [SCRIPT, ...args], { encoding: 'utf8', timeout: 30000 });

test('node: startup.mjs names a bad engine, library, config, rep count or a baseline library without --baseline in one line and exits 2', () => {
  const cases = [
    [['--engine', 'netscape'], /^startup: unknown engine netscape \(chromium, firefox, webkit\)$/],
    [['--libs', 'conecurl,pageflip'], /^startup: unknown library pageflip \(.*page-flip.*\)$/],
    [['--configs', 'tablet-20'], /^startup: unknown config tablet-20 \(double-20, single-20, phone-20\)$/],
    [['--engine', 'webkit', '--configs', 'phone-20'], /^startup: phone-20 is a phone, measured in Chromium only/],
    [['--reps', '0'], /^startup: --reps takes a whole number of runs, 1 or more \(got 0\)$/],
    [['--libs', 'conecurl-baseline'], /^startup: conecurl-baseline needs --baseline <dir>/],
  ];
  for (const [args, message] of cases) {
    const result = run(...args);
    assert.equal(result.status, 2, `${args.join(' ')}: exit ${result.status}, stderr ${result.stderr}`);
    const lines = result.stderr.trim().split('\n');
    assert.equal(lines.length, 1, `${args.join(' ')}: one line, got ${result.stderr}`);
    assert.match(lines[0], message);
    assert.equal(result.stdout, '');
  }
});
