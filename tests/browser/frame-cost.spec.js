// Browser: what a frame and a page upload cost, as counts that do not flake: calls from JS into the
// wasm engine and WebGL calls per turning frame, and page pixels that never pass through the wasm
// heap. Counted by wrapping WebGL2's methods and the engine's wasm functions before the page loads.
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';

const FIXTURE = '/tests/browser/fixtures/flipbook-fixture.html';

// WebGL calls in one turning frame of a double-page book with shadows: two resting pages and one
// lifted leaf (BookRenderer::draw). Depth test off (1). Shadow pass: framebuffer, viewport, clear,
// blend on, blend equation, program, curl and its trig, draw, blend off (10). The resting spread,
// drawn once into its cache as the turn began, laid down with the shadow on it: framebuffer,
// viewport, depth mask, clear, scissor on, scissor box, program, draw, scissor off (9). The leaf:
// depth test on, program, curl, trig, draw (5): 25 (24 counted: the blend equation stays MAX). Matrices,
// sizes, the eye, the options and bound textures are set only when they change, samplers and constants
// never after linking (97 calls a frame before that; 43, and 45 with the stacks' edges, before the
// resting spread was cached; 31 with a shadow pass of its own over the resting pages). The stacks'
// edges (thickness) rest in the cache: they cost a turning frame nothing.
const MAX_GL_CALLS_PER_TURNING_FRAME = 25;
// In single display the view slides towards the spine while a leaf turns (issue 40), so each frame
// sets the camera again: its matrix in the shadow and leaf programs, the eye, and the cache's offset (4).
const MAX_GL_CALLS_PER_SINGLE_TURNING_FRAME = MAX_GL_CALLS_PER_TURNING_FRAME + 4;

/** Counts every WebGL2 call and every call from JS into a wasm function, on window.__counts. */
function countCalls() {
  const counts = { gl: 0, wasm: 0, glByName: {}, texImageFromBytes: 0, texImageFromImage: 0 };
  window.__counts = counts;
  const proto = WebGL2RenderingContext.prototype;
  for (const name of Object.getOwnPropertyNames(proto)) {
    const descriptor = Object.getOwnPropertyDescriptor(proto, name);
    if (name === 'constructor' || typeof descriptor.value !== 'function') continue;
    const original = descriptor.value;
    proto[name] = function counted(...args) {
      counts.gl++;
      counts.glByName[name] = (counts.glByName[name] || 0) + 1;
      if (name === 'texImage2D') {
        // (target, level, format, width, height, border, format, type, bytes[, offset]): pixels from
        // memory, the wasm heap's for the engine; only the 1x1 paper texel may come that way.
        if (args.some((arg) => ArrayBuffer.isView(arg)) && !(args[3] === 1 && args[4] === 1)) counts.texImageFromBytes++;
        // (target, level, internalformat, format, type, source): straight from a browser image.
        else if (args.length === 6 && args[5] && typeof args[5] === 'object') counts.texImageFromImage++;
      }
      if (name === 'texSubImage2D') {
        // A band of a page (page-textures.js, while leaves move): from a browser image too, never from memory.
        const source = args[args.length - 1];
        if (ArrayBuffer.isView(source)) counts.texImageFromBytes++;
        else if (source && typeof source === 'object') counts.texImageFromImage++;
      }
      return original.apply(this, args);
    };
  }
  // Main-thread image scaling: every drawImage on a 2D canvas that draws its source at another size (the
  // upload's scratch canvas, a check); an unscaled copy (the reduction probe's 2 x 2 read) is no scaling pass.
  counts.drawImage = 0;
  for (const Context of [CanvasRenderingContext2D, globalThis.OffscreenCanvasRenderingContext2D].filter(Boolean)) {
    const drawImage = Context.prototype.drawImage;
    Context.prototype.drawImage = function countedDrawImage(source, ...rest) {
      const [width, height] = rest.length === 8 ? [rest[6], rest[7]] : rest.length === 4 ? [rest[2], rest[3]] : [];
      const natural = [source.naturalWidth || source.videoWidth || source.width, source.naturalHeight || source.videoHeight || source.height];
      if (width !== undefined && (width !== natural[0] || height !== natural[1])) counts.drawImage++;
      return drawImage.call(this, source, ...rest);
    };
  }
  // Every ImageBitmap made, to count those still open (a closed one reads 0 x 0).
  window.__bitmaps = [];
  const createImageBitmap = window.createImageBitmap;
  window.createImageBitmap = (...args) => createImageBitmap.apply(window, args).then((bitmap) => {
    window.__bitmaps.push(bitmap);
    return bitmap;
  });
  const wrap = (fn) => function countedWasm(...args) { counts.wasm++; return fn.apply(this, args); };
  // Embind calls wasm through the function table; the glue calls the exports.
  const wrappedEntries = new WeakMap();
  const tableGet = WebAssembly.Table.prototype.get;
  WebAssembly.Table.prototype.get = function get(index) {
    const entry = tableGet.call(this, index);
    if (typeof entry !== 'function') return entry;
    if (!wrappedEntries.has(entry)) wrappedEntries.set(entry, wrap(entry));
    return wrappedEntries.get(entry);
  };
  const withCountedExports = (result) => {
    const instance = result.instance ?? result;
    const exports = {};
    for (const [key, value] of Object.entries(instance.exports)) exports[key] = typeof value === 'function' ? wrap(value) : value;
    const counted = { exports };
    return result.instance ? { module: result.module, instance: counted } : counted;
  };
  for (const name of ['instantiate', 'instantiateStreaming']) {
    const original = WebAssembly[name];
    WebAssembly[name] = (...args) => original.apply(WebAssembly, args).then(withCountedExports);
  }
}

