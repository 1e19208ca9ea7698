// Profiling aid for "first page shown": where the time from navigation to the first frame goes, phase by
// phase (bundle, wasm fetch and instantiate, WebGL context, shader programs, first page fetched, decoded
// and uploaded, first draw), from timestamps an init script takes around the browser calls that do each,
// and any performance.mark()s the page made. docs/benchmark.md "Where the first page's time goes".
// Usage: node scripts/bench/startup.mjs [--libs conecurl,floor-webgl] [--configs double-20,single-20,phone-20] [--reps 5]
//        [--port 8097] [--baseline <dir>] (another checkout, measured as conecurl-baseline: name it in --libs)
//        [--no-bundle] (reuse bench-results/startup/bundles) [--rows] (also each run's figures, one JSON line a config)
//        [--engine chromium|firefox|webkit] (Firefox and WebKit through scripts/engines.mjs, desktop configs only)
//        [--stack] (a failure's stack trace; without it, one line)
// The libraries take turns within each rep, so a slow spell of the machine falls on all of them. Chromium: a
// fresh browser each run. Firefox and WebKit: one browser for all runs of a config, after one visit not measured
// (as the bench's engine rows), the instrument run by harness.js (`instrument=startup`) before the library loads.
import { spawn } from 'node:child_process';
import path from 'node:path';
import { chromium } from '@playwright/test';
import { chromiumLaunchOptions } from '../chromium.mjs';
import { ENGINES, engineExecutables, launchEngine, startDisplay } from '../engines.mjs';
import { BASELINE, LIBRARIES, bundleBaseline, bundleLibraries } from './bundle.mjs';
import { writePageImages } from './page-images.mjs';
import { PHONES, phoneUse } from '../../tests/browser/phone.js';
import { arg, runMain, usage as badArgument } from './cli.mjs';

const root = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../..');
const usage = (message) => badArgument('startup', message);
const libs = arg('--libs', arg('--lib', 'conecurl')).split(',');
const baselineDir = arg('--baseline', null);
if (libs.includes(BASELINE) && !baselineDir) usage(`${BASELINE} needs --baseline <dir> (another conecurl checkout with its dist/ built)`);
const configIds = arg('--configs', 'double-20,phone-20').split(',');
const reps = Number(arg('--reps', '5'));
for (const lib of libs) if (lib !== BASELINE && !LIBRARIES.includes(lib)) usage(`unknown library ${lib} (${[...LIBRARIES, BASELINE].join(', ')})`);
if (!Number.isInteger(reps) || reps < 1) usage(`--reps takes a whole number of runs, 1 or more (got ${arg('--reps')})`);
const port = Number(arg('--port', process.env.CONECURL_BENCH_PORT || '8097'));
const engine = arg('--engine', 'chromium');
if (engine !== 'chromium' && !ENGINES.includes(engine)) usage(`unknown engine ${engine} (chromium, ${ENGINES.join(', ')})`);
const INSTRUMENT = path.join(root, 'scripts/bench/startup-instrument.js');
const CONFIGS = {  // as scripts/bench/run.mjs measures them
  'double-20': { display: 'double', pages: 20, use: { viewport: { width: 1600, height: 1100 }, deviceScaleFactor: 1 } },
  'single-20': { display: 'single', pages: 20, use: { viewport: { width: 1600, height: 1100 }, deviceScaleFactor: 1 } },
  'phone-20': { display: 'single', pages: 20, use: phoneUse(PHONES['phone-portrait']) },
};
for (const id of configIds) {
  if (!CONFIGS[id]) usage(`unknown config ${id} (${Object.keys(CONFIGS).join(', ')})`);
  if (engine !== 'chromium' && CONFIGS[id].use.isMobile) usage(`${id} is a phone, measured in Chromium only (no phone emulation in ${engine} here)`);
}

