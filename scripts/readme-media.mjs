// The README's picture and animation, made from the real renderer like the reference images: the demo's
// book (web/demo/book-pages.js) in a Flipbook in Debian's Chromium (WebGL2 on SwiftShader), one turn
// posed frame by frame with the book's own frozen-frame call (book.previewTurn(direction, t)), written
// as docs/media/curl.png (one frame mid-curl) and docs/media/turn.png (an animated PNG of the turn).
// Usage: npm run readme-media (builds first), or node scripts/readme-media.mjs [--out DIR] [--frames N]
// Look at both images before committing them.
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { fileURLToPath } from 'node:url';
import { chromium } from '@playwright/test';
import { chromiumLaunchOptions } from './chromium.mjs';
import { serveDirectory } from './serve.mjs';
import { decodePng } from '../tests/browser/png.js';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const arg = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i > 0 ? process.argv[i + 1] : fallback;
};
const outDir = path.resolve(root, arg('--out', 'docs/media'));
const FRAMES = Number(arg('--frames', '24'));      // frames of the animation, t = 0 to 1
const CURL_T = Number(arg('--curl-t', '0.3'));     // the still: the broad curve of the turn's second phase
const START_PAGE = Number(arg('--page', '4'));     // a spread of text and a figure, the right page turning
const SIZE = { width: 800, height: 500 };          // the still, in CSS px (device scale 1)
const ANIMATION_SCALE = Number(arg('--scale', '0.75'));  // the animation is drawn smaller: 600 x 375
const FRAME_MS = 60;                               // each frame of the turn; the first and last are held
const HOLD_MS = 900;
const BACKGROUND = '#f3efe8';

// The page the browser opens: the demo's forty drawn pages in a Flipbook, as demo.js makes them.
const PAGE = `<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>conecurl README media</title><link rel="icon" href="data:,">
<style>html, body { margin: 0; background: ${BACKGROUND}; } #book { width: 100vw; height: 100vh; }</style>
</head><body><div id="book"></div>
<script type="module">
  import { Flipbook } from '/web/src/index.js';
  import { DEMO_PAGE_COUNT, drawBookPage, isHardPage } from '/web/demo/book-pages.js';
  const start = Number(new URLSearchParams(location.search).get('page'));
  const pages = Array.from({ length: DEMO_PAGE_COUNT }, (_, index) => ({ src: () => drawBookPage(index), hard: isHardPage(index) }));
  try {
    window.book = await Flipbook.create(document.getElementById('book'), {
      pages, display: 'double', startPage: start, antialias: true, fallback: false,
    });
    document.body.dataset.ready = 'yes';
  } catch (error) {
    document.body.dataset.error = String(error?.stack ?? error);
  }
</script></body></html>`;

// ---------------------------------------------------------------------------------------------------
// PNG and APNG writing (https://www.w3.org/TR/png-3/): 8-bit RGB, each row filtered with the filter
// that minimises the sum of absolute differences, zlib at level 9. An animation's later frames hold
// only the rectangle that changed since the frame before (dispose none, blend source).

const CRC_TABLE = Array.from({ length: 256 }, (_, n) => {
  let c = n;
  for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
  return c >>> 0;
});
function crc32(bytes) {
  let c = 0xffffffff;
  for (const b of bytes) c = CRC_TABLE[(c ^ b) & 255] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}
function chunk(type, data) {
  const head = Buffer.alloc(8);
  head.writeUInt32BE(data.length, 0);
  head.write(type, 4, 'ascii');
  const body = Buffer.concat([head.subarray(4), data]);
  const crc = Buffer.alloc(4);
  crc.writeUInt32BE(crc32(body), 0);
  return Buffer.concat([head.subarray(0, 4), body, crc]);
}
const u32 = (...values) => {
  const buffer = Buffer.alloc(values.length * 4);
  values.forEach((v, i) => buffer.writeUInt32BE(v, i * 4));
  return buffer;
};

/** The rectangle { x, y, width, height } of `image` (RGBA, rows top to bottom) as filtered, deflated RGB scanlines. */
function deflateRect(image, { x, y, width, height }) {
  const stride = width * 3;
  const raw = Buffer.alloc(height * (stride + 1));
  let previous = new Uint8Array(stride);
  const candidate = Array.from({ length: 5 }, () => new Uint8Array(stride));
  for (let row = 0; row < height; row++) {
    const line = new Uint8Array(stride);
    for (let col = 0; col < width; col++) {
      const at = ((y + row) * image.width + x + col) * 4;
      line.set(image.data.subarray(at, at + 3), col * 3);
    }
    let best = 0;
    let bestCost = Infinity;
    for (let filter = 0; filter < 5; filter++) {
      const out = candidate[filter];
      let cost = 0;
      for (let i = 0; i < stride; i++) {
        const left = i >= 3 ? line[i - 3] : 0;
        const up = previous[i];
        const upLeft = i >= 3 ? previous[i - 3] : 0;
        let predictor = 0;
        if (filter === 1) predictor = left;
        else if (filter === 2) predictor = up;
        else if (filter === 3) predictor = (left + up) >> 1;
        else if (filter === 4) {
          const p = left + up - upLeft;
          const [pa, pb, pc] = [Math.abs(p - left), Math.abs(p - up), Math.abs(p - upLeft)];
          predictor = pa <= pb && pa <= pc ? left : pb <= pc ? up : upLeft;
        }
        const value = (line[i] - predictor) & 255;
        out[i] = value;
        cost += value < 128 ? value : 256 - value;
      }
      if (cost < bestCost) [best, bestCost] = [filter, cost];
    }
    raw[row * (stride + 1)] = best;
    raw.set(candidate[best], row * (stride + 1) + 1);
    previous = line;
  }
  return zlib.deflateSync(raw, { level: 9, memLevel: 9 });
}

