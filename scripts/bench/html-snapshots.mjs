// Measures the HTML-page rasterisers on the demo magazine's pages in headless Chromium: the time to draw
// a page to a canvas (median and worst of several runs) and how far its pixels are from the browser's
// own rendering of the same element (an element screenshot): mean difference per channel (0-255) and
// the share of pixels off by more than 32. Not a test: it prints figures for choosing html-pages.js's.
// Usage: node scripts/bench/html-snapshots.mjs [--runs 7]
import { spawn } from 'node:child_process';
import { chromium } from '@playwright/test';
import { chromiumLaunchOptions } from '../chromium.mjs';
import { summarize } from './metrics.mjs';

const runs = Number(process.argv[process.argv.indexOf('--runs') + 1]) || 7;
const port = 8098;
const server = spawn(process.execPath, ['scripts/serve.mjs', '--port', String(port)], { stdio: 'ignore' });
await new Promise((resolve) => setTimeout(resolve, 500));
const browser = await chromium.launch(chromiumLaunchOptions());
try {
  const page = await browser.newPage({ viewport: { width: 800, height: 600 }, deviceScaleFactor: 1 });
  await page.goto(`http://127.0.0.1:${port}/scripts/bench/html-snapshot.html`);
  await page.waitForFunction(() => document.body.dataset.ready);
  const count = await page.evaluate(() => window.pages.length);
  const names = await page.evaluate(() => Object.keys(window.rasterisers));
  const results = Object.fromEntries(names.map((name) => [name, { ms: [], diff: [], off: [] }]));
  for (let i = 0; i < count; i++) {
    await page.evaluate((i) => window.show(i), i);
    await page.waitForTimeout(100);
    const reference = (await page.locator('#box').screenshot()).toString('base64');
    for (const name of names) {
      for (let run = 0; run < runs; run++) {
        const r = await page.evaluate(({ name, reference }) => window.measure(name, reference), { name, reference });
        results[name].ms.push(r.ms);
        if (run === 0) { results[name].diff.push(r.meanDiff); results[name].off.push(r.pixelsOff); }
      }
    }
  }
  console.log(`${count} demo magazine pages (400 x 500 CSS px, scale 1), ${runs} runs each; first runs included in the worst`);
  console.log('| rasteriser | ms per page, median | ms, worst | mean pixel difference (0-255) | pixels off by > 32 |');
  console.log('|---|---|---|---|---|');
  for (const [name, r] of Object.entries(results)) {
    const ms = summarize(r.ms);
    const diff = r.diff.reduce((a, b) => a + b, 0) / r.diff.length;
    const off = r.off.reduce((a, b) => a + b, 0) / r.off.length;
    console.log(`| ${name} | ${ms.median.toFixed(1)} | ${ms.max.toFixed(1)} | ${diff.toFixed(2)} | ${(100 * off).toFixed(2)} % |`);
  }
} finally {
  await browser.close();
  server.kill();
}
