// Sums the suites' own reports (CTest log, node TAP, Playwright JSON) into one closing line, so a
// reader of CI sees at a glance how many tests ran in all; exits non-zero if any failed or none ran.
import fs from 'node:fs';
import path from 'node:path';

const dir = process.argv[2];
const read = (name) => {
  try { return fs.readFileSync(path.join(dir, name), 'utf8'); } catch { return ''; }
};
const suites = [];

// CTest: "100% tests passed, 0 tests failed out of 57" after "ctest variant: NAME", once per variant.
for (const m of read('native.log').matchAll(/ctest variant: (\S+)[\s\S]*?tests passed, (\d+) tests? failed out of (\d+)/g)) {
  suites.push({ name: m[1], passed: Number(m[3]) - Number(m[2]), failed: Number(m[2]) });
}
const tap = read('node.tap');
const tapCount = (key) => Number((tap.match(new RegExp(`^# ${key} (\\d+)`, 'm')) || [0, 0])[1]);
if (tap) suites.push({ name: 'node', passed: tapCount('pass'), failed: tapCount('fail') + tapCount('cancelled') });
try {
  const stats = JSON.parse(read('browser.json')).stats;
  suites.push({ name: 'browser (chromium)', passed: stats.expected, failed: stats.unexpected + stats.flaky, skipped: stats.skipped });
} catch { suites.push({ name: 'browser (chromium)', passed: 0, failed: 1, note: 'no report' }); }
// The cross-engine suite's TAP: each engine's tests are named "ENGINE: ...", counted per engine; an engine
// whose suite did not run at all (its browser failed to start) is a failure, not a silence.
const enginesTap = read('engines.tap');
for (const engine of ['firefox', 'webkit']) {
  const results = [...enginesTap.matchAll(new RegExp(`^\\s*(not )?ok \\d+ - ${engine}: (.*)$`, 'gm'))]
    .map((m) => ({ failed: Boolean(m[1]), skipped: / # SKIP\b/.test(m[2]) }));
  const failedSuite = new RegExp(`^\\s*not ok \\d+ - ${engine}$`, 'm').test(enginesTap);
  const skipped = results.filter((r) => r.skipped).length;
  const passed = results.filter((r) => !r.failed && !r.skipped).length;
  const failed = results.filter((r) => r.failed).length;
  suites.push({ name: `browser (${engine})`, passed, skipped, failed: failed || (failedSuite || passed === 0 ? 1 : 0),
    ...(passed === 0 && failed === 0 ? { note: 'no tests ran' } : {}) });
}

// Where the time went: each suite's wall time (times.tsv, written by scripts/test.sh) and the slowest
// tests of all suites, so that a slow suite can be cut where it is slow.
const slowest = [];
for (const m of read('native.log').matchAll(/Test +#\d+: (\S+) \.*\s+\w+\s+([\d.]+) sec/g)) {
  slowest.push({ name: `native: ${m[1]}`, seconds: Number(m[2]) });
}
for (const m of (tap + enginesTap).matchAll(/^\s*(?:not )?ok \d+ - (.*)\n\s*---\n\s*duration_ms: ([\d.]+)/gm)) {
  if (/^(firefox|webkit)$/.test(m[1])) continue;  // an engine's whole suite, not a test
  slowest.push({ name: m[1], seconds: Number(m[2]) / 1000 });
}
try {
  const walk = (suite) => {
    for (const spec of suite.specs ?? []) {
      for (const t of spec.tests ?? []) {
        for (const r of t.results ?? []) slowest.push({ name: `${spec.file}: ${spec.title}`, seconds: r.duration / 1000 });
      }
    }
    for (const child of suite.suites ?? []) walk(child);
  };
  for (const suite of JSON.parse(read('browser.json')).suites ?? []) walk(suite);
} catch { /* no browser report: said above */ }
const times = read('times.tsv').trim().split('\n').filter(Boolean).map((line) => line.split('\t'));
if (times.length > 0) {
  const total = times.reduce((sum, [, seconds]) => sum + Number(seconds), 0);
  console.log(`time by suite: ${times.map(([name, seconds]) => `${name} ${seconds} s`).join(', ')}; ${total} s in all`);
}
if (slowest.length > 0) {
  console.log('slowest tests:');
  const clip = (text) => (text.length > 130 ? `${text.slice(0, 127)}...` : text);
  for (const { name, seconds } of slowest.sort((a, b) => b.seconds - a.seconds).slice(0, 15)) {
    console.log(`  ${seconds.toFixed(1).padStart(6)} s  ${clip(name)}`);
  }
}

let passed = 0, failed = 0, skipped = 0;
for (const s of suites) {
  passed += s.passed; failed += s.failed; skipped += s.skipped || 0;
  console.log(`  ${s.name}: ${s.passed} passed, ${s.failed} failed${s.skipped ? `, ${s.skipped} skipped` : ''}${s.note ? ` (${s.note})` : ''}`);
}
console.log(`all suites: ${passed} passed, ${failed} failed, ${skipped} skipped`);
process.exit(failed === 0 && passed > 0 ? 0 : 1);
