// Before and after pictures of a turn, for a change to the renderer: the same forward turn at t = 0.15,
// 0.6 and 0.95 drawn by this tree and by another checkout (a git worktree of an older commit with its
// dist/ built), side by side in one PNG per screen and t (before left, after right), and how many pixels
// differ. Screens: the phone of the phone tests (390x844 at ratio 3, single page) and a desktop spread.
// Usage: node scripts/turn-pictures.mjs --before ../conecurl-before [--out turn-pictures] [--port 8099]
//        [--times 0.15,0.6,0.95] [--screens phone,desktop] [--name turn] (files <name>-<screen>-<t>.png)
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { chromium } from '@playwright/test';
import { chromiumLaunchOptions } from './chromium.mjs';
import { PHONES, phoneUse } from '../tests/browser/phone.js';

const root = path.resolve(path.dirname(new URL(import.meta.url).pathname), '..');
const arg = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i > 0 ? process.argv[i + 1] : fallback;
};
const before = arg('--before', null);
const out = path.resolve(arg('--out', 'turn-pictures'));
const port = Number(arg('--port', '8099'));
if (!before || !fs.existsSync(path.join(before, 'dist/test/conecurl-engine.mjs'))) {
  console.error('turn-pictures: --before must name another checkout with its dist/ built (bash scripts/build-wasm.sh there)');
  process.exit(1);
}
const TIMES = arg('--times', '0.15,0.6,0.95').split(',').map(Number);
const NAME = arg('--name', 'turn');
if (TIMES.some((t) => !(t >= 0 && t <= 1))) {
  console.error('turn-pictures: --times must be numbers from 0 to 1 separated by commas (e.g. 0.15,0.6)');
  process.exit(1);
}
const ALL_SCREENS = {
  phone: { use: phoneUse(PHONES['phone-portrait']), options: { pages: 8, display: 'single', startPage: 2 } },
  desktop: { use: { viewport: { width: 1000, height: 640 }, deviceScaleFactor: 1 }, options: { pages: 8, display: 'double', startPage: 1 } },
};
const SCREENS = Object.fromEntries(arg('--screens', 'phone,desktop').split(',').map((name) => {
  if (!ALL_SCREENS[name]) {
    console.error(`turn-pictures: unknown screen ${name} in --screens (phone, desktop)`);
    process.exit(1);
  }
  return [name, ALL_SCREENS[name]];
}));

function serve(tree, at) {
  return spawn(process.execPath, [path.join(tree, 'scripts/serve.mjs'), '--port', String(at)], { cwd: tree, stdio: 'ignore' });
}

/** PNG bytes of each screen and t, drawn by the tree served at `at`. */
async function pictures(browser, at) {
  const shots = {};
  for (const [screen, { use, options }] of Object.entries(SCREENS)) {
    const page = await (await browser.newContext(use)).newPage();
    await page.goto(`http://127.0.0.1:${at}/tests/browser/fixtures/phone-book-fixture.html`);
    await page.waitForFunction(() => document.body.dataset.ready === 'true');
    await page.evaluate(async (options) => { await window.openBook(options); await window.book.whenIdle(); }, options);
    for (const t of TIMES) {
      await page.evaluate((t) => window.book.previewTurn('forward', t), t);
      shots[`${screen}-${t}`] = await page.locator('#container').screenshot({ scale: 'css' });  // CSS px: small enough to keep
    }
    await page.context().close();
  }
  return shots;
}

fs.mkdirSync(out, { recursive: true });
const servers = [serve(root, port), serve(path.resolve(before), port + 1)];
await new Promise((resolve) => setTimeout(resolve, 800));
const browser = await chromium.launch(chromiumLaunchOptions());
try {
  const after = await pictures(browser, port);
  const old = await pictures(browser, port + 1);
  const page = await browser.newPage();
  for (const key of Object.keys(after)) {
    // Side by side, in a page of this tree: before left, after right, with the count of pixels that differ.
    const { png, differing, total } = await page.evaluate(async ([a, b]) => {
      const load = async (base64) => createImageBitmap(await (await fetch(`data:image/png;base64,${base64}`)).blob());
      const [left, right] = [await load(a), await load(b)];
      const canvas = Object.assign(document.createElement('canvas'), { width: left.width + right.width + 8, height: Math.max(left.height, right.height) });
      const g = canvas.getContext('2d');
      g.fillStyle = '#888';
      g.fillRect(0, 0, canvas.width, canvas.height);
      g.drawImage(left, 0, 0);
      g.drawImage(right, left.width + 8, 0);
      const pixels = (image) => { const c = new OffscreenCanvas(image.width, image.height); const x = c.getContext('2d'); x.drawImage(image, 0, 0); return x.getImageData(0, 0, image.width, image.height).data; };
      const [p, q] = [pixels(left), pixels(right)];
      let count = 0;
      for (let i = 0; i < p.length; i += 4) if (Math.abs(p[i] - q[i]) + Math.abs(p[i + 1] - q[i + 1]) + Math.abs(p[i + 2] - q[i + 2]) > 24) count++;
      return { png: canvas.toDataURL('image/png').split(',')[1], differing: count, total: p.length / 4 };
    }, [old[key].toString('base64'), after[key].toString('base64')]);
    const file = path.join(out, `${NAME}-${key}.png`);
    fs.writeFileSync(file, Buffer.from(png, 'base64'));
    console.log(`${path.relative(root, file)}: before | after; ${differing} of ${total} pixels differ by more than 8 a channel on average`);
  }
} finally {
  await browser.close();
  for (const server of servers) server.kill();
}
