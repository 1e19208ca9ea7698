// Browser: what a book's first view asks for before its WebGL context, as counts and orders of calls, never
// times (docs/benchmark.md "Where the first page's time goes"): the opening pages are fetched and decoded
// while the context is made, each once; and a book needs one context where its GPU allows it.
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';

const FIXTURE = '/tests/browser/fixtures/flipbook-fixture.html';

/** Logs, in order, page-image fetches and 'webgl2' contexts made (a context not handed out before), and counts decodes. */
function logFirstView() {
  const log = [];
  window.__log = log;
  window.__contexts = [];
  const fetch = window.fetch;
  window.fetch = function loggedFetch(input, ...rest) {
    const url = String(input?.url ?? input);
    if (url.includes('?page=')) log.push(`fetch ${new URL(url).searchParams.get('page')}`);
    return fetch.call(this, input, ...rest);
  };
  const getContext = HTMLCanvasElement.prototype.getContext;
  HTMLCanvasElement.prototype.getContext = function loggedGetContext(type, ...rest) {
    const context = getContext.call(this, type, ...rest);
    if (type === 'webgl2' && context && !window.__contexts.includes(context)) {
      window.__contexts.push(context);
      log.push(`context (${window.__contexts.filter((gl) => gl.isContextLost()).length} lost before)`);
    }
    return context;
  };
  window.__decodes = 0;
  const createImageBitmap = window.createImageBitmap;
  window.createImageBitmap = (source, ...rest) => {
    if (source instanceof Blob) window.__decodes++;
    return createImageBitmap.call(window, source, ...rest);
  };
}

/** As on a GPU: the renderer string WebGL reports names one (the rasterizer is still SwiftShader). */
function reportGpu() {
  const UNMASKED_RENDERER_WEBGL = 0x9246;
  const getParameter = WebGL2RenderingContext.prototype.getParameter;
  WebGL2RenderingContext.prototype.getParameter = function gpuRenderer(name) {
    return name === UNMASKED_RENDERER_WEBGL ? 'ANGLE (NVIDIA, NVIDIA GeForce RTX 3060, D3D11)' : getParameter.call(this, name);
  };
}

test('browser: a book asks for the open spread before it makes its WebGL context and for its neighbours once the spread has landed, and fetches and decodes each once (order and counts of calls)', async ({ page }) => {
  await page.addInitScript(logFirstView);
  await openReady(page, FIXTURE);
  const result = await page.evaluate(async () => {
    const pages = Array.from({ length: 12 }, (_, i) => `/tests/browser/references/curl-t0-00.png?page=${i}`);
    await window.openBook({ pages, display: 'double', startPage: 4 });
    const log = window.__log;
    const firstContext = log.findIndex((entry) => entry.startsWith('context'));
    const fetched = log.filter((entry) => entry.startsWith('fetch')).map((entry) => Number(entry.split(' ')[1]));
    return {
      open: window.book.openPages,
      resident: window.book.residentPages,
      fetchedBefore: log.slice(0, firstContext).map((entry) => Number(entry.split(' ')[1])).sort((a, b) => a - b),
      firstFetched: fetched.slice(0, 2).sort((a, b) => a - b),
      fetches: log.filter((entry) => entry.startsWith('fetch')).length,
      decodes: window.__decodes,
    };
  });
  console.log(`first view: open ${result.open}, resident ${result.resident}, fetched before the context ${result.fetchedBefore}, `
    + `${result.fetches} fetches, ${result.decodes} decodes`);
  expect(result.open).toEqual([3, 4]);
  expect(result.resident.length).toBeGreaterThan(2);
  expect(result.fetchedBefore).toEqual(result.open);  // the open spread asked for first, before the context
  expect(result.firstFetched).toEqual(result.open);   // and nothing else before it: its neighbours wait for it
  expect(result.fetches).toBe(result.resident.length);    // each once: nothing fetched again once the surface is made
  expect(result.decodes).toBe(result.resident.length);    // and decoded once, at the size the surface draws it
});

// In the page: the fixture's book, then a second book beside it; the WebGL contexts made after the first.
async function openTwoBooks() {
  await window.openBook({ pages: 4, display: 'double' });
  const first = window.__contexts.length;
  const other = document.createElement('div');
  other.style.cssText = 'width: 640px; height: 400px';
  document.body.append(other);
  const second = await window.Flipbook.create(other, { pages: [window.makeNumberedPage(0), window.makeNumberedPage(1)] });
  return { first, books: [window.book, second] };
}

