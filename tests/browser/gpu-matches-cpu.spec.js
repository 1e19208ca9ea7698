// Browser (WebGL2 on SwiftShader): the vertex shader that draws the page, read back through transform
// feedback, computes the same curled positions as the C++ reference, to within 1e-4 of the page height.
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';

const TIMES = [0, 0.05, 0.1, 0.15, 0.25, 0.3, 0.4, 0.5, 0.6, 0.75, 0.9, 1];

test('browser: transform-feedback positions match C++ curlPoint at 12 turn times (max error < 1e-4 H)', async ({ page }) => {
  await openReady(page, '/tests/browser/fixtures/curl-fixture.html');
  const results = await page.evaluate((times) => {
    const { engine, view } = window.fixture;
    const renderer = view.renderer;
    const points = renderer.gridPoints();
    const height = renderer.pageHeight();
    return times.map((t) => {
      const params = renderer.paramsAt(t);
      const captured = renderer.captureCurledVertices(params);
      let maxError = 0;
      let maxNormalAngle = 0;
      for (let i = 0; i < points.length / 2; i++) {
        const ref = engine.curlPoint(points[2 * i], points[2 * i + 1], params);
        const c = captured.subarray(6 * i, 6 * i + 6);
        maxError = Math.max(maxError, Math.abs(ref.x - c[0]), Math.abs(ref.y - c[1]), Math.abs(ref.z - c[2]));
        const dot = ref.normal.x * c[3] + ref.normal.y * c[4] + ref.normal.z * c[5];
        maxNormalAngle = Math.max(maxNormalAngle, Math.acos(Math.min(1, dot)));
      }
      return { t, vertices: points.length / 2, captured: captured.length / 6, maxError: maxError / height, maxNormalAngle };
    });
  }, TIMES);
  console.log('GPU vs C++ (error in page heights, normal angle in rad):');
  for (const r of results) console.log(`  t=${r.t}: ${r.maxError.toExponential(2)}  normal ${r.maxNormalAngle.toExponential(2)}`);
  for (const r of results) {
    expect(r.captured, `every vertex captured at t=${r.t}`).toBe(r.vertices);
    expect(r.maxError, `position error at t=${r.t}`).toBeLessThan(1e-4);
    // The shader's normal is the paper's float32 forward difference (step 1e-3 H): first-order error
    // of about step x curvature, against the exact normal; 0.01 rad is still far from a wrong side.
    expect(r.maxNormalAngle, `normal angle at t=${r.t}`).toBeLessThan(0.01);
  }
});

test('browser: the readback test would notice a wrong shader (different t gives a large error)', async ({ page }) => {
  await openReady(page, '/tests/browser/fixtures/curl-fixture.html');
  const error = await page.evaluate(() => {
    const { engine, view } = window.fixture;
    const renderer = view.renderer;
    const points = renderer.gridPoints();
    const captured = renderer.captureCurledVertices(renderer.paramsAt(0.31));
    const ref = renderer.paramsAt(0.3);
    let maxError = 0;
    for (let i = 0; i < points.length / 2; i++) {
      const p = engine.curlPoint(points[2 * i], points[2 * i + 1], ref);
      maxError = Math.max(maxError, Math.abs(p.x - captured[6 * i]), Math.abs(p.z - captured[6 * i + 2]));
    }
    return maxError;
  });
  expect(error).toBeGreaterThan(1e-3);
});
