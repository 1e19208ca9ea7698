// One measurement of one library in one configuration, in a fresh Chromium: navigation to first
// rendered book, 10 turns (rAF intervals, main-thread and per-process CPU per frame), 2 s idle CPU,
// memory after GC, and the drawing buffers the page drew into. Returns plain numbers; the report turns them into tables.
// measureInEngine() reads the page's own figures (first frame, frames, turns) the same way in Firefox or WebKit.
import { chromium } from '@playwright/test';
import {
  busiestRenderer, cpuDelta, heapAfterGc, mainThread, processCpu, pssBytes, rendererAndGpu,
} from './metrics.mjs';
import { chromiumLaunchOptions } from '../chromium.mjs';

const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

// The page's own figures, read alike in every engine: `evaluate(fn, arg)` runs fn(arg) in the page and
// awaits its promise (Playwright's page.evaluate, or the browser.evaluate of scripts/engines.mjs).

/** { readyMs, firstFrameMs }: navigation start to the book mounted and to its first frame on screen (harness.js). */
export const firstFrame = (evaluate) => evaluate(async () => {
  while (!window.bench) await new Promise((resolve) => setTimeout(resolve, 5));
  return window.bench.ready();
});

/**
 * Lets loading that the library started on its own (all page images, for some) finish first, so the
 * turns measure turning: waits until the page's resource entries stop growing (15 s at most). Returns
 * the time this took (ms).
 */
export async function settle(evaluate) {
  const start = Date.now();
  let resources = -1;
  for (;;) {
    const now = await evaluate(() => performance.getEntriesByType('resource').length);
    if (now === resources || Date.now() - start > 15000) break;
    resources = now;
    await sleep(400);
  }
  return Date.now() - start;
}

/**
 * `count` turns forward in the page (harness.js's window.bench.turns): the rAF frame intervals, each turn's
 * start and landing (ms since the first frame), the library's figures after each turn, and the wall time (s).
 */
export async function turnFrames(evaluate, count, turnTimeoutMs) {
  const wallBefore = Date.now();
  const { stamps, turns, turnStats } = await evaluate(([n, timeout]) => window.bench.turns(n, timeout), [count, turnTimeoutMs]);
  const turnSeconds = (Date.now() - wallBefore) / 1000;
  const intervals = stamps.slice(1).map((t, i) => t - stamps[i]);
  return {
    intervals,
    frames: intervals.length,
    turns: turns.map((t) => ({ start: t.start - stamps[0], end: t.end - stamps[0] })),
    turnStats,
    turnSeconds,
  };
}

/** The wasm files the page fetched (URL, decoded bytes): the runner checks conecurl and a baseline each loaded its own. */
export const fetchedWasm = (evaluate) => evaluate(() => performance.getEntriesByType('resource')
  .filter((entry) => new URL(entry.name).pathname.endsWith('.wasm'))
  .map((entry) => ({ url: entry.name, bytes: entry.decodedBodySize })));

/** What the engine's WebGL2 draws with (the unmasked renderer where the engine tells it), from a context of its own. */
export const webglRenderer = (evaluate) => evaluate(() => {
  const gl = document.createElement('canvas').getContext('webgl2');
  if (!gl) return 'no WebGL2';
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const renderer = gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER);
  gl.getExtension('WEBGL_lose_context')?.loseContext();
  return renderer;
});

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

    const evaluate = (fn, arg) => page.evaluate(fn, arg);
    await page.goto(url, { waitUntil: 'commit' });
    const { readyMs, firstFrameMs } = await firstFrame(evaluate);
    const settleMs = await settle(evaluate);

    const cpuBefore = await processCpu(browserSession);
    const mainBefore = await mainThread(pageSession);
    const turning = await turnFrames(evaluate, turns, turnTimeoutMs);
    const mainAfter = await mainThread(pageSession);
    const cpuAfter = await processCpu(browserSession);
    // Read after the CPU sample, so it costs the turns nothing: the buffers as the turns drew into them.
    const drawing = await page.evaluate(() => window.bench.drawing());
    const turnCpu = cpuDelta(cpuBefore, cpuAfter);
    const rendererPid = busiestRenderer(turnCpu);
    const processes = rendererAndGpu(turnCpu, rendererPid);
    const { frames, turnSeconds: wallTurns } = turning;

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
    const wasm = await fetchedWasm(evaluate);
    const renderer = await webglRenderer(evaluate);

    return {
      readyMs,
      firstFrameMs,
      settleMs,
      turns: turning.turns,
      turnSeconds: wallTurns,
      askedTurnMs,
      intervals: turning.intervals,
      frames,
      perFrame: {
        mainThreadMs: (1000 * (mainAfter.TaskDuration - mainBefore.TaskDuration)) / frames,
        scriptMs: (1000 * (mainAfter.ScriptDuration - mainBefore.ScriptDuration)) / frames,
        rendererCpuMs: (1000 * processes.renderer) / frames,
        gpuCpuMs: (1000 * processes.gpu) / frames,
      },
      turning: { rendererCpuPercent: (100 * processes.renderer) / wallTurns, gpuCpuPercent: (100 * processes.gpu) / wallTurns },
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
      turnStats: turning.turnStats,
      drawing,
      wasm,
      renderer,
      errors,
    };
  } finally {
    await browser.close();
  }
}

/**
 * One measurement in Firefox or WebKit: `browser` is scripts/engines.mjs's, kept from one measurement to
 * the next (one browser per engine), its viewport set to the configuration's. The same harness page,
 * book and turns as measureOnce(), read by the same functions; the CPU and memory figures are Chromium's
 * (CDP, its process model) and are not taken. The harness is served without caching, so every visit
 * fetches its bundle, wasm and pages again.
 */
export async function measureInEngine(browser, { url, turns, askedTurnMs, turnTimeoutMs }) {
  await browser.goto(url);
  const { readyMs, firstFrameMs } = await firstFrame(browser.evaluate);
  const settleMs = await settle(browser.evaluate);
  const turning = await turnFrames(browser.evaluate, turns, turnTimeoutMs);
  const drawing = await browser.evaluate(() => window.bench.drawing());
  const stats = await browser.evaluate(() => window.bench.stats());
  const wasm = await fetchedWasm(browser.evaluate);
  const renderer = await webglRenderer(browser.evaluate);
  return { readyMs, firstFrameMs, settleMs, askedTurnMs, ...turning, stats, drawing, wasm, renderer };
}
