// The reader's first spread on a phone, both roads in one run: a PDF published with `conecurl publish`
// (its index.html) against the same PDF opened at run time through pdf.js (the package's
// reader.html#file=). A phone profile (390x844 at ratio 3, touch), CDP network throttling (1.6 Mbit/s
// down, 150 ms round trip) and a 4x CPU slowdown; a fresh browser a run, roads alternated. The server
// compresses text (HTML, JS, JSON, CSS, wasm) as a CDN would and answers range requests (pdf.js asks
// for the PDF in ranges). Reports, per road, the time to the first spread drawn and the bytes loaded
// before it (encoded, as they came over the wire), the requests and the JavaScript before it, and checks them
// against the targets. The first spread is the first page image drawn: a page's placeholder where it has one (the
// published road inlines the cover's: a blurred cover is what the reader sees first, drawn over the whole
// page), else its reading image; the time to the reading image ("sharp") is reported beside it.
// Usage: node scripts/bench/first-spread.mjs --pdf book.pdf [--pdf magazine.pdf] [--reps 3] [--out bench-results]
//        [--kbps 1600] [--latency 150] [--cpu 4] [--republish] [--timeline (each request of the first run)]
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import zlib from 'node:zlib';
import { chromium } from '@playwright/test';
import { chromiumLaunchOptions } from '../chromium.mjs';
import { arg } from './cli.mjs';
import { FIRST_SPREAD_TARGETS } from './first-spread-targets.mjs';
import { summarize } from './metrics.mjs';
import { throttledPhonePage } from './throttled-phone.mjs';

const root = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../..');
const args = process.argv.slice(2);
const pdfs = args.flatMap((a, i) => (a === '--pdf' ? [path.resolve(args[i + 1])] : []));
const reps = Number(arg('--reps', '3'));
const out = path.resolve(root, arg('--out', 'bench-results'));
const kbps = Number(arg('--kbps', '1600'));
const latency = Number(arg('--latency', '150'));
const cpu = Number(arg('--cpu', '4'));
if (pdfs.length === 0) {
  console.error('first-spread: give the PDF to measure: --pdf book.pdf (more than one --pdf measures each)');
  process.exit(2);
}

const COMPRESSED = /\.(html|js|mjs|json|css|wasm|svg)$/;
const TYPES = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.mjs': 'text/javascript', '.json': 'application/json',
  '.css': 'text/css', '.wasm': 'application/wasm', '.svg': 'image/svg+xml', '.webp': 'image/webp', '.avif': 'image/avif',
  '.jpg': 'image/jpeg', '.png': 'image/png', '.pdf': 'application/pdf',
};
const gzipped = new Map();  // file -> its gzip, made once
// Every response the server sent: { url, at (epoch ms it was asked for), bytes (the body as sent) }. A dedicated
// worker's requests (pdf.js's worker script, and the PDF it fetches) are throttled with the page but not
// seen by the page's CDP session: they are counted from here.
const served = [];

/** The repository at /, each published site at /sites/<name>/, each PDF at /pdf/<name>.pdf. */
function serve(routes) {
  const server = http.createServer((req, res) => {
    const url = new URL(req.url, 'http://x');
    const pathname = decodeURIComponent(url.pathname);
    const route = routes.find(([prefix]) => pathname.startsWith(prefix));
    const entry = { url: `${url.pathname}${url.search}`, at: Date.now(), bytes: 0 };
    served.push(entry);
    const write = res.write.bind(res);
    const end = res.end.bind(res);
    res.write = (chunk, ...rest) => { entry.bytes += chunk?.length ?? 0; return write(chunk, ...rest); };
    res.end = (chunk, ...rest) => { if (chunk && typeof chunk !== 'function') entry.bytes += chunk.length; return end(chunk, ...rest); };
    let file = path.normalize(path.join(route[1], pathname.slice(route[0].length)));
    if (!file.startsWith(route[1])) return res.writeHead(403).end();
    if (fs.existsSync(file) && fs.statSync(file).isDirectory()) file = path.join(file, 'index.html');
    if (!fs.existsSync(file)) return res.writeHead(404).end();
    const type = TYPES[path.extname(file)] ?? 'application/octet-stream';
    const size = fs.statSync(file).size;
    const range = /^bytes=(\d+)-(\d*)$/.exec(req.headers.range ?? '');
    if (range) {
      const start = Number(range[1]);
      const end = range[2] ? Math.min(Number(range[2]), size - 1) : size - 1;
      res.writeHead(206, { 'Content-Type': type, 'Content-Range': `bytes ${start}-${end}/${size}`, 'Content-Length': end - start + 1, 'Accept-Ranges': 'bytes' });
      return fs.createReadStream(file, { start, end }).pipe(res);
    }
    if (COMPRESSED.test(file) && /\bgzip\b/.test(req.headers['accept-encoding'] ?? '')) {
      if (!gzipped.has(file)) gzipped.set(file, zlib.gzipSync(fs.readFileSync(file), { level: 9 }));
      const body = gzipped.get(file);
      return res.writeHead(200, { 'Content-Type': type, 'Content-Encoding': 'gzip', 'Content-Length': body.length }).end(body);
    }
    res.writeHead(200, { 'Content-Type': type, 'Content-Length': size, 'Accept-Ranges': 'bytes' });
    fs.createReadStream(file).pipe(res);
  });
  return new Promise((resolve) => server.listen(0, '127.0.0.1', () => resolve(server)));
}