/**
 * Per-frame deltas of the counters over `frames` animation frames taken in the middle of a turn, of a
 * new book with `options` (null: of the book open now). Only frames after which the leaf is still in
 * flight count: where a slow machine lets a turn land before enough frames were taken, the next turn
 * (back the other way) gives the rest, so the figures never depend on how fast frames come.
 */
async function countTurningFrames(page, options, frames = 6) {
  if (options) await page.evaluate((options) => window.openBook(options), options);
  return page.evaluate(async ({ frames }) => {
    await window.settle();
    const book = window.book;
    const nextFrame = () => new Promise((resolve) => requestAnimationFrame(resolve));
    const sample = () => ({ ...window.__counts, glByName: { ...window.__counts.glByName } });
    const deltas = [];
    // Landed, as the turned event says (book.animating would add a call into the engine to the count).
    let landed = false;
    book.addEventListener('turned', () => { landed = true; });
    for (let turns = 0; deltas.length < frames; turns++) {
      if (turns === 10) throw new Error(`only ${deltas.length} of ${frames} turning frames in ${turns} turns: each landed first`);
      landed = false;
      const turning = turns % 2 === 0 ? book.next() : book.prev();
      for (let i = 0; i < 4; i++) await nextFrame();  // past the turn's first frames (residency, events)
      let previous = sample();
      while (deltas.length < frames) {
        await nextFrame();
        if (landed) break;  // a frame since the last sample landed the leaf: not a turning frame
        const now = sample();
        deltas.push({
          wasm: now.wasm - previous.wasm,
          gl: now.gl - previous.gl,
          glByName: Object.fromEntries(Object.entries(now.glByName)
            .map(([name, n]) => [name, n - (previous.glByName[name] || 0)]).filter(([, n]) => n > 0)),
        });
        previous = now;
      }
      if (!(await turning)) throw new Error('a turn for the count did not land');
    }
    return deltas;
  }, { frames });
}

test.beforeEach(async ({ page }) => { await page.addInitScript(countCalls); });

test('browser: a turning frame costs one call into the wasm engine and a bounded number of WebGL calls (double and single, thickness on and off, counts)', async ({ page }) => {
  await openReady(page, FIXTURE);
  for (const [display, thickness] of [['double', true], ['single', true], ['double', false], ['single', false]]) {
    const frames = await countTurningFrames(page, { pages: 8, display, duration: 3000, loadWindow: 8, startPage: 1, thickness });
    const worst = frames.reduce((a, b) => (b.gl > a.gl ? b : a));
    const name = `${display}, thickness ${thickness}`;
    console.log(`frame cost, ${name}: JS->wasm calls per frame ${frames.map((f) => f.wasm).join(' ')}; `
      + `WebGL calls per frame ${frames.map((f) => f.gl).join(' ')}; worst frame ${JSON.stringify(worst.glByName)}`);
    const most = display === 'single' ? MAX_GL_CALLS_PER_SINGLE_TURNING_FRAME : MAX_GL_CALLS_PER_TURNING_FRAME;
    for (const frame of frames) {
      expect(frame.wasm, `${name}: JS->wasm calls in a turning frame`).toBe(1);
      expect(frame.gl, `${name}: a turning frame drew nothing`).toBeGreaterThan(0);
      expect(frame.gl, `${name}: WebGL calls in a turning frame: ${JSON.stringify(frame.glByName)}`).toBeLessThanOrEqual(most);
      // The stacks rest: they are in the cached resting spread, never drawn in a turning frame. The
      // cache is laid down by one triangle that puts the shadow on it (drawArrays), no blit.
      expect(frame.glByName.drawArrays ?? 0, `${name}: the cached resting spread laid down, and no stack draws`).toBe(1);
      expect(frame.glByName.blitFramebuffer ?? 0, `${name}: blits`).toBe(0);
      // Samplers and constant uniforms are set after linking, never per frame.
      expect(frame.glByName.uniform1i ?? 0).toBe(0);
      expect(frame.glByName.getUniformLocation ?? 0).toBe(0);
    }
  }
});

