// Browser (phone): a PDF's selectable text does not stand in a finger's way. On a coarse pointer the
// book turns from anywhere on the page (turnArea 'page'), and a tap on a word reaches the book through
// the text layer (text-layer.js hands touch to the canvas; a finger selects by a long press).
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';
import { touchscreen } from './phone.js';

test('browser (phone): a tap on a word in a PDF page\'s outer third turns forward, and one in its inner third turns back', async ({ page }) => {
  await openReady(page, '/web/demo/');
  await page.selectOption('#source', 'pdf');
  await expect(page.locator('#where')).toHaveText('Page 1 of 12', { timeout: 60_000 });
  await page.evaluate(async () => {
    const book = window.conecurlDemo.book;
    await book.flip(2);
    await book.whenIdle();
  });
  expect(await page.evaluate(() => window.conecurlDemo.book.options.turnArea)).toBe('page');
  // A point on a line of the text layer (viewport px) that lies in the given third of the open page.
  const wordIn = (third) => page.evaluate((third) => {
    const book = window.conecurlDemo.book;
    const canvas = book.element.querySelector('canvas').getBoundingClientRect();
    const [place] = book.openPagePlaces();
    const [from, to] = third === 'outer' ? [0.7, 0.95] : [0.05, 0.3];
    const low = canvas.left + place.x + from * place.width;
    const high = canvas.left + place.x + to * place.width;
    for (const span of book.element.querySelectorAll('[data-text-layer] span')) {
      const r = span.getBoundingClientRect();
      const x = Math.min(r.right - 2, high);
      const y = r.top + r.height / 2;
      if (x > Math.max(low, r.left + 2) && document.elementFromPoint(x, y) === span) return { x, y, text: span.textContent };
    }
    return null;
  }, third);
  await page.waitForFunction(() => window.conecurlDemo.book.element.querySelector('[data-text-layer] span'));
  const touch = await touchscreen(page);

  const outer = await wordIn('outer');
  expect(outer, 'a word in the outer third of page 3').not.toBeNull();
  await touch.tap(outer);
  await expect(page.locator('#where')).toHaveText('Page 4 of 12', { timeout: 30_000 });
  await page.evaluate(() => window.conecurlDemo.book.whenIdle());
  await page.waitForFunction(() => !window.conecurlDemo.book.animating && window.conecurlDemo.book.element.querySelector('[data-text-layer] span'));

  const inner = await wordIn('inner');
  expect(inner, 'a word in the inner third of page 4').not.toBeNull();
  await touch.tap(inner);
  await expect(page.locator('#where')).toHaveText('Page 3 of 12', { timeout: 30_000 });
});
