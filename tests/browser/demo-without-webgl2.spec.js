// Browser: the demo in a Chromium with WebGL switched off (--disable-3d-apis: what a reader of Chrome 139+
// without a GPU gets, where software WebGL is off): Flipbook.create rejects with the static fallback, and
// the demo keeps that book as its own, as a host does, so its Next, Prev, page shown and Jump work, and a
// click on the book's page turns it.
import { test, expect } from '@playwright/test';
import { chromiumLaunchOptions } from '../../scripts/chromium.mjs';
import { openReady } from './helpers.js';

const launch = chromiumLaunchOptions();
// The demo's desktop screen (demo.spec.js): two pages open.
test.use({ launchOptions: { ...launch, args: [...launch.args, '--disable-3d-apis'] }, viewport: { width: 1280, height: 800 } });

test('browser (no WebGL2): the demo shows the static fallback and turns it: Next, Prev and Jump, a click on the right page, the page shown following', async ({ page }) => {
  const problems = await openReady(page, '/web/demo/');
  await expect(page.locator('#status')).toContainText('WebGL2 is not available');
  expect(await page.evaluate(() => window.conecurlDemo.book.surface.kind)).toBe('canvas');  // still pages
  await expect(page.locator('#where')).toHaveText('Page 1 of 40');
  await page.click('#next');
  await expect(page.locator('#where')).toHaveText('Pages 2–3 of 40');
  expect(await page.evaluate(() => window.conecurlDemo.book.page)).toBe(1);
  // A click on the right page, away from the spine, turns forward (as on the WebGL book).
  const right = await page.evaluate(() => {
    const book = window.conecurlDemo.book;
    const canvas = book.element.querySelector('canvas').getBoundingClientRect();
    const place = book.openPagePlaces().find((p) => p.page === 2);
    return { x: canvas.left + place.x + place.width * 0.8, y: canvas.top + place.y + place.height / 2 };
  });
  await page.mouse.click(right.x, right.y);
  await expect(page.locator('#where')).toHaveText('Pages 4–5 of 40');
  expect(await page.evaluate(() => window.conecurlDemo.book.page)).toBe(3);
  await page.click('#prev');
  await expect(page.locator('#where')).toHaveText('Pages 2–3 of 40');
  await page.fill('#jump-page', '30');
  await page.click('#jump button');
  await expect(page.locator('#where')).toHaveText('Pages 30–31 of 40');
  expect(problems).toEqual([]);
});