test('browser: a turn that starts before idle time finished the first view finishes it in its first frames (the mipmaps), and the idle task asked for it then calls nothing in the engine mid-turn (counts)', async ({ page }) => {
  await openReady(page, FIXTURE);
  const result = await page.evaluate(async () => {
    // The page's idle callbacks are held from before the book is made, and run when the test says, mid-turn.
    const held = new Map();
    let ids = 0;
    const { requestIdleCallback, cancelIdleCallback } = window;
    window.requestIdleCallback = (callback) => { held.set(++ids, callback); return ids; };
    window.cancelIdleCallback = (id) => { held.delete(id); };
    const nextFrame = () => new Promise((resolve) => requestAnimationFrame(resolve));
    try {
      await window.openBook({ pages: 8, display: 'double', duration: 3000, loadWindow: 8, startPage: 1 });
      const mipmaps = () => window.__counts.glByName.generateMipmap ?? 0;
      const atRest = mipmaps();  // the first view's pages have none yet: their finish waits on idle time
      const turning = window.book.next();
      for (let i = 0; i < 4; i++) await nextFrame();
      const inTurn = mipmaps() - atRest;
      const before = window.__counts.wasm;
      const callbacks = [...held.values()];
      held.clear();
      for (const callback of callbacks) callback({ didTimeout: false, timeRemaining: () => 50 });
      const idleCalls = window.__counts.wasm - before;
      const stillMoving = window.book.animating;
      return { inTurn, idleCalls, stillMoving, landed: await turning };
    } finally {
      Object.assign(window, { requestIdleCallback, cancelIdleCallback });
    }
  });
  console.log(`first view finished by a turn: ${JSON.stringify(result)}`);
  expect(result.inTurn, 'mipmaps made by the turn\'s first frames').toBeGreaterThan(0);
  expect(result.stillMoving).toBe(true);
  expect(result.idleCalls, 'calls into the engine from the idle tasks run mid-turn').toBe(0);
  expect(result.landed).toBe(true);
});

test('browser: the page sound (opt-in) adds one call into the engine a frame (FrameLoop.motion) once a gesture made its AudioContext, none while muted, and no WebGL call (counts)', async ({ page }) => {
  await openReady(page, FIXTURE);
  const options = { pages: 8, display: 'double', duration: 3000, loadWindow: 8, startPage: 1, sound: true, muted: true };
  const waiting = await countTurningFrames(page, options);
  expect(await page.evaluate(() => window.book.sound.state)).toBe('muted');
  await page.evaluate(() => { window.book.muted = false; });
  const point = await page.evaluate(() => window.halfPoint(0.75, 0.5));
  await page.mouse.click(point.x, point.y);  // the gesture: the sound listens from now on
  expect(await page.evaluate(() => window.book.sound.state)).toBe('running');
  const playing = await countTurningFrames(page, null);
  console.log(`frame cost with sound: JS->wasm calls per frame ${waiting.map((f) => f.wasm).join(' ')} muted, `
    + `${playing.map((f) => f.wasm).join(' ')} after; WebGL calls ${playing.map((f) => f.gl).join(' ')}`);
  for (const frame of waiting) expect(frame.wasm).toBe(1);
  for (const frame of playing) {
    expect(frame.wasm).toBe(2);
    // These turns reach the last page, so the book centres itself as it closes: its camera moves and
    // every frame draws the resting spread (stacks, one page) anew and copies it to be laid down with
    // its shadow: 14 WebGL calls more at most (39 counted).
    expect(frame.gl).toBeLessThanOrEqual(MAX_GL_CALLS_PER_TURNING_FRAME + 14);
  }
});

test('browser: page pixels never pass through the wasm heap: reading a 1000-page book through leaves wasm memory flat, and every page texture comes from a browser image', async ({ page }) => {
  test.setTimeout(180_000);
  await openReady(page, FIXTURE);
  const result = await page.evaluate(async () => {
    const pages = Array.from({ length: 1000 }, (_, i) => `/tests/browser/references/curl-t0-00.png?page=${i}`);
    await window.openBook({ pages, display: 'double', duration: 150, loadWindow: 2 });
    await window.settle();
    const { loadEngine } = await import('/web/src/engine.js');
    const engine = await loadEngine();  // the module the book uses: its heap and its memory
    const memory = Object.values(engine.asm).find((value) => value instanceof WebAssembly.Memory);
    const before = { inUse: engine.heapBytesInUse(), memory: memory.buffer.byteLength, images: window.__counts.texImageFromImage };
    // Through the book in jumps of 20 pages, with a turn at each stop: every stop loads new pages.
    for (let target = 20; target < 1000; target += 20) {
      await window.book.flip(target, { animate: false });
      await window.book.next();
      await window.settle();
    }
    return {
      before,
      after: { inUse: engine.heapBytesInUse(), memory: memory.buffer.byteLength },
      uploads: window.__counts.texImageFromImage - before.images,
      fromBytes: window.__counts.texImageFromBytes,
    };
  });
  console.log(`1000-page book: ${result.uploads} page uploads; wasm bytes in use ${result.before.inUse} -> ${result.after.inUse}; `
    + `wasm memory ${result.before.memory} -> ${result.after.memory}; uploads from byte arrays ${result.fromBytes}`);
  expect(result.uploads).toBeGreaterThan(200);
  expect(result.fromBytes).toBe(0);
  expect(result.after.memory).toBe(result.before.memory);
  expect(result.after.inUse - result.before.inUse).toBeLessThanOrEqual(1024);
});

