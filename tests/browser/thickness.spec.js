// Browser (WebGL2 on SwiftShader): the book's thickness read back from the drawn frame. The stacks'
// edge bands outside the open pages follow the leaves on each side; thickness off draws none.
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';

const FIXTURE = '/tests/browser/fixtures/book-fixture.html';

// Opaque pixels along the canvas row through the middle of the pages, outside the resting rectangle
// (one pixel of the page's own antialiased edge left out): the left and right edge bands' widths.
function bandsAcrossTheMiddle() {
  const { view } = window.fixture;
  view.drawNow();
  const pixels = view.readPixels();
  const rect = view.book.restingRect(pixels.width, pixels.height);
  const y = Math.round(rect.y + rect.height / 2);
  const opaque = (x) => pixels.data[(y * pixels.width + x) * 4 + 3] > 128;
  let left = 0;
  for (let x = Math.floor(rect.x) - 2; x >= 0 && opaque(x); x--) left++;
  let right = 0;
  for (let x = Math.ceil(rect.x + rect.width) + 1; x < pixels.width && opaque(x); x++) right++;
  // Anything drawn at all outside the rectangle on this row, banded or not.
  let outside = 0;
  for (let x = 0; x < pixels.width; x++) {
    const inRect = x >= Math.floor(rect.x) - 1 && x <= Math.ceil(rect.x + rect.width);
    if (!inRect && pixels.data[(y * pixels.width + x) * 4 + 3] > 0) outside++;
  }
  return { left, right, outside };
}

async function bandsOverTenTurns(page, query) {
  await openReady(page, `${FIXTURE}?${query}`);
  return page.evaluate((measure) => {
    const bands = new Function(`return (${measure})`)();  // eslint-disable-line no-new-func
    const { view } = window.fixture;
    const out = [bands()];
    for (let i = 0; i < 10; i++) {
      view.book.startTurn('forward');
      view.book.setLatestTurnProgress(0.5);
      const midTurn = bands();  // the leaf is in the air: in neither stack
      view.book.advance(10);    // it lands
      out.push({ ...bands(), midTurn });
    }
    return out;
  }, bandsAcrossTheMiddle.toString());
}

test('browser: over ten turns the left stack\'s edge band grows and the right one\'s shrinks (readback)', async ({ page }) => {
  // 12 leaves, one turned: a leaf is about a pixel of band here, so a turn moves each band by a pixel
  // or so (less as the depth nears its cap); the pixel grid may hold one still, never move it back.
  const steps = await bandsOverTenTurns(page, 'pages=24&position=1&thickness=0.006');
  console.log(`edge bands (left/right px) over ten turns: ${steps.map((s) => `${s.left}/${s.right}`).join(' ')}`);
  for (let i = 1; i < steps.length; i++) {
    expect(steps[i].left, `left band after turn ${i}`).toBeGreaterThanOrEqual(steps[i - 1].left);
    expect(steps[i].right, `right band after turn ${i}`).toBeLessThanOrEqual(steps[i - 1].right);
    // Mid-turn the leaf has left the right stack and not yet joined the left one.
    expect(steps[i].midTurn.right, `right band mid-turn ${i}`).toBeLessThanOrEqual(steps[i - 1].right);
    expect(steps[i].midTurn.left, `left band mid-turn ${i}`).toBe(steps[i - 1].left);
  }
  // One leaf on the left at the start and eleven after ten turns; eleven on the right, then one.
  expect(steps[10].left - steps[0].left).toBeGreaterThanOrEqual(6);
  expect(steps[0].right - steps[10].right).toBeGreaterThanOrEqual(6);
  expect(steps[10].left).toBeGreaterThan(steps[10].right);
  expect(steps[0].right).toBeGreaterThan(steps[0].left);
});

test('browser: thickness off draws nothing outside the pages, before or after ten turns (readback)', async ({ page }) => {
  const steps = await bandsOverTenTurns(page, 'pages=40&position=1&thickness=off');
  for (const [i, step] of steps.entries()) {
    expect(step.outside, `pixels outside the pages after ${i} turns`).toBe(0);
    expect(step.midTurn?.left ?? 0).toBe(0);
  }
});

test('browser: thickness changes live: setOptions turns the bands off and back on, and a thicker paper draws wider bands (readback)', async ({ page }) => {
  await openReady(page, `${FIXTURE}?pages=40&position=10`);
  const result = await page.evaluate((measure) => {
    const bands = new Function(`return (${measure})`)();  // eslint-disable-line no-new-func
    const { view } = window.fixture;
    const on = bands();
    view.setOptions({ thickness: false });
    const off = bands();
    view.setOptions({ thickness: 0.02 });
    const thick = bands();
    let refused = '';
    try { view.setOptions({ thickness: 0.5 }); } catch (error) { refused = String(error); }
    return { on, off, thick, refused };
  }, bandsAcrossTheMiddle.toString());
  expect(result.on.left).toBeGreaterThan(0);
  expect(result.on.right).toBeGreaterThan(0);
  expect(result.off.outside).toBe(0);
  expect(result.thick.left).toBeGreaterThan(result.on.left);
  expect(result.thick.right).toBeGreaterThan(result.on.right);
  expect(result.refused).toBe('RangeError: conecurl: thickness must be true, false or a number from 0 to 0.02 (a leaf, of the page width)');
});

// Reference image (scripts/update-references.sh rewrites it; look at it before committing): a thick
// book with hard covers, open, a leaf in flight over its stacks.
test('browser: thick book with hard covers mid-turn matches its reference image', async ({ page }) => {
  await openReady(page, `${FIXTURE}?pages=40&position=6&hard=0,1,38,39&thickness=0.012&turn=forward&t=0.3`);
  await expect(page.locator('#book')).toHaveScreenshot('thickness-hard-covers-t0-30.png', { maxDiffPixelRatio: 0.005, threshold: 0.1 });
});