// In the page once the book is ready: the phases' timestamps, as the instrument and the resource timings saw them.
function collect([ready, first]) {
  const { calls, events, long, frames } = window.__startup;
  const resources = performance.getEntriesByType('resource');
  const res = (test) => resources.filter((r) => test(new URL(r.name).pathname));
  const span = (list) => (list.length ? [Math.min(...list.map((r) => r.startTime)), Math.max(...list.map((r) => r.responseEnd))] : [NaN, NaN]);
  // The library's entry file (bundle.mjs names it <lib>.js): its chunks, lazy ones too, come after it.
  const lib = new URLSearchParams(location.search).get('lib');
  const [, bundleEnd] = span(res((p) => p.includes('/bundles/') && p.endsWith(`/${lib}.js`)));
  const [wasmStart, wasmEnd] = span(res((p) => p.endsWith('.wasm')));
  const inst = events.filter((e) => e.name.startsWith('instantiate'));
  const pngs = res((p) => p.endsWith('.png'));
  const firstPng = pngs.length ? Math.min(...pngs.map((r) => r.startTime)) : NaN;
  const bitmaps = events.filter((e) => e.name === 'createImageBitmap').sort((a, b) => a.end - b.end);
  const c = (name) => calls[name] ?? { count: 0, ms: 0, first: NaN, last: NaN };
  const draws = [c('drawArrays').first, c('drawElements').first].filter(Number.isFinite);
  const shaderMs = ['compileShader', 'linkProgram', 'getShaderParameter', 'getProgramParameter', 'getUniformLocation', 'getActiveUniform']
    .reduce((sum, n) => sum + c(n).ms, 0);
  // Between create() resolving and the first frame: the main thread blocked in GL calls, pages fetched, frames run.
  const between = (start) => start >= ready && start <= first;
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
    afterReady: {
      glBlockedMs: long.filter((call) => between(call.start)).reduce((sum, call) => sum + call.ms, 0),
      pngsRequested: pngs.filter((r) => between(r.startTime)).length,
      frames: frames.filter(between).length,
      longestFrameGapMs: frames.filter((now) => now >= ready).slice(0, 4).reduce((gap, now, i, list) => (i ? Math.max(gap, now - list[i - 1]) : gap), 0),
    },
    marks: performance.getEntriesByType('mark').map((m) => [m.name, m.startTime]),
  };
}

const queryOf = (lib, config, bundles, images) => new URLSearchParams({ lib, pages: String(config.pages), display: config.display, duration: '600', bundles, images });
const bookReady = async () => {
  while (!window.bench) await new Promise((resolve) => setTimeout(resolve, 5));
  return window.bench.ready();
};

// One navigation of `lib` in `config` in a fresh Chromium.
async function measureOnce(lib, config, bundles, images) {
  const browser = await chromium.launch(chromiumLaunchOptions());
  try {
    const context = await browser.newContext(config.use);
    await context.addInitScript({ path: INSTRUMENT });
    const page = await context.newPage();
    await page.goto(`http://127.0.0.1:${port}/scripts/bench/harness.html?${queryOf(lib, config, bundles, images)}`, { waitUntil: 'commit' });
    const { readyMs, firstFrameMs } = await page.evaluate(bookReady);
    return await page.evaluate(collect, [readyMs, firstFrameMs]);
  } finally {
    await browser.close();
  }
}

// One navigation of `lib` in `config` in `browser` (scripts/engines.mjs), the harness running the instrument.
async function measureInEngine(browser, lib, config, bundles, images) {
  await browser.goto(`http://127.0.0.1:${port}/scripts/bench/harness.html?${queryOf(lib, config, bundles, images)}&instrument=startup`);
  const { readyMs, firstFrameMs } = await browser.evaluate(bookReady);
  return browser.evaluate(collect, [readyMs, firstFrameMs]);
}

const med = (rows, f) => {
  const values = rows.map(f).filter(Number.isFinite).sort((a, b) => a - b);
  return values.length ? values[Math.floor(values.length / 2)].toFixed(0).padStart(5) : '    -';
};