test('browser: pages that arrive together mid-turn are uploaded one band a frame (texSubImage2D), never several uploads in one turning frame, and all of them by the end', async ({ page }) => {
  await openReady(page, FIXTURE);
  const result = await page.evaluate(async () => {
    // Pages from 3 on wait at a gate, opened mid-turn: several loads land in the same task.
    let open;
    const gate = new Promise((resolve) => { open = resolve; });
    const pages = Array.from({ length: 12 }, (_, i) => async () => {
      if (i >= 3) await gate;
      return window.makeNumberedPage(i);
    });
    await window.openBook({ pages, display: 'double', duration: 3000, loadWindow: 2 });
    const book = window.book;
    const nextFrame = () => new Promise((resolve) => requestAnimationFrame(resolve));
    const turning = book.next();
    await nextFrame();
    await nextFrame();
    open();
    const perFrame = [];
    const drawsPerFrame = [];
    // Uploads of page pixels from images: whole (texImage2D) or a band (texSubImage2D).
    const uploads = () => window.__counts.texImageFromImage;
    let last = uploads();
    let lastDraws = window.__counts.glByName.drawElements;
    // Every frame of the turn from here on (at least 12 on any machine: the engine's clock advances at
    // most 0.25 s a frame), the frame that lands it not counted.
    for (;;) {
      await nextFrame();
      if (!book.animating) break;
      perFrame.push(uploads() - last);
      drawsPerFrame.push(window.__counts.glByName.drawElements - lastDraws);
      last = uploads();
      lastDraws = window.__counts.glByName.drawElements;
    }
    await turning;
    await window.settle();
    return { perFrame, drawsPerFrame, resident: [3, 4].map((p) => book.pageState(p).state) };
  });
  console.log(`${result.perFrame.length} turning frames after the gate opened: uploads per frame ${result.perFrame.join('')}; `
    + `draw calls per frame ${result.drawsPerFrame.join('')}`);
  expect(Math.max(...result.perFrame)).toBe(1);
  // One frame drawn per animation frame: an upload must not start a second chain of frames. A frame
  // draws the leaf's shadow, the shadow on the two resting pages and the leaf (4), and when a resting
  // page arrived, the resting spread again first (2 more); a second frame would add 4.
  expect(Math.max(...result.drawsPerFrame)).toBeLessThanOrEqual(6);
  expect(result.perFrame.reduce((a, b) => a + b, 0)).toBeGreaterThanOrEqual(2);
  expect(result.resident).toEqual(['loaded', 'loaded']);
});

test('browser: large encoded pages are decoded at the size they are drawn, off the main thread: no scaling pass on a canvas, textures at the decoded size, sharper when zoomed in', async ({ page }) => {
  await openReady(page, FIXTURE);
  const result = await page.evaluate(async () => {
    // Six 2000 x 2500 PNG pages (Blobs): far more pixels than a 640 x 400 book shows.
    const big = document.createElement('canvas');
    Object.assign(big, { width: 2000, height: 2500 });
    const g = big.getContext('2d');
    g.fillStyle = '#3a6'; g.fillRect(0, 0, 2000, 2500);
    g.fillStyle = '#a33'; g.fillRect(0, 0, 1000, 1250);
    const blob = await new Promise((resolve) => big.toBlob(resolve, 'image/png'));
    const drawsBefore = window.__counts.drawImage;
    await window.openBook({ pages: Array.from({ length: 6 }, () => blob), display: 'double', startPage: 1, loadWindow: 2 });
    await window.settle();
    const book = window.book;
    const sizes = book.residentPages.map((i) => book.surface.pageImageSize(i));
    const draws = window.__counts.drawImage - drawsBefore;
    // Zoomed in, the open pages are decoded again from their source, larger.
    const sharpened = [];
    const bothSharp = new Promise((resolve) => book.addEventListener('sharpened', (e) => {
      if (sharpened.push(e.detail) === 2) resolve();
    }));
    book.zoom = 4;
    await bothSharp;  // the open pages, decoded again once the zoom rests (the test's timeout bounds it)
    return { sizes, draws, resident: book.residentPages.length, zoomedWidth: book.surface.pageImageSize(1).width, sharpened };
  });
  console.log(`large pages: textures ${JSON.stringify(result.sizes[0])} for 2000x2500 sources; canvas draws ${result.draws}; `
    + `zoomed: ${result.zoomedWidth} px wide (${result.sharpened.length} sharpened)`);
  expect(result.resident).toBeGreaterThan(2);
  expect(result.draws).toBe(0);
  for (const size of result.sizes) {
    expect(size.width).toBeLessThan(1000);
    expect(size.height / size.width).toBeCloseTo(1.25, 2);
  }
  expect(result.zoomedWidth).toBeGreaterThan(2 * result.sizes[0].width);
  expect(result.sharpened.map((s) => s.index).sort()).toEqual([1, 2]);
});

