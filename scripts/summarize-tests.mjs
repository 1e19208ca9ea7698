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
  suites.push({ name: 'browser', passed: stats.expected, failed: stats.unexpected + stats.flaky, skipped: stats.skipped });
} catch { suites.push({ name: 'browser', passed: 0, failed: 1, note: 'no report' }); }

let passed = 0, failed = 0, skipped = 0;
for (const s of suites) {
  passed += s.passed; failed += s.failed; skipped += s.skipped || 0;
  console.log(`  ${s.name}: ${s.passed} passed, ${s.failed} failed${s.note ? ` (${s.note})` : ''}`);
}
console.log(`all suites: ${passed} passed, ${failed} failed, ${skipped} skipped`);
process.exit(failed === 0 && passed > 0 ? 0 : 1);
