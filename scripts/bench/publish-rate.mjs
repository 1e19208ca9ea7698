// How fast `conecurl publish` turns PDFs into sites, in pages per second: (a) a real 311-page text manual
// (gnuplot.pdf from Debian's gnuplot-doc, fetched once with apt-get download and cached in build/bench-pdf/)
// and (b) a 40-page magazine of full-page photo-like images made here. Prints a table, writes JSON.
// Usage: node scripts/bench/publish-rate.mjs [--jobs n] [--zoom z] [--out bench-results]
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { PDFDocument } from 'pdf-lib';
import { loadCanvas } from '../../cli/publish/pdfjs-node.mjs';

const root = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../..');
const cache = path.join(root, 'build/bench-pdf');

function parseArgs(argv) {
  const options = { jobs: os.availableParallelism(), zoom: 2, out: 'bench-results' };
  for (let i = 0; i < argv.length; i++) {
    const name = argv[i];
    if (!['--jobs', '--zoom', '--out'].includes(name) || i + 1 >= argv.length) throw new Error(`publish-rate: unknown or incomplete argument ${name}`);
    options[name.slice(2)] = name === '--out' ? argv[++i] : Number(argv[++i]);
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

const bytesUnder = (dir) => fs.readdirSync(dir, { recursive: true }).reduce((sum, name) => {
  const stat = fs.statSync(path.join(dir, name));
  return stat.isFile() ? sum + stat.size : sum;
}, 0);

function measure(label, pdf, options) {
  const out = fs.mkdtempSync(path.join(os.tmpdir(), 'conecurl-publish-rate-'));
  try {
    const started = process.hrtime.bigint();
    const run = spawnSync(process.execPath, [path.join(root, 'cli/conecurl.mjs'), 'publish', pdf, '--out', path.join(out, 'site'),
      '--jobs', String(options.jobs), '--zoom', String(options.zoom), '--no-download'],
    { encoding: 'utf8' });
    const seconds = Number(process.hrtime.bigint() - started) / 1e9;
    if (run.status !== 0) throw new Error(`publish-rate: ${label} failed (exit ${run.status}): ${run.stderr.trim()}`);
    const pages = JSON.parse(fs.readFileSync(path.join(out, 'site/book/book.json'), 'utf8')).pageCount;
    const book = path.join(out, 'site/book');
    return { label, pages, seconds, pagesPerSecond: pages / seconds, msPerPagePerJob: (seconds * 1000 * options.jobs) / pages,
      bytesOut: bytesUnder(book), imageBytes: ['pages', 'zoom', 'thumbs'].reduce((s, d) => s + (fs.existsSync(path.join(book, d)) ? bytesUnder(path.join(book, d)) : 0), 0),
      jobs: options.jobs, zoom: options.zoom, cores: os.availableParallelism() };
  } finally {
    fs.rmSync(out, { recursive: true, force: true });
  }
}

async function main() {
  const options = parseArgs(process.argv.slice(2));
  const inputs = [['real manual (gnuplot.pdf)', realManual()], ['magazine (40 full-page photos)', await magazine()]].filter(([, file]) => file);
  const rows = inputs.map(([label, file]) => measure(label, file, options));
  const mb = (n) => `${(n / 1024 / 1024).toFixed(1)} MB`;
  console.log('\n| PDF | pages | seconds | pages/s | ms/page/job | bytes out (images) | jobs | cores | zoom |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- |');
  for (const r of rows) {
    console.log(`| ${r.label} | ${r.pages} | ${r.seconds.toFixed(1)} | ${r.pagesPerSecond.toFixed(2)} | ${r.msPerPagePerJob.toFixed(0)} | ${mb(r.bytesOut)} (${mb(r.imageBytes)}) | ${r.jobs} | ${r.cores} | ${r.zoom} |`);
  }
  const out = path.resolve(root, options.out);
  fs.mkdirSync(out, { recursive: true });
  fs.writeFileSync(path.join(out, 'publish-rate.json'), `${JSON.stringify({ date: new Date().toISOString(), node: process.version, loadavg: os.loadavg(), rows }, null, 1)}\n`);
  console.log(`publish-rate: wrote ${path.relative(root, path.join(out, 'publish-rate.json'))} (load average ${os.loadavg().map((l) => l.toFixed(1)).join(' ')})`);
}

main().catch((error) => {
  console.error(error.message);
  process.exitCode = 1;
});
