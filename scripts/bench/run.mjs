// `npm run bench`: conecurl against page-flip, turn.js and the two floors (the smallest WebGL and 2D-canvas
// books) in one run, in headless Chromium on this machine, then conecurl against the WebGL floor in Firefox and WebKit. Generates the page images, bundles the libraries, measures every library x configuration
// x repetition in a fresh browser (order alternated), then writes JSON, Markdown and an SVG chart.
// With --baseline <dir> (another checkout of conecurl, e.g. a git worktree of an older commit with its dist/
// built), that tree's conecurl is measured too, in the same run, and the report shows before and after.
// Configurations: a double spread and a single page on a desktop screen with 20 and 1000 pages, and a phone
// (390x844 at ratio 3, single page, 20 pages) judged by targets of its own.
// Usage: node scripts/bench/run.mjs [--reps 3] [--configs double-20,single-1000,phone-20] [--libs conecurl,floor-webgl]
//        [--duration 600] [--turns 10] [--port 8095] [--out bench-results] [--baseline ../conecurl-before] [--publish]
//        [--skip-publish-rate] (leaves out publish-rate.mjs, the pages per second of `conecurl publish`, run last)
//        [--skip-first-spread] (leaves out first-spread.mjs: a published PDF's first spread on a throttled phone against pdf.js's)
//        [--skip-lighthouse] (leaves out lighthouse.mjs: Lighthouse's mobile preset on the published sites and reader.html#file=)
//        [--engines firefox,webkit|none] (the other engines measured after Chromium, in the run's first desktop configuration)
import { spawn, spawnSync } from 'node:child_process';
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import { chromium } from '@playwright/test';
import { BASELINE, bundleBaseline, bundleLibraries, checkoutCommit, LIBRARIES } from './bundle.mjs';
import { firstFrame, measureInEngine, measureOnce } from './measure.mjs';
import { ENGINES, engineExecutables, launchEngine, startDisplay } from '../engines.mjs';
import { chromiumLaunchOptions } from '../chromium.mjs';
import { firstTurnAgainstLater, summarize } from './metrics.mjs';
import { writePageImages } from './page-images.mjs';
import { ENGINE_LIBS, frameChart, screenOf, markdown, readmeTables, summarizeEngines, summarizeRuns } from './report.mjs';
import { PHONES, phoneUse } from '../../tests/browser/phone.js';

const root = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../..');
// `screen` says which targets judge a configuration (FLOOR_TARGETS in report.mjs); `use` is the Playwright
// context each is measured in. The phone is the phone-portrait screen of the phone tests (tests/browser/phone.js).
const desktop = (width, height) => ({ viewport: { width, height }, deviceScaleFactor: 1 });
const PHONE = PHONES['phone-portrait'];
const CONFIGS = [
  { id: 'double-20', screen: 'desktop', display: 'double', pages: 20, use: desktop(1600, 1100), label: 'Two-page spread, 1600x1100, 20 pages' },
  { id: 'double-1000', screen: 'desktop', display: 'double', pages: 1000, use: desktop(1600, 1100), label: 'Two-page spread, 1600x1100, 1000 pages' },
  { id: 'single-20', screen: 'desktop', display: 'single', pages: 20, use: desktop(800, 1100), label: 'Single page, 800x1100, 20 pages' },
  { id: 'single-1000', screen: 'desktop', display: 'single', pages: 1000, use: desktop(800, 1100), label: 'Single page, 800x1100, 1000 pages' },
  { id: 'phone-20', screen: 'phone', display: 'single', pages: 20, use: phoneUse(PHONE),
    label: `Phone, single page, ${PHONE.width}x${PHONE.height} at ratio ${phoneUse(PHONE).deviceScaleFactor} (mobile viewport, touch), 20 pages` },
];

