// Profiling aid for "first page shown": where the time from navigation to the first frame goes, phase by
// phase (bundle, wasm fetch and instantiate, WebGL context, shader programs, first page fetched, decoded
// and uploaded, first draw), from timestamps an init script takes around the browser calls that do each,
// and any performance.mark()s the page made. docs/benchmark.md "Where the first page's time goes".
// Usage: node scripts/bench/startup.mjs [--lib conecurl] [--configs double-20,phone-20] [--reps 5] [--port 8097]
//        [--no-bundle] (reuse bench-results/startup/bundles) [--rows] (also each run's figures, one JSON line a config)
import { spawn } from 'node:child_process';
import path from 'node:path';
import { chromium } from '@playwright/test';
import { chromiumLaunchOptions } from '../chromium.mjs';
import { bundleLibraries } from './bundle.mjs';
import { writePageImages } from './page-images.mjs';
import { PHONES, phoneUse } from '../../tests/browser/phone.js';

const root = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../..');
const arg = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i > 0 ? process.argv[i + 1] : fallback;
};
const lib = arg('--lib', 'conecurl');
const configIds = arg('--configs', 'double-20,phone-20').split(',');
const reps = Number(arg('--reps', '5'));
const port = Number(arg('--port', process.env.CONECURL_BENCH_PORT || '8097'));
const CONFIGS = {  // as scripts/bench/run.mjs measures them
  'double-20': { display: 'double', pages: 20, use: { viewport: { width: 1600, height: 1100 }, deviceScaleFactor: 1 } },
  'phone-20': { display: 'single', pages: 20, use: phoneUse(PHONES['phone-portrait']) },
};
for (const id of configIds) if (!CONFIGS[id]) throw new Error(`startup: unknown config ${id} (${Object.keys(CONFIGS).join(', ')})`);

// Runs in the page before anything else: wraps the calls each phase makes and notes when each ran and
// how long it blocked the main thread (GL calls that wait for the GPU process block here).
function instrument() {
  const t = { calls: {}, events: [] };
  window.__startup = t;
  const note = (name, start, end) => {
    const c = (t.calls[name] ??= { count: 0, ms: 0, first: start, last: end });
    c.count++;
    c.ms += end - start;
    c.last = end;
  };
  const wrap = (proto, name, label = name) => {
    const f = proto[name];
    if (typeof f !== 'function') return;
    proto[name] = function wrapped(...args) {
      const start = performance.now();
      try { return f.apply(this, args); } finally { note(label, start, performance.now()); }
    };
  };
  const wrapAsync = (object, name, label = name) => {
    const f = object[name];
    object[name] = function wrapped(...args) {
      const start = performance.now();
      const result = f.apply(this, args);
      Promise.resolve(result).then(() => t.events.push({ name: label, start, end: performance.now(), what: String(args[0]?.url ?? args[0] ?? '').slice(-40) }), () => {});
      return result;
    };
  };
  const gl = WebGL2RenderingContext.prototype;
  for (const name of ['compileShader', 'linkProgram', 'getShaderParameter', 'getProgramParameter', 'getUniformLocation',
    'getActiveUniform', 'texImage2D', 'texSubImage2D', 'drawArrays', 'drawElements', 'getParameter', 'getExtension',
    'getSupportedExtensions', 'readPixels', 'clear']) wrap(gl, name);
  wrap(HTMLCanvasElement.prototype, 'getContext');
  wrapAsync(WebAssembly, 'instantiateStreaming');
  wrapAsync(WebAssembly, 'instantiate');
  wrapAsync(window, 'createImageBitmap');
  wrapAsync(window, 'fetch');
}

