// The cross-engine suite (issue 36): the journeys a reader and a host make, run in Firefox and in WebKit
// (firefox.test.mjs, webkit.test.mjs) with the Chromium suite's assertions wherever the engine allows.
// One browser per engine on an Xvfb display of its own; every page gets tests/engines/heard.js first, so
// what a page throws is heard even where the driver hears no console.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { PNG } from 'pngjs';
import pixelmatch from 'pixelmatch';
import { cropPng, launchEngine, startDisplay, engineExecutables } from '../../scripts/engines.mjs';
import { serveDirectory } from '../../scripts/serve.mjs';
import { shownAtInPage as shownAt } from '../browser/shown-at.js';
import { COARSE_STROKES, FAINTEST_STROKE, fineStrokesInPage } from '../browser/fine-strokes.js';
import { VELOCITY_WINDOW_MS } from '../../web/src/input/pointer-drag.js';
import { documentJourneys } from './documents.mjs';
import { readAloudJourneys, speechEnvironment } from './read-aloud.mjs';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const FLIPBOOK = '/tests/browser/fixtures/flipbook-fixture.html';
const HTML = '/tests/browser/fixtures/html-fixture.html';
const UPDATE = process.env.CONECURL_UPDATE_REFERENCES === '1';

/** Reference images of one engine: tests/engines/references/ENGINE/NAME.png. */
const referencePath = (engine, name) => path.join(root, 'tests/engines/references', engine, `${name}.png`);

/** The part of a screenshot inside `rect` (CSS px at ratio 1), decoded. */
const cropTo = (buffer, rect) => PNG.sync.read(cropPng(buffer, rect));

/**
 * Compares `png` with the engine's reference image NAME (rewritten instead under
 * scripts/update-references.sh). Tolerance as the Chromium suite's: a pixel differs past 0.1, and at most
 * 0.5% of pixels may (software rasterisers are deterministic on one machine; other CPUs antialias a little
 * differently). A failure leaves the actual image and the difference beside the build's logs.
 */
function matchesReference(engine, name, png) {
  const file = referencePath(engine, name);
  if (UPDATE) {
    fs.mkdirSync(path.dirname(file), { recursive: true });
    fs.writeFileSync(file, PNG.sync.write(png));
    return;
  }
  assert.ok(fs.existsSync(file), `no reference image ${path.relative(root, file)}: run scripts/update-references.sh and look at it`);
  const want = PNG.sync.read(fs.readFileSync(file));
  assert.deepEqual([png.width, png.height], [want.width, want.height], `${name}: size differs from the reference`);
  const diff = new PNG({ width: png.width, height: png.height });
  const differ = pixelmatch(png.data, want.data, diff.data, png.width, png.height, { threshold: 0.1 });
  if (differ > 0.005 * png.width * png.height) {
    const out = path.join(root, 'build/test-logs/engines', engine);
    fs.mkdirSync(out, { recursive: true });
    fs.writeFileSync(path.join(out, `${name}-actual.png`), PNG.sync.write(png));
    fs.writeFileSync(path.join(out, `${name}-diff.png`), PNG.sync.write(diff));
    assert.fail(`${name}: ${differ} pixels differ from the reference (${(100 * differ / (png.width * png.height)).toFixed(2)}%); see ${path.relative(root, out)}`);
  }
}

// --- in-page helpers (run inside the page: they see only their arguments and the page) ---

/** Opens window.book in the flipbook fixture with `options` and records its events in window.events. */
async function openBookIn(options) {
  await window.openBook(options);
  window.events = [];
  for (const type of ['turnstart', 'turned', 'turncancel', 'zoom', 'pageerror']) {
    window.book.addEventListener(type, (e) => window.events.push({ type, ...e.detail }));
  }
  // Told when a wait times out: what the book heard and where it stands.
  window.__explain = () => `events ${window.events.map((e) => e.type).join(' ')}; page ${window.book.page}, animating ${window.book.animating}, `
    + `queued ${window.book.surface.queuedTurns}, frames drawn ${window.book.surface.framesDrawn}, focus on ${document.activeElement?.className || document.activeElement?.nodeName}`;
  await window.settle();
  return { page: window.book.page, display: window.book.display };
}

