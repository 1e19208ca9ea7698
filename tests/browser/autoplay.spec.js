// Browser: autoplay (autoplay.js) turns the book on its own, waits while the pointer is over it, while
// it has focus and while the tab is hidden, and stops at the end unless it loops. The waits below are
// for turns that must come (bounded by the test's timeout) or must not (far longer than the interval).
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';

const FIXTURE = '/tests/browser/fixtures/flipbook-fixture.html';
const INTERVAL = 120;

async function open(page, autoplay) {
  await page.evaluate(async (autoplay) => {
    await window.openBook({ pages: 5, display: 'single', duration: 60, autoplay });
    window.turns = [];
    window.book.addEventListener('turned', (event) => window.turns.push(event.detail.page));
  }, autoplay);
}
// Turns that came while `ms` passed on the page's own clock: those landed, and one under way. A window in
// which no turn may come: the page's timer fires after any autoplay timer due sooner, however slowly the
// machine runs them, so a slow machine cannot hide a turn that should not come (nor invent one).
const turnsAfterWaiting = (page, ms) => page.evaluate(async (ms) => {
  const before = window.turns.length;
  await new Promise((resolve) => setTimeout(resolve, ms));  // after any autoplay timer due sooner, on any machine
  return window.turns.length - before + (window.book.animating ? 1 : 0);
}, ms);

test('browser: autoplay turns on its own and stops at the last page; with loop it goes back to the first', async ({ page }) => {
  const problems = await openReady(page, FIXTURE);
  await open(page, { interval: INTERVAL });
  await page.waitForFunction(() => window.book.page === 4 && !window.book.animating, null, { timeout: 30_000 });
  expect(await page.evaluate(() => window.turns)).toEqual([1, 2, 3, 4]);
  expect(await turnsAfterWaiting(page, 6 * INTERVAL)).toBe(0);  // stopped at the end

  await open(page, { interval: INTERVAL, loop: true });
  await page.waitForFunction(() => window.turns.includes(4) && window.turns.lastIndexOf(0) > window.turns.indexOf(4), null, { timeout: 30_000 });
  await page.waitForFunction(() => window.turns.filter((p) => p === 1).length >= 1 && window.turns[window.turns.length - 1] >= 1,
    null, { timeout: 30_000 });  // and on again from the first page
  expect(problems).toEqual([]);
});

test('browser: autoplay waits while the pointer is over the book, while it has focus and while the tab is hidden', async ({ page }) => {
  const problems = await openReady(page, FIXTURE);
  await open(page, { interval: INTERVAL, loop: true });
  await page.waitForFunction(() => window.turns.length >= 1, null, { timeout: 30_000 });

  const box = await page.locator('#container').boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + 5);  // over the book, away from its corners
  await page.waitForFunction(() => window.book.element.matches(':hover') && !window.book.animating);
  expect(await turnsAfterWaiting(page, 8 * INTERVAL)).toBe(0);
  await page.mouse.move(0, box.y + box.height + 50);  // away
  await page.waitForFunction((n) => window.turns.length > n, await page.evaluate(() => window.turns.length), { timeout: 30_000 });

  await page.evaluate(() => window.book.element.focus());
  await page.waitForFunction(() => !window.book.animating);
  expect(await turnsAfterWaiting(page, 8 * INTERVAL)).toBe(0);
  await page.evaluate(() => document.activeElement.blur());
  await page.waitForFunction((n) => window.turns.length > n, await page.evaluate(() => window.turns.length), { timeout: 30_000 });

  await page.evaluate(() => {
    Object.defineProperty(document, 'visibilityState', { configurable: true, get: () => 'hidden' });
    document.dispatchEvent(new Event('visibilitychange'));
  });
  await page.waitForFunction(() => !window.book.animating);
  expect(await turnsAfterWaiting(page, 8 * INTERVAL)).toBe(0);
  await page.evaluate(() => {
    Object.defineProperty(document, 'visibilityState', { configurable: true, get: () => 'visible' });
    document.dispatchEvent(new Event('visibilitychange'));
  });
  await page.waitForFunction((n) => window.turns.length > n, await page.evaluate(() => window.turns.length), { timeout: 30_000 });
  expect(problems).toEqual([]);
});
