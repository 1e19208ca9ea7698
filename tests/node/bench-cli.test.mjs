// Node: the bench scripts a developer runs by hand (startup.mjs, trace.mjs, profile-gpu.mjs, through
// scripts/bench/cli.mjs) say what is wrong with what they were given in one line and exit 2, before they
// serve, bundle or write anything (no stack trace).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import path from 'node:path';

const BENCH = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../../scripts/bench');

/** Runs scripts/bench/SCRIPT with each case's arguments: exit 2, one line on stderr matching its pattern, nothing on stdout. */
function saysInOneLine(script, cases) {
  for (const [args, message] of cases) {
    const result = spawnSync(process.execPath, [path.join(BENCH, script), ...args], { encoding: 'utf8', timeout: 30000 });
    assert.equal(result.status, 2, `${script} ${args.join(' ')}: exit ${result.status}, stderr ${result.stderr}`);
    const lines = result.stderr.trim().split('\n');
    assert.equal(lines.length, 1, `${script} ${args.join(' ')}: one line, got ${result.stderr}`);
    assert.match(lines[0], message);
    assert.equal(result.stdout, '');
  }
}

test('node: startup.mjs names a bad engine, library, config, rep count or a baseline library without --baseline in one line and exits 2', () => {
  saysInOneLine('startup.mjs', [
    [['--engine', 'netscape'], /^startup: unknown engine netscape \(chromium, firefox, webkit\)$/],
    [['--libs', 'conecurl,pageflip'], /^startup: unknown library pageflip \(.*page-flip.*\)$/],
    [['--configs', 'tablet-20'], /^startup: unknown config tablet-20 \(double-20, single-20, phone-20\)$/],
    [['--engine', 'webkit', '--configs', 'phone-20'], /^startup: phone-20 is a phone, measured in Chromium only/],
    [['--reps', '0'], /^startup: --reps takes a whole number of runs, 1 or more \(got 0\)$/],
    [['--libs', 'conecurl-baseline'], /^startup: conecurl-baseline needs --baseline <dir>/],
  ]);
});

test('node: trace.mjs names a bad config, turn count, options or a library with no bundle in one line and exits 2', () => {
  saysInOneLine('trace.mjs', [
    [['--config', 'phone-20'], /^trace: --config must be like double-20 or single-20, got phone-20$/],
    [['--turns', '0'], /^trace: --turns takes a whole number of turns, 1 or more \(got 0\)$/],
    [['--options', '{shadows:false}'], /^trace: --options must be a JSON object/],
    [['--lib', 'no-such-library'], /^trace: bench-results\/bundles\/no-such-library\.js is missing; run npm run bench once first$/],
  ]);
});

test('node: profile-gpu.mjs names a bad config, frame or round count, variant or bundles folder in one line and exits 2', () => {
  saysInOneLine('profile-gpu.mjs', [
    [['--config', 'tablet-20'], /^profile-gpu: unknown config tablet-20 \(double-20, single-20, phone-20\)$/],
    [['--frames', '1'], /^profile-gpu: --frames takes a whole number of frames, 2 or more \(got 1\)$/],
    [['--rounds', 'x'], /^profile-gpu: --rounds takes a whole number, 1 or more \(got x\)$/],
    [['--variants', '0,99'], /^profile-gpu: no variant 99 \(0\.\.\d+\)$/],
    [['--bundles', 'build/no-such-bundles'], /^profile-gpu: build\/no-such-bundles\/conecurl\.js is missing; run npm run bench once first$/],
  ]);
});
