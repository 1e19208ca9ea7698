// How fast `conecurl publish` turns PDFs into page images, in pages per second, against the roads a user
// would script instead, all in one run: (a) a real 311-page text manual (gnuplot.pdf from Debian's
// gnuplot-doc, fetched once with apt-get download and cached in build/bench-pdf/) and (b) a 40-page magazine
// of full-page photo-like images made here. Roads: `conecurl publish --zoom 0`, `conecurl publish` (zoom 2),
// and each page drawn 1600 px tall by poppler's `pdftoppm` or MuPDF's `mutool draw`, then `cwebp -q 80`,
// one page per core. Prints tables (rates; where publish's time goes, step by step), writes JSON.
// Usage: node scripts/bench/publish-rate.mjs [--jobs n] [--pages n (the first n of each PDF)] [--out bench-results]
// The tools: `bash scripts/setup.sh --bench` (Debian packages poppler-utils, mupdf-tools, webp); a road whose
// tool is missing is left out with a line that says what to install.
import { spawn, spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { PDFDocument } from 'pdf-lib';
import { loadCanvas } from '../../cli/publish/pdfjs-node.mjs';

const root = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../..');
const cache = path.join(root, 'build/bench-pdf');

function parseArgs(argv) {
  const options = { jobs: os.availableParallelism(), pages: 0, out: 'bench-results' };
  for (let i = 0; i < argv.length; i++) {
    const name = argv[i];
    if (!['--jobs', '--pages', '--out'].includes(name) || i + 1 >= argv.length) throw new Error(`publish-rate: unknown or incomplete argument ${name} (use --jobs n, --pages n, --out dir)`);
    options[name.slice(2)] = name === '--out' ? argv[++i] : Number(argv[++i]);
    if (name !== '--out' && !(Number.isInteger(options[name.slice(2)]) && options[name.slice(2)] >= (name === '--jobs' ? 1 : 0))) {
      throw new Error(`publish-rate: ${name} needs a whole number, got ${argv[i]}`);
    }
  }
  return options;
}

/** The manual: from the cache, else from Debian (apt-get download gnuplot-doc), or null with a note. */
function realManual() {
  const file = path.join(cache, 'gnuplot.pdf');
  if (fs.existsSync(file)) return file;
  fs.mkdirSync(cache, { recursive: true });
  const got = spawnSync('apt-get', ['download', 'gnuplot-doc'], { cwd: cache, encoding: 'utf8' });
  const deb = fs.readdirSync(cache).find((name) => name.startsWith('gnuplot-doc') && name.endsWith('.deb'));
  if (got.status !== 0 || !deb) {
    console.log(`publish-rate: no gnuplot-doc package (${(got.stderr || got.error?.message || '').trim().split('\n')[0]}); the real-PDF row is left out`);
    return null;
  }
  spawnSync('dpkg-deb', ['-x', deb, 'deb'], { cwd: cache });
  fs.copyFileSync(path.join(cache, 'deb/usr/share/doc/gnuplot/gnuplot.pdf'), file);
  return file;
}

/** A deterministic photo-like page: gradients, soft shapes and noise from a fixed-seed generator. */
function photo(createCanvas, n, width, height) {
  const canvas = createCanvas(width, height);
  const ctx = canvas.getContext('2d');
  let state = 1234567 + n * 7919;
  const next = () => ((state = (state * 1103515245 + 12345) % 2147483648) / 2147483648);
  const sky = ctx.createLinearGradient(0, 0, width, height);
  sky.addColorStop(0, `hsl(${(n * 37) % 360}, 60%, 70%)`);
  sky.addColorStop(1, `hsl(${(n * 37 + 140) % 360}, 50%, 25%)`);
  ctx.fillStyle = sky;
  ctx.fillRect(0, 0, width, height);
  for (let k = 0; k < 40; k++) {
    const x = next() * width;
    const y = next() * height;
    const r = 20 + next() * width * 0.2;
    const blob = ctx.createRadialGradient(x, y, 0, x, y, r);
    blob.addColorStop(0, `hsla(${Math.floor(next() * 360)}, 70%, ${30 + next() * 50}%, 0.8)`);
    blob.addColorStop(1, 'hsla(0, 0%, 0%, 0)');
    ctx.fillStyle = blob;
    ctx.fillRect(x - r, y - r, 2 * r, 2 * r);
  }
  const pixels = ctx.getImageData(0, 0, width, height);
  for (let i = 0; i < pixels.data.length; i += 4) {
    const grain = (next() - 0.5) * 40;
    for (let c = 0; c < 3; c++) pixels.data[i + c] = Math.max(0, Math.min(255, pixels.data[i + c] + grain));
  }
  ctx.putImageData(pixels, 0, 0);
  return canvas.encodeSync('jpeg', 85);
}

async function magazine(pages = 40) {
  const file = path.join(cache, `magazine-${pages}.pdf`);
  if (fs.existsSync(file)) return file;
  const { createCanvas } = loadCanvas();
  const pdf = await PDFDocument.create();
  for (let n = 0; n < pages; n++) {
    const image = await pdf.embedJpg(photo(createCanvas, n, 1240, 1600));
    pdf.addPage([595, 768]).drawImage(image, { x: 0, y: 0, width: 595, height: 768 });
  }
  fs.mkdirSync(cache, { recursive: true });
  fs.writeFileSync(file, await pdf.save());
  return file;
}

const HEIGHT = 1600;  // every road's page image: this many pixels tall
const QUALITY = 80;   // WebP quality, cwebp's -q and publish's default

const bytesUnder = (dir) => fs.readdirSync(dir, { recursive: true }).reduce((sum, name) => {
  const stat = fs.statSync(path.join(dir, name));
  return stat.isFile() ? sum + stat.size : sum;
}, 0);

/** Whether `command` is on PATH. */
const onPath = (command) => spawnSync('sh', ['-c', `command -v ${command}`], { stdio: 'ignore' }).status === 0;

/** The page count of `pdf` (pdf-lib reads the page tree; nothing is drawn). */
async function pageCount(pdf) {
  return (await PDFDocument.load(fs.readFileSync(pdf), { ignoreEncryption: true, updateMetadata: false })).getPageCount();
}

/** `conecurl publish` as a user runs it (one worker per job), with its steps recorded (CONECURL_PUBLISH_STEPS, main.js). */
function publishRoad(label, zoom) {
  return {
    label, kind: 'publish', zoom,
    async run({ pdf, pages, jobs, dir }) {
      const stepsFile = path.join(dir, 'steps.json');
      const site = path.join(dir, 'site');
      const started = process.hrtime.bigint();
      const run = spawnSync(process.execPath, [path.join(root, 'cli/conecurl.mjs'), 'publish', pdf, '--out', site,
        '--jobs', String(jobs), '--zoom', String(zoom), '--height', String(HEIGHT), '--quality', String(QUALITY), '--no-download', '--pages', `1-${pages}`],
      { encoding: 'utf8', env: { ...process.env, CONECURL_PUBLISH_STEPS: stepsFile } });
      const seconds = Number(process.hrtime.bigint() - started) / 1e9;
      if (run.status !== 0) throw new Error(`${label} failed (exit ${run.status}): ${run.stderr.trim().split('\n')[0]}`);
      const book = path.join(site, 'book');
      const imageBytes = ['pages', 'zoom', 'thumbs'].reduce((sum, d) => sum + (fs.existsSync(path.join(book, d)) ? bytesUnder(path.join(book, d)) : 0), 0);
      return { seconds, imageBytes, readingBytes: bytesUnder(path.join(book, 'pages')), bytesOut: bytesUnder(site),
        steps: JSON.parse(fs.readFileSync(stepsFile, 'utf8')) };
    },
  };
}

/** Runs `command args`, resolving to its exit code (a missing command or a signal: non-zero). */
function exec(command, args) {
  return new Promise((resolve) => {
    const child = spawn(command, args, { stdio: ['ignore', 'ignore', 'ignore'] });
    child.on('error', () => resolve(127));
    child.on('close', (code) => resolve(code ?? 1));
  });
}

/**
 * A road a user would script: `draw(pdf, n, ppm)` makes page n's PPM (HEIGHT px tall) with the tool, then
 * `cwebp -q QUALITY` encodes it; `jobs` pages at once, each its own processes, as `xargs -P` would run them.
 * PPM between the two, the cheapest hand-over (no PNG compression to pay).
 */
function scriptRoad(label, tool, debianPackage, draw) {
  return {
    label, kind: 'script', tool, debianPackage, tools: [tool, 'cwebp'],
    async run({ pdf, pages, jobs, dir }) {
      const images = path.join(dir, 'pages');
      fs.mkdirSync(images);
      let next = 1;
      let failed = 0;
      const started = process.hrtime.bigint();
      const worker = async () => {
        for (let n = next++; n <= pages; n = next++) {
          const ppm = path.join(dir, `${n}.ppm`);
          const [command, args] = draw(pdf, n, ppm);
          const ok = (await exec(command, args)) === 0
            && (await exec('cwebp', ['-quiet', '-q', String(QUALITY), ppm, '-o', path.join(images, `${String(n).padStart(4, '0')}.webp`)])) === 0;
          if (!ok) failed += 1;
          fs.rmSync(ppm, { force: true });
        }
      };
      await Promise.all(Array.from({ length: jobs }, worker));
      const seconds = Number(process.hrtime.bigint() - started) / 1e9;
      if (failed === pages) throw new Error(`${label} failed on every page: try ${command(draw(pdf, 1, 'page.ppm'))} by hand`);
      const bytes = bytesUnder(images);
      return { seconds, imageBytes: bytes, readingBytes: bytes, bytesOut: bytes, failed };
    },
  };
}
const command = ([name, args]) => [name, ...args].join(' ');

const ROADS = [
  publishRoad('conecurl publish --zoom 0', 0),
  scriptRoad('pdftoppm + cwebp', 'pdftoppm', 'poppler-utils',
    (pdf, n, ppm) => ['pdftoppm', ['-f', String(n), '-l', String(n), '-scale-to-y', String(HEIGHT), '-scale-to-x', '-1', '-singlefile', pdf, ppm.replace(/\.ppm$/, '')]]),
  scriptRoad('mutool draw + cwebp', 'mutool', 'mupdf-tools',
    (pdf, n, ppm) => ['mutool', ['draw', '-q', '-h', String(HEIGHT), '-o', ppm, pdf, String(n)]]),
  publishRoad('conecurl publish (zoom 2)', 2),
];

async function measure(road, input, options) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'conecurl-publish-rate-'));
  try {
    const loadBefore = os.loadavg()[0];
    const result = await road.run({ pdf: input.file, pages: input.pages, jobs: options.jobs, dir });
    return { pdf: input.label, road: road.label, pages: input.pages, ...result, pagesPerSecond: input.pages / result.seconds,
      msPerPagePerJob: (result.seconds * 1000 * options.jobs) / input.pages, jobs: options.jobs, cores: os.availableParallelism(),
      loadBefore, loadAfter: os.loadavg()[0] };
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

const STEPS = ['page', 'wait', 'render', 'scale', 'encode', 'write', 'text', 'links'];

async function main() {
  const options = parseArgs(process.argv.slice(2));
  const roads = ROADS.filter((road) => {
    const missing = (road.tools ?? []).filter((tool) => !onPath(tool));
    if (missing.length === 0) return true;
    const packages = missing.map((tool) => (tool === 'cwebp' ? 'webp' : road.debianPackage));
    console.log(`publish-rate: ${missing.join(' and ')} not found, so "${road.label}" is left out: run bash scripts/setup.sh --bench (or apt-get install ${packages.join(' ')})`);
    return false;
  });
  const inputs = [];
  for (const [label, file] of [['real manual (gnuplot.pdf)', realManual()], ['magazine (40 full-page photos)', await magazine()]]) {
    if (!file) continue;
    const count = await pageCount(file);
    inputs.push({ label, file, pages: options.pages > 0 ? Math.min(options.pages, count) : count });
  }
  const rows = [];
  for (const input of inputs) {
    for (const road of roads) {
      try {
        const row = await measure(road, input, options);
        rows.push(row);
        console.log(`publish-rate: ${input.label}, ${road.label}: ${row.pagesPerSecond.toFixed(2)} pages/s`);
      } catch (error) {
        console.error(`publish-rate: ${input.label}, ${road.label}: ${error.message}`);
        process.exitCode = 1;
      }
    }
  }
  const mb = (n) => `${(n / 1024 / 1024).toFixed(1)} MB`;
  console.log(`\n| PDF | road | pages | seconds | pages/s | ms/page/job | reading images (all images) | load before/after |\n| --- | --- | --- | --- | --- | --- | --- | --- |`);
  for (const r of rows) {
    console.log(`| ${r.pdf} | ${r.road} | ${r.pages}${r.failed ? ` (${r.failed} failed)` : ''} | ${r.seconds.toFixed(1)} | ${r.pagesPerSecond.toFixed(2)} | ${r.msPerPagePerJob.toFixed(0)} `
      + `| ${mb(r.readingBytes)} (${mb(r.imageBytes)}) | ${r.loadBefore.toFixed(1)}/${r.loadAfter.toFixed(1)} |`);
  }
  console.log(`\n${options.jobs} jobs on ${os.availableParallelism()} cores; each image ${HEIGHT} px tall, WebP quality ${QUALITY}.`);
  const published = rows.filter((r) => r.steps);
  if (published.length > 0) {
    // Where publish's time goes: its phases (wall ms) and each page's steps (ms a page, in a worker).
    const ms = (n) => (n === undefined ? '' : Math.round(n).toLocaleString('en'));
    console.log(`\n| PDF | road | process start | open PDF | reader files | workers ready (mean) | pages | finish | ${STEPS.join(' | ')} | a page in all |`
      + `\n| --- | --- | --- | --- | --- | --- | --- | --- | ${STEPS.map(() => '---').join(' | ')} | --- |`);
    for (const r of published) {
      const { phases, pages, workerStartMs, pageCount: count } = r.steps;
      const mean = workerStartMs.length ? workerStartMs.reduce((a, b) => a + b, 0) / workerStartMs.length : undefined;
      const perPage = STEPS.map((step) => (pages[step] === undefined ? '' : (pages[step] / count).toFixed(0)));
      const all = Object.values(pages).reduce((a, b) => a + b, 0) / count;
      console.log(`| ${r.pdf} | ${r.road} | ${ms(phases.start)} | ${ms(phases.open)} | ${ms(phases.runtime)} | ${ms(mean)} | ${ms(phases.pages)} | ${ms(phases.finish)} | ${perPage.join(' | ')} | ${all.toFixed(0)} |`);
    }
    console.log('(phases: wall ms; steps: ms a page in one worker, encode = every image of the page, write = its files, text and links = what the reader gets besides images)');
  }
  const manual = (road) => rows.find((r) => r.pdf.startsWith('real manual') && r.road === road);
  const zero = manual(ROADS[0].label);
  const others = ROADS.filter((road) => road.kind === 'script').map((road) => manual(road.label)).filter(Boolean);
  if (zero && others.length > 0) {
    const best = others.reduce((a, b) => (a.pagesPerSecond >= b.pagesPerSecond ? a : b));
    console.log(`\npublish-rate: target (--zoom 0 at least as fast as the faster script road on the manual): ${zero.pagesPerSecond >= best.pagesPerSecond ? 'met' : 'missed'}`
      + ` (${zero.pagesPerSecond.toFixed(2)} against ${best.road}'s ${best.pagesPerSecond.toFixed(2)} pages/s)`);
  }
  const out = path.resolve(root, options.out);
  fs.mkdirSync(out, { recursive: true });
  fs.writeFileSync(path.join(out, 'publish-rate.json'), `${JSON.stringify({ date: new Date().toISOString(), node: process.version, cpus: os.cpus()[0]?.model,
    command: `node scripts/bench/publish-rate.mjs ${process.argv.slice(2).join(' ')}`.trim(), rows }, null, 1)}\n`);
  console.log(`publish-rate: wrote ${path.relative(root, path.join(out, 'publish-rate.json'))}`);
}

main().catch((error) => {
  console.error(error.message);
  process.exitCode = 1;
});
