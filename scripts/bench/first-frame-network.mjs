// "First page shown" as a phone on a mobile network sees it: the bench page of phone-20 in a fresh
// browser per run, with CDP's network emulation adding latency to every request and capping the
// download rate, so what a library fetches after what shows (the local server of `npm run bench`
// answers at once and cannot). Prints each contender's first frame per run and the median.
// Needs the bundles and pages of a previous `npm run bench` (with --baseline for conecurl-baseline).
// Usage: node scripts/bench/first-frame-network.mjs [--out bench-results] [--libs conecurl,conecurl-baseline,floor-webgl]
//        [--reps 5] [--latency 150] [--kbps 4000] [--port 8098]
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { chromium } from '@playwright/test';
import { chromiumLaunchOptions } from '../chromium.mjs';
import { arg } from './cli.mjs';
import { summarize } from './metrics.mjs';
import { throttledPhonePage } from './throttled-phone.mjs';

const root = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../..');
const out = arg('--out', 'bench-results');
const libs = arg('--libs', 'conecurl,conecurl-baseline,floor-webgl').split(',');
const reps = Number(arg('--reps', '5'));
const latency = Number(arg('--latency', '150'));
const kbps = Number(arg('--kbps', '4000'));
const port = Number(arg('--port', process.env.CONECURL_BENCH_PORT || '8098'));
const bundlesOf = (lib) => (lib === 'conecurl-baseline' ? `${out}/bundles/baseline` : `${out}/bundles`);
for (const lib of libs) {
  if (!fs.existsSync(path.join(root, bundlesOf(lib), `${lib}.js`))) {
    console.error(`first-frame-network: ${bundlesOf(lib)}/${lib}.js is missing; run npm run bench -- --out ${out} (with --baseline for conecurl-baseline) first`);
    process.exit(1);
  }
}

const server = spawn(process.execPath, [path.join(root, 'scripts/serve.mjs'), '--port', String(port)], { stdio: 'ignore' });
await new Promise((resolve) => setTimeout(resolve, 500));
const firstFrames = Object.fromEntries(libs.map((lib) => [lib, []]));
try {
  for (let rep = 0; rep < reps; rep++) {
    for (const lib of rep % 2 ? [...libs].reverse() : libs) {  // order alternated, as the bench does
      const browser = await chromium.launch(chromiumLaunchOptions());
      try {
        const { page } = await throttledPhonePage(browser, { latency, kbps });
        const query = new URLSearchParams({ lib, pages: '20', display: 'single', duration: '600', bundles: `/${bundlesOf(lib)}`, images: `/${out}/pages` });
        await page.goto(`http://127.0.0.1:${port}/scripts/bench/harness.html?${query}`);
        const { firstFrameMs } = await page.evaluate(async () => {
          while (!window.bench) await new Promise((resolve) => setTimeout(resolve, 5));
          return window.bench.ready();
        });
        firstFrames[lib].push(Math.round(firstFrameMs));
        console.log(`[${rep + 1}/${reps}] ${lib}: first frame ${Math.round(firstFrameMs)} ms`);
      } finally {
        await browser.close();
      }
    }
  }
} finally {
  server.kill();
}
console.log(`phone-20 with ${latency} ms latency a request and ${kbps} kbit/s, ${reps} runs each:`);
for (const lib of libs) console.log(`  ${lib}: first frame median ${Math.round(summarize(firstFrames[lib]).median)} ms (${firstFrames[lib].join(', ')})`);
