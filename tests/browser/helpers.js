// Shared steps of the browser tests: open a page and wait until it says it is ready, failing with
// the page's own error (or any uncaught error) instead of a timeout.
import { expect } from '@playwright/test';

export async function openReady(page, url) {
  const problems = [];
  page.on('pageerror', (error) => problems.push(error.message));
  page.on('console', (message) => { if (message.type() === 'error') problems.push(message.text()); });
  await page.goto(url);
  await page.waitForFunction(() => document.body.dataset.ready || document.body.dataset.error);
  const error = await page.evaluate(() => document.body.dataset.error || null);
  expect(error, 'page reported an error').toBeNull();
  return problems;
}

/** As in a browser or GPU without WebGL2: from the next navigation on, every canvas refuses a 'webgl2' context. */
export async function withoutWebGL2(page) {
  await page.addInitScript(() => {
    const getContext = HTMLCanvasElement.prototype.getContext;
    HTMLCanvasElement.prototype.getContext = function (type, ...rest) {
      return type === 'webgl2' ? null : getContext.call(this, type, ...rest);
    };
  });
}

/**
 * Presses the mouse at path[0] and moves it along `path` (viewport points); at every 4th point and the
 * last, once the held leaf has caught up, measures how far `drawn()` (a viewport point) is from the
 * pointer. Returns the worst distance in CSS px; the button stays down.
 */
export async function dragAlong(page, path, drawn) {
  await page.mouse.move(path[0].x, path[0].y);
  await page.mouse.down();
  let worst = 0;
  for (let i = 1; i < path.length; i++) {
    await page.mouse.move(path[i].x, path[i].y);
    if (i % 4 === 0 || i === path.length - 1) {
      await page.waitForFunction(() => !window.book.surface.book.moving());
      const at = await drawn();
      worst = Math.max(worst, Math.hypot(at.x - path[i].x, at.y - path[i].y));
    }
  }
  return worst;
}