test('browser: decoded pages are not held twice: the ImageBitmaps decoded for textures are closed once uploaded, and after a lost context the pages are decoded again (counts, pixels)', async ({ page }) => {
  await openReady(page, FIXTURE);
  const before = await page.evaluate(async () => {
    // Eight PNG pages (Blobs), page i filled with its own grey 20 + 25 i.
    const canvas = Object.assign(document.createElement('canvas'), { width: 200, height: 250 });
    const g = canvas.getContext('2d');
    const pages = [];
    for (let i = 0; i < 8; i++) {
      g.fillStyle = `rgb(${20 + 25 * i}, ${20 + 25 * i}, ${20 + 25 * i})`;
      g.fillRect(0, 0, 200, 250);
      pages.push(await new Promise((resolve) => canvas.toBlob(resolve, 'image/png')));
    }
    await window.openBook({ pages, display: 'double', startPage: 3, loadWindow: 2, lighting: false, shadows: false, gutter: false });
    await window.settle();
    const book = window.book;
    window.openBitmaps = () => window.__bitmaps.filter((bitmap) => bitmap.width > 0).length;
    // The grey at the middle of each open page, as page numbers.
    window.shownGreys = () => {
      book.surface.drawNow();
      const pixels = book.surface.readPixels();
      return book.openPagePlaces().map((place) => {
        const x = Math.round(place.x + place.width / 2);
        const y = Math.round(place.y + place.height / 2);  // readPixels rows run top to bottom
        return (pixels.data[(y * pixels.width + x) * 4] - 20) / 25;
      });
    };
    const before = { decoded: window.__bitmaps.length, open: window.openBitmaps(), resident: book.residentPages.length, shown: window.shownGreys() };
    const gl = book.surface.canvas.getContext('webgl2');
    const lose = gl.getExtension('WEBGL_lose_context');
    const event = (name) => new Promise((resolve) => book.surface.canvas.addEventListener(name, resolve, { once: true }));
    const lost = event('webglcontextlost');
    lose.loseContext();
    await lost;
    // Chrome ignores a restore asked for in the task that dispatched webglcontextlost: one task later
    // it takes it, on any machine.
    await new Promise((resolve) => setTimeout(resolve));
    const restored = event('webglcontextrestored');
    lose.restoreContext();
    await restored;
    return before;
  });
  // The restored context has a texture for every resident page again: each decoded anew and uploaded.
  await page.waitForFunction((resident) => window.book.surface.renderer.residentPageImages() === resident, before.resident);
  const after = await page.evaluate(async () => {
    await window.book.whenIdle();
    return { decoded: window.__bitmaps.length, open: window.openBitmaps(), textures: window.book.surface.renderer.residentPageImages(), shown: window.shownGreys() };
  });
  const result = { before, after };
  console.log(`decoded pages: ${JSON.stringify(result)}`);
  expect(result.before.resident).toBeGreaterThanOrEqual(6);
  expect(result.before.decoded).toBeGreaterThanOrEqual(result.before.resident);
  expect(result.before.open).toBe(0);
  expect(result.before.shown.map(Math.round)).toEqual([3, 4]);
  // Restored: every resident page decoded again, closed again, and the open pages drawn from them.
  expect(result.after.decoded).toBeGreaterThanOrEqual(result.before.decoded + result.before.resident);
  expect(result.after.open).toBe(0);
  expect(result.after.textures).toBe(result.before.resident);
  expect(result.after.shown.map(Math.round)).toEqual([3, 4]);
});

test('browser: a page texture set while the book rests draws a frame only if that page is on screen (the neighbours loading around the spread cost none; counts)', async ({ page }) => {
  await openReady(page, FIXTURE);
  const frames = await page.evaluate(async () => {
    await window.openBook({ pages: 12, display: 'double', startPage: 3 });
    await window.settle();
    const view = window.book.surface;
    const image = Object.assign(document.createElement('canvas'), { width: 40, height: 50 });
    const twoFrames = () => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve)));
    const drawnAfter = async (change) => {
      const before = view.framesDrawn;
      change();
      await twoFrames();
      return view.framesDrawn - before;
    };
    // Until no frame is drawn for four in a row: the frames the last arrivals asked for are done.
    for (let quiet = 0; quiet < 4;) {
      const before = view.framesDrawn;
      await new Promise((resolve) => requestAnimationFrame(resolve));
      quiet = view.framesDrawn === before ? quiet + 1 : 0;
    }
    return {
      onScreen: view.pagesOnScreen(),
      nothing: await drawnAfter(() => {}),
      offScreenSet: await drawnAfter(() => view.setPageImage(9, image)),
      offScreenReleased: await drawnAfter(() => view.releasePageImage(9)),
      onScreenSet: await drawnAfter(() => view.setPageImage(3, image)),
    };
  });
  expect(frames.onScreen).toEqual([3, 4]);
  expect(frames.nothing).toBe(0);
  expect(frames.offScreenSet).toBe(0);
  expect(frames.offScreenReleased).toBe(0);
  expect(frames.onScreenSet).toBe(1);
});

// The renderer's draws and program switches in one drawNow() of the book fixture, and how many times
// it drew the resting spread into its cache (BookRenderer.restingSpreadDraws).
async function drawCounts(page, change = '') {
  return page.evaluate((change) => {
    const { view } = window.fixture;
    // eslint-disable-next-line no-new-func
    new Function('view', change)(view);
    const before = { ...window.__counts.glByName };
    const spread = view.renderer.restingSpreadDraws();
    view.drawNow();
    const delta = (name) => (window.__counts.glByName[name] || 0) - (before[name] || 0);
    return {
      draws: delta('drawElements') + delta('drawArrays'),
      blits: delta('blitFramebuffer'),
      programs: delta('useProgram'),
      spreadDrawn: view.renderer.restingSpreadDraws() - spread,
    };
  }, change);
}