/** One run of one road: ms to the first spread drawn and to its reading image ("sharp"), the bytes received and
 * requests sent before each (`timeline`: print each request). */
async function measure(url, { timeline = false } = {}) {
  served.length = 0;
  const browser = await chromium.launch(chromiumLaunchOptions());
  try {
    const { page, cdp } = await throttledPhonePage(browser, { latency, kbps, upKbps: kbps / 2, cpu });
    const received = [];  // [monotonic s, encoded bytes]
    let start = null;      // the document's request, in CDP's monotonic seconds...
    let startWall = null;  // ...and in epoch seconds: the page's clock (timeOrigin) is mapped through it
    const urls = [];
    const requests = new Map();  // id -> { url, sent, done, bytes } in monotonic s
    cdp.on('Network.requestWillBeSent', (e) => {
      if (start === null && e.type === 'Document') [start, startWall] = [e.timestamp, e.wallTime];
      urls.push(e.request.url);
      requests.set(e.requestId, { url: e.request.url, sent: e.timestamp, done: null, bytes: 0 });
    });
    cdp.on('Network.responseReceived', (e) => received.push([e.timestamp, e.response.encodedDataLength ?? 0]));  // headers
    cdp.on('Network.dataReceived', (e) => {
      received.push([e.timestamp, e.encodedDataLength]);
      const request = requests.get(e.requestId);
      if (request) request.bytes += e.encodedDataLength;
    });
    cdp.on('Network.loadingFinished', (e) => { const request = requests.get(e.requestId); if (request) request.done = e.timestamp; });
    await page.addInitScript(() => {
      const upload = WebGL2RenderingContext.prototype.texImage2D;
      // Two frames after an upload: the frame that draws it is on screen.
      const shown = (name) => requestAnimationFrame(() => requestAnimationFrame(() => { window[name] = performance.now(); }));
      WebGL2RenderingContext.prototype.texImage2D = function pageUpload(...args) {
        const source = args.length === 6 ? args[5] : null;
        (window.__uploads ??= []).push([Math.round(performance.now()), source?.width ?? args[3]]);
        // A page image: its placeholder (the published cover's is 128 px wide) or its reading image (256 px
        // and more); not the 1-pixel textures the renderer makes for itself.
        if (!window.__uploaded && source && source.width >= 64) {
          window.__uploaded = true;
          shown('__firstSpread');
        }
        if (!window.__uploadedSharp && source && source.width >= 256) {
          window.__uploadedSharp = true;
          shown('__sharpSpread');
        }
        return upload.apply(this, args);
      };
    });
    await page.goto(url, { waitUntil: 'commit' });
    // The first spread on screen: two frames after the open page's image went to the GPU (the engine hands a
    // page to WebGL whole, texImage2D of an image; on the phone one page is open). Both roads draw with it.
    // Left to load as a reader's browser loads it (nothing imported from here, which would race its preloads).
    await page.waitForFunction(() => window.__sharpSpread !== undefined || document.querySelector('.conecurl-reader-problem'),
      null, { timeout: 180_000, polling: 100 });
    const { ms, sharpMs, origin, uploads, problem } = await page.evaluate(() => ({
      ms: window.__firstSpread, sharpMs: window.__sharpSpread, origin: performance.timeOrigin, uploads: window.__uploads ?? [],
      problem: document.querySelector('.conecurl-reader-problem')?.textContent ?? null,
    }));
    if (problem) throw new Error(`first-spread: the reader said: ${problem}`);
    const cdpTime = (at) => start + ((origin + at) / 1000 - startWall);  // a time of the page's clock in CDP's
    const until = cdpTime(ms);  // the first spread
    const bytesUntil = (t) => received.filter(([at]) => at <= t).reduce((sum, [, n]) => sum + n, 0);
    const seen = bytesUntil(until);
    // pdf.js's worker (its script, and the PDF it fetches) is a dedicated worker: its data never reaches the
    // page's session. Its requests made before the first spread are counted whole, as the server sent them.
    // (Any other request's bytes are the session's, received before the first spread: in flight, in part.)
    const pathOf = (u) => { const parsed = new URL(u); return `${parsed.pathname}${parsed.search}`; };
    const counted = new Set([...requests.values()].filter((r) => r.bytes > 0).map((r) => pathOf(r.url)));
    const fromWorker = (url) => /pdf\.worker|^\/pdf\//.test(url);
    const unseen = served.filter((entry) => fromWorker(entry.url) && !counted.has(entry.url) && entry.at <= origin + ms);
    const workerBytes = unseen.reduce((sum, entry) => sum + entry.bytes, 0);
    if (timeline) {
      const rows = [...requests.values()].sort((a, b) => a.sent - b.sent);
      for (const r of rows.filter((row) => row.bytes > 0 || row.done !== null || row.sent <= until)) {
        const shift = (startWall * 1000 - origin) / 1000;  // CDP's times on the page's clock (from its navigation start)
        const at = (t) => (t === null ? '   -  ' : `${Math.round((t - start + shift) * 1000)}`.padStart(6));
        console.log(`  ${at(r.sent)} ${at(r.done)} ms ${`${(r.bytes / 1024).toFixed(1)}`.padStart(7)} KB  ${r.url.startsWith('data:') ? r.url.slice(0, 40) : new URL(r.url).pathname}`);
      }
      for (const entry of unseen) console.log(`  (worker) ${`${(entry.bytes / 1024).toFixed(1)}`.padStart(7)} KB  ${entry.url}`);
      console.log(`  textures (ms, width): ${uploads.map(([t, w]) => `${t}:${w}`).join(' ')}`);
      console.log(`  first spread at ${Math.round(ms)} ms, its reading image at ${Math.round(sharpMs)} ms`);
    }
    // The requests asked for before the first spread's page went to WebGL (the worker's included: the spread is
    // drawn from it, and the neighbours are asked for once it is), but data: URLs (read in place), and the
    // JavaScript among them (its bytes as they came over the wire, whole: a script is run only once it has all come).
    const uploadAt = uploads.find(([, width]) => width >= 64)?.[0] ?? ms;
    const before = [...requests.values()].filter((r) => r.sent <= cdpTime(uploadAt) && !r.url.startsWith('data:'));
    const isScript = (u) => /\.m?js$/.test(new URL(u, 'http://x').pathname);
    const scriptBytes = before.filter((r) => isScript(r.url)).reduce((sum, r) => sum + r.bytes, 0)
      + unseen.filter((entry) => isScript(entry.url)).reduce((sum, entry) => sum + entry.bytes, 0);
    return {
      ms: Math.round(ms), bytes: seen + workerBytes, workerBytes, requests: before.length + unseen.length, scriptBytes,
      sharpMs: Math.round(sharpMs), sharpBytes: bytesUntil(cdpTime(sharpMs)) + workerBytes,
      pdfjs: urls.some((u) => /pdfjs|pdf\.worker/.test(u)),
    };
  } finally {
    await browser.close();
  }
}

