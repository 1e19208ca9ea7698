// Node test of `conecurl publish` on pages of odd shapes and sizes (issue 38): a page 10:1 wide, one 1:10
// tall and one 200 inches a side each publish, every image within its format's limits, in bounded memory.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { PDFDocument, StandardFonts, rgb } from 'pdf-lib';
import { checkManifest } from '../../web/src/document/format.js';
import { sizeFromBytes } from '../../web/src/pages/image-header.js';
import { MAX_SIDE, PIXEL_BUDGET, fitScale } from '../../cli/publish/render-page.mjs';
import { readJson, root, tempDir } from './publish-run.mjs';

const GB = 1024 ** 3;

/** A one-page PDF of `width` x `height` (PDF units, 72 a inch): a frame and a line of text. */
async function onePagePdf(width, height) {
  const pdf = await PDFDocument.create();
  const font = await pdf.embedFont(StandardFonts.Helvetica);
  const page = pdf.addPage([width, height]);
  const unit = Math.min(width, height) / 10;
  page.drawRectangle({ x: unit, y: unit, width: width - 2 * unit, height: height - 2 * unit, borderColor: rgb(0.2, 0.3, 0.8), borderWidth: unit / 4 });
  page.drawText('An odd page', { x: unit * 1.5, y: height / 2, size: unit, font });
  return pdf.save();
}

/** Runs `conecurl publish ...args` (default jobs); resolves { code, stderr, maxRss (bytes, the whole process with its workers) }. */
function publishMeasured(args) {
  // The child reports its own peak resident size as it exits (resourceUsage's maxRSS is in KB).
  const report = 'data:text/javascript,process.on("exit",()=>process.stderr.write(`maxRSS=${process.resourceUsage().maxRSS}\\n`))';
  return new Promise((resolve) => {
    const child = spawn(process.execPath, ['--import', report, path.join(root, 'cli/conecurl.mjs'), 'publish', ...args], { cwd: root, stdio: ['ignore', 'ignore', 'pipe'] });
    let stderr = '';
    child.stderr.on('data', (d) => { stderr += d; });
    const guard = setTimeout(() => child.kill('SIGKILL'), 300_000);
    child.on('close', (code, signal) => {
      clearTimeout(guard);
      const kb = Number(/maxRSS=(\d+)/.exec(stderr)?.[1]);
      resolve({ code: signal ? `killed (${signal})` : code, stderr, maxRss: kb * 1024 });
    });
  });
}

const CASES = [
  // The page: at the default 1600 px height its zoom image would be 32000 x 3200.
  { name: 'wide 10:1', size: [6120, 612], args: [], limited: { zoom: 0, by: '24 megapixels an image' } },
  // At 3 x the PDF's size its reading image would be 1836 x 18360: past WebP's 16383, and 34 megapixels
  // (the pixel budget binds first on any page less than 11 times longer than wide: 16383² / 24e6).
  { name: 'tall 1:10', size: [612, 6120], args: ['--scale', '3'], limited: { zoom: 0, by: '24 megapixels an image' } },
  // 200 inches a side (PDF's largest page) at 72 px an inch: 14400 x 14400 asked, 207 megapixels.
  { name: '200 inches a side', size: [14400, 14400], args: ['--scale', '1'], limited: { zoom: 0, by: '24 megapixels an image' } },
];

for (const { name, size, args, limited } of CASES) {
  test(`node: conecurl publish of a page ${name} publishes it with every image within WebP's 16383 px a side and ${PIXEL_BUDGET / 1e6} megapixels, says so in book.json, and peaks under 1 GB (needs pdfjs-dist, @napi-rs/canvas, pdf-lib)`, async (t) => {
    const dir = tempDir(t);
    const pdf = path.join(dir, 'odd.pdf');
    fs.writeFileSync(pdf, await onePagePdf(...size));
    const out = path.join(dir, 'site');
    const run = await publishMeasured([pdf, '--out', out, ...args]);
    assert.equal(run.code, 0, run.stderr);
    const [page] = checkManifest(readJson(path.join(out, 'book/book.json')), 'book.json').pages;
    assert.equal(page.failed, undefined, 'the page is published');
    assert.deepEqual([page.width, page.height], size);
    assert.equal(page.limited?.zoom, limited.zoom, JSON.stringify(page.limited));
    assert.equal(page.limited.by, limited.by);
    assert.ok(page.limited.reading > 0 && page.limited.reading < 1, `the reading image is smaller than asked: ${page.limited.reading}`);
    assert.equal(page.zoomSrc, undefined, 'no zoom image where it would be no larger than the reading one');
    const images = [page.src, page.thumbSrc, 'cover.jpg'];
    for (const image of images) {
      const { width, height } = sizeFromBytes(new Uint8Array(fs.readFileSync(path.join(out, 'book', image))));
      const side = image.endsWith('.jpg') ? MAX_SIDE.jpeg : MAX_SIDE.webp;
      assert.ok(width <= side && height <= side && width * height <= PIXEL_BUDGET, `${image} is ${width} x ${height}`);
      assert.ok(Math.abs(width / height - size[0] / size[1]) / (size[0] / size[1]) < 0.02, `${image} keeps the page's shape: ${width} x ${height}`);
    }
    t.diagnostic(`peak memory ${(run.maxRss / 1024 ** 2).toFixed(0)} MB`);
    assert.ok(run.maxRss > 0 && run.maxRss < GB, `peak resident memory ${(run.maxRss / 1024 ** 2).toFixed(0)} MB`);
  });
}

test('node: fitScale gives the scale asked where it fits, else the largest within the side limit and the pixel budget, rounding included (needs nothing)', () => {
  assert.equal(fitScale(612, 792, 2, MAX_SIDE.webp), 2);
  const long = fitScale(200, 6000, 4, MAX_SIDE.webp);  // 1:30, 24000 px tall asked: the side binds
  assert.ok(Math.round(6000 * long) <= MAX_SIDE.webp && Math.round(6000 * long) > MAX_SIDE.webp - 20, `${6000 * long}`);
  const big = fitScale(14400, 14400, 1, MAX_SIDE.webp);  // 207 megapixels asked: the budget binds
  assert.ok(Math.round(14400 * big) ** 2 <= PIXEL_BUDGET && Math.round(14400 * big) ** 2 > PIXEL_BUDGET * 0.99);
  assert.equal(Math.max(1, Math.round(0.5 * fitScale(0.5, 200000, 1, MAX_SIDE.webp))), 1, 'a sliver keeps at least a pixel');
});