test('browser: while a leaf moves the resting spread is drawn once and laid down after: draws and programs per turning frame are few and the same for 8 and 200 pages, thin or thick; it is drawn again once after a page image arrives, options, a resize, a zoom, a leaf that lifts or lands (counts)', async ({ page }) => {
  const perFrame = {};
  for (const [pages, thickness] of [[8, 'off'], [200, '0.012']]) {
    // The fixture's canvas is multisampled (BookView's antialias defaults to true): the cache is laid
    // down by one draw, not a blit. position 40 of 200 pages: thick stacks on both sides.
    await openReady(page, `/tests/browser/fixtures/book-fixture.html?pages=${pages}&position=${pages === 8 ? 1 : 40}&thickness=${thickness}&turn=forward&t=0.3`);
    const first = await drawCounts(page, "view.showTurn('forward', 0.35)");
    const frames = [];
    for (const t of [0.4, 0.5, 0.6, 0.7]) frames.push(await drawCounts(page, `view.showTurn('forward', ${t})`));
    perFrame[`${pages} pages, thickness ${thickness}`] = frames;
    expect(first.spreadDrawn, 'the fixture drew the spread already: the same turn composes it').toBe(0);
    for (const frame of frames) {
      expect(frame.spreadDrawn).toBe(0);
      // The shadow mask of the leaf (1), the cache laid down with the shadow on it (1), the leaf (1);
      // programs: shadow mask, the cache laid down, leaf.
      expect(frame.draws).toBe(3);
      expect(frame.blits).toBe(0);
      expect(frame.programs).toBe(3);
    }
  }
  console.log(`draws per turning frame: ${JSON.stringify(perFrame)}`);
  expect(perFrame['200 pages, thickness 0.012']).toEqual(perFrame['8 pages, thickness off']);

  // What rests changes: the next frame draws the spread again, once; the frames after lay the cache
  // down again. A change of the camera (resize, zoom) is kept once the camera held still a frame
  // (while it moves, as a closed book centres itself, each frame draws the spread without keeping it). Pages are uploaded straight through the renderer (BookView would wait for a frame).
  // At position 40 of 200 pages, a leaf turning forward, pages 79 and 82 rest; 120 is far off.
  const upload = (index) => `const image = Object.assign(document.createElement('canvas'), { width: 40, height: 50 });
    view.renderer.setPageImage(${index}, image, 40, 50);`;
  const steps = {
    'a resting page arrives': upload(79),
    'the other resting page arrives': upload(82),
    'lighting off': 'view.setOptions({ lighting: false })',
    'gutter off': 'view.setOptions({ gutter: false })',
    'a resize': "view.canvas.style.width = '600px'",
    'a zoom': 'view.zoomAbout(1.5, 300, 200)',
    'a second leaf lifts': "view.book.startTurn('forward'); view.book.setLatestTurnProgress(0.05)",
    // The fixture's turns last 1 s (the engine's default): the first leaf, at 0.7, lands; the second,
    // at 0.05, is still in flight.
    'the first leaf lands': 'view.book.advance(0.4)',
  };
  const redrawn = {};
  for (const [name, change] of Object.entries(steps)) {
    const changed = await drawCounts(page, change);
    const after = await drawCounts(page);
    const later = await drawCounts(page);
    redrawn[name] = [changed.spreadDrawn, after.spreadDrawn, later.spreadDrawn];
  }
  // Nothing that rests changes: an off-screen page arrives, the moving leaf moves.
  const unchanged = [
    await drawCounts(page, upload(120)),
    await drawCounts(page, 'view.book.advance(0.01)'),
  ].map((frame) => frame.spreadDrawn);
  console.log(`resting spread drawn (the frame of the change, the next two): ${JSON.stringify(redrawn)}; unchanged ${unchanged}`);
  for (const [name, [changed, after, later]] of Object.entries(redrawn)) {
    expect(changed, name).toBe(1);
    expect(after, name).toBeLessThanOrEqual(name === 'a resize' || name === 'a zoom' ? 1 : 0);
    expect(later, name).toBe(0);
  }
  expect(unchanged).toEqual([0, 0]);
});

test('browser: every turning frame lays the cached resting spread down: the resting left page shows in each of the first frames of a turn, shadows on and off, on a canvas that takes the blit (pixels)', async ({ page }) => {
  await openReady(page, FIXTURE);
  for (const shadows of [true, false]) {
    const result = await page.evaluate(async (shadows) => {
      await window.openBook({ pages: 8, display: 'double', duration: 3000, loadWindow: 8, startPage: 1, shadows });
      await window.settle();
      const book = window.book;
      const place = book.openPagePlaces()[0];  // the left page: it rests while the right leaf turns
      const x = Math.round(place.x + place.width / 2);
      const y = Math.round(place.y + place.height * 0.8);  // below the page's number: its own colour
      const pixel = () => {
        const { data, width } = book.surface.readPixels();
        return [...data.subarray((y * width + x) * 4, (y * width + x) * 4 + 4)];
      };
      book.surface.drawNow();
      const resting = pixel();
      // Read in the task that drew each frame (the view's onMotion runs right after the frame's step; the
      // page sound, its only other user, is off): once a frame is presented, the canvas reads clear. (A
      // callback of the test's own next to the book's read a presented frame whenever the turn's first
      // frame was asked for after it.) The engine's clock advances at most 0.25 s a frame: four frames of
      // a 3 s turn keep the leaf and its shadow (cast right and down) off the left page.
      const frames = [];
      const view = book.surface;
      let drawn = view.framesDrawn;
      const four = new Promise((resolve) => {
        view.onMotion = () => {
          if (view.framesDrawn === drawn) return;
          drawn = view.framesDrawn;
          frames.push(pixel());
          if (frames.length < 4) return;
          view.onMotion = null;
          resolve();
        };
      });
      const turning = book.next();
      await four;
      await turning;
      return { resting, frames };
    }, shadows);
    console.log(`shadows ${shadows}: left page ${result.resting} at rest, ${JSON.stringify(result.frames)} in the first turning frames`);
    expect(result.resting[3]).toBe(255);
    for (const frame of result.frames) expect(frame).toEqual(result.resting);
  }
});

