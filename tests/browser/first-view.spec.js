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
