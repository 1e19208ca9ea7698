// Measures the demo as a phone reader sees it: for each phone screen and book (drawn, PDF with its
// toolbar), the book's box, the open page's size in CSS px and as a fraction of the box, the display
// `auto` chose, and the toolbar's overflow. `npm run measure:phone` (serves the repository itself).
import { chromium } from '@playwright/test';
import { spawn } from 'node:child_process';
import { chromiumLaunchOptions } from './chromium.mjs';
import { PHONES, phoneUse } from '../tests/browser/phone.js';

const port = 8095;
const server = spawn(process.execPath, ['scripts/serve.mjs', '--port', String(port)], { stdio: 'ignore' });
const base = `http://127.0.0.1:${port}/web/demo/`;
const browser = await chromium.launch(chromiumLaunchOptions());
try {
  for (let i = 0; i < 50; i++) {
    try { if ((await fetch(base)).ok) break; } catch { /* not listening yet */ }
    await new Promise((r) => setTimeout(r, 100));  // polls the server's start, 5 s at most
  }
  const rows = [];
  for (const [name, screen] of Object.entries(PHONES)) {
    for (const source of ['drawn', 'pdf']) {
      const context = await browser.newContext(phoneUse(screen));
      const page = await context.newPage();
      await page.goto(base);
      await page.waitForFunction(() => document.body.dataset.ready || document.body.dataset.error, null, { timeout: 120_000 });
      if (source === 'pdf') {
        await page.selectOption('#source', 'pdf');
        await page.waitForFunction(() => /of 12$/.test(document.querySelector('#where').textContent) && document.querySelector('[role=toolbar]'), null, { timeout: 120_000 });
      }
      await page.waitForFunction(() => !window.conecurlDemo.book.animating, null, { timeout: 120_000 });
      rows.push({ screen: name, source, ...await page.evaluate(() => {
        const book = window.conecurlDemo.book;
        const box = book.element.getBoundingClientRect();
        const canvas = book.element.querySelector('canvas').getBoundingClientRect();
        const places = book.openPagePlaces();
        const toolbar = document.querySelector('[role=toolbar]');
        const r = (v) => Math.round(v);
        return {
          box: `${r(box.width)}x${r(box.height)}`,
          display: book.display,
          pages: places.map((p) => `${r(p.width)}x${r(p.height)}`).join(' + '),
          pageOfBox: places.length ? (places.reduce((s, p) => s + p.width, 0) / canvas.width).toFixed(2) + ' w, '
            + (places[0].height / canvas.height).toFixed(2) + ' h' : '-',
          bookBottom: r(box.bottom),
          toolbar: toolbar ? `${toolbar.scrollWidth} of ${toolbar.clientWidth} px, bottom ${r(toolbar.getBoundingClientRect().bottom)}` : '-',
          screenWidth: document.documentElement.scrollWidth,
        };
      }) });
      await context.close();
    }
  }
  console.table(rows);
} finally {
  await browser.close();
  server.kill();
}