test('browser: on a GPU, antialias \'auto\' makes one WebGL context per book, on its own canvas, multisampled (counts of contexts made)', async ({ page }) => {
  await page.addInitScript(reportGpu);
  await page.addInitScript(logFirstView);
  await openReady(page, FIXTURE);
  const result = await page.evaluate(async (openTwo) => {
    const { first, books } = await new Function(`return (${openTwo})`)()();  // eslint-disable-line no-new-func
    const drawnOn = (book) => book.element.querySelector('canvas').getContext('webgl2').getContextAttributes().antialias;
    return { first, both: window.__contexts.length, antialias: books.map(drawnOn) };
  }, openTwoBooks.toString());
  expect(result.first).toBe(1);  // the probe's context is the renderer's
  expect(result.both).toBe(2);
  expect(result.antialias).toEqual([true, true]);
});

test('browser: in software, antialias \'auto\' leaves the book\'s canvas without multisampling: the first book of a page makes two contexts (the probe\'s, lost before the renderer\'s is made), later books one (counts)', async ({ page }) => {
  await page.addInitScript(logFirstView);
  await openReady(page, FIXTURE);
  const result = await page.evaluate(async (openTwo) => {
    const { first, books: [one, two] } = await new Function(`return (${openTwo})`)()();  // eslint-disable-line no-new-func
    const drawnOn = (book) => book.element.querySelector('canvas').getContext('webgl2');
    return {
      first,
      both: window.__contexts.length,
      antialias: [drawnOn(one), drawnOn(two)].map((gl) => gl.getContextAttributes().antialias),
      sameContexts: drawnOn(one) === window.__contexts[1] && drawnOn(two) === window.__contexts[2],
      contexts: window.__log.filter((entry) => entry.startsWith('context')),
    };
  }, openTwoBooks.toString());
  expect(result.first).toBe(2);
  expect(result.both).toBe(3);
  expect(result.antialias).toEqual([false, false]);
  expect(result.sameContexts).toBe(true);
  // The probe's context, on the canvas the first book gave up, is lost before the renderer's is made:
  // then nothing is queued on it, where later its loss would wait on all the GPU process had queued.
  expect(result.contexts).toEqual(['context (0 lost before)', 'context (1 lost before)', 'context (1 lost before)']);
});

test('browser: create() and ready come once the first view is drawn, not after its neighbours: a neighbour held back, create() resolves, and the neighbour loads once let go (whenIdle waits for it)', async ({ page }) => {
  await openReady(page, FIXTURE);
  const result = await page.evaluate(async () => {
    let letGo;
    const held = new Promise((resolve) => { letGo = resolve; });
    const fetch = window.fetch;
    window.fetch = async function holdingFetch(input, ...rest) {
      if (String(input?.url ?? input).includes('?page=5')) await held;  // the next page, a neighbour of 3 and 4
      return fetch.call(this, input, ...rest);
    };
    const pages = Array.from({ length: 12 }, (_, i) => `/tests/browser/references/curl-t0-00.png?page=${i}`);
    const container = document.getElementById('container');
    const events = [];
    const book = await window.Flipbook.create(container, { pages, display: 'double', startPage: 4, on: { ready: () => events.push('ready') } });
    const atCreate = { open: book.openPages, states: [3, 4, 5].map((index) => book.pageState(index).state), frames: book.surface.framesDrawn };
    await new Promise((resolve) => setTimeout(resolve, 0));  // events are heard just after create() resolves
    let idle = false;
    const idling = book.whenIdle().then(() => { idle = true; });
    await new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve)));
    const idleWhileHeld = idle;
    letGo();
    await idling;
    const after = [3, 4, 5].map((index) => book.pageState(index).state);
    book.destroy();
    return { atCreate, events, idleWhileHeld, after };
  });
  expect(result.atCreate.open).toEqual([3, 4]);
  expect(result.atCreate.states.slice(0, 2)).toEqual(['loaded', 'loaded']);
  expect(['idle', 'loading']).toContain(result.atCreate.states[2]);  // page 5 still on its way (asked for after the first frame)
  expect(result.atCreate.frames).toBeGreaterThan(0);  // the first view drawn
  expect(result.events).toEqual(['ready']);
  expect(result.idleWhileHeld).toBe(false);
  expect(result.after).toEqual(['loaded', 'loaded', 'loaded']);
});

