// One measurement of one library in one configuration, in a fresh Chromium: navigation to first
// rendered book, 10 turns (rAF intervals, main-thread and per-process CPU per frame), 2 s idle CPU,
// memory after GC, and the drawing buffers the page drew into. Returns plain numbers; the report turns them into tables.
import { chromium } from '@playwright/test';
import {
  busiestRenderer, cpuDelta, heapAfterGc, mainThread, processCpu, pssBytes, rendererAndGpu,
} from './metrics.mjs';
import { chromiumLaunchOptions } from '../chromium.mjs';


const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

/**
 * @param {object} o
 * @param {string} o.url          harness URL with the query for this library and configuration
 * @param {object} o.use         Playwright context options of the configuration's screen: viewport and
 *   deviceScaleFactor, and on a phone isMobile and hasTouch
 * @param {number} o.turns        turns to make
 * @param {number} o.askedTurnMs  the turn duration the page was asked for (returned with the result)
 * @param {number} o.turnTimeoutMs
 * @param {number} o.idleMs       how long idle CPU is sampled
 */
export async function measureOnce({ url, use, turns, askedTurnMs, turnTimeoutMs, idleMs }) {
  const browser = await chromium.launch(chromiumLaunchOptions());
  const errors = [];
  try {
    const context = await browser.newContext(use);
    const page = await context.newPage();
    page.on('pageerror', (error) => errors.push(String(error)));
    page.on('console', (message) => { if (message.type() === 'error') errors.push(message.text()); });
    const pageSession = await context.newCDPSession(page);
    const browserSession = await browser.newBrowserCDPSession();
    await pageSession.send('Performance.enable');

    await page.goto(url, { waitUntil: 'commit' });
    const { readyMs, firstFrameMs } = await page.evaluate(async () => {
      while (!window.bench) await new Promise((resolve) => setTimeout(resolve, 5));
      return window.bench.ready();
    });

    // Let loading that the library started on its own (all page images, for some) finish first, so
    // the turns measure turning; the time this took is reported.
    const settleStart = Date.now();
    let resources = -1;
    for (;;) {
      const now = await page.evaluate(() => performance.getEntriesByType('resource').length);
      if (now === resources || Date.now() - settleStart > 15000) break;
      resources = now;
      await sleep(400);
    }
    const settleMs = Date.now() - settleStart;

    const cpuBefore = await processCpu(browserSession);
    const mainBefore = await mainThread(pageSession);
    const wallBefore = Date.now();
    const { stamps, turns: turnTimes, turnStats } = await page.evaluate(
      ([count, timeout]) => window.bench.turns(count, timeout), [turns, turnTimeoutMs]);
    const wallTurns = (Date.now() - wallBefore) / 1000;
    const mainAfter = await mainThread(pageSession);
    const cpuAfter = await processCpu(browserSession);
    // Read after the CPU sample, so it costs the turns nothing: the buffers as the turns drew into them.
    const drawing = await page.evaluate(() => window.bench.drawing());
    const turnCpu = cpuDelta(cpuBefore, cpuAfter);
    const rendererPid = busiestRenderer(turnCpu);
    const turning = rendererAndGpu(turnCpu, rendererPid);
    const intervals = stamps.slice(1).map((t, i) => t - stamps[i]);
    const frames = intervals.length;

    await sleep(1000);  // the GPU process may still be finishing the last frames
    const idleCpuBefore = await processCpu(browserSession);
    const idleMainBefore = await mainThread(pageSession);
    const idleStart = Date.now();
    await sleep(idleMs);
    const idleMainAfter = await mainThread(pageSession);
    const idleCpuAfter = await processCpu(browserSession);
    const idleSeconds = (Date.now() - idleStart) / 1000;
    const idle = rendererAndGpu(cpuDelta(idleCpuBefore, idleCpuAfter), rendererPid);

    const jsHeapBytes = await heapAfterGc(pageSession);
    const gpuPids = cpuAfter.filter((p) => p.type === 'GPU').map((p) => p.pid);
    const rendererPss = pssBytes(rendererPid);
    const gpuPss = gpuPids.reduce((sum, pid) => sum + (pssBytes(pid) || 0), 0);
    const stats = await page.evaluate(() => window.bench.stats());
    // The wasm files the page fetched (URL, decoded bytes): the runner checks conecurl and a baseline each
    // loaded its own.
    const wasm = await page.evaluate(() => performance.getEntriesByType('resource')
      .filter((entry) => new URL(entry.name).pathname.endsWith('.wasm'))
      .map((entry) => ({ url: entry.name, bytes: entry.decodedBodySize })));

    return {
      readyMs,
      firstFrameMs,
      settleMs,
      turns: turnTimes.map((t) => ({ start: t.start - stamps[0], end: t.end - stamps[0] })),
      turnSeconds: wallTurns,
      askedTurnMs,
      intervals,
      frames,
      perFrame: {
        mainThreadMs: (1000 * (mainAfter.TaskDuration - mainBefore.TaskDuration)) / frames,
        scriptMs: (1000 * (mainAfter.ScriptDuration - mainBefore.ScriptDuration)) / frames,
        rendererCpuMs: (1000 * turning.renderer) / frames,
        gpuCpuMs: (1000 * turning.gpu) / frames,
      },
      turning: { rendererCpuPercent: (100 * turning.renderer) / wallTurns, gpuCpuPercent: (100 * turning.gpu) / wallTurns },
      idle: {
        seconds: idleSeconds,
        rendererCpuPercent: (100 * idle.renderer) / idleSeconds,
        gpuCpuPercent: (100 * idle.gpu) / idleSeconds,
        browserCpuPercent: (100 * idle.browser) / idleSeconds,
        totalCpuPercent: (100 * (idle.renderer + idle.gpu)) / idleSeconds,
        mainThreadPercent: (100 * (idleMainAfter.TaskDuration - idleMainBefore.TaskDuration)) / idleSeconds,
      },
      memory: { jsHeapBytes, rendererPssBytes: rendererPss, gpuPssBytes: gpuPss },
      stats,
      turnStats,
      drawing,
      wasm,
      errors,
    };
  } finally {
    await browser.close();
  }
}
