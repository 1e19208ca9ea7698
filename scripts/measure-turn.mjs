// Measures one page turn of the demo in headless Chromium (SwiftShader): frame intervals from
// requestAnimationFrame timestamps, the time spent drawing each frame (wasm + GL calls on the main
// thread), and the page grid chosen for the canvas with its mesh error. Not a test: it prints figures.
// Usage: node scripts/measure-turn.mjs [--dpr 1,2] [--turns 5]
import { spawn } from 'node:child_process';
import { chromium } from '@playwright/test';
import { chromiumLaunchOptions } from './chromium.mjs';

const arg = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i > 0 ? process.argv[i + 1] : fallback;
};
const ratios = arg('--dpr', '1,2').split(',').map(Number);
const turns = Number(arg('--turns', '5'));
const port = 8097;

const server = spawn(process.execPath, ['scripts/serve.mjs', '--port', String(port)], { stdio: 'ignore' });
await new Promise((resolve) => setTimeout(resolve, 500));
const browser = await chromium.launch(chromiumLaunchOptions());
const stats = (values) => {
  const sorted = [...values].sort((a, b) => a - b);
  const at = (q) => sorted[Math.min(sorted.length - 1, Math.floor(q * sorted.length))];
  return { n: sorted.length, median: at(0.5), p95: at(0.95), max: sorted[sorted.length - 1] };
};
try {
  for (const dpr of ratios) {
    const page = await browser.newPage({ viewport: { width: 1400, height: 720 }, deviceScaleFactor: dpr });
    await page.goto(`http://127.0.0.1:${port}/web/demo/?page=5`);
    await page.waitForFunction(() => document.body.dataset.ready || document.body.dataset.error);
    const result = await page.evaluate(async (turns) => {
      const { view } = window.conecurlDemo;
      const draw = view.drawNow.bind(view);
      const drawTimes = [];
      view.drawNow = () => { const t0 = performance.now(); draw(); drawTimes.push(performance.now() - t0); };
      const intervals = [];
      for (let i = 0; i < turns; i++) {
        let last = 0;
        let running = true;
        const sample = (now) => {
          if (last) intervals.push(now - last);
          last = now;
          if (running) requestAnimationFrame(sample);
        };
        requestAnimationFrame(sample);
        await view.next();
        running = false;
      }
      return {
        canvas: `${view.canvas.width}x${view.canvas.height}`,
        grid: `${view.renderer.gridRows()}x${view.renderer.gridColumns()}`,
        gridErrorPixels: view.renderer.gridErrorPixels(),
        intervals,
        drawTimes,
      };
    }, turns);
    const frame = stats(result.intervals);
    const drawing = stats(result.drawTimes);
    console.log(`dpr ${dpr}: canvas ${result.canvas}, grid ${result.grid} rows x columns, mesh error `
      + `${result.gridErrorPixels.toFixed(3)} px`);
    console.log(`  frame interval over ${turns} turns: median ${frame.median.toFixed(1)} ms, p95 ${frame.p95.toFixed(1)} ms, `
      + `max ${frame.max.toFixed(1)} ms (${frame.n} frames)`);
    console.log(`  draw call (main thread): median ${drawing.median.toFixed(2)} ms, max ${drawing.max.toFixed(2)} ms`);
    await page.close();
  }
} finally {
  await browser.close();
  server.kill();
}