function parseArgs(argv) {
  const options = {
    reps: 3, configs: CONFIGS.map((c) => c.id), libs: [...LIBRARIES], duration: 600, turns: 10, idleMs: 2000,
    port: Number(process.env.CONECURL_BENCH_PORT) || 8095, out: 'bench-results', publish: false, baseline: null, publishRate: true, firstSpread: true,
    lighthouse: true,
    engines: [...ENGINES],
  };
  for (let i = 0; i < argv.length; i++) {
    const name = argv[i];
    const value = () => {
      if (i + 1 >= argv.length) throw new Error(`bench: ${name} needs a value`);
      return argv[++i];
    };
    const count = (v, min) => {
      const n = Number(v);
      if (!Number.isInteger(n) || n < min) throw new Error(`bench: ${name} must be a whole number from ${min}, got ${v}`);
      return n;
    };
    if (name === '--reps') options.reps = count(value(), 1);
    else if (name === '--turns') options.turns = count(value(), 1);
    else if (name === '--duration') options.duration = count(value(), 100);
    else if (name === '--port') options.port = count(value(), 1);
    else if (name === '--out') options.out = value();
    else if (name === '--publish') options.publish = true;
    else if (name === '--skip-publish-rate') options.publishRate = false;
    else if (name === '--skip-first-spread') options.firstSpread = false;
    else if (name === '--skip-lighthouse') options.lighthouse = false;
    else if (name === '--baseline') options.baseline = path.resolve(value());
    else if (name === '--engines') {
      const list = value().split(',').filter((v) => v !== 'none');
      const unknown = list.filter((v) => !ENGINES.includes(v));
      if (unknown.length) throw new Error(`bench: unknown engines ${unknown.join(', ')} (known: ${ENGINES.join(', ')}, or none)`);
      options.engines = list;
    }
    else if (name === '--configs' || name === '--libs') {
      const list = value().split(',');
      const known = name === '--configs' ? CONFIGS.map((c) => c.id) : LIBRARIES;
      const unknown = list.filter((v) => !known.includes(v));
      if (unknown.length) throw new Error(`bench: unknown ${name.slice(2)} ${unknown.join(', ')} (known: ${known.join(', ')})`);
      options[name.slice(2)] = list;
    } else throw new Error(`bench: unknown argument ${name}`);
  }
  const full = options.reps >= 3 && options.configs.length === CONFIGS.length && options.libs.length === LIBRARIES.length
    && options.engines.length === ENGINES.length;
  if (options.publish && !full) throw new Error('bench: --publish needs the full run (all configurations, libraries and engines, 3+ repetitions)');
  return options;
}

async function startServer(port) {
  const server = spawn(process.execPath, [path.join(root, 'scripts/serve.mjs'), '--port', String(port)], { stdio: ['ignore', 'ignore', 'pipe'] });
  let stderr = '';
  server.stderr.on('data', (d) => { stderr += d; });
  const up = () => new Promise((resolve) => {
    http.get(`http://127.0.0.1:${port}/scripts/bench/harness.html`, (res) => { res.resume(); resolve(res.statusCode === 200); })
      .on('error', () => resolve(false));
  });
  for (let i = 0; i < 50; i++) {
    if (server.exitCode !== null) throw new Error(`bench: the server on port ${port} exited (${stderr.trim() || 'port in use?'})`);
    if (await up()) return server;
    await new Promise((resolve) => setTimeout(resolve, 100));
  }
  server.kill();
  throw new Error(`bench: the server on port ${port} did not answer`);
}

async function chromiumVersion() {
  const browser = await chromium.launch(chromiumLaunchOptions());
  const version = browser.version();
  await browser.close();
  return `Chromium ${version}`;
}

// docs/benchmark.md's "Latest published run" holds the latest short table between these markers.
const BENCH_DOC = 'docs/benchmark.md';
const LATEST_START = '<!-- bench:latest:start -->';
const LATEST_END = '<!-- bench:latest:end -->';

function publishToBenchDoc(tables) {
  const file = path.join(root, BENCH_DOC);
  const text = fs.readFileSync(file, 'utf8');
  const start = text.indexOf(LATEST_START);
  const end = text.indexOf(LATEST_END);
  if (start < 0 || end < start) throw new Error(`bench: ${BENCH_DOC} has no ${LATEST_START} ... ${LATEST_END} block to update`);
  // The tables link from the repository's root (docs/bench/latest.md); the page is in docs/ itself.
  const linked = tables.replaceAll('](docs/', '](');
  fs.writeFileSync(file, `${text.slice(0, start + LATEST_START.length)}\n${linked}\n${text.slice(end)}`);
}

// The wasm a contender fetched (from the page's resource timing) must be the one in its own bundle folder:
// conecurl and the baseline both ship a conecurl-engine.wasm. Returns an error message, or null.
function wrongWasm(result, lib, bundlesDir, base) {
  const fetched = result.wasm || [];
  const expected = fs.readdirSync(bundlesDir).filter((file) => file.endsWith('.wasm'));
  if (expected.length !== 1) return `${lib}: ${bundlesDir} holds ${expected.length} wasm files, not one`;
  const url = `${base}/${path.relative(root, path.join(bundlesDir, expected[0])).split(path.sep).join('/')}`;
  const size = fs.statSync(path.join(bundlesDir, expected[0])).size;
  if (fetched.length !== 1 || fetched[0].url !== url || fetched[0].bytes !== size) {
    return `${lib} fetched ${JSON.stringify(fetched)}, expected its own ${url} of ${size} bytes`;
  }
  return null;
}

