// Browser (WebGL2 on SwiftShader): key frames of a turn at fixed t. Pixel classes prove which side is
// seen and that it reads the right way round; reference screenshots catch any other visual change.
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';

// The turn of the first leaf from the spine in the middle (center off: a closed book would sit centred).
const FIXTURE = '/tests/browser/fixtures/book-fixture.html?pages=2&sides=1&position=0&center=off';
const CANVAS = { width: 640, height: 400 };
const SPINE_X = CANVAS.width / 2;

async function classify(page, t) {
  return page.evaluate((t) => window.fixture.classifyAt(t), t);
}

test('browser: at t=0 only the front is seen, its top-left marker at the top of the right page near the spine', async ({ page }) => {
  await openReady(page, FIXTURE);
  const { counts, centroids, total } = await classify(page, 0);
  expect(counts.front / total).toBeGreaterThan(0.2);
  expect(counts.back + counts.backMarker).toBe(0);
  const marker = centroids.frontMarker;
  expect(marker.x).toBeGreaterThan(SPINE_X);
  expect(marker.x).toBeLessThan(SPINE_X + 100);
  expect(marker.y).toBeLessThan(CANVAS.height / 3);
});

test('browser: at t=1 only the back is seen, unmirrored: its top-left marker at the outer top of the left page', async ({ page }) => {
  await openReady(page, FIXTURE);
  const { counts, centroids, total } = await classify(page, 1);
  expect(counts.back / total).toBeGreaterThan(0.2);
  expect(counts.front + counts.frontMarker).toBe(0);
  const marker = centroids.backMarker;
  // A mirrored back would put the marker next to the spine instead.
  expect(marker.x).toBeLessThan(SPINE_X - 150);
  expect(marker.y).toBeLessThan(CANVAS.height / 3);
});

test('browser: mid-turn (t=0.1, 0.15) both sides are seen and the canvas is not blank', async ({ page }) => {
  await openReady(page, FIXTURE);
  for (const t of [0.1, 0.15]) {
    const { counts, total } = await classify(page, t);
    // At t=0.1 the curled-over corner covers ~0.7% of the canvas (~4700 px); 0.3% is a clear patch.
    expect(counts.front / total, `front at t=${t}`).toBeGreaterThan(0.003);
    expect(counts.back / total, `back at t=${t}`).toBeGreaterThan(0.003);
    expect(counts.background / total, `page drawn at t=${t}`).toBeLessThan(0.95);
  }
});

test('browser: every frame of a turn draws the page (no blank frame over 101 t values)', async ({ page }) => {
  await openReady(page, FIXTURE);
  const blank = await page.evaluate(() => {
    const out = [];
    for (let i = 0; i <= 100; i++) {
      const { counts, total } = window.fixture.classifyAt(i / 100);
      if (counts.background / total > 0.97) out.push(i / 100);
    }
    return out;
  });
  expect(blank).toEqual([]);
});

// Reference images: scripts/update-references.sh rewrites them (look at each before committing).
// Tolerance: SwiftShader is deterministic on one machine; other CPUs may rasterise antialiased edges
// and text a little differently, so up to 0.5% of pixels may differ by more than the 0.1 threshold.
for (const t of [0, 0.05, 0.15, 0.3, 0.6, 0.9, 1]) {
  test(`browser: frame at t=${t} matches its reference image`, async ({ page }) => {
    await openReady(page, `${FIXTURE}&turn=forward&t=${t}`);
    await expect(page.locator('#book')).toHaveScreenshot(`curl-t${t.toFixed(2)}.png`, {
      maxDiffPixelRatio: 0.005,
      threshold: 0.1,
    });
  });
}