/**
 * Defines ENGINE's suite: a node:test `describe` whose tests share one browser. Test names say what they
 * prove and that they need the engine (`(firefox)`, `(webkit)`).
 */
export function engineSuite(engine) {
  describe(`${engine}`, { concurrency: false }, () => {
    let display, server, base, browser;
    const url = (p) => new URL(p, base).href;
    const evaluate = (fn, ...args) => browser.evaluate(fn, ...args);

    /** Opens PATH and waits until it says it is ready (or why not); returns nothing, asserts no error. */
    async function open(p) {
      await browser.goto(url(p));
      await browser.waitFor(() => document.body && (document.body.dataset.ready || document.body.dataset.error));
      const error = await evaluate(() => document.body.dataset.error || null);
      assert.equal(error, null, `${p} reported an error`);
    }
    /** What the open page (and its same-origin frames) threw, rejected or logged as an error. */
    const heard = () => evaluate(() => [window, ...Array.from(document.querySelectorAll('iframe'), (f) => f.contentWindow)]
      .flatMap((w) => { try { return w.__heard || []; } catch { return []; } }));
    /**
     * A test of ENGINE: FN, then nothing heard in the page it left open. A driver command that never
     * answers fails the test at its time limit (sized, as the Chromium suite's, for a machine several times
     * slower than a quiet 2-core one) instead of holding the whole run.
     */
    const journey = (name, fn, options = {}) => test(`${engine}: ${name} (browser: ${engine})`, { timeout: 300_000, ...options }, async () => {
      await fn();
      assert.deepEqual(await heard(), [], 'the page threw, rejected or logged an error');
    });

    before(async () => {
      const exe = engineExecutables(engine);
      display = await startDisplay(exe.xvfb);
      const heardJs = '<script src="/tests/engines/heard.js"></script>';
      ({ server, url: base } = await serveDirectory(root, { headHtml: heardJs }));
      browser = await launchEngine(engine, { display: display.display, width: 800, height: 600, env: speechEnvironment() });
      console.log(`# ${engine}: ${browser.version} on ${display.display}, serving ${base}`);
    });
    after(async () => {
      await browser?.close();
      server?.close();
      display?.stop();
    });

    journey('the demo\'s book draws its pages (page 3 at rest) and matches the reference images at rest and at t = 0.15, 0.6 and 0.95', async () => {
      await open('/web/demo/?page=2');
      const book = await evaluate(() => {
        const b = window.conecurlDemo.book;
        const box = document.getElementById('book').getBoundingClientRect();
        return { page: b.page, surface: b.surface.kind, box: { x: box.x, y: box.y, width: box.width, height: box.height } };
      });
      assert.equal(book.surface, 'webgl', 'the demo drew with WebGL2');
      assert.equal(book.page, 2);
      // Drawn: the book's canvas holds many colours, not one.
      const colours = await evaluate(() => {
        const s = window.conecurlDemo.book.surface;
        s.drawNow();
        const px = s.readPixels();
        const seen = new Set();
        for (let i = 0; i < px.data.length; i += 4 * 97) seen.add((px.data[i] >> 4) << 8 | (px.data[i + 1] >> 4) << 4 | px.data[i + 2] >> 4);
        return seen.size;
      });
      assert.ok(colours > 20, `the canvas shows ${colours} colours`);
      await evaluate(() => window.conecurlDemo.book.whenIdle());
      matchesReference(engine, 'demo-at-rest', cropTo(await browser.screenshot(), book.box));
      for (const t of [0.15, 0.6, 0.95]) {
        await open(`/web/demo/?page=2&t=${t}`);
        await evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
        matchesReference(engine, `demo-turn-t${t}`, cropTo(await browser.screenshot(), book.box));
      }
    });

    journey('a corner dragged with real pointer input turns the page past the spine; a click and the arrow keys turn too', async () => {
      await open(FLIPBOOK);
      assert.deepEqual(await evaluate(openBookIn, { pages: 10, display: 'double', startPage: 2, duration: 300 }), { page: 1, display: 'double' });
      // Drag the right page's bottom corner over the spine, in steps, and hold it there.
      const from = await evaluate(() => window.halfPoint(0.985, 0.97));
      const to = await evaluate(() => window.halfPoint(0.15, 0.9));
      const path = Array.from({ length: 9 }, (_, i) => ({ x: from.x + ((to.x - from.x) * i) / 8, y: from.y + ((to.y - from.y) * i) / 8 }));
      await browser.drag(path, { release: false });
      const held = await evaluate(() => ({ flying: window.book.surface.book.frame().filter((l) => !l.resting).length, turned: window.events.length }));
      assert.deepEqual(held, { flying: 1, turned: 1 }, 'the pointer holds a leaf (its turnstart heard, nothing landed)');
      await browser.mouse.up();
      await browser.waitFor(() => window.events.some((e) => e.type === 'turned'));
      await evaluate(() => window.settle());
      assert.equal(await evaluate(() => window.book.page), 3, 'let go past the spine, the page turned');
      assert.deepEqual(await evaluate(shownAt, [[0.2, 0.85], [0.8, 0.85]]), [3, 4]);

      // A click on the right page turns forward.
      const right = await evaluate(() => window.halfPoint(0.75, 0.5));
      await browser.click(right.x, right.y);
      await browser.waitFor(() => window.events.filter((e) => e.type === 'turned').length === 2);
      await evaluate(() => window.settle());
      assert.equal(await evaluate(() => window.book.page), 5);

      // The keys, with the book focused: back, then forward.
      await evaluate(() => window.book.element.focus());
      await browser.key('ArrowLeft');
      await browser.waitFor(() => window.events.filter((e) => e.type === 'turned').length === 3);
      await evaluate(() => window.settle());
      assert.equal(await evaluate(() => window.book.page), 3);
      await browser.key('ArrowRight');
      await browser.waitFor(() => window.events.filter((e) => e.type === 'turned').length === 4);
      await evaluate(() => window.settle());
      assert.equal(await evaluate(() => window.book.page), 5);
    });

    journey('a fling: a short quick stroke from the corner, let go well short of the spine, turns the page', async () => {
      await open(FLIPBOOK);
      await evaluate(openBookIn, { pages: 10, display: 'double', startPage: 4, duration: 300 });
      // One action sequence, 16 ms a move by the browser's clock: the speed is the stroke's, not the round trips'.
      const corner = await evaluate(() => window.halfPoint(0.985, 0.9));
      const short = await evaluate(() => window.halfPoint(0.75, 0.9));
      // The page's clock says whether the stroke came as one: a busy machine can deliver the moves far apart
      // (WebKit's driver waits for each), and a stroke that pauses before it lets go is rightly a stop. Such a
      // delivery is made again, at most 3 tries; a fling that came as one must turn the page.
      for (let tries = 1; ; tries++) {
        await evaluate(() => {
          window.strokeListening?.abort();
          window.strokeListening = new AbortController();
          window.strokeTimes = [];
          window.events.length = 0;
          for (const type of ['pointerdown', 'pointermove', 'pointerup']) {
            window.book.surface.canvas.addEventListener(type, (e) => {
              if (type === 'pointerdown' || window.strokeTimes.length > 0) window.strokeTimes.push(e.timeStamp);
            }, { capture: true, signal: window.strokeListening.signal });
          }
        });
        await browser.stroke([corner, { x: corner.x - 6, y: corner.y }, { x: (corner.x + short.x) / 2, y: corner.y }, short], 16);
        await browser.waitFor(() => window.events.some((e) => e.type === 'turned' || e.type === 'turncancel'));
        await evaluate(() => window.settle());
        const { turned, gaps } = await evaluate(() => ({
          turned: window.events.some((e) => e.type === 'turned'),
          gaps: window.strokeTimes.slice(1).map((t, i) => Math.round(t - window.strokeTimes[i])),
        }));
        // Came as a fling: let go within the release's velocity window (VELOCITY_WINDOW_MS) of the last
        // move, and no move further than 120 ms from the one before (WebKit's driver: up to about 107 ms).
        if (turned || (gaps.at(-1) < VELOCITY_WINDOW_MS && Math.max(...gaps) <= 120)) break;
        assert.ok(tries < 3, `the stroke came ${tries} times with its events too far apart for a fling (ms: ${gaps.join(', ')})`);
      }
      assert.deepEqual(await evaluate(() => [window.book.page, window.events.filter((e) => e.type === 'turncancel').length]), [5, 0], 'the fling turned the page');
      assert.deepEqual(await evaluate(shownAt, [[0.2, 0.85], [0.8, 0.85]]), [5, 6]);
    });

    journey('a leaf dragged short of the spine and held still before it is let go falls back (turncancel), and the book turns on after', async () => {
      // A leaf let go falls back in each engine (a released leaf's cone once flew out of its domain: llvmpipe took
      // seconds a frame and WebKitGTK froze; page_drag_test.cpp holds the cause).
      await open(FLIPBOOK);
      await evaluate(openBookIn, { pages: 10, display: 'double', startPage: 2, duration: 300 });
      const corner = await evaluate(() => window.halfPoint(0.985, 0.97));
      const short = await evaluate(() => window.halfPoint(0.75, 0.9));
      const path = Array.from({ length: 9 }, (_, i) => ({ x: corner.x + ((short.x - corner.x) * i) / 8, y: corner.y + ((short.y - corner.y) * i) / 8 }));
      // Held 300 ms by the browser's clock: past the velocity window, so the release is a stop, not a fling.
      await browser.stroke(path, 16, { holdMs: 300 });
      await browser.waitFor(() => window.events.some((e) => e.type === 'turned' || e.type === 'turncancel'));
      await evaluate(() => window.settle());
      assert.deepEqual(await evaluate(() => [window.book.page, window.events.map((e) => e.type)]), [1, ['turnstart', 'turncancel']]);
      assert.deepEqual(await evaluate(shownAt, [[0.2, 0.85], [0.8, 0.85]]), [1, 2]);
      assert.equal(await evaluate(() => window.book.next()), true);
      await evaluate(() => window.settle());
      assert.deepEqual(await evaluate(shownAt, [[0.2, 0.85], [0.8, 0.85]]), [3, 4]);
    });

    journey('hard covers, right-to-left, vertical, single and double display turn and show the right pages', async () => {
      await open(FLIPBOOK);
      const cases = [
        { options: { pages: 8, display: 'double', hardCovers: true }, at: [[0.25, 0.85], [0.75, 0.85]], after: 1, shows: [1, 2] },
        { options: { pages: 8, display: 'double', direction: 'rtl', startPage: 1 }, at: [[0.2, 0.85], [0.8, 0.85]], after: 3, shows: [4, 3] },
        // Points clear of the numbered pages' digits (mid-page) and corner markers (top left).
        { options: { pages: 8, display: 'double', direction: 'vertical', startPage: 1 }, at: [[0.75, 0.1], [0.75, 0.6]], after: 3, shows: [3, 4] },
        { options: { pages: 8, display: 'single', startPage: 2 }, at: [[0.5, 0.85]], after: 3, shows: [3] },
      ];
      for (const { options, at, after: page, shows } of cases) {
        await evaluate(openBookIn, { duration: 300, ...options });
        assert.equal(await evaluate(() => window.book.next()), true, JSON.stringify(options));
        await evaluate(() => window.settle());
        assert.equal(await evaluate(() => window.book.page), page, `page after next() with ${JSON.stringify(options)}`);
        assert.deepEqual(await evaluate(shownAt, at), shows, `shown with ${JSON.stringify(options)}`);
      }
      // A hard cover turns as a board by drag too: the cover of a closed book, dragged from its edge.
      await evaluate(openBookIn, { pages: 8, display: 'double', hardCovers: true, duration: 300 });
      const edge = await evaluate(() => window.halfPoint(0.98, 0.5));
      const left = await evaluate((y) => ({ x: window.book.surface.canvas.getBoundingClientRect().left + 12, y }), edge.y);
      await browser.drag(Array.from({ length: 7 }, (_, i) => ({ x: edge.x + ((left.x - edge.x) * i) / 6, y: edge.y })));
      await browser.waitFor(() => window.events.some((e) => e.type === 'turned'));
      await evaluate(() => window.settle());
      assert.equal(await evaluate(() => window.book.page), 1);
    });

    journey('a double-click zooms in at the pointer, a drag pans, a click does not turn while zoomed, 0 zooms back', async () => {
      await open(FLIPBOOK);
      await evaluate(openBookIn, { pages: 8, display: 'double', startPage: 2, duration: 300 });
      const point = await evaluate(() => window.halfPoint(0.3, 0.6));
      await browser.doubleClick(point.x, point.y);
      await browser.waitFor(() => window.book.zoom === 2);
      await evaluate(() => window.settle());
      assert.equal(await evaluate(() => window.book.page), 1, 'the double-click did not turn');
      const before = await evaluate(() => window.book.restingRect());
      await browser.drag([point, { x: point.x - 20, y: point.y - 10 }, { x: point.x - 40, y: point.y - 20 }, { x: point.x - 60, y: point.y - 30 }]);
      const moved = await evaluate(() => window.book.restingRect());
      assert.ok(Math.abs(moved.x - before.x + 60) < 1.5 && Math.abs(moved.y - before.y + 30) < 1.5,
        `a drag pans by the pointer's move: ${moved.x - before.x}, ${moved.y - before.y}`);
      await evaluate(() => window.settle());
      assert.deepEqual(await evaluate(() => [window.book.page, window.events.filter((e) => e.type === 'turnstart').length]), [1, 0]);
      await evaluate(() => window.book.element.focus());
      await browser.key('0');
      await browser.waitFor(() => window.book.zoom === 1);
    });

    journey('a page image reduced 4-5x keeps its 1-px strokes as an even grey, and one reduced 1.8x keeps every stroke, on both roads: a Blob decoded at the size drawn and a canvas scaled on a canvas (the engine\'s one-sample reductions stepped down by halves; on screen without llvmpipe\'s anisotropic filtering, found by drawing)', async () => {
      await open(FLIPBOOK);
      const { shown } = await evaluate(fineStrokesInPage);
      assert.deepEqual(shown.map((p) => p.page), [1, 2]);
      for (const p of shown) {
        assert.ok(p.min > 150 && p.max < 232 && Math.abs(p.mean - 191) < 25, `page ${p.page}: red ${p.min}-${p.max}, mean ${p.mean} (dropped or striped strokes)`);
      }
      // Reduced 1.8x: every stroke is in the images handed to WebGL, and on screen: both engines draw on
      // llvmpipe, whose anisotropic filtering drops some (a stroke reads 236-237), and the renderer's probe
      // turns it off (anisotropy_probe.cpp), whatever the renderer string says (WebKitGTK's: "Apple GPU").
      const coarse = await evaluate(fineStrokesInPage, COARSE_STROKES);
      assert.equal(coarse.uploads.length, 2);
      for (const faintest of coarse.uploads) assert.ok(faintest <= FAINTEST_STROKE, `an image reduced 1.8x: its faintest stroke reads ${faintest} (dropped)`);
      for (const p of coarse.shown) assert.ok(p.faintest <= FAINTEST_STROKE, `page ${p.page} reduced 1.8x: its faintest stroke on screen reads ${p.faintest} (dropped)`);
      assert.equal(coarse.anisotropy, 1, 'the probe took anisotropic filtering off llvmpipe\'s pages');
    });

    journey('a context lost mid-turn pauses it; restored, every texture is back and the turn lands', async () => {
      await open(FLIPBOOK);
      await evaluate(openBookIn, { pages: 12, display: 'double', duration: 1000, startPage: 1 });
      await evaluate(() => { window.turning = window.book.next(); });
      await browser.waitFor(() => (window.book.surface.book.frame().find((leaf) => !leaf.resting)?.curl.rho ?? 0) > 0.3);
      await evaluate(async () => {
        const canvas = window.book.surface.canvas;
        window.loseExtension = canvas.getContext('webgl2').getExtension('WEBGL_lose_context');
        const lost = new Promise((resolve) => canvas.addEventListener('webglcontextlost', resolve, { once: true }));
        window.loseExtension.loseContext();
        await lost;
      });
      assert.deepEqual(await evaluate(() => [window.book.surface.contextLost, window.book.animating, window.events.filter((e) => e.type === 'turned').length]), [true, true, 0]);
      await evaluate(async () => {
        const canvas = window.book.surface.canvas;
        await new Promise((resolve) => setTimeout(resolve));  // a later task than the loss
        const restored = new Promise((resolve) => canvas.addEventListener('webglcontextrestored', resolve, { once: true }));
        window.loseExtension.restoreContext();
        await restored;
      });
      assert.equal(await evaluate(() => window.turning), true);
      await evaluate(() => window.settle());
      const textures = await evaluate(() => {
        const { surface: view, residentPages: cached } = window.book;
        return { missing: cached.filter((i) => !view.renderer.hasPageImage(i)), page: window.book.page };
      });
      assert.deepEqual(textures, { missing: [], page: 3 });
      assert.deepEqual(await evaluate(shownAt, [[0.2, 0.85], [0.8, 0.85]]), [3, 4]);
    });

    journey('a phone-sized screen (390x844, in an iframe where the window cannot be that narrow) shows one page filling the width and turns, and its turn matches the reference images at t = 0.3 and 0.45', async () => {
      await browser.setViewport(800, 900);
      try {
        await browser.goto(url('/tests/engines/phone-frame.html?src=/web/demo/'));
        await browser.waitFor(() => window.frameReady);
        const phone = await evaluate(() => {
          const w = document.querySelector('iframe').contentWindow;
          const b = w.conecurlDemo.book;
          const box = w.document.getElementById('book').getBoundingClientRect();
          return { innerWidth: w.innerWidth, display: b.display, width: Math.round(box.width), page: b.page };
        });
        assert.deepEqual(phone, { innerWidth: 390, display: 'single', width: phone.width, page: 0 });
        assert.ok(phone.width >= 340, `the book is ${phone.width} px wide on a 390 px screen`);
        await evaluate(() => new Promise((resolve) => {
          const b = document.querySelector('iframe').contentWindow.conecurlDemo.book;
          b.addEventListener('turned', () => resolve(), { once: true });
          b.next();
        }));
        assert.equal(await evaluate(() => document.querySelector('iframe').contentWindow.conecurlDemo.book.page), 1);
        // The single-display turn as this engine draws it (issue 40): paper on the back, a soft shadow,
        // the view leaving the spine room. A paper page of text (page 5; the ones before are boards),
        // posed, then posed again once its pages have loaded.
        await evaluate(() => document.querySelector('iframe').contentWindow.conecurlDemo.book.flip(4, { animate: false }));
        const frame = await evaluate(() => {
          const r = document.querySelector('iframe').getBoundingClientRect();
          return { x: r.x, y: r.y, width: r.width, height: r.height };
        });
        for (const t of [0.3, 0.45]) {
          await evaluate((t) => {
            const w = document.querySelector('iframe').contentWindow;
            const b = w.conecurlDemo.book;
            b.previewTurn('forward', t);
            return b.whenIdle().then(() => new Promise((resolve) => {
              b.previewTurn('forward', t);
              w.requestAnimationFrame(() => w.requestAnimationFrame(resolve));
            }));
          }, t);
          matchesReference(engine, `phone-single-turn-t${t}`, cropTo(await browser.screenshot(), frame));
        }
      } finally {
        await browser.setViewport(800, 600);
      }
    });

    journey('the toolbar\'s Fullscreen enters and leaves fullscreen twice, and each change is heard as the book\'s fullscreenchange', async () => {
      await open(FLIPBOOK);
      await evaluate(openBookIn, { pages: 6, display: 'double', controls: true, duration: 300 });
      await evaluate(() => {
        window.changes = [];
        window.refused = 0;  // requests the browser refused (fullscreenerror), each answered by another click
        window.book.addEventListener('fullscreenchange', (e) => window.changes.push(e.detail.fullscreen));
        document.addEventListener('fullscreenerror', () => { window.refused += 1; });
        window.windowed = [innerWidth, innerHeight];  // the viewport out of fullscreen
      });
      // Where the button is once the layout has settled: out of fullscreen, the viewport back to its size
      // (Firefox tells the change before its window is restored) and the button where it was a frame ago.
      const button = async () => {
        await browser.waitFor(() => document.fullscreenElement !== null || (innerWidth === window.windowed[0] && innerHeight === window.windowed[1]));
        return browser.waitFor(() => new Promise((resolve) => {
          const at = () => {
            const b = Array.from(document.querySelectorAll('[role="toolbar"] button')).find((el) => /fullscreen/i.test(el.getAttribute('aria-label') || el.textContent));
            const r = b.getBoundingClientRect();
            return { x: r.x + r.width / 2, y: r.y + r.height / 2 };
          };
          const before = at();
          requestAnimationFrame(() => requestAnimationFrame(() => {
            const now = at();
            resolve(now.x === before.x && now.y === before.y ? now : false);
          }));
        }));
      };
      for (const round of [1, 2]) {
        // A real click: entering fullscreen needs a user gesture. A request the browser refuses (told by
        // fullscreenerror: one made while the last exit still settles) is made again by another click.
        for (let tries = 0; ; tries++) {
          const refused = await evaluate(() => window.refused);
          const at = await button();
          await browser.click(at.x, at.y);
          const heard = await browser.waitFor((n, r) => (window.changes.length === 2 * n - 1 ? 'entered' : window.refused > r ? 'refused' : false), round, refused);
          if (heard === 'entered') break;
          assert.ok(tries < 3, `fullscreen refused ${tries + 1} times, round ${round}`);
        }
        assert.equal(await evaluate(() => window.book.fullscreen), true, `entered, round ${round}`);
        const again = await button();
        await browser.click(again.x, again.y);
        await browser.waitFor((n) => window.changes.length === 2 * n, round);
        assert.equal(await evaluate(() => [window.book.fullscreen, document.fullscreenElement]).then((v) => v[0]), false, `left, round ${round}`);
      }
      assert.deepEqual(await evaluate(() => window.changes), [true, false, true, false]);
    });

    journey('page errors are heard: an error thrown and a promise rejected in the page reach the suite, where the driver hears no console', async () => {
      await open(FLIPBOOK);
      await evaluate(() => {
        setTimeout(() => { throw new Error('thrown for the test'); });
        Promise.reject(new Error('rejected for the test'));
      });
      const got = await browser.waitFor(() => window.__heard.length >= 2 && window.__heard.slice());
      assert.ok(got.some((line) => /thrown for the test/.test(line)), got.join(' | '));
      assert.ok(got.some((line) => /rejected for the test/.test(line)), got.join(' | '));
      await evaluate(() => { window.__heard.length = 0; });
    });

    // The journeys of the other files, on the same browser: documents (live HTML pages, the PDF viewer, a
    // published site) and read-aloud on the engine's own voices.
    const context = { engine, url, open, evaluate, journey, heard, get browser() { return browser; } };
    documentJourneys(context);
    readAloudJourneys(context);
  });
}
