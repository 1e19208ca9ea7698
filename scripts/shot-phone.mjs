import { chromium } from '@playwright/test';
import { chromiumLaunchOptions } from './chromium.mjs';
const browser = await chromium.launch(chromiumLaunchOptions());
for (const [name, w, h] of [['portrait', 390, 844], ['landscape', 844, 390]]) {
  const page = await browser.newPage({ viewport: { width: w, height: h }, deviceScaleFactor: 3, isMobile: true, hasTouch: true });
  await page.goto('http://127.0.0.1:8191/web/demo/');
  await page.waitForFunction(() => document.body.dataset.ready);
  await page.selectOption('#source', 'story');
  await page.waitForFunction(() => /of 8$/.test(document.querySelector('#where').textContent));
  await page.evaluate(() => window.conecurlDemo.book.whenIdle());
  await page.screenshot({ path: `/tmp/ph-${name}-0.png` });
  await page.evaluate(() => { window.words = 0; window.conecurlDemo.book.addEventListener('readaloudword', () => { window.words++; }); });
  const read = page.locator('[role=toolbar] [data-control=readAloud]');
  const visible = await read.isVisible();
  console.log(name, 'read visible', visible, 'moved', await page.evaluate(() => [...document.querySelectorAll('.conecurl-menu [role=menuitem]')].filter((i) => !i.hidden).map((i) => i.dataset.control)));
  if (visible) await read.tap(); else { await page.locator('[data-control=more]').tap(); await page.locator('.conecurl-menu [data-control=readAloud]').tap(); }
  await page.waitForFunction(() => window.words >= 3, null, { timeout: 30000 });
  await page.screenshot({ path: `/tmp/ph-${name}-1.png` });
  const settings = page.locator('[role=toolbar] [data-control=readAloudSettings]');
  if (await settings.isVisible()) await settings.tap(); else { await page.locator('[data-control=more]').tap(); await page.screenshot({ path: `/tmp/ph-${name}-more.png` }); await page.locator('.conecurl-menu [data-control=readAloudSettings]').tap(); }
  await page.waitForFunction(() => [...document.querySelectorAll('.conecurl-read-menu')].some((m) => !m.hidden));
  const box = await page.evaluate(() => { const m = [...document.querySelectorAll('.conecurl-read-menu')].find((x) => !x.hidden).getBoundingClientRect(); return [m.left, m.top, m.right, m.bottom]; });
  console.log(name, 'popup box', box.map(Math.round), 'screen', w, h);
  await page.screenshot({ path: `/tmp/ph-${name}-2.png` });
  await page.close();
}
await browser.close();
