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