/**
 * Tracks what the first view asks of the GL beyond drawing: reads of the drawing buffer's size (in Firefox a
 * round trip that waits on all the GPU process has queued) and the page textures' mipmaps. `needsMipmaps`:
 * textures whose image was uploaded (texImage2D from a browser image) and not mipmapped since.
 */
function trackGlAsks() {
  const asks = { bufferReads: 0, mipmaps: 0, needsMipmaps: new Set() };
  window.__asks = asks;
  const proto = WebGL2RenderingContext.prototype;
  for (const name of ['drawingBufferWidth', 'drawingBufferHeight']) {
    const { get } = Object.getOwnPropertyDescriptor(proto, name);
    Object.defineProperty(proto, name, { configurable: true, get() { asks.bufferReads++; return get.call(this); } });
  }
  const bound = new WeakMap();  // context -> { unit, textures: unit -> TEXTURE_2D bound there }
  const state = (gl) => { if (!bound.has(gl)) bound.set(gl, { unit: 0, textures: [] }); return bound.get(gl); };
  const { activeTexture, bindTexture, texImage2D, generateMipmap, deleteTexture } = proto;
  Object.assign(proto, {
    activeTexture(unit) { state(this).unit = unit; return activeTexture.call(this, unit); },
    bindTexture(target, texture) {
      if (target === this.TEXTURE_2D) state(this).textures[state(this).unit] = texture;
      return bindTexture.call(this, target, texture);
    },
    texImage2D(...args) {
      const s = state(this);
      if (args.length === 6 && args[1] === 0 && args[5] && typeof args[5] === 'object') asks.needsMipmaps.add(s.textures[s.unit]);
      return texImage2D.apply(this, args);
    },
    generateMipmap(target) {
      asks.mipmaps++;
      const s = state(this);
      asks.needsMipmaps.delete(s.textures[s.unit]);
      return generateMipmap.call(this, target);
    },
    deleteTexture(texture) { asks.needsMipmaps.delete(texture); return deleteTexture.call(this, texture); },
  });
}

test('browser: the first view waits on no GL answer it does not need: no drawing-buffer size asked and no page mipmaps made before create() resolves; idle time once it is on screen makes every page texture\'s, a turn asked sooner makes them at its first frame, and turning frames ask no buffer size (counts)', async ({ page }) => {
  await page.addInitScript(trackGlAsks);
  await openReady(page, FIXTURE);
  const result = await page.evaluate(async () => {
    const asks = window.__asks;
    // Asks since `from` (a snapshot), and the textures waiting for their mipmaps now.
    const snap = (from = { bufferReads: 0, mipmaps: 0 }) => ({ bufferReads: asks.bufferReads - from.bufferReads, mipmaps: asks.mipmaps - from.mipmaps, needsMipmaps: asks.needsMipmaps.size });
    const idleCallback = window.requestIdleCallback;
    const runs = [];
    for (const turnFirst of [false, true]) {
      // The page's idle callbacks are held while the book is made (a slow machine may be idle before create() resolves).
      const held = [];
      window.requestIdleCallback = (callback, options) => held.push([callback, options]);
      window.book?.destroy();
      asks.needsMipmaps.clear();
      const before = snap();
      const pages = Array.from({ length: 8 }, (_, i) => window.makeNumberedPage(i));
      // The turn asked first is slow (3 s): its frames move wherever a busy machine puts them. A 150 ms one
      // whose first frame came later than that landed in that frame, at rest, and no frame of it moved.
      window.book = await window.Flipbook.create(document.getElementById('container'), { pages, display: 'double', duration: turnFirst ? 3000 : 150, startPage: 3 });
      const run = { turnFirst, atCreate: snap(before) };
      if (turnFirst) {
        // Idle time still held: the turn's first frame makes the mipmaps and asks the buffer's size.
        if (!(await window.book.next())) throw new Error('the turn did not land');
        run.afterTurn = snap(before);
        window.requestIdleCallback = idleCallback;
        for (const [callback, options] of held.splice(0)) idleCallback(callback, options);
      } else {
        window.requestIdleCallback = idleCallback;
        await window.book.whenIdle();  // the neighbours, asked for after the first frame
        await window.settle();
        for (const [callback, options] of held.splice(0)) idleCallback(callback, options);
        for (let i = 0; i < 10 && asks.needsMipmaps.size > 0; i++) await new Promise((resolve) => idleCallback(resolve));
        run.afterIdle = snap(before);
        const reads = asks.bufferReads;
        if (!(await window.book.next()) || !(await window.book.prev())) throw new Error('a turn did not land');
        run.turnReads = asks.bufferReads - reads;
      }
      run.resident = window.book.residentPages.length;
      runs.push(run);
    }
    return runs;
  });
  console.log(`GL asks of the first view: ${JSON.stringify(result)}`);
  const [idleFirst, turnFirst] = result;
  for (const run of result) {
    expect(run.atCreate.bufferReads).toBe(0);
    expect(run.atCreate.mipmaps).toBe(0);
    expect(run.atCreate.needsMipmaps).toBeGreaterThanOrEqual(2);  // the open spread's pages, up without them
  }
  expect(idleFirst.afterIdle.needsMipmaps).toBe(0);
  expect(idleFirst.afterIdle.mipmaps).toBeGreaterThanOrEqual(idleFirst.resident);  // each page's, once
  expect(idleFirst.afterIdle.bufferReads).toBeGreaterThan(idleFirst.atCreate.bufferReads);  // asked once the view was on screen
  expect(idleFirst.turnReads).toBe(0);  // known for this canvas size: no frame of a turn asks again
  expect(turnFirst.afterTurn.needsMipmaps).toBe(0);
  expect(turnFirst.afterTurn.bufferReads).toBeGreaterThan(turnFirst.atCreate.bufferReads);
});

