// Browser tests run in Debian's Chromium (never a downloaded one) with WebGL2 on SwiftShader, so they
// behave the same on any machine without a GPU. The repository is served by scripts/serve.mjs.
import { defineConfig } from '@playwright/test';
import { chromiumLaunchOptions } from './scripts/chromium.mjs';
import { PHONES, phoneUse } from './tests/browser/phone.js';

// CONECURL_TEST_PORT lets several checkouts run their browser tests side by side.
const port = Number(process.env.CONECURL_TEST_PORT) || 8089;

export default defineConfig({
  testDir: 'tests/browser',
  // Limits sized for a machine several times slower than a quiet 2-core one (a wait that is met returns
  // at once, so a wide limit costs nothing when tests pass); heavy tests set their own.
  timeout: 120_000,
  workers: 2,
  forbidOnly: !!process.env.CI,
  // Reference images live beside the tests; only scripts/update-references.sh rewrites them.
  snapshotPathTemplate: '{testDir}/references/{arg}{ext}',
  expect: { timeout: 30_000, toHaveScreenshot: { animations: 'disabled', caret: 'hide' } },
  use: {
    baseURL: `http://127.0.0.1:${port}`,
    viewport: { width: 800, height: 600 },
    deviceScaleFactor: 1,
    launchOptions: chromiumLaunchOptions(),
  },
  // Desktop specs run once at 800x600; every *.phone.spec.js runs on each phone (tests/browser/phone.js).
  projects: [
    { name: 'desktop', testIgnore: /\.phone\.spec\.js$/ },
    ...Object.entries(PHONES).map(([name, screen]) => ({ name, testMatch: /\.phone\.spec\.js$/, use: phoneUse(screen) })),
  ],
  webServer: {
    command: `node scripts/serve.mjs --port ${port}`,
    url: `http://127.0.0.1:${port}/web/demo/`,
    reuseExistingServer: !process.env.CI,
  },
});
