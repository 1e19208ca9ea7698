// What the consumer tests (consumers.spec.js, frameworks.spec.js) judge a built app by: the problems a
// page reports, and which test page's colour its books show (screenshots).
import { pageAtColor } from './fixtures/test-pages.js';
import { decodePng } from './png.js';

/** A page image fills about 30% of a 640x400 book showing it; its number and corner mark take a little. */
export const SHOWN = 0.2;
export const ABSENT = 0.005;

/**
 * Console errors (and, with `webglWarnings`, any console line about WebGL, such as Chrome losing the
 * oldest context), uncaught exceptions and failed requests of a page, collected from the start.
 */
export function watchProblems(page, { webglWarnings = false } = {}) {
  const problems = [];
  page.on('pageerror', (error) => problems.push(`uncaught: ${error.message}`));
  page.on('console', (message) => {
    if (message.type() === 'error' || (webglWarnings && /WebGL/.test(message.text()))) problems.push(`console ${message.type()}: ${message.text()}`);
  });
  page.on('response', (response) => { if (response.status() >= 400) problems.push(`${response.status()}: ${response.url()}`); });
  return problems;
}

/** Share of an element's on-screen pixels that show each of `pageCount` test pages' colours. */
export async function pageShares(locator, pageCount) {
  const { width, height, data } = decodePng(await locator.screenshot());
  const counts = new Array(pageCount).fill(0);
  let samples = 0;
  for (let y = 0; y < height; y += 2) {
    for (let x = 0; x < width; x += 2) {
      const i = (y * width + x) * 4;
      const index = pageAtColor([data[i], data[i + 1], data[i + 2]], pageCount);
      if (index >= 0) counts[index]++;
      samples++;
    }
  }
  return counts.map((count) => count / samples);
}
