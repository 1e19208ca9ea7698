// Browser (phone): the demo as a phone reader opens it, in portrait, landscape and on a small phone:
// the book first and inside the screen, its page filling the box, one page chosen by display 'auto',
// nothing wider than the screen, and reference images of the drawn book on the two 390x844 screens.
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';

test('browser (phone): the demo puts the book first, inside the screen, one page filling at least 92% of its box, with no sideways scroll', async ({ page }) => {
  const problems = await openReady(page, '/web/demo/');
  await page.evaluate(() => window.conecurlDemo.book.whenIdle());
  const seen = await page.evaluate(() => {
    const book = window.conecurlDemo.book;
    const box = book.element.querySelector('canvas').getBoundingClientRect();
    const [place] = book.openPagePlaces();
    return {
      display: book.display,
      places: book.openPagePlaces().length,
      box: { top: box.top, bottom: box.bottom, left: box.left, right: box.right, width: box.width, height: box.height },
      page: { width: place.width, height: place.height },
      headerTop: document.querySelector('header').getBoundingClientRect().top,
      scrollWidth: document.documentElement.scrollWidth,
      screen: { width: innerWidth, height: innerHeight },
    };
  });
  expect(seen.display).toBe('single');
  expect(seen.places).toBe(1);
  expect(seen.scrollWidth).toBe(seen.screen.width);
  // The book comes before the title and lies wholly on the first screen.
  expect(seen.box.top).toBeLessThan(seen.headerTop);
  expect(seen.box.top).toBeGreaterThanOrEqual(0);
  expect(seen.box.bottom).toBeLessThanOrEqual(seen.screen.height);
  expect(seen.box.left).toBeGreaterThanOrEqual(0);
  expect(seen.box.right).toBeLessThanOrEqual(seen.screen.width);
  // The page fills its box in the dimension the box limits it by.
  const fill = Math.max(seen.page.width / seen.box.width, seen.page.height / seen.box.height);
  expect(fill).toBeGreaterThanOrEqual(0.92);
  // Landscape: the book takes the screen's height (less the page's padding).
  if (seen.screen.width > seen.screen.height) expect(seen.box.height).toBeGreaterThanOrEqual(seen.screen.height - 20);
  expect(problems).toEqual([]);
});

test('browser (phone): the demo\'s drawn book on a phone matches its reference image', async ({ page }, testInfo) => {
  test.skip(testInfo.project.name === 'phone-small', 'the two 390x844 screens are the reference pictures');
  await openReady(page, '/web/demo/');
  await page.evaluate(() => window.conecurlDemo.book.whenIdle());
  await expect(page).toHaveScreenshot(`demo-${testInfo.project.name}.png`, { maxDiffPixelRatio: 0.005, threshold: 0.1 });
});