const firstLine = (error) => String(error && error.message ? error.message : error).split('\n')[0];

/**
 * The other engines' rows: conecurl and the WebGL floor (ENGINE_LIBS) in Firefox and WebKit through
 * scripts/engines.mjs, in `config` (the run's first desktop configuration), at the harness URL Chromium
 * was measured at. One Xvfb display, one browser per engine (launched after the previous one closed) kept
 * for all its measurements, each repetition's order alternated as Chromium's; first one visit that is not
 * measured, so that no measured page pays the browser's first page and WebGL context; a start that fails is tried once more. Returns { config,
 * info: { engine: { version } | { missing } | { failed } }, runs }: an engine that is not installed, or
 * does not start, says so instead of stopping the run.
 */
async function measureEngines({ engines, config, reps, turns, duration, harnessUrl, check }) {
  const info = {};
  const runs = [];
  if (!config) {
    for (const engine of engines) info[engine] = { missing: 'the run has no desktop configuration to measure it in' };
    return { config: null, info, runs };
  }
  const { width, height } = config.use.viewport;
  let display = null;
  try {
    for (const engine of engines) {
      let exe;
      try {
        exe = engineExecutables(engine);
      } catch (error) {
        info[engine] = { missing: firstLine(error) };
        console.log(`bench: ${engine} not measured: ${info[engine].missing}`);
        continue;
      }
      let browser = null;
      // A second try where the first start fails: on a shared machine a driver may lose a race with another's.
      for (let attempt = 1; attempt <= 2 && !browser; attempt++) {
        try {
          display ??= await startDisplay(exe.xvfb);
          browser = await launchEngine(engine, { display: display.display, width, height });
          info[engine] = { version: browser.version };
          await browser.goto(harnessUrl(ENGINE_LIBS[0], config));
          await firstFrame(browser.evaluate);
        } catch (error) {
          info[engine] = { failed: firstLine(error) };
          console.log(`bench: ${engine} did not start (try ${attempt} of 2): ${info[engine].failed}`);
          await browser?.close().catch(() => {});
          browser = null;
        }
      }
      if (!browser) continue;
      try {
        for (let rep = 1; rep <= reps; rep++) {
          for (const lib of rep % 2 ? ENGINE_LIBS : [...ENGINE_LIBS].reverse()) {
            const run = { engine, rep, config: config.id, lib, loadavg: os.loadavg()[0] };
            const t0 = Date.now();
            try {
              run.result = await measureInEngine(browser, { url: harnessUrl(lib, config), turns, askedTurnMs: duration, turnTimeoutMs: 30000 });
              const wrong = check(run.result, lib);
              if (wrong) throw new Error(wrong);
              const f = summarize(run.result.intervals);
        const turnsApart = firstTurnAgainstLater(run.result);
              console.log(`[${engine} ${rep}/${reps}] ${config.id} ${lib}: first frame ${run.result.firstFrameMs.toFixed(0)} ms, `
                + `${run.result.frames} frames, median ${f.median.toFixed(1)} ms, p95 ${f.p95.toFixed(1)} ms, WebGL ${run.result.renderer} `
                + `(${((Date.now() - t0) / 1000).toFixed(0)} s)`);
            } catch (error) {
              delete run.result;
              run.error = firstLine(error);
              console.log(`[${engine} ${rep}/${reps}] ${config.id} ${lib}: FAILED ${run.error}`);
            }
            runs.push(run);
          }
        }
      } finally {
        await browser.close().catch(() => {});
      }
    }
  } finally {
    display?.stop();
  }
  return { config: config.id, info, runs };
}