test('browser: the cached resting spread is laid down over its own rectangle only, and the frame it makes is the frame that drew the spread, pixel for pixel: double and single, thick stacks with tabs and ticks, zoomed, whole and at half scale', async ({ page }) => {
  await openReady(page, FIXTURE);
  for (const display of ['double', 'single']) {
    const result = await page.evaluate(async (display) => {
      await window.openBook({ pages: 60, display, startPage: 20, thickness: 0.012 });
      await window.settle();
      const view = window.book.surface;
      const marks = [{ page: 3, kind: 'tab' }, { page: 45, kind: 'tab' }, { page: 12, kind: 'tick' }, { page: 50, kind: 'tick' }];
      const compared = [];
      for (const [zoom, scale] of [[1, 1], [1, 0.5], [1.6, 1]]) {
        if (zoom !== 1) view.zoomAbout(zoom, 200, 150);
        view.renderer.setOptions({ movingScale: scale });
        view.showTurn('forward', 0.3);  // the camera holds still from here: the spread is kept at its next drawing
        view.setEdgeMarks(marks);  // marks (again): the next frame draws the spread
        const spread = view.renderer.restingSpreadDraws();
        view.showTurn('forward', 0.3);
        const drawn = view.readPixels();
        view.showTurn('forward', 0.3);
        const laid = view.readPixels();
        let differing = 0;
        let covered = 0;
        for (let i = 0; i < drawn.data.length; i += 4) {
          covered += drawn.data[i + 3] > 0 ? 1 : 0;
          for (let c = 0; c < 4; c++) {
            if (drawn.data[i + c] !== laid.data[i + c]) { differing++; break; }
          }
        }
        compared.push({ zoom, scale, spreadDraws: view.renderer.restingSpreadDraws() - spread, differing, covered });
      }
      return compared;
    }, display);
    console.log(`${display}: ${JSON.stringify(result)}`);
    for (const { zoom, scale, spreadDraws, differing, covered } of result) {
      const name = `${display}, zoom ${zoom}, scale ${scale}`;
      expect(spreadDraws, `${name}: the first frame drew the spread, the second laid the cache down`).toBe(1);
      expect(covered, name).toBeGreaterThan(10000);
      expect(differing, name).toBe(0);
    }
  }
});

test('browser: on a multisampled canvas (BookView\'s default) the cache is laid down whole with the shadow on it: the frame that drew the spread and the two after it are the same picture, resting pages included (pixels)', async ({ page }) => {
  await openReady(page, '/tests/browser/fixtures/book-fixture.html?pages=8&position=1&turn=forward&t=0.3');
  const result = await page.evaluate(() => {
    const { view } = window.fixture;
    const frames = [];
    view.setEdgeMarks([]);  // the next frame draws the spread again
    for (let i = 0; i < 3; i++) {
      view.drawNow();
      frames.push(view.readPixels());
    }
    const [first] = frames;
    const covered = (image) => { let n = 0; for (let i = 3; i < image.data.length; i += 4) n += image.data[i] > 0 ? 1 : 0; return n; };
    const differing = frames.slice(1).map((image) => image.data.filter((value, i) => value !== first.data[i]).length);
    const left = view.openPagePlaces()[0];
    const x = Math.round(left.x + left.width * 0.3);
    const y = Math.round(first.height - (left.y + left.height * 0.8));
    return { samples: view.renderer ? 'ok' : 'none', covered: covered(first), all: first.width * first.height, differing,
      leftPage: [...first.data.subarray((y * first.width + x) * 4, (y * first.width + x) * 4 + 4)] };
  });
  console.log(`multisampled: ${JSON.stringify(result)}`);
  expect(result.covered / result.all).toBeGreaterThan(0.3);  // both resting pages, not the leaf alone
  expect(result.leftPage[3]).toBe(255);
  expect(result.differing).toEqual([0, 0]);
});

test('browser: a book\'s first view links only the two programs it draws, idle time then links the turning ones, and no turn links any (counts of linkProgram)', async ({ page }) => {
  await openReady(page, FIXTURE);
  const counts = await page.evaluate(async () => {
    const linked = () => window.__counts.glByName.linkProgram ?? 0;
    const links = [];
    // Shadows on, then off: idle time links the leaf, its shadow and the shadow received (3), or the leaf alone.
    for (const shadows of [true, false]) {
      const before = linked();
      // The page's idle callbacks are held while the book is made: what create() linked is the first view's alone.
      const held = [];
      const idleCallback = window.requestIdleCallback;
      window.requestIdleCallback = (callback, options) => held.push([callback, options]);
      window.book?.destroy();
      const pages = Array.from({ length: 8 }, (_, i) => window.makeNumberedPage(i));
      window.book = await window.Flipbook.create(document.getElementById('container'), { pages, display: 'double', duration: 150, startPage: 1, shadows });
      const firstView = linked() - before;  // create() resolved with the first view drawn
      window.requestIdleCallback = idleCallback;
      await window.book.whenIdle();  // the neighbours, asked for after the first frame
      await window.settle();
      for (const [callback, options] of held.splice(0)) idleCallback(callback, options);
      // At rest, with no frame coming, the book's idle callback (asked for once its first frame is shown) links them.
      const expected = shadows ? 3 : 1;
      for (let i = 0; i < 10 && linked() - before - firstView < expected; i++) await new Promise((resolve) => idleCallback(resolve));
      const idle = linked() - before - firstView;
      if (!(await window.book.next()) || !(await window.book.next()) || !(await window.book.prev())) throw new Error('a turn did not land');
      links.push({ shadows, firstView, idle, turns: linked() - before - firstView - idle });
    }
    return links;
  });
  console.log(`programs linked: ${JSON.stringify(counts)}`);
  // The stacks and the flat pages (BookRenderer's constructor); then the leaf, and with shadows its
  // shadow and the shadow on the resting pages (BookRenderer::prepareTurn; the canvas is not multisampled here: no composite).
  expect(counts).toEqual([
    { shadows: true, firstView: 2, idle: 3, turns: 0 },
    { shadows: false, firstView: 2, idle: 1, turns: 0 },
  ]);
});

