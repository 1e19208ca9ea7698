// Browser (phone): a thumb's drag in single display completes the turn when let go past the middle of
// the page and falls back before it (cpp/core/page_drag.cpp shouldCompleteTurn), with CDP touch.
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';
import { touchscreen } from './phone.js';

/** A single-display book filling the phone's screen at page 2 of 8 (phone-book-fixture.html); the open page's viewport rect. */
async function openPhoneBook(page, direction) {
  await openReady(page, '/tests/browser/fixtures/phone-book-fixture.html');
  return page.evaluate(async (direction) => {
    await window.openBook({ pages: 8, display: 'single', startPage: 2, direction, duration: 300 });
    await window.book.whenIdle();
    window.events = [];
    const canvas = window.book.surface.canvas.getBoundingClientRect();
    const [open] = window.book.openPagePlaces();
    return { x: canvas.left + open.x, y: canvas.top + open.y, width: open.width, height: open.height };
  }, direction);
}

/** The turn events the book said since it opened (or since the last reset), by type. */
const turnEvents = (page) => page.evaluate(() => ({
  page: window.book.page,
  events: window.events.map((e) => e.type).filter((type) => type.startsWith('turn')),
}));

for (const direction of ['ltr', 'rtl']) {
  for (const [fromSpine, ending, page] of [[0.4, 'turned', 3], [0.6, 'turncancel', 2]]) {
    test(`browser (phone): single display, ${direction}, a touch drag from the free edge let go at ${fromSpine} of the page from the spine, held still, ends in ${ending}`, async ({ page: tab }) => {
      const open = await openPhoneBook(tab, direction);
      // The spine is the page's left edge (ltr) or its right edge (rtl); the grip starts 2 px inside the
      // free edge at 80% of the height, where a corner grip starts. A horizontal stroke: the canvas pans y.
      const at = (f) => (direction === 'ltr' ? open.x + f * open.width : open.x + open.width - f * open.width);
      const y = open.y + 0.8 * open.height;
      const touch = await touchscreen(tab);
      const from = { x: at(1) + (direction === 'ltr' ? -2 : 2), y };
      const to = { x: at(fromSpine), y };
      // Held still 150 ms before lifting: Chromium sends no move for a finger that stands still, so the
      // release itself must tell pointer-drag.js that the speed fell to nothing (no fling).
      await touch.drag(from, to, { steps: 12, durationMs: 320, holdMs: 150 });
      await tab.waitForFunction((ending) => window.events.some((e) => e.type === ending), ending);
      await tab.evaluate(() => window.settle());
      expect(await turnEvents(tab)).toEqual({ page, events: ['turnstart', ending] });
    });
  }
}

test('browser (phone): single display, a quick flick let go at 0.6 of the page from the spine still turns (a fling), and one held still falls back', async ({ page: tab }) => {
  const open = await openPhoneBook(tab, 'ltr');
  const y = open.y + 0.8 * open.height;
  const touch = await touchscreen(tab);
  // The same stroke twice, 120 ms long: lifted at once it is a fling on (turned), held 150 ms first it is not.
  await touch.drag({ x: open.x + open.width - 2, y }, { x: open.x + 0.6 * open.width, y }, { steps: 6, durationMs: 120, holdMs: 0 });
  await tab.waitForFunction(() => window.events.some((e) => e.type === 'turned'));
  await tab.evaluate(() => window.settle());
  expect(await turnEvents(tab)).toEqual({ page: 3, events: ['turnstart', 'turned'] });
  await tab.evaluate(() => { window.events = []; });
  await touch.drag({ x: open.x + open.width - 2, y }, { x: open.x + 0.6 * open.width, y }, { steps: 6, durationMs: 120, holdMs: 150 });
  await tab.waitForFunction(() => window.events.some((e) => e.type === 'turncancel'));
  await tab.evaluate(() => window.settle());
  expect(await turnEvents(tab)).toEqual({ page: 3, events: ['turnstart', 'turncancel'] });
});