const SIGNATURE = Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);
const ihdr = (width, height) => chunk('IHDR', Buffer.concat([u32(width, height), Buffer.from([8, 2, 0, 0, 0])]));

/** A still PNG of `image` (RGBA in; RGB out: the book is opaque). */
function encodePng(image) {
  const whole = { x: 0, y: 0, width: image.width, height: image.height };
  return Buffer.concat([SIGNATURE, ihdr(image.width, image.height), chunk('IDAT', deflateRect(image, whole)),
    chunk('IEND', Buffer.alloc(0))]);
}

/** The rectangle where `image` differs from `before` (at least 1 x 1). */
function changedRect(before, image) {
  let [x0, y0, x1, y1] = [image.width, image.height, -1, -1];
  for (let y = 0; y < image.height; y++) {
    for (let x = 0; x < image.width; x++) {
      const at = (y * image.width + x) * 4;
      if (before.data[at] !== image.data[at] || before.data[at + 1] !== image.data[at + 1] || before.data[at + 2] !== image.data[at + 2]) {
        [x0, y0, x1, y1] = [Math.min(x0, x), Math.min(y0, y), Math.max(x1, x), Math.max(y1, y)];
      }
    }
  }
  return x1 < 0 ? { x: 0, y: 0, width: 1, height: 1 } : { x: x0, y: y0, width: x1 - x0 + 1, height: y1 - y0 + 1 };
}

/** An animated PNG of `frames` (RGBA images of one size), each shown `delays[i]` ms, looping forever. */
function encodeApng(frames, delays) {
  const { width, height } = frames[0];
  const parts = [SIGNATURE, ihdr(width, height), chunk('acTL', u32(frames.length, 0))];
  let sequence = 0;
  frames.forEach((frame, i) => {
    const rect = i === 0 ? { x: 0, y: 0, width, height } : changedRect(frames[i - 1], frame);
    const delay = Buffer.alloc(4);
    delay.writeUInt16BE(delays[i], 0);   // numerator, ms
    delay.writeUInt16BE(1000, 2);        // denominator
    parts.push(chunk('fcTL', Buffer.concat([u32(sequence++, rect.width, rect.height, rect.x, rect.y), delay, Buffer.from([0, 0])])));
    const data = deflateRect(frame, rect);
    parts.push(i === 0 ? chunk('IDAT', data) : chunk('fdAT', Buffer.concat([u32(sequence++), data])));
  });
  parts.push(chunk('IEND', Buffer.alloc(0)));
  return Buffer.concat(parts);
}

// ---------------------------------------------------------------------------------------------------

/** Opens the book at `size`, then returns a function that screenshots the frame of the next turn at t. */
async function openBook(browser, url, size) {
  const page = await browser.newPage({ viewport: size, deviceScaleFactor: 1 });
  page.on('pageerror', (error) => console.error(`readme-media: page error: ${error.message}`));
  await page.route(`${url}readme-media.html*`, (route) => route.fulfill({ contentType: 'text/html', body: PAGE }));
  await page.goto(`${url}readme-media.html?page=${START_PAGE}`);
  await page.waitForFunction(() => document.body.dataset.ready || document.body.dataset.error, null, { timeout: 120_000 });
  const error = await page.evaluate(() => document.body.dataset.error);
  if (error) throw new Error(`readme-media: the book did not open: ${error}`);
  return async (t) => {
    await page.evaluate(async (t) => {
      const { book } = window;
      const frame = () => new Promise((resolve) => requestAnimationFrame(resolve));
      if (!book.previewTurn('forward', t)) throw new Error('previewTurn refused: no next page');
      await book.whenIdle();                  // the posed leaf's pages, loaded if they were not
      book.previewTurn('forward', t);         // and posed again, with them
      const drawn = book.surface.framesDrawn;
      while (book.surface.framesDrawn === drawn) await frame();
      await frame();
    }, t);
    return decodePng(await page.screenshot({ type: 'png' }));
  };
}

async function main() {
  const { server, url } = await serveDirectory(root);
  const browser = await chromium.launch(chromiumLaunchOptions());
  try {
    fs.mkdirSync(outDir, { recursive: true });
    const still = await openBook(browser, url, SIZE);
    const curl = encodePng(await still(CURL_T));
    fs.writeFileSync(path.join(outDir, 'curl.png'), curl);
    console.log(`readme-media: ${path.relative(root, path.join(outDir, 'curl.png'))} ${SIZE.width}x${SIZE.height}, t = ${CURL_T}, ${(curl.length / 1024).toFixed(0)} KB`);

    const small = { width: Math.round(SIZE.width * ANIMATION_SCALE), height: Math.round(SIZE.height * ANIMATION_SCALE) };
    const shoot = await openBook(browser, url, small);
    const frames = [];
    for (let i = 0; i < FRAMES; i++) frames.push(await shoot(i / (FRAMES - 1)));
    const delays = frames.map((_, i) => (i === 0 || i === FRAMES - 1 ? HOLD_MS : FRAME_MS));
    const turn = encodeApng(frames, delays);
    fs.writeFileSync(path.join(outDir, 'turn.png'), turn);
    console.log(`readme-media: ${path.relative(root, path.join(outDir, 'turn.png'))} ${small.width}x${small.height}, ${FRAMES} frames, ${(turn.length / 1024).toFixed(0)} KB`);
    if (process.env.README_MEDIA_FRAME) {  // one middle frame as a still PNG, to look at
      fs.writeFileSync(process.env.README_MEDIA_FRAME, encodePng(frames[Math.floor(FRAMES / 2)]));
    }
  } finally {
    await browser.close();
    server.close();
  }
}

export { encodePng, encodeApng };

if (process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url)) await main();
