// Measures one page turn of the demo in headless Chromium (SwiftShader): frame intervals from
// requestAnimationFrame timestamps, the time spent drawing each frame (wasm + GL calls on the main
// thread), the GPU process's CPU time per frame, and the page grid chosen for the canvas with its mesh
// error. Not a test: it prints figures (on a shared machine they are noisy: compare runs side by side).
// Usage: node scripts/measure-turn.mjs [--dpr 1,2] [--turns 5] [--port 8097]
//        [--context alpha=false,preserveDrawingBuffer=true] (WebGL context attributes forced, to measure them)
import { spawn } from 'node:child_process';
import { chromium } from '@playwright/test';
import { chromiumLaunchOptions } from './chromium.mjs';
import { cpuDelta, processCpu } from './bench/metrics.mjs';

const arg = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i > 0 ? process.argv[i + 1] : fallback;
};
const ratios = arg('--dpr', '1,2').split(',').map(Number);
const turns = Number(arg('--turns', '5'));
const port = Number(arg('--port', '8097'));
// name=value pairs forced on every WebGL2 context the page makes (true/false values).
const forced = Object.fromEntries((arg('--context', '') || '').split(',').filter(Boolean)
  .map((pair) => pair.split('=')).map(([name, value]) => [name, value === 'true']));

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
    if (Object.keys(forced).length) {
      await page.addInitScript((forced) => {
        const getContext = HTMLCanvasElement.prototype.getContext;
        HTMLCanvasElement.prototype.getContext = function (type, attributes, ...rest) {
          return getContext.call(this, type, type === 'webgl2' ? { ...attributes, ...forced } : attributes, ...rest);
        };
      }, forced);
    }
    await page.goto(`http://127.0.0.1:${port}/web/demo/?page=5`);
    await page.waitForFunction(() => document.body.dataset.ready || document.body.dataset.error);
    const cdp = await browser.newBrowserCDPSession();
    const cpuBefore = await processCpu(cdp);
    const result = await page.evaluate(async (turns) => {
      const { book } = window.conecurlDemo;  // the demo's Flipbook; its surface is the BookView that draws
      await book.whenIdle();
      const view = book.surface;
      // Each frame's one call into the engine (FrameLoop.tick: the clock, the composition and the draw).
      const loop = window.conecurlDemo.engine.FrameLoop.prototype;
      const tick = loop.tick;
      const drawTimes = [];
      loop.tick = function timedTick(...args) {
        const t0 = performance.now();
        const flags = tick.apply(this, args);
        drawTimes.push(performance.now() - t0);
        return flags;
      };
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
        await book.next();
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
    const gpuSeconds = cpuDelta(cpuBefore, await processCpu(cdp)).filter((p) => p.type === 'GPU').reduce((sum, p) => sum + p.cpu, 0);
    const frame = stats(result.intervals);
    const drawing = stats(result.drawTimes);
    console.log(`dpr ${dpr}: canvas ${result.canvas}, grid ${result.grid} rows x columns, mesh error `
      + `${result.gridErrorPixels.toFixed(3)} px`);
    console.log(`  frame interval over ${turns} turns: median ${frame.median.toFixed(1)} ms, p95 ${frame.p95.toFixed(1)} ms, `
      + `max ${frame.max.toFixed(1)} ms (${frame.n} frames)`);
    console.log(`  frame's engine call (main thread): median ${drawing.median.toFixed(2)} ms, max ${drawing.max.toFixed(2)} ms`);
    console.log(`  GPU process CPU over the turns: ${(gpuSeconds * 1000).toFixed(0)} ms, `
      + `${((gpuSeconds * 1000) / Math.max(1, result.drawTimes.length)).toFixed(1)} ms per drawn frame (${result.drawTimes.length} drawn)`);
    await page.close();
  }
} finally {
  await browser.close();
  server.kill();
}
