// Browser (WebGL2 on SwiftShader): the vertex shader that draws each leaf, read back through
// transform feedback, puts every vertex where the C++ reference (curlPoint placed by
// leafPointToWorld) does, to within 1e-4 of the page height, for every spine position and both
// directions of turn.
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';

const TIMES = [0, 0.05, 0.1, 0.15, 0.25, 0.3, 0.4, 0.5, 0.6, 0.75, 0.9, 1];

// Runs in the page: poses a turn and compares the captured leaf with the C++ reference.
async function measure(page, { direction, turn, times, pageCount = 6, start = 1, hardPages, resting = false }) {
  return page.evaluate(async ({ direction, turn, times, pageCount, start, hardPages, resting }) => {
    const { engine } = window.fixture;
    const { BookView } = await import('/web/src/surfaces/book-view.js');
    const canvas = document.createElement('canvas');
    canvas.style.cssText = 'width:320px;height:200px';
    document.body.append(canvas);
    const view = await BookView.create(canvas, { engine, pageCount, direction, hardPages });
    view.jumpTo(start);
    const binding = view.book.binding();
    const height = view.book.pageHeight();
    const results = [];
    for (const t of times) {
      view.showTurn(turn, t);
      const frame = view.book.frame();
      const index = frame.findIndex((leaf) => leaf.resting === resting);
      const draw = frame[index];
      const captured = view.renderer.captureLeaf(view.book, index);
      const points = view.renderer.gridPoints();
      let maxError = 0;
      let maxNormalAngle = 0;
      for (let i = 0; i < points.length / 2; i++) {
        const [x, y] = [points[2 * i], points[2 * i + 1]];
        const ref = engine.leafPointToWorld(draw, binding, height, x, y);
        const c = captured.subarray(6 * i, 6 * i + 6);
        maxError = Math.max(maxError, Math.abs(ref.x - c[0]), Math.abs(ref.y - c[1]), Math.abs(ref.z - c[2]));
        const n = engine.leafNormalToWorld(draw, binding, height, x, y);
        maxNormalAngle = Math.max(maxNormalAngle, Math.acos(Math.min(1, n.x * c[3] + n.y * c[4] + n.z * c[5])));
      }
      results.push({ t, vertices: points.length / 2, captured: captured.length / 6, maxError: maxError / height, maxNormalAngle });
    }
    view.destroy();
    canvas.remove();
    return results;
  }, { direction, turn, times, pageCount, start, hardPages, resting });
}

for (const direction of ['ltr', 'rtl', 'vertical']) {
  for (const turn of ['forward', 'backward']) {
    test(`browser: ${direction} ${turn} turn: transform-feedback positions match C++ at 12 turn times (< 1e-4 H)`, async ({ page }) => {
      await openReady(page, '/tests/browser/fixtures/book-fixture.html?pages=2&sides=1&position=0');
      const results = await measure(page, { direction, turn, times: TIMES });
      console.log(`GPU vs C++, ${direction} ${turn}: worst ${Math.max(...results.map((r) => r.maxError)).toExponential(2)} H, `
        + `normal ${Math.max(...results.map((r) => r.maxNormalAngle)).toExponential(2)} rad`);
      for (const r of results) {
        expect(r.captured, `every vertex captured at t=${r.t}`).toBe(r.vertices);
        expect(r.maxError, `position error at t=${r.t}`).toBeLessThan(1e-4);
        // The shader's normal is the paper's float32 forward difference (step 1e-3 H): first-order error
        // of about step x curvature against the exact normal. 0.01 rad; a side mix-up would be ~pi.
        expect(r.maxNormalAngle, `normal angle at t=${r.t}`).toBeLessThan(0.01);
      }
    });
  }
}

test('browser: hard leaf (cover) turns rigidly and matches C++ too', async ({ page }) => {
  await openReady(page, '/tests/browser/fixtures/book-fixture.html?pages=2&sides=1&position=0');
  const results = await measure(page, { direction: 'ltr', turn: 'forward', times: [0.2, 0.5, 0.8], start: 0, hardPages: [0, 1] });
  for (const r of results) expect(r.maxError, `position error at t=${r.t}`).toBeLessThan(1e-4);
});

test('browser: the readback comparison would notice a wrong pose (t 0.31 against 0.30 differs by > 1e-3)', async ({ page }) => {
  await openReady(page, '/tests/browser/fixtures/book-fixture.html?pages=2&sides=1&position=0');
  const error = await page.evaluate(() => {
    const { engine, view } = window.fixture;
    view.showTurn('forward', 0.3);
    const reference = view.book.frame().find((leaf) => !leaf.resting);
    view.showTurn('forward', 0.31);
    const index = view.book.frame().findIndex((leaf) => !leaf.resting);
    const captured = view.renderer.captureLeaf(view.book, index);
    const points = view.renderer.gridPoints();
    let maxError = 0;
    for (let i = 0; i < points.length / 2; i++) {
      const p = engine.leafPointToWorld(reference, 'left', 1, points[2 * i], points[2 * i + 1]);
      maxError = Math.max(maxError, Math.abs(p.x - captured[6 * i]), Math.abs(p.z - captured[6 * i + 2]));
    }
    return maxError;
  });
  expect(error).toBeGreaterThan(1e-3);
});

test('browser: resting leaves, drawn by the shader\'s flat path, lie where C++ puts them, both stacks, every spine position', async ({ page }) => {
  await openReady(page, '/tests/browser/fixtures/book-fixture.html?pages=2&sides=1&position=0');
  for (const direction of ['ltr', 'rtl', 'vertical']) {
    for (const turn of ['forward', 'backward']) {
      // Mid-turn, so the frame holds a resting leaf under the lifted one on the side it is leaving.
      const results = await measure(page, { direction, turn, times: [0.5], start: 2, resting: true });
      for (const r of results) {
        expect(r.captured, `${direction} ${turn}: every vertex captured`).toBe(r.vertices);
        expect(r.maxError, `${direction} ${turn}: position error`).toBeLessThan(1e-4);
        expect(r.maxNormalAngle, `${direction} ${turn}: normal angle`).toBeLessThan(1e-3);
      }
    }
  }
});