test('browser: where the driver compiles beside the page (KHR_parallel_shader_compile, stood in for here), idle time asks for a turn\'s programs in one task, asks only whether they are done until the driver says so, and checks them after: no idle task waits on a compile (counts of compileShader, linkProgram and status queries by idle task)', async ({ page }) => {
  await openReady(page, FIXTURE);
  const result = await page.evaluate(async () => {
    const c = window.__counts.glByName;
    // The extension, answered by the test: its driver says a program is done only once window.__driverDone.
    const COMPLETION_STATUS_KHR = 0x91B1;
    const proto = WebGL2RenderingContext.prototype;
    const { getExtension, getProgramParameter } = proto;
    let completionAsks = 0;
    window.__driverDone = false;
    proto.getExtension = function fakeParallel(name) {
      return name === 'KHR_parallel_shader_compile' ? { COMPLETION_STATUS_KHR } : getExtension.call(this, name);
    };
    proto.getProgramParameter = function fakeCompletion(program, pname) {
      if (pname !== COMPLETION_STATUS_KHR) return getProgramParameter.call(this, program, pname);  // counted as before
      completionAsks++;
      return window.__driverDone;
    };
    const snap = () => ({ compile: c.compileShader ?? 0, link: c.linkProgram ?? 0, shaderQueries: c.getShaderParameter ?? 0, programQueries: c.getProgramParameter ?? 0, completionAsks });
    const idleCallback = window.requestIdleCallback;
    const tasks = [];  // what each idle callback of the page asked of WebGL, in order
    window.requestIdleCallback = (callback, options) => idleCallback((deadline) => {
      const before = snap();
      try { callback(deadline); } finally {
        const after = snap();
        const asked = Object.fromEntries(Object.keys(after).map((k) => [k, after[k] - before[k]]));
        if (Object.values(asked).some((n) => n > 0)) tasks.push(asked);
      }
    }, options);
    const idleRounds = async (n, until = () => false) => {
      for (let i = 0; i < n && !until(); i++) await new Promise((resolve) => idleCallback(resolve));
    };
    try {
      window.book?.destroy();
      const pages = Array.from({ length: 8 }, (_, i) => window.makeNumberedPage(i));
      const linkedBefore = snap().link;
      window.book = await window.Flipbook.create(document.getElementById('container'), { pages, display: 'double', duration: 150, startPage: 1, shadows: true });
      const firstView = snap().link - linkedBefore;
      await window.book.whenIdle();
      await window.settle();
      await idleRounds(40, () => tasks.some((t) => t.compile > 0));
      await idleRounds(3);  // the driver not done: the book only asks
      const whileCompiling = tasks.splice(0);
      window.__driverDone = true;
      await idleRounds(40, () => tasks.some((t) => t.programQueries > 0));
      const afterDone = tasks.splice(0);
      const linked = snap().link;
      const landed = (await window.book.next()) && (await window.book.prev());
      return { firstView, whileCompiling, afterDone, turnLinks: snap().link - linked, landed };
    } finally {
      window.requestIdleCallback = idleCallback;
      Object.assign(proto, { getExtension, getProgramParameter });
    }
  });
  console.log(`idle tasks' GL asks while the driver compiles: ${JSON.stringify(result.whileCompiling)}; once it is done: ${JSON.stringify(result.afterDone)}`);
  expect(result.firstView).toBe(2);
  // The leaf, its shadow and the shadow received: both stages of each asked for, nothing checked.
  expect(result.whileCompiling[0]).toEqual({ compile: 6, link: 3, shaderQueries: 0, programQueries: 0, completionAsks: 0 });
  const polls = result.whileCompiling.slice(1);
  expect(polls.length).toBeGreaterThanOrEqual(1);
  for (const poll of polls) {
    expect(poll).toMatchObject({ compile: 0, link: 0, shaderQueries: 0, programQueries: 0 });
    expect(poll.completionAsks).toBe(1);  // it stops at the first program not done
  }
  // Once done: one ask a program, then each one's link status (and its uniforms), no stage's status.
  const checking = result.afterDone.find((t) => t.programQueries > 0);
  expect(checking).toMatchObject({ compile: 0, link: 0, shaderQueries: 0, completionAsks: 3 });
  expect(checking.programQueries).toBeGreaterThanOrEqual(3);
  expect(result.landed).toBe(true);
  expect(result.turnLinks).toBe(0);
});
