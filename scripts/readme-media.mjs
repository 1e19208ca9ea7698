// The README's picture and animation, made from the real renderer like the reference images: the demo's
// book (web/demo/book-pages.js) in a Flipbook in Debian's Chromium (WebGL2 on SwiftShader), one turn
// posed frame by frame with the book's own frozen-frame call (book.previewTurn(direction, t)), written
// as docs/media/curl.png (one frame mid-curl), docs/media/turn.png (an animated PNG of the turn) and
// docs/media/phone-turn.png (the same turn as a phone shows it: one page at a time).
// Usage: npm run readme-media (builds first), or node scripts/readme-media.mjs [--out DIR] [--frames N]
// [--curl-t T] [--page N] [--scale S]; README_MEDIA_FRAME=file.png also writes the middle frame as a still
// (and the phone's as file-phone.png).
// Look at both images before committing them.
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { fileURLToPath } from 'node:url';
import { chromium } from '@playwright/test';
import { chromiumLaunchOptions } from './chromium.mjs';
import { serveDirectory } from './serve.mjs';
import { decodePng, pngPredictor } from '../tests/browser/png.js';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const arg = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i > 0 ? process.argv[i + 1] : fallback;
};
const outDir = path.resolve(root, arg('--out', 'docs/media'));
const FRAMES = Number(arg('--frames', '24'));      // frames of the animation, t = 0 to 1
const CURL_T = Number(arg('--curl-t', '0.08'));    // the still: the first phase, the page lifting in a curl
const START_PAGE = Number(arg('--page', '4'));     // a spread of text and a figure, the right page turning
const SIZE = { width: 800, height: 500 };          // the still, in CSS px (device scale 1)
const ANIMATION_SCALE = Number(arg('--scale', '0.75'));  // the animation is drawn smaller: 600 x 375
const FRAME_MS = 60;                               // each frame of the turn; the first and last are held
const HOLD_MS = 900;
const BACKGROUND = '#f3efe8';
const PHONE = { width: 195, height: 375 };         // a phone's screen at half size: the single display

// The page the browser opens: the demo's forty drawn pages in a Flipbook, as demo.js makes them.
const PAGE = `<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>conecurl README media</title><link rel="icon" href="data:,">
<style>html, body { margin: 0; background: ${BACKGROUND}; } #book { width: 100vw; height: 100vh; }</style>
</head><body><div id="book"></div>
<script type="module">
  import { Flipbook } from '/web/src/index.js';
  import { DEMO_PAGE_COUNT, drawBookPage, isHardPage } from '/web/demo/book-pages.js';
  const query = new URLSearchParams(location.search);
  const start = Number(query.get('page'));
  const pages = Array.from({ length: DEMO_PAGE_COUNT }, (_, index) => ({ src: () => drawBookPage(index), hard: isHardPage(index) }));
  try {
    window.book = await Flipbook.create(document.getElementById('book'), {
      pages, display: query.get('display'), startPage: start, antialias: true, fallback: false,
    });
    document.body.dataset.ready = 'yes';
  } catch (error) {
    document.body.dataset.error = String(error?.stack ?? error);
  }
</script></body></html>`;

// ---------------------------------------------------------------------------------------------------
// PNG and APNG writing (https://www.w3.org/TR/png-3/): 8-bit RGB, each row filtered with the filter
// that minimises the sum of absolute differences, or 8-bit palette indices (the animation, to stay
// small), zlib at level 9. An animation's later frames hold only the rectangle that changed since the
// frame before (dispose none, blend source).

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

/**
 * The rectangle { x, y, width, height } of `image` as filtered, deflated scanlines: RGB from an RGBA
 * image, or palette indices from an indexed one ({ width, height, indices }).
 */