const results = [];
for (const pdf of pdfs) {
  const name = path.basename(pdf, '.pdf').replace(/[^\w.-]+/g, '-');
  const site = path.join(out, 'first-spread', name);
  if (args.includes('--republish') || !fs.existsSync(path.join(site, 'index.html'))) {
    console.log(`first-spread: publishing ${pdf} into ${path.relative(root, site)}`);
    fs.rmSync(site, { recursive: true, force: true });  // our own folder under bench-results
    execFileSync(process.execPath, [path.join(root, 'cli/conecurl.mjs'), 'publish', pdf, '--out', site], { stdio: ['ignore', 'ignore', 'inherit'] });
  }
  const server = await serve([['/sites/', path.join(out, 'first-spread')], ['/pdf/', path.dirname(pdf)], ['/', root]]);
  const base = `http://127.0.0.1:${server.address().port}`;
  const roads = {
    published: (options) => measure(`${base}/sites/${name}/index.html`, options),
    // The package's bundled reader.html (dist/reader/, what its docs name), pdf.js found by its import map.
    pdfjs: (options) => measure(`${base}/dist/reader/reader.html#file=/pdf/${encodeURIComponent(path.basename(pdf))}`, options),
  };
  const runs = { published: [], pdfjs: [] };
  try {
    for (let rep = 0; rep < reps; rep++) {
      for (const road of rep % 2 ? ['pdfjs', 'published'] : ['published', 'pdfjs']) {
        const run = await roads[road]({ timeline: args.includes('--timeline') && rep === 0 });
        runs[road].push(run);
        console.log(`[${name} ${rep + 1}/${reps}] ${road}: first spread ${run.ms} ms after ${(run.bytes / 1024).toFixed(0)} KB, ${run.requests} requests and `
          + `${(run.scriptBytes / 1024).toFixed(1)} KB of JavaScript; its reading image ${run.sharpMs} ms after ${(run.sharpBytes / 1024).toFixed(0)} KB${run.pdfjs ? ' (pdf.js loaded)' : ''}`);
      }
    }
  } finally {
    server.close();
  }
  const median = (road, key) => summarize(runs[road].map((r) => r[key])).median;
  const medians = (road) => Object.fromEntries(['ms', 'bytes', 'requests', 'scriptBytes', 'sharpMs', 'sharpBytes'].map((key) => [key, median(road, key)]));
  const result = {
    pdf: path.basename(pdf), reps, kbps, latency, cpu,
    published: { ...medians('published'), runs: runs.published },
    pdfjs: { ...medians('pdfjs'), runs: runs.pdfjs },
  };
  result.timeRatio = result.published.ms / result.pdfjs.ms;
  result.meets = { time: result.timeRatio <= FIRST_SPREAD_TARGETS.timeRatio, bytes: result.published.bytes <= FIRST_SPREAD_TARGETS.bytes,
    requests: result.published.requests <= FIRST_SPREAD_TARGETS.requests, scriptBytes: result.published.scriptBytes <= FIRST_SPREAD_TARGETS.scriptBytes,
    noPdfjs: runs.published.every((r) => !r.pdfjs) };
  results.push(result);
}

