// Browser (phone): in single display the open page fills its box (the camera's small single-display
// margin, cpp/core/book_camera.cpp frameMargin), in every direction, and a forward turn on a phone
// matches its reference images at t = 0.15, 0.3, 0.45 and 0.6 (issue 40: paper on the back, a soft
// shadow, the curl in view): on both phones; on the portrait one also rtl, a hard cover, and a moving
// frame at 1.5 device px per CSS px.
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';

/** A single-display book of numbered pages filling the phone's screen (phone-book-fixture.html); its box and open page (CSS px). */
async function openPhoneBook(page, options = {}) {
  await openReady(page, '/tests/browser/fixtures/phone-book-fixture.html');
  return page.evaluate(async (options) => {
    await window.openBook({ pages: 8, display: 'single', startPage: 2, ...options });
    await window.book.whenIdle();
    const canvas = window.book.surface.canvas.getBoundingClientRect();
    const [open] = window.book.openPagePlaces();
    return { box: { width: canvas.width, height: canvas.height }, open };
  }, options);
}

test('browser (phone): a single page fills at least 92% of its box in the dimension the box limits, ltr, rtl and vertical', async ({ page }) => {
  for (const direction of ['ltr', 'rtl', 'vertical']) {
    const { box, open } = await openPhoneBook(page, { direction });
    const fill = Math.max(open.width / box.width, open.height / box.height);
    expect(fill, `${direction}: ${JSON.stringify({ box, open })}`).toBeGreaterThanOrEqual(0.92);
    // Centred and whole.
    expect(Math.abs(open.x + open.width / 2 - box.width / 2)).toBeLessThan(1);
    expect(Math.abs(open.y + open.height / 2 - box.height / 2)).toBeLessThan(1);
    expect(open.x).toBeGreaterThanOrEqual(0);
    expect(open.y).toBeGreaterThanOrEqual(0);
  }
});

// name -> [the book's options, the page it opens at, whether only the portrait phone shows it]
const TURNS = {
  '': [{}, 2, false],
  '-rtl': [{ direction: 'rtl' }, 2, true],
  '-hard-cover': [{ hardCovers: true }, 0, true],
  '-moving': [{ resolution: 1.5 }, 2, true],
};
for (const [suffix, [options, startPage, portraitOnly]] of Object.entries(TURNS)) {
  for (const t of [0.15, 0.3, 0.45, 0.6]) {
    test(`browser (phone): a single-display forward turn${suffix.replace('-', ', ')} at t=${t} matches its reference image`, async ({ page }, testInfo) => {
      const project = testInfo.project.name;
      test.skip(project === 'phone-small', 'portrait and landscape show the turn; the small phone is a smaller portrait');
      test.skip(portraitOnly && project !== 'phone-portrait', 'the portrait phone shows this one');
      await openPhoneBook(page, { ...options, startPage });
      // The moving resolution: the frame is drawn at 1.5 / 3 of the pixels and scaled up, as a turn is.
      if (options.resolution) await page.evaluate(() => window.book.surface.renderer.setOptions({ movingScale: 0.5 }));
      expect(await page.evaluate((t) => window.book.previewTurn('forward', t), t)).toBe(true);
      await expect(page.locator('#container')).toHaveScreenshot(`${project}-single-turn${suffix}-${t}.png`,
        { maxDiffPixelRatio: 0.005, threshold: 0.1 });
    });
  }
}