function deflateRect(image, { x, y, width, height }) {
  const channels = image.indices ? 1 : 3;
  const stride = width * channels;
  const raw = Buffer.alloc(height * (stride + 1));
  let previous = new Uint8Array(stride);
  const candidate = Array.from({ length: 5 }, () => new Uint8Array(stride));
  for (let row = 0; row < height; row++) {
    const line = new Uint8Array(stride);
    for (let col = 0; col < width; col++) {
      const at = (y + row) * image.width + x + col;
      if (image.indices) line[col] = image.indices[at];
      else line.set(image.data.subarray(at * 4, at * 4 + 3), col * 3);
    }
    // Palette indices are not magnitudes: rows stay unfiltered (the PNG specification's advice).
    let best = 0;
    let bestCost = Infinity;
    for (let filter = 0; filter < (image.indices ? 1 : 5); filter++) {
      const out = candidate[filter];
      let cost = 0;
      for (let i = 0; i < stride; i++) {
        const left = i >= channels ? line[i - channels] : 0;
        const up = previous[i];
        const upLeft = i >= channels ? previous[i - channels] : 0;
        const value = (line[i] - pngPredictor(filter, left, up, upLeft)) & 255;
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

/**
 * One palette of at most 256 colours for all `frames` (median cut over their colours at 5 bits a
 * channel, each box's colour the mean of its pixels), and each frame as indices into it (nearest
 * colour, no dithering: dithered text and paper compress worse and look noisier).
 */
function quantize(frames) {
  const bin = (data, at) => ((data[at] >> 3) << 10) | ((data[at + 1] >> 3) << 5) | (data[at + 2] >> 3);
  const count = new Float64Array(32768);
  const sum = new Float64Array(32768 * 3);
  for (const { data } of frames) {
    for (let at = 0; at < data.length; at += 4) {
      const b = bin(data, at);
      count[b]++;
      sum[b * 3] += data[at]; sum[b * 3 + 1] += data[at + 1]; sum[b * 3 + 2] += data[at + 2];
    }
  }
  const used = [];
  for (let b = 0; b < 32768; b++) if (count[b]) used.push(b);
  const channel = (b, c) => (b >> (10 - 5 * c)) & 31;
  const describe = (bins) => {
    const lo = [31, 31, 31]; const hi = [0, 0, 0]; let pixels = 0;
    for (const b of bins) {
      pixels += count[b];
      for (let c = 0; c < 3; c++) { lo[c] = Math.min(lo[c], channel(b, c)); hi[c] = Math.max(hi[c], channel(b, c)); }
    }
    const axis = [0, 1, 2].reduce((a, c) => (hi[c] - lo[c] > hi[a] - lo[a] ? c : a), 0);
    return { bins, pixels, axis, range: hi[axis] - lo[axis] };
  };
  const boxes = [describe(used)];
  while (boxes.length < 256) {
    // Split the box with the most pixels times extent, at the weighted median of its longest axis.
    let pick = -1;
    boxes.forEach((box, i) => {
      if (box.range > 0 && (pick < 0 || box.pixels * box.range > boxes[pick].pixels * boxes[pick].range)) pick = i;
    });
    if (pick < 0) break;
    const { bins, pixels, axis } = boxes[pick];
    bins.sort((a, b) => channel(a, axis) - channel(b, axis));
    let seen = 0;
    let cut = 1;
    for (; cut < bins.length - 1; cut++) {
      seen += count[bins[cut - 1]];
      if (seen >= pixels / 2) break;
    }
    boxes.splice(pick, 1, describe(bins.slice(0, cut)), describe(bins.slice(cut)));
  }
  const palette = boxes.map(({ bins, pixels }) => [0, 1, 2].map((c) => Math.round(bins.reduce((t, b) => t + sum[b * 3 + c], 0) / pixels)));
  const nearest = new Uint8Array(32768);
  for (const b of used) {
    const [r, g, bl] = [0, 1, 2].map((c) => sum[b * 3 + c] / count[b]);
    let best = 0; let bestDistance = Infinity;
    palette.forEach(([pr, pg, pb], i) => {
      const distance = (pr - r) ** 2 + (pg - g) ** 2 + (pb - bl) ** 2;
      if (distance < bestDistance) [best, bestDistance] = [i, distance];
    });
    nearest[b] = best;
  }
  const indexed = frames.map(({ width, height, data }) => {
    const indices = new Uint8Array(width * height);
    for (let i = 0; i < indices.length; i++) indices[i] = nearest[bin(data, i * 4)];
    return { width, height, indices };
  });
  return { palette, indexed };
}

const SIGNATURE = Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);
const ihdr = (width, height, colourType = 2) => chunk('IHDR', Buffer.concat([u32(width, height), Buffer.from([8, colourType, 0, 0, 0])]));

/** A still PNG of `image` (RGBA in; RGB out: the book is opaque). */
function encodePng(image) {
  const whole = { x: 0, y: 0, width: image.width, height: image.height };
  return Buffer.concat([SIGNATURE, ihdr(image.width, image.height), chunk('IDAT', deflateRect(image, whole)),
    chunk('IEND', Buffer.alloc(0))]);
}

/** The rectangle where `image` differs from `before` (at least 1 x 1); both RGBA or both indexed. */
function changedRect(before, image) {
  const differs = image.indices
    ? (i) => before.indices[i] !== image.indices[i]
    : (i) => before.data[i * 4] !== image.data[i * 4] || before.data[i * 4 + 1] !== image.data[i * 4 + 1]
      || before.data[i * 4 + 2] !== image.data[i * 4 + 2];
  let [x0, y0, x1, y1] = [image.width, image.height, -1, -1];
  for (let y = 0; y < image.height; y++) {
    for (let x = 0; x < image.width; x++) {
      if (differs(y * image.width + x)) [x0, y0, x1, y1] = [Math.min(x0, x), Math.min(y0, y), Math.max(x1, x), Math.max(y1, y)];
    }
  }
  return x1 < 0 ? { x: 0, y: 0, width: 1, height: 1 } : { x: x0, y: y0, width: x1 - x0 + 1, height: y1 - y0 + 1 };
}

/**
 * An animated PNG of `frames` (RGBA images of one size), each shown `delays[i]` ms, looping forever;
 * with `palette`, the frames share one palette of 256 colours (a third of the bytes of RGB).
 */
function encodeApng(rgbaFrames, delays, { palette = false } = {}) {
  const { width, height } = rgbaFrames[0];
  const quantized = palette ? quantize(rgbaFrames) : null;
  const frames = quantized ? quantized.indexed : rgbaFrames;
  const parts = [SIGNATURE, ihdr(width, height, quantized ? 3 : 2)];
  if (quantized) parts.push(chunk('PLTE', Buffer.from(quantized.palette.flat())));
  parts.push(chunk('acTL', u32(frames.length, 0)));
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
async function openBook(browser, url, size, display = 'double') {
  const page = await browser.newPage({ viewport: size, deviceScaleFactor: 1 });
  page.on('pageerror', (error) => console.error(`readme-media: page error: ${error.message}`));
  await page.route(`${url}readme-media.html*`, (route) => route.fulfill({ contentType: 'text/html', body: PAGE }));
  await page.goto(`${url}readme-media.html?page=${START_PAGE}&display=${display}`);
  await page.waitForFunction(() => document.body.dataset.ready || document.body.dataset.error, null, { timeout: 120_000 });
  const error = await page.evaluate(() => document.body.dataset.error);
  if (error) throw new Error(`readme-media: the book did not open: ${error}`);
  return async (t) => {
    await page.evaluate(async (t) => {
      const { book } = window;
      const frame = () => new Promise((resolve) => requestAnimationFrame(resolve));
      if (!book.previewTurn('forward', t)) throw new Error('previewTurn refused: no next page');
      await book.whenIdle();                  // the posed leaf's pages, loaded if they were not
      const drawn = book.surface.framesDrawn;
      book.previewTurn('forward', t);         // and posed again, with them: drawn at once (BookView.showTurn)
      if (book.surface.framesDrawn === drawn) throw new Error('previewTurn drew no frame');
      await frame();                          // the drawn frame composited before the screenshot
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
    const turn = encodeApng(frames, delays, { palette: true });
    fs.writeFileSync(path.join(outDir, 'turn.png'), turn);
    console.log(`readme-media: ${path.relative(root, path.join(outDir, 'turn.png'))} ${small.width}x${small.height}, ${FRAMES} frames, ${(turn.length / 1024).toFixed(0)} KB`);
    if (process.env.README_MEDIA_FRAME) {  // one middle frame as a still PNG, to look at
      fs.writeFileSync(process.env.README_MEDIA_FRAME, encodePng(frames[Math.floor(FRAMES / 2)]));
    }

    const phone = await openBook(browser, url, PHONE, 'single');
    const phoneFrames = [];
    for (let i = 0; i < FRAMES; i++) phoneFrames.push(await phone(i / (FRAMES - 1)));
    const phoneTurn = encodeApng(phoneFrames, delays, { palette: true });
    fs.writeFileSync(path.join(outDir, 'phone-turn.png'), phoneTurn);
    console.log(`readme-media: ${path.relative(root, path.join(outDir, 'phone-turn.png'))} ${PHONE.width}x${PHONE.height}, ${FRAMES} frames, ${(phoneTurn.length / 1024).toFixed(0)} KB`);
    if (process.env.README_MEDIA_FRAME) {
      fs.writeFileSync(process.env.README_MEDIA_FRAME.replace(/\.png$/, '-phone.png'), encodePng(phoneFrames[Math.floor(FRAMES / 2)]));
    }
  } finally {
    await browser.close();
    server.close();
  }
}

export { encodePng, encodeApng };

if (process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url)) await main();
