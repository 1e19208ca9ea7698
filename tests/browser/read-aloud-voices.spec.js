// Browser: read-aloud on real voices in Chromium, as the Firefox and WebKit journeys do
// (tests/engines/read-aloud.mjs): Debian's Chromium speaks through speech-dispatcher when launched with
// --enable-speech-dispatcher, here given the suite's own configuration (espeak-ng, no sound card needed).
import { test, expect, chromium } from '@playwright/test';
import { chromiumLaunchOptions } from '../../scripts/chromium.mjs';
import { speechEnvironment } from '../engines/speech.mjs';
import { LONG_PAGE, SHORT_PAGES, checkReading, openStoryBook } from '../engines/read-aloud.mjs';
import { openReady } from './helpers.js';

test('browser: read-aloud on Chromium\'s real voices (speech-dispatcher, espeak-ng): a 300-word page said to its end, each sentence marked, the book turning, to readaloudend', async ({ baseURL }) => {
  const options = chromiumLaunchOptions();
  const browser = await chromium.launch({ ...options, args: [...options.args, '--enable-speech-dispatcher'],
    env: { ...process.env, ...speechEnvironment() } });
  try {
    const page = await browser.newPage({ baseURL, viewport: { width: 800, height: 600 } });
    const problems = await openReady(page, '/tests/browser/fixtures/html-fixture.html');
    expect(await page.evaluate(openStoryBook, { long: LONG_PAGE, short: SHORT_PAGES })).toBe(5);
    const first = await page.evaluate(async () => ({ can: await window.book.canReadAloud(), voices: (await window.book.readAloudVoices()).length }));
    expect(first.can, 'canReadAloud() answers true the first time').toBe(true);
    expect(first.voices).toBeGreaterThan(0);
    await page.evaluate(() => { window.book.readAloud({ rate: 3 }).catch((e) => window.log.push({ type: 'rejected', error: String(e) })); });
    await page.waitForFunction(() => window.log.some((e) => e.type === 'readaloudend' || e.type === 'rejected'), null, { timeout: 90_000 });
    checkReading(await page.evaluate(() => window.log));
    expect(await page.evaluate(() => [window.book.readingAloud, document.querySelectorAll('[data-reading]').length])).toEqual([null, 0]);
    expect(problems).toEqual([]);
  } finally {
    await browser.close();
  }
});