function report(lib, id, rows) {
  const m = (f) => med(rows, f);
  console.log(`\n${lib} ${id}: medians of ${rows.length} runs, ms after navigation start (block = main thread blocked in those calls)`);
  console.log(`  bundle's entry loaded    ${m((r) => r.bundleEnd)}`);
  console.log(`  wasm fetch               ${m((r) => r.wasmFetch[0])} .. ${m((r) => r.wasmFetch[1])}`);
  console.log(`  wasm instantiated        ${m((r) => r.instantiated)}`);
  console.log(`  WebGL context            ${m((r) => r.context[0])}   block ${m((r) => r.context[1])}`);
  console.log(`  programs (${rows[0].programs} linked)      ${m((r) => r.shaders[0])} .. ${m((r) => r.shaders[1])}   block ${m((r) => r.shaders[2])}`);
  console.log(`  first page requested     ${m((r) => r.pagesRequested)}`);
  console.log(`  shown pages decoded      ${m((r) => r.pagesDecoded)}`);
  console.log(`  first upload             ${m((r) => r.upload[0])}   block ${m((r) => r.upload[1])}`);
  console.log(`  first draw call          ${m((r) => r.firstDraw)}`);
  console.log(`  create() resolved        ${m((r) => r.ready)}`);
  console.log(`  first frame (bench)      ${m((r) => r.first)}`);
  console.log(`  create() -> first frame  ${m((r) => r.first - r.ready)}   of it: GL block ${m((r) => r.afterReady.glBlockedMs)}, `
    + `${m((r) => r.afterReady.frames)} frames, longest gap ${m((r) => r.afterReady.longestFrameGapMs)}, ${m((r) => r.afterReady.pngsRequested)} pages asked`);
  for (const [i, [name]] of (rows[0].marks || []).entries()) console.log(`  ${name.padEnd(24)} ${m((r) => r.marks[i]?.[1])}`);
}

// Firefox or WebKit on a display of its own at the config's viewport, after one visit not measured (its first
// page and WebGL context): a measure(lib, config, bundles, images) function, with close().
async function engineMeasure(config, bundles, images) {
  const exe = engineExecutables(engine);
  const display = await startDisplay(exe.xvfb);
  const { width, height } = config.use.viewport;
  const browser = await launchEngine(engine, { display: display.display, width, height });
  const measure = (lib, ...rest) => measureInEngine(browser, lib, ...rest);
  measure.close = async () => { await browser.close().catch(() => {}); display.stop(); };
  try {
    await measureInEngine(browser, libs[0], config, bundles, images);
  } catch (error) {
    await measure.close();
    throw error;
  }
  console.log(`startup: ${engine} ${browser.version}`);
  return measure;
}

// Bundles the libraries, serves the page and measures each config; a failure is one line (`--stack`: its trace), exit 1.
async function main() {
  const server = spawn(process.execPath, [path.join(root, 'scripts/serve.mjs'), '--port', String(port)], { stdio: 'ignore' });
  const out = path.join(root, 'bench-results/startup');
  try {
    writePageImages(path.join(out, 'pages'), 20);
    const bundlesDir = path.join(out, 'bundles');
    if (!process.argv.includes('--no-bundle')) await bundleLibraries(bundlesDir);
    const dirs = Object.fromEntries(libs.map((lib) => [lib, bundlesDir]));
    if (baselineDir) {
      const built = await bundleBaseline(path.resolve(baselineDir), bundlesDir);
      dirs[BASELINE] = built.bundles;
      console.log(`startup: ${BASELINE} is ${built.dir} at ${built.commit}`);
    }
    const rel = (p) => `/${path.relative(root, p)}`;
    for (const id of configIds) {
      const config = CONFIGS[id];
      const rows = Object.fromEntries(libs.map((lib) => [lib, []]));
      const measure = engine === 'chromium' ? measureOnce : await engineMeasure(config, rel(dirs[libs[0]]), rel(path.join(out, 'pages')));
      try {
        for (let rep = 0; rep < reps; rep++) {
          for (const lib of libs) rows[lib].push(await measure(lib, config, rel(dirs[lib]), rel(path.join(out, 'pages'))));
        }
      } finally {
        await measure.close?.();
      }
      for (const lib of libs) {
        // --rows: each run's figures as one JSON line, to pool runs of several invocations.
        if (process.argv.includes('--rows')) console.log(`rows ${lib} ${id} ${JSON.stringify(rows[lib])}`);
        report(lib, id, rows[lib]);
      }
    }
  } finally {
    server.kill();
  }
}

runMain('startup', main);