const server = spawn(process.execPath, [path.join(root, 'scripts/serve.mjs'), '--port', String(port)], { stdio: 'ignore' });
const out = path.join(root, 'bench-results/startup');
try {
  writePageImages(path.join(out, 'pages'), 20);
  if (!process.argv.includes('--no-bundle')) await bundleLibraries(path.join(out, 'bundles'));
  const rel = (p) => `/${path.relative(root, p)}`;
  for (const id of configIds) {
    const config = CONFIGS[id];
    const rows = [];
    for (let rep = 0; rep < reps; rep++) {
      const browser = await chromium.launch(chromiumLaunchOptions());
      try {
        const context = await browser.newContext(config.use);
        await context.addInitScript(instrument);
        const page = await context.newPage();
        const query = new URLSearchParams({ lib, pages: String(config.pages), display: config.display, duration: '600',
          bundles: rel(path.join(out, 'bundles')), images: rel(path.join(out, 'pages')) });
        await page.goto(`http://127.0.0.1:${port}/scripts/bench/harness.html?${query}`, { waitUntil: 'commit' });
        const { readyMs, firstFrameMs } = await page.evaluate(async () => {
          while (!window.bench) await new Promise((resolve) => setTimeout(resolve, 5));
          return window.bench.ready();
        });
        rows.push(await page.evaluate(([ready, first]) => {
          const { calls, events } = window.__startup;
          const resources = performance.getEntriesByType('resource');
          const res = (test) => resources.filter((r) => test(new URL(r.name).pathname));
          const span = (list) => (list.length ? [Math.min(...list.map((r) => r.startTime)), Math.max(...list.map((r) => r.responseEnd))] : [NaN, NaN]);
          const [bundleStart, bundleEnd] = span(res((p) => p.endsWith('.js') && p.includes('/bundles/')));
          const [wasmStart, wasmEnd] = span(res((p) => p.endsWith('.wasm')));
          const inst = events.filter((e) => e.name.startsWith('instantiate'));
          const pngs = res((p) => p.endsWith('.png'));
          const firstPng = pngs.length ? Math.min(...pngs.map((r) => r.startTime)) : NaN;
          const bitmaps = events.filter((e) => e.name === 'createImageBitmap').sort((a, b) => a.end - b.end);
          const c = (name) => calls[name] ?? { count: 0, ms: 0, first: NaN, last: NaN };
          const draws = [c('drawArrays').first, c('drawElements').first].filter(Number.isFinite);
          const shaderMs = ['compileShader', 'linkProgram', 'getShaderParameter', 'getProgramParameter', 'getUniformLocation', 'getActiveUniform']
            .reduce((sum, n) => sum + c(n).ms, 0);
          return {
            bundleEnd,
            wasmFetch: [wasmStart, wasmEnd],
            instantiated: inst.length ? Math.max(...inst.map((e) => e.end)) : NaN,
            context: [c('getContext').first, c('getContext').ms],
            programs: c('linkProgram').count,
            shaders: [c('compileShader').first, c('getProgramParameter').last, shaderMs],
            pagesRequested: firstPng,
            pagesDecoded: bitmaps.length ? bitmaps[Math.min(bitmaps.length, 2) - 1].end : NaN,
            upload: [c('texImage2D').first, c('texImage2D').ms + c('texSubImage2D').ms],
            firstDraw: Math.min(...draws),
            ready,
            first,
            marks: performance.getEntriesByType('mark').map((m) => [m.name, m.startTime]),
          };
        }, [readyMs, firstFrameMs]));
      } finally {
        await browser.close();
      }
    }
    // --rows: each run's figures as one JSON line, to pool runs of several invocations (before and after alternated).
    if (process.argv.includes('--rows')) console.log(`rows ${lib} ${id} ${JSON.stringify(rows)}`);
    const med = (f) => {
      const values = rows.map(f).filter(Number.isFinite).sort((a, b) => a - b);
      return values.length ? values[Math.floor(values.length / 2)].toFixed(0).padStart(5) : '    -';
    };
    console.log(`\n${lib} ${id}: medians of ${reps} runs, ms after navigation start (block = main thread blocked in those calls)`);
    console.log(`  bundle loaded            ${med((r) => r.bundleEnd)}`);
    console.log(`  wasm fetch               ${med((r) => r.wasmFetch[0])} .. ${med((r) => r.wasmFetch[1])}`);
    console.log(`  wasm instantiated        ${med((r) => r.instantiated)}`);
    console.log(`  WebGL context            ${med((r) => r.context[0])}   block ${med((r) => r.context[1])}`);
    console.log(`  programs (${rows[0].programs} linked)      ${med((r) => r.shaders[0])} .. ${med((r) => r.shaders[1])}   block ${med((r) => r.shaders[2])}`);
    console.log(`  first page requested     ${med((r) => r.pagesRequested)}`);
    console.log(`  shown pages decoded      ${med((r) => r.pagesDecoded)}`);
    console.log(`  first upload             ${med((r) => r.upload[0])}   block ${med((r) => r.upload[1])}`);
    console.log(`  first draw call          ${med((r) => r.firstDraw)}`);
    console.log(`  create() resolved        ${med((r) => r.ready)}`);
    console.log(`  first frame (bench)      ${med((r) => r.first)}`);
    for (const [i, [name]] of (rows[0].marks || []).entries()) console.log(`  ${name.padEnd(24)} ${med((r) => r.marks[i]?.[1])}`);
  }
} finally {
  server.kill();
}