test('browser: a canvas larger than the browser lets its drawing buffer be (Chromium shrinks an 8000x8000 one) is drawn at the buffer\'s size once its first view is on screen: the first view took the canvas\'s size, idle time asks the buffer\'s and draws again (a BookView of its own, so nothing else draws; the last frame\'s viewport)', async ({ page }) => {
  await page.addInitScript(() => {
    const viewport = WebGL2RenderingContext.prototype.viewport;
    WebGL2RenderingContext.prototype.viewport = function recorded(...args) { window.__lastViewport = args; return viewport.apply(this, args); };
  });
  await openReady(page, FIXTURE);
  const result = await page.evaluate(async () => {
    window.book?.destroy();
    const { BookView } = await import('/web/src/surfaces/book-view.js');
    const canvas = document.createElement('canvas');
    canvas.style.cssText = 'position: absolute; left: 0; top: 0; width: 8000px; height: 8000px';
    document.body.append(canvas);
    const view = await BookView.create(canvas, { pageCount: 4 });
    view.drawNow();
    const gl = canvas.getContext('webgl2');  // the renderer's context: getContext hands back the one made
    const atFirst = { canvas: [canvas.width, canvas.height], viewport: [...window.__lastViewport], frames: view.framesDrawn };
    const buffer = [gl.drawingBufferWidth, gl.drawingBufferHeight];
    const drawnAtBuffer = () => window.__lastViewport[2] === buffer[0] && window.__lastViewport[3] === buffer[1];
    for (let i = 0; i < 10 && !drawnAtBuffer(); i++) {
      await new Promise((resolve) => requestIdleCallback(resolve));
      await new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve)));
    }
    const after = { viewport: [...window.__lastViewport], frames: view.framesDrawn };
    view.destroy({ releaseContext: true });
    canvas.remove();
    return { atFirst, buffer, after };
  });
  console.log(`an 8000x8000 canvas: ${JSON.stringify(result)}`);
  expect(result.atFirst.canvas).toEqual([8000, 8000]);
  expect(result.buffer[0]).toBeLessThan(8000);  // the premise: the browser gave a smaller buffer
  expect(result.atFirst.viewport).toEqual([0, 0, 8000, 8000]);  // the first view asked nothing
  expect(result.after.viewport).toEqual([0, 0, ...result.buffer]);  // drawn again at the buffer's size
  expect(result.after.frames).toBeGreaterThan(result.atFirst.frames);
});
