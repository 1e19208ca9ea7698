// Profiling aid for the GPU-process target: where conecurl's GPU-process CPU goes. In one browser it
// draws the same turning pose frame after frame under variants that switch one cost off at a time
// (shadow pass, lighting, grid size, canvas size), round-robin so a shared machine's load hits all
// alike, and prints GPU-process CPU and frame interval per frame for each. Needs the bundles and
// pages of a previous `npm run bench`.
// Usage: node scripts/bench/profile-gpu.mjs [--config double-20|single-20|phone-20] [--frames 12] [--rounds 3] [--port 8096]
//        [--variants 0,6] (indices into VARIANTS) [--bundles bench-results/bundles] (another build of conecurl; its pages beside it)
import fs from 'node:fs';
import path from 'node:path';
import { arg, runMain, usage as badArgument, withServedChromium } from './cli.mjs';
import { cpuDelta, processCpu, summarize } from './metrics.mjs';
import { PHONES, phoneUse } from '../../tests/browser/phone.js';

const root = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../..');
const usage = (message) => badArgument('profile-gpu', message);
const config = arg('--config', 'double-20');
const framesPerSample = Number(arg('--frames', '12'));
const rounds = Number(arg('--rounds', '3'));
const port = Number(arg('--port', process.env.CONECURL_BENCH_PORT || '8096'));
const bundles = arg('--bundles', 'bench-results/bundles');
const CONFIGS = {  // as scripts/bench/run.mjs measures them
  'double-20': { display: 'double', use: { viewport: { width: 1600, height: 1100 }, deviceScaleFactor: 1 } },
  'single-20': { display: 'single', use: { viewport: { width: 800, height: 1100 }, deviceScaleFactor: 1 } },
  'phone-20': { display: 'single', use: phoneUse(PHONES['phone-portrait']) },
};
if (!CONFIGS[config]) usage(`unknown config ${config} (${Object.keys(CONFIGS).join(', ')})`);
if (!Number.isInteger(framesPerSample) || framesPerSample < 2) usage(`--frames takes a whole number of frames, 2 or more (got ${arg('--frames')})`);
if (!Number.isInteger(rounds) || rounds < 1) usage(`--rounds takes a whole number, 1 or more (got ${arg('--rounds')})`);
const { display, use } = CONFIGS[config];
const pages = '20';

// Each variant: [name, setup, teardown], evaluated in the page with `view` (BookView) in scope.
const VARIANTS = [
  ['turning pose, defaults', '', ''],
  ['shadows off', 'view.setOptions({ shadows: false })', 'view.setOptions({ shadows: true })'],
  ['lighting and gutter off', 'view.setOptions({ lighting: false, gutter: false })', 'view.setOptions({ lighting: true, gutter: true })'],
  ['all effects off', 'view.setOptions({ shadows: false, lighting: false, gutter: false })', 'view.setOptions({ shadows: true, lighting: true, gutter: true })'],
  ['grid 12 rows (coarse mesh)', 'view.renderer.setGridRows(12)', 'view.renderer.setGridRows(0)'],
  ['canvas at half size (1/4 pixels)', "document.getElementById('book').style.cssText = 'width:50%;height:50%'",
    "document.getElementById('book').style.cssText = ''"],
  ['moving frames at scale 1/2 (1/4 pixels)', 'view.renderer.setOptions({ movingScale: 0.5 })', 'view.renderer.setOptions({ movingScale: 1 })'],
  ['resting spread, redrawn', 'window.__rest = true', 'window.__rest = false'],
  ['no drawing (rAF only)', 'window.__skip = true', 'window.__skip = false'],
];

const chosen = arg('--variants', null);
const variants = chosen ? chosen.split(',').map((i) => {
  if (!VARIANTS[Number(i)]) usage(`no variant ${i} (0..${VARIANTS.length - 1})`);
  return VARIANTS[Number(i)];
}) : VARIANTS;
if (!fs.existsSync(path.join(root, bundles, 'conecurl.js'))) usage(`${bundles}/conecurl.js is missing; run npm run bench once first`);

// Draws the pose under each variant and prints the medians; a failure is one line (`--stack`: its trace), exit 1.
async function main() {
  await withServedChromium(port, async (browser) => {
    const page = await (await browser.newContext(use)).newPage();
    const cdp = await browser.newBrowserCDPSession();
    const query = new URLSearchParams({ lib: 'conecurl', pages, display, duration: '600', bundles: `/${bundles}`, images: `/${path.dirname(bundles)}/pages` });
    await page.goto(`http://127.0.0.1:${port}/scripts/bench/harness.html?${query}`);
    await page.evaluate(async () => { while (!window.bench) await new Promise((r) => setTimeout(r, 5)); await window.bench.ready(); });
    await page.evaluate(async () => { const book = await window.bench.mounted(); await book.turn(); await book.turn(); });
    const samples = new Map(variants.map(([name]) => [name, { gpu: [], interval: [], draw: [] }]));
    for (let round = 0; round < rounds; round++) {
      for (const [name, setup, teardown] of variants) {
        await page.evaluate(async (code) => { const view = (await window.bench.mounted()).view(); new Function('view', code)(view); }, setup);
        await page.waitForTimeout(300);
        const before = await processCpu(cdp);
        const { stamps, draws } = await page.evaluate(async (count) => {
          const view = (await window.bench.mounted()).view();
          const stampsIn = [];
          const drawsIn = [];
          for (let i = 0; i < count; i++) {
            await new Promise((resolve) => requestAnimationFrame(resolve));
            const t0 = performance.now();
            if (window.__rest) view.drawNow();
            else if (!window.__skip) view.showTurn('forward', 0.1 + (0.8 * (i % 8)) / 8);
            drawsIn.push(performance.now() - t0);
            stampsIn.push(performance.now());
          }
          view.jumpTo(view.position);  // back to rest, no pose left behind
          return { stamps: stampsIn, draws: drawsIn };
        }, framesPerSample);
        const after = await processCpu(cdp);
        const gpu = cpuDelta(before, after).filter((p) => p.type === 'GPU').reduce((sum, p) => sum + p.cpu, 0);
        const sample = samples.get(name);
        sample.gpu.push((1000 * gpu) / framesPerSample);
        sample.interval.push(summarize(stamps.slice(1).map((t, i) => t - stamps[i])).median);
        sample.draw.push(summarize(draws).median);
        await page.evaluate(async (code) => { const view = (await window.bench.mounted()).view(); new Function('view', code)(view); }, teardown);
      }
    }
    const canvas = await page.evaluate(async () => {
      const view = (await window.bench.mounted()).view();
      return `${view.canvas.width}x${view.canvas.height}, grid ${view.renderer.gridRows()}x${view.renderer.gridColumns()}`;
    });
    console.log(`conecurl ${config} (canvas ${canvas}), ${framesPerSample} frames x ${rounds} rounds per variant; medians over rounds`);
    console.log(`${'variant'.padEnd(36)} ${'GPU ms/frame'.padStart(13)} ${'interval ms'.padStart(12)} ${'draw call ms'.padStart(13)}`);
    for (const [name, s] of samples) {
      console.log(`${name.padEnd(36)} ${summarize(s.gpu).median.toFixed(1).padStart(13)} ${summarize(s.interval).median.toFixed(1).padStart(12)} `
        + `${summarize(s.draw).median.toFixed(2).padStart(13)}`);
    }
  });
}

runMain('profile-gpu', main);
