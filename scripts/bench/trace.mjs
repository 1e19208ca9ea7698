// Profiling aid for a missed target: records a Chrome trace of one library turning pages (bundles and
// page images from the last `npm run bench`) and prints where each process's threads spent their
// time, by slice name. Open the JSON in chrome://tracing or Perfetto for the timeline.
// Usage: node scripts/bench/trace.mjs [--lib conecurl] [--config double-20] [--turns 3] [--duration 600]
//        [--options '{"shadows":false}'] [--port 8096] [--startup] (trace navigation to first frame instead)
import fs from 'node:fs';
import path from 'node:path';
import { arg, runMain, usage as badArgument, withServedChromium } from './cli.mjs';

const root = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../..');
const usage = (message) => badArgument('trace', message);
const lib = arg('--lib', 'conecurl');
const config = arg('--config', 'double-20');
const turns = Number(arg('--turns', '3'));
const duration = Number(arg('--duration', '600'));
const extra = arg('--options', '{}');
const port = Number(arg('--port', process.env.CONECURL_BENCH_PORT || '8096'));
const startup = process.argv.includes('--startup');
const [display, pages] = config.split('-');
if (!['single', 'double'].includes(display) || !Number(pages)) usage(`--config must be like double-20 or single-20, got ${config}`);
if (!Number.isInteger(turns) || turns < 1) usage(`--turns takes a whole number of turns, 1 or more (got ${arg('--turns')})`);
try {
  JSON.parse(extra);
} catch {
  usage(`--options must be a JSON object, e.g. '{"shadows":false}' (got ${extra})`);
}
for (const needed of [`bench-results/bundles/${lib}.js`, `bench-results/pages/page-${String(Number(pages)).padStart(4, '0')}.png`]) {
  if (!fs.existsSync(path.join(root, needed))) usage(`${needed} is missing; run npm run bench once first`);
}

const CATEGORIES = ['devtools.timeline', 'disabled-by-default-devtools.timeline', 'toplevel', 'gpu', 'viz', 'cc', 'blink', 'v8'];

// Traces the page and prints each thread's time by slice name; a failure is one line (`--stack`: its trace), exit 1.
async function main() {
  const outFile = path.join(root, 'bench-results/traces', `${lib}-${config}${startup ? '-startup' : ''}.json`);
  await withServedChromium(port, async (browser) => {
    const viewport = display === 'double' ? { width: 1600, height: 1100 } : { width: 800, height: 1100 };
    const page = await browser.newPage({ viewport, deviceScaleFactor: 1 });
    const query = new URLSearchParams({ lib, pages, display, duration: String(duration), bundles: '/bench-results/bundles', images: '/bench-results/pages', options: extra });
    const ready = () => page.evaluate(async () => { while (!window.bench) await new Promise((r) => setTimeout(r, 5)); return window.bench.ready(); });
    fs.mkdirSync(path.dirname(outFile), { recursive: true });
    if (startup) {
      await page.goto('about:blank');
      await browser.startTracing(page, { path: outFile, categories: CATEGORIES });
      await page.goto(`http://127.0.0.1:${port}/scripts/bench/harness.html?${query}`);
      const { readyMs, firstFrameMs } = await ready();
      await browser.stopTracing();
      console.log(`${lib} ${config}: ready ${readyMs.toFixed(0)} ms, first frame ${firstFrameMs.toFixed(0)} ms after navigation start`);
    } else {
      await page.goto(`http://127.0.0.1:${port}/scripts/bench/harness.html?${query}`);
      await ready();
      await page.waitForTimeout(500);
      await browser.startTracing(page, { path: outFile, categories: CATEGORIES });
      const { stamps } = await page.evaluate(([n]) => window.bench.turns(n, 60000), [turns]);
      await page.waitForTimeout(300);
      await browser.stopTracing();
      const intervals = stamps.slice(1).map((t, i) => Math.round(t - stamps[i]));
      console.log(`${lib} ${config}: ${intervals.length} frames, intervals (ms): ${intervals.join(' ')}`);
    }
  });

  // Self time is not in the trace; summing complete events per thread by name gives inclusive time,
  // which is what "where did this thread spend its time" needs at this level.
  const { traceEvents } = JSON.parse(fs.readFileSync(outFile, 'utf8'));
  const names = new Map();
  for (const e of traceEvents) {
    if (e.ph === 'M' && e.name === 'process_name') names.set(`p${e.pid}`, e.args.name);
    if (e.ph === 'M' && e.name === 'thread_name') names.set(`t${e.pid}:${e.tid}`, e.args.name);
  }
  const totals = new Map();
  for (const e of traceEvents) {
    if (e.ph !== 'X' || !e.dur) continue;
    const thread = `${names.get(`p${e.pid}`) || e.pid} / ${names.get(`t${e.pid}:${e.tid}`) || e.tid}`;
    if (!totals.has(thread)) totals.set(thread, new Map());
    const byName = totals.get(thread);
    byName.set(e.name, (byName.get(e.name) || 0) + e.dur / 1000);
  }
  const busiest = [...totals].map(([thread, byName]) => [thread, byName, Math.max(...byName.values())]).sort((a, b) => b[2] - a[2]);
  for (const [thread, byName] of busiest.slice(0, 8)) {
    console.log(`\n${thread}`);
    for (const [name, ms] of [...byName].sort((a, b) => b[1] - a[1]).slice(0, 12)) console.log(`  ${ms.toFixed(0).padStart(7)} ms  ${name}`);
  }
  console.log(`\ntrace: ${path.relative(root, outFile)}`);
}

runMain('trace', main);