async function main() {
  const options = parseArgs(process.argv.slice(2));
  const out = path.resolve(root, options.out);
  if (!out.startsWith(root + path.sep)) throw new Error(`bench: --out must be inside the repository (it is served to the pages), got ${out}`);
  const wasm = path.join(root, 'dist/conecurl-engine.wasm');
  if (!fs.existsSync(wasm)) throw new Error('bench: dist/conecurl-engine.wasm is missing; run `npm run build` (npm run bench does)');
  const started = Date.now();
  const loadavgStart = os.loadavg();
  const configs = CONFIGS.filter((c) => options.configs.includes(c.id));
  const maxPages = Math.max(...configs.map((c) => c.pages));

  const images = writePageImages(path.join(out, 'pages'), maxPages);
  console.log(`bench: ${maxPages} page images ready (${images.written} written)`);
  const loadBytes = await bundleLibraries(path.join(out, 'bundles'));
  const bundleDirs = Object.fromEntries(LIBRARIES.map((lib) => [lib, path.join(out, 'bundles')]));
  const contenders = [...options.libs];
  let baseline = null;
  if (options.baseline) {
    const built = await bundleBaseline(options.baseline, path.join(out, 'bundles'));
    baseline = { dir: built.dir, commit: built.commit, label: `conecurl (before, ${built.commit})` };
    loadBytes[BASELINE] = built.loadBytes;
    bundleDirs[BASELINE] = built.bundles;
    contenders.push(BASELINE);
    console.log(`bench: baseline ${built.dir} at ${built.commit} bundled into ${path.relative(root, built.bundles)}/`);
  }
  console.log('bench: libraries bundled');
  const server = await startServer(options.port);
  const chromiumName = await chromiumVersion();
  const base = `http://127.0.0.1:${options.port}`;
  const relative = (dir) => `/${path.relative(root, dir).split(path.sep).join('/')}`;

  const harnessUrl = (lib, config) => `${base}/scripts/bench/harness.html?${new URLSearchParams({
    lib, pages: String(config.pages), display: config.display, duration: String(options.duration),
    bundles: relative(bundleDirs[lib]), images: relative(path.join(out, 'pages')),
  })}`;

  const plan = [];
  for (let rep = 0; rep < options.reps; rep++) {
    configs.forEach((config, c) => {
      const order = (rep + c) % 2 === 0 ? contenders : [...contenders].reverse();
      order.forEach((lib) => plan.push({ rep: rep + 1, config, lib }));
    });
  }
  console.log(`bench: ${plan.length} measurements (${options.reps} repetitions x ${configs.length} configurations x ${contenders.length} libraries)`);

  const runs = [];
  let engines = { config: null, info: {}, runs: [] };
  try {
    for (const [index, { rep, config, lib }] of plan.entries()) {
      const url = harnessUrl(lib, config);
      const t0 = Date.now();
      const run = { rep, config: config.id, lib, loadavg: os.loadavg()[0] };
      try {
        const result = await measureOnce({
          url, use: config.use, turns: options.turns, askedTurnMs: options.duration, turnTimeoutMs: 30000, idleMs: options.idleMs,
        });
        const wrong = (lib === 'conecurl' || lib === BASELINE) ? wrongWasm(result, lib, bundleDirs[lib], base) : null;
        if (wrong) throw new Error(wrong);
        run.result = result;
        const f = summarize(run.result.intervals);
        const turnsApart = firstTurnAgainstLater(run.result);
        console.log(`[${index + 1}/${plan.length}] rep ${rep} ${config.id} ${lib}: first frame ${run.result.firstFrameMs.toFixed(0)} ms, `
          + `frame median ${f.median.toFixed(0)} ms, max ${f.max.toFixed(0)} ms, main ${run.result.perFrame.mainThreadMs.toFixed(1)} ms/frame, `
          + `GPU ${run.result.perFrame.gpuCpuMs.toFixed(0)} ms/frame, idle ${run.result.idle.totalCpuPercent.toFixed(1)}%, `
          + `first turn max ${turnsApart.first.max.toFixed(0)} ms (median ${turnsApart.first.median.toFixed(0)}), later turns max ${turnsApart.later.max.toFixed(0)} ms (median ${turnsApart.later.median.toFixed(0)})`
          + `${run.result.wasm.length ? `, wasm ${run.result.wasm.map((w) => `${w.url.slice(base.length)} ${w.bytes} B`).join(', ')}` : ''}`
          + ` (${((Date.now() - t0) / 1000).toFixed(0)} s)`);
      } catch (error) {
        run.error = firstLine(error);
        console.log(`[${index + 1}/${plan.length}] rep ${rep} ${config.id} ${lib}: FAILED ${run.error}`);
      }
      runs.push(run);
    }
    engines = await measureEngines({
      engines: options.engines, config: configs.find((c) => screenOf(c) === 'desktop'), reps: options.reps, turns: options.turns,
      duration: options.duration, harnessUrl,
      check: (result, lib) => (lib === 'conecurl' ? wrongWasm(result, lib, bundleDirs[lib], base) : null),
    });
  } finally {
    server.kill();
  }

  const meta = {
    date: new Date().toISOString().replace(/\.\d+Z$/, 'Z'),
    chromium: chromiumName,
    node: process.version,
    cpus: os.cpus().length,
    cpuModel: os.cpus()[0]?.model,
    loadavgStart,
    loadavgEnd: os.loadavg(),
    reps: options.reps,
    turns: options.turns,
    turnDurationMs: options.duration,
    idleMs: options.idleMs,
    wallSeconds: (Date.now() - started) / 1000,
    ...(baseline ? { baseline, commit: checkoutCommit(root) } : {}),
  };
  const { summary, ratios, targets, floorTargets, beforeAfter } = summarizeRuns(runs, configs, loadBytes);
  const engineRows = summarizeEngines(runs, engines, configs, meta);
  const report = { meta, configs, loadBytes, floorTargets, targets, ...(beforeAfter ? { beforeAfter } : {}), summary, ratios, engineRows, runs, engineRuns: engines.runs };
  const md = markdown({ meta, loadBytes, summary, ratios, targets, floorTargets, beforeAfter, configs, engineRows });
  fs.mkdirSync(out, { recursive: true });
  fs.writeFileSync(path.join(out, 'latest.json'), `${JSON.stringify(report, null, 1)}\n`);
  fs.writeFileSync(path.join(out, 'latest.md'), md);
  fs.writeFileSync(path.join(out, 'frame-intervals.svg'), frameChart(runs, configs));
  if (options.publish) {
    const docs = path.join(root, 'docs/bench');
    fs.mkdirSync(docs, { recursive: true });
    for (const file of ['latest.json', 'latest.md', 'frame-intervals.svg']) fs.copyFileSync(path.join(out, file), path.join(docs, file));
    publishToBenchDoc(readmeTables({ meta, loadBytes, summary, targets, floorTargets, beforeAfter, configs, engineRows }));
  }
  console.log(`\n${md}`);
  console.log(`bench: wrote ${path.relative(root, out)}/latest.{json,md} and frame-intervals.svg${options.publish ? `, copied to docs/bench/ and ${BENCH_DOC}` : ''}`
    + ` in ${Math.round(meta.wallSeconds)} s`);
  if (options.publishRate) {
    // The publish command's rate, in a process of its own (it uses every core, so it runs after the books).
    const rate = spawnSync(process.execPath, [path.join(root, 'scripts/bench/publish-rate.mjs'), '--out', options.out], { stdio: 'inherit' });
    if (rate.status !== 0) process.exitCode = 1;
  }
  // The PDFs publish-rate.mjs measured (build/bench-pdf/), for the reader's measurements below.
  const pdfs = ['gnuplot.pdf', 'magazine-40.pdf'].map((name) => path.join(root, 'build/bench-pdf', name)).filter((file) => fs.existsSync(file));
  if ((options.firstSpread || options.lighthouse) && pdfs.length === 0) {
    console.log('bench: no PDF in build/bench-pdf/ for first-spread.mjs and lighthouse.mjs (publish-rate.mjs puts them there)');
  }
  let spreadSites = null;
  if (options.firstSpread && pdfs.length) {
    // The reader's first spread on a throttled phone: each PDF published and through pdf.js.
    const spread = spawnSync(process.execPath, [path.join(root, 'scripts/bench/first-spread.mjs'), '--out', options.out, '--republish',
      ...pdfs.flatMap((file) => ['--pdf', file])], { stdio: 'inherit' });
    if (spread.status !== 0) process.exitCode = 1;
    else spreadSites = path.join(options.out, 'first-spread');
  }
  if (options.lighthouse && pdfs.length) {
    // Lighthouse's mobile preset on the same sites (those first-spread.mjs just published, else published afresh) and on reader.html#file=.
    const audit = spawnSync(process.execPath, [path.join(root, 'scripts/bench/lighthouse.mjs'), '--out', options.out,
      ...(spreadSites ? ['--sites', spreadSites] : ['--republish']), ...pdfs.flatMap((file) => ['--pdf', file])], { stdio: 'inherit' });
    if (audit.status !== 0) process.exitCode = 1;
  }
  if ([...runs, ...engines.runs].some((r) => r.error)) {
    console.error('bench: some measurements failed (see above)');
    process.exitCode = 1;
  }
}

main().catch((error) => {
  console.error(error.message || error);
  process.exit(1);
});