fs.mkdirSync(out, { recursive: true });
fs.writeFileSync(path.join(out, 'first-spread.json'), `${JSON.stringify({ date: new Date().toISOString(), targets: FIRST_SPREAD_TARGETS, results }, null, 2)}\n`);
console.log(`\nFirst spread on a phone (390x844 at ratio 3), ${kbps} kbit/s down, ${latency} ms round trip, CPU ${cpu}x slower; medians of ${reps}:`);
console.log('| PDF | published: time | bytes before it | requests | JavaScript | its reading image: time, bytes | pdf.js: time | bytes before it | time ratio (target ≤ 0.33) | bytes (≤ 300 KB) | requests (≤ 8) | JavaScript (≤ 45 KB) |');
console.log('|---|---|---|---|---|---|---|---|---|---|---|---|');
const met = (yes) => (yes ? 'met' : 'missed');
for (const r of results) {
  const kb = (b) => `${(b / 1024).toFixed(0)} KB`;
  const p = r.published;
  console.log(`| ${r.pdf} | ${p.ms} ms | ${kb(p.bytes)} | ${p.requests} | ${(p.scriptBytes / 1024).toFixed(1)} KB | ${p.sharpMs} ms, ${kb(p.sharpBytes)} | ${r.pdfjs.ms} ms | ${kb(r.pdfjs.bytes)} | `
    + `${r.timeRatio.toFixed(2)} ${met(r.meets.time)} | ${met(r.meets.bytes)} | ${met(r.meets.requests)} | ${met(r.meets.scriptBytes)} |`);
}
console.log(`(written to ${path.relative(root, path.join(out, 'first-spread.json'))})`);
