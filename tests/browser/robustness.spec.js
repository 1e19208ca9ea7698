// Browser: the book meets bad input, WebGL faults and careless teardown and keeps working: failed and
// cross-origin pages, odd image sizes, odd page counts, bad options, no WebGL2 (the static fallback),
// lost contexts mid-turn and mid-drag, destroy() at any moment, many create/destroy cycles, hostile
// strings, and the renderer's checks at the Embind boundary. Issue 5.
import { test, expect } from '@playwright/test';
import { openReady, withoutWebGL2 } from './helpers.js';
import { shownAtInPage } from './shown-at.js';

const FIXTURE = '/tests/browser/fixtures/flipbook-fixture.html';
const ELEMENT_FIXTURE = '/tests/browser/fixtures/element-fixture.html';
const EN_DASH = '\u2013';
// A real page image of the repository, and the same on another origin (localhost vs 127.0.0.1).
const IMAGE_PATH = '/tests/browser/references/curl-t0-00.png';

/** What window.book shows at points (fractions of its resting pages' rectangle): see shown-at.js. */
const shownAt = (page, points) => page.evaluate(shownAtInPage, points);

// Points low on each page (clear of the page number and the corner marker of the numbered pages).
const SPREAD = [[0.2, 0.85], [0.8, 0.85]];
const SINGLE = [[0.5, 0.85]];

const openBook = (page, options) => page.evaluate((options) => window.openBook(options), options);
const announcement = (page) => page.evaluate(() => window.book.element.querySelector('[aria-live]').textContent);
/** Resolves after `count` animation frames: a window counted in the frames a clock or callback would use. */
const framesPass = (page, count) => page.evaluate((count) => new Promise((resolve) => {
  const frame = (n) => (n === 0 ? resolve() : requestAnimationFrame(() => frame(n - 1)));
  frame(count);
}), count);
/**
 * A window for something that must NOT happen after destroy() (a late animation frame, timer or load
 * callback): 30 animation frames, and a timer longer than any the book sets (CLICK_SERIES_MS, 300 ms),
 * set after all of them, so those fire first on any machine. A slow machine only stretches the window.
 */
const quietWindow = (page) => Promise.all([framesPass(page, 30), page.evaluate(() => new Promise((resolve) => setTimeout(resolve, 400)))]);

/** Records the book's events from the moment it is made (Flipbook and StaticBook alike). */
async function recordEvents(page) {
  await page.evaluate(async () => {
    window.events = [];
    const { StaticBook } = await import('/web/src/book/static-book.js');
    window.StaticBook = StaticBook;
    for (const Class of [window.Flipbook, StaticBook]) {
      const original = Class.prototype.dispatchEvent;
      Class.prototype.dispatchEvent = function (event) {
        window.events.push({ type: event.type, detail: event.detail });
        return original.call(this, event);
      };
    }
  });
}

test('browser: a page that 404s, is not an image, or whose source throws shows plain paper and fires pageerror with its index and reason; the other pages show and the book turns', async ({ page }) => {
  await openReady(page, FIXTURE);
  await recordEvents(page);
  await page.evaluate(async () => {
    const c = (i) => window.makeNumberedPage(i);
    const notAnImage = new Blob(['these bytes are no picture'], { type: 'image/png' });
    const pages = [c(0), '/no/such/page.png', '/package.json', c(3), notAnImage, c(5),
      () => { throw new Error('the page server is down'); }, c(7)];
    await window.openBook({ pages, display: 'double', duration: 200, startPage: 1, loadWindow: 8 });
  });
  const errors = await page.evaluate(() => window.events.filter((e) => e.type === 'pageerror')
    .map(({ detail }) => ({ index: detail.index, reason: detail.reason, name: detail.error.name, message: detail.error.message })));
  const byIndex = Object.fromEntries(errors.map((e) => [e.index, e]));
  expect(Object.keys(byIndex).map(Number).sort()).toEqual([1, 2, 4, 6]);
  expect(byIndex[1]).toMatchObject({ reason: 'http', name: 'PageLoadError' });
  expect(byIndex[1].message).toMatch(/^conecurl: page 1 \('\/no\/such\/page\.png'\): HTTP 404/);
  expect(byIndex[2].reason).toBe('decode');
  expect(byIndex[2].message).toContain("'/package.json'): not a decodable image (application/json");
  expect(byIndex[4].reason).toBe('decode');
  expect(byIndex[4].message).toContain('not a decodable image (image/png, 26 bytes)');
  expect(byIndex[6].reason).toBe('source');
  expect(byIndex[6].message).toContain('the page server is down');
  expect(await page.evaluate(() => window.events.filter((e) => e.type === 'progress').at(-1).detail))
    .toEqual({ loaded: 8, total: 8, pending: 0 });

  // Spread 1: both pages failed, both plain paper. The book turns on through the failures.
  expect(await shownAt(page, SPREAD)).toEqual(['paper', 'paper']);
  expect(await page.evaluate(() => window.book.next())).toBe(true);
  expect(await shownAt(page, SPREAD)).toEqual([3, 'paper']);
  expect(await page.evaluate(() => window.book.next())).toBe(true);
  expect(await shownAt(page, SPREAD)).toEqual([5, 'paper']);
  expect(await page.evaluate(() => window.book.prev())).toBe(true);
  await page.evaluate(() => window.book.flip(0, { animate: false }));
  expect(await shownAt(page, SPREAD)).toEqual(['none', 0]);
  await page.evaluate(() => window.book.flip(7, { animate: false }));
  expect(await shownAt(page, SPREAD)).toEqual([7, 'none']);  // an even book ends with its last page alone
});

test('browser: a cross-origin page without CORS fires a pageerror naming CORS (URL and <img>), never a SecurityError or a tainted canvas; with CORS the same image loads', async ({ page }) => {
  const uncaught = [];
  page.on('pageerror', (error) => uncaught.push(error.message));
  await openReady(page, FIXTURE);
  await recordEvents(page);
  const port = new URL(page.url()).port;
  const otherOrigin = `http://localhost:${port}`;
  const result = await page.evaluate(async ({ otherOrigin, path }) => {
    // An <img> from the other origin without crossorigin: it shows on screen, but its pixels are not ours.
    const foreign = new Image();
    foreign.src = `${otherOrigin}${path}?as=img`;
    await foreign.decode();
    const pages = [window.makeNumberedPage(0), `${otherOrigin}${path}`, `${otherOrigin}${path}?cors=1`, foreign];
    const ready = new Promise((resolve) => { window.readyHeard = resolve; });
    await window.openBook({ pages, display: 'double', startPage: 1, loadWindow: 4, on: { ready: () => window.readyHeard() } });
    await ready;  // the first view's events come just after create, ready the last of them
    await window.book.whenIdle();  // and the pages loaded around it have loaded or failed
    const view = window.book.surface;
    view.drawNow();
    const pixels = view.readPixels();  // would throw on a tainted canvas
    return {
      errors: window.events.filter((e) => e.type === 'pageerror')
        .map(({ detail }) => ({ index: detail.index, reason: detail.reason, message: detail.error.message })),
      resident: [1, 2, 3].map((i) => view.renderer.hasPageImage(i)),
      read: pixels.width > 0,
    };
  }, { otherOrigin, path: IMAGE_PATH });
  expect(result.errors.map((e) => [e.index, e.reason])).toEqual(expect.arrayContaining([[1, 'cors'], [3, 'cors']]));
  expect(result.errors).toHaveLength(2);
  for (const error of result.errors) expect(error.message).toMatch(/CORS/);
  expect(result.errors.find((e) => e.index === 1).message).toContain(`blocked by CORS: ${otherOrigin} does not let`);
  expect(result.errors.find((e) => e.index === 3).message).toContain('crossorigin="anonymous"');
  expect(result.resident).toEqual([false, true, false]);  // the page served with CORS loaded
  expect(result.read).toBe(true);
  expect(uncaught).toEqual([]);
  expect(await shownAt(page, SPREAD)).toEqual(['paper', expect.not.stringMatching(/^paper$/)]);
});

test('browser: a 1x1 image and a non-power-of-two image fill their page the right way round; an image wider than MAX_TEXTURE_SIZE is scaled to it and shown', async ({ page }) => {
  await openReady(page, FIXTURE);
  const sizes = await page.evaluate(async () => {
    const { pageColor } = await import('/tests/browser/fixtures/test-pages.js');
    const css = (i) => `rgb(${pageColor(i).join(',')})`;
    const canvasOf = (width, height, paint) => {
      const canvas = Object.assign(document.createElement('canvas'), { width, height });
      paint(canvas.getContext('2d'));
      return canvas;
    };
    const onePixel = canvasOf(1, 1, (g) => { g.fillStyle = css(2); g.fillRect(0, 0, 1, 1); });
    // 333 x 517: quadrants in the colours of pages 3, 4 (top) and 5, 6 (bottom).
    const npot = canvasOf(333, 517, (g) => {
      [[0, 0, 3], [1, 0, 4], [0, 1, 5], [1, 1, 6]].forEach(([qx, qy, i]) => {
        g.fillStyle = css(i);
        g.fillRect(qx * 167, qy * 259, 167, 259);
      });
    });
    const probe = document.createElement('canvas').getContext('webgl2');
    const maxTextureSize = probe.getParameter(probe.MAX_TEXTURE_SIZE);
    probe.getExtension('WEBGL_lose_context').loseContext();
    // Wider than the GPU allows: left half page 7's colour, right half page 8's.
    const wide = canvasOf(maxTextureSize + 1000, 300, (g) => {
      g.fillStyle = css(7);
      g.fillRect(0, 0, (maxTextureSize + 1000) / 2, 300);
      g.fillStyle = css(8);
      g.fillRect((maxTextureSize + 1000) / 2, 0, (maxTextureSize + 1000) / 2, 300);
    });
    await window.openBook({
      pages: [window.makeNumberedPage(0), npot, onePixel, wide], display: 'double', startPage: 1,
      lighting: false, shadows: false, gutter: false,
    });
    const view = window.book.surface;
    return { maxTextureSize, npot: view.pageImageSize(1), onePixel: view.pageImageSize(2), wide: view.pageImageSize(3) };
  });
  expect(sizes.onePixel).toEqual({ width: 1, height: 1 });  // never scaled up
  expect(sizes.npot).toEqual({ width: 333, height: 517 });
  expect(sizes.wide.width).toBeLessThanOrEqual(sizes.maxTextureSize);
  // Left page (the NPOT image): its four quadrants where they belong. Right page (1x1): one colour throughout.
  const quadrants = [[0.12, 0.25], [0.38, 0.25], [0.12, 0.75], [0.38, 0.75]];
  const corners = [[0.52, 0.03], [0.98, 0.03], [0.52, 0.97], [0.98, 0.97], [0.75, 0.5]];
  expect(await shownAt(page, [...quadrants, ...corners])).toEqual([3, 4, 5, 6, 2, 2, 2, 2, 2]);
  await page.evaluate(() => window.book.flip(3, { animate: false }));
  expect(await shownAt(page, [[0.1, 0.5], [0.4, 0.5]])).toEqual([7, 8]);
});

test('browser: one page and an odd page count have defined layouts in single and double display; next/prev/flip resolve false at the ends', async ({ page }) => {
  await openReady(page, FIXTURE);
  const turn = (how) => page.evaluate((how) => window.book[how](), how);
  const state = () => page.evaluate(() => ({ page: window.book.page, animating: window.book.animating }));

  // One page, double: the page alone on the right; turning it shows its blank back alone on the left.
  await openBook(page, { pages: 1, display: 'double', duration: 150 });
  expect(await shownAt(page, SPREAD)).toEqual(['none', 0]);
  expect(await turn('prev')).toBe(false);
  expect(await turn('next')).toBe(true);
  expect(await state()).toEqual({ page: 0, animating: false });
  expect(await shownAt(page, SPREAD)).toEqual(['paper', 'none']);
  expect(await turn('next')).toBe(false);
  expect(await turn('prev')).toBe(true);
  expect(await shownAt(page, SPREAD)).toEqual(['none', 0]);
  await page.evaluate(() => window.book.flip(0));
  expect(await announcement(page)).toBe('Page 1 of 1');

  // One page, single: nothing to turn either way.
  await openBook(page, { pages: 1, display: 'single', duration: 150 });
  expect(await shownAt(page, SINGLE)).toEqual([0]);
  expect([await turn('next'), await turn('prev')]).toEqual([false, false]);
  expect(await shownAt(page, SINGLE)).toEqual([0]);

  // Five pages, double: spreads [-,0] [1,2] [3,4], then the last page's blank back alone.
  await openBook(page, { pages: 5, display: 'double', duration: 150 });
  await page.evaluate(() => window.book.flip(4));
  expect(await state()).toEqual({ page: 3, animating: false });
  expect(await shownAt(page, SPREAD)).toEqual([3, 4]);
  expect(await announcement(page)).toBe(`Pages 4${EN_DASH}5 of 5`);
  expect(await turn('next')).toBe(true);
  expect(await state()).toEqual({ page: 4, animating: false });
  expect(await shownAt(page, SPREAD)).toEqual(['paper', 'none']);
  expect(await turn('next')).toBe(false);
  expect(await turn('prev')).toBe(true);
  expect(await shownAt(page, SPREAD)).toEqual([3, 4]);

  // Five pages, single: one page at a time, false past either end.
  await openBook(page, { pages: 5, display: 'single', duration: 150, startPage: 4 });
  expect(await shownAt(page, SINGLE)).toEqual([4]);
  expect(await turn('next')).toBe(false);
  expect(await turn('prev')).toBe(true);
  expect(await shownAt(page, SINGLE)).toEqual([3]);
  await page.evaluate(() => window.book.flip(0, { animate: false }));
  expect(await turn('prev')).toBe(false);
  expect(await shownAt(page, SINGLE)).toEqual([0]);

  // Zero pages: a clear TypeError at create.
  const empty = await page.evaluate(() => window.Flipbook.create(document.getElementById('container'), { pages: [] })
    .then(() => 'created', (error) => `${error.name}: ${error.message}`));
  expect(empty).toBe("TypeError: conecurl: option 'pages' must be a non-empty array of at most 1000000 page sources, got an array of 0");
});

test('browser: bad options reach a TypeError naming the option and what it allows, through Flipbook.create, setOptions, flip and StaticBook.create', async ({ page }) => {
  await openReady(page, FIXTURE);
  const messages = await page.evaluate(async () => {
    const { StaticBook } = await import('/web/src/book/static-book.js');
    const container = document.getElementById('container');
    const pages = [window.makeNumberedPage(0), window.makeNumberedPage(1)];
    const attempt = async (call) => {
      try { await call(); return 'no error'; } catch (error) { return `${error.name}: ${error.message}`; }
    };
    const out = {
      duration: await attempt(() => window.Flipbook.create(container, { pages, duration: NaN })),
      loadWindow: await attempt(() => window.Flipbook.create(container, { pages, loadWindow: -2 })),
      entry: await attempt(() => window.Flipbook.create(container, { pages: [pages[0], { src: pages[1], hard: 'yes' }] })),
      unknown: await attempt(() => StaticBook.create(container, { pages, colour: 'red' })),
      optionNames: (await import('/web/src/book/options.js')).OPTION_NAMES,
      staticLabel: await attempt(() => StaticBook.create(container, { pages, label: 42 })),
    };
    const book = await window.Flipbook.create(container, { pages, display: 'double' });
    out.live = await attempt(() => book.setOptions({ gutter: 'off' }));
    out.flip = await attempt(() => book.flip(1, { animate: 'no' }));
    out.flipIndex = await attempt(() => book.flip(NaN));
    out.regions = container.querySelectorAll('.conecurl-book').length;  // the refused creates left nothing behind
    book.destroy();
    return out;
  });
  expect(messages.duration).toBe("TypeError: conecurl: option 'duration' must be a positive number of milliseconds, got NaN");
  expect(messages.loadWindow).toBe("TypeError: conecurl: option 'loadWindow' must be a whole number of pages from 1, got -2");
  expect(messages.entry).toBe("TypeError: conecurl: option 'pages[1].hard' must be true or false; got \"yes\"");
  // Every option the book knows, in the order options.js checks them (the list lives there alone).
  expect(messages.optionNames.slice(0, 4)).toEqual(['pages', 'display', 'minPageWidth', 'direction']);
  expect(messages.unknown).toBe(`TypeError: conecurl: unknown option 'colour' (allowed: ${messages.optionNames.join(', ')})`);
  expect(messages.staticLabel).toBe("TypeError: conecurl: option 'label' must be a non-empty string, got 42");
  expect(messages.live).toBe("TypeError: conecurl: option 'gutter' must be true or false, got \"off\"");
  expect(messages.flip).toBe("TypeError: conecurl: flip option 'animate' must be true or false, got \"no\"");
  expect(messages.flipIndex).toBe('RangeError: conecurl: page NaN is not in 0..1');
  expect(messages.regions).toBe(1);
});

test.describe('without WebGL2', () => {
  test.beforeEach(async ({ page }) => { await withoutWebGL2(page); });

  test('browser (no WebGL2): create fires error and rejects with code webgl2-unavailable and a static fallback: pages, next/prev/flip, events, keys, clicks, alt text, destroy', async ({ page }) => {
    const uncaught = [];
    page.on('pageerror', (error) => uncaught.push(error.message));
    await openReady(page, FIXTURE);
    await recordEvents(page);
    const created = await page.evaluate(async () => {
      window.hacked = false;
      const pages = Array.from({ length: 7 }, (_, i) => ({ src: window.makeNumberedPage(i), alt: `Picture ${i}` }));
      pages[2].alt = '<img src=x onerror="window.hacked=true">Hens';
      const container = document.getElementById('container');
      const rejection = await window.Flipbook.create(container, { pages, display: 'double', label: 'Farm <b>book</b>' })
        .then(() => null, (error) => error);
      window.book = rejection.fallback;
      const errorEvent = window.events.findIndex((e) => e.type === 'error');
      return {
        name: rejection.name,
        message: rejection.message,
        code: rejection.code,
        isStatic: rejection.fallback instanceof window.StaticBook,
        // The error event came before the rejection, carrying the same error.
        errorEventFirst: errorEvent >= 0 && window.events[errorEvent].detail.error === rejection,
        regions: container.querySelectorAll('.conecurl-book').length,
        label: window.book.element.getAttribute('aria-label'),
        page: window.book.page,
        pageCount: window.book.pageCount,
        display: window.book.display,
      };
    });
    expect(created).toEqual({
      name: 'Error',
      message: 'conecurl: WebGL2 is not available (not supported by this browser or GPU, switched off, or too many WebGL contexts are live)',
      code: 'webgl2-unavailable',
      isStatic: true,
      errorEventFirst: true,
      regions: 1,
      label: 'Farm <b>book</b>',
      page: 0,
      pageCount: 7,
      display: 'double',
    });
    expect(await shownAt(page, SPREAD)).toEqual(['none', 0]);

    // Methods: turns cut to the next spread, with turnstart and turned; false at the ends.
    await page.evaluate(() => { window.events.length = 0; });
    expect(await page.evaluate(() => window.book.prev())).toBe(false);
    expect(await page.evaluate(() => window.book.next())).toBe(true);
    expect(await shownAt(page, SPREAD)).toEqual([1, 2]);
    expect(await page.evaluate(() => window.events.map((e) => [e.type, e.detail.page]).filter(([t]) => t !== 'progress')))
      .toEqual([['turnstart', 1], ['turned', 1]]);
    expect(await announcement(page)).toBe(`Pages 2${EN_DASH}3 of 7`);
    const texts = () => page.evaluate(() => Array.from(window.book.element.querySelectorAll('p'), (p) => p.textContent));
    expect(await texts()).toEqual(['Page 2: Picture 1', 'Page 3: <img src=x onerror="window.hacked=true">Hens']);
    await page.evaluate(() => window.book.flip(6));
    expect(await shownAt(page, SPREAD)).toEqual([5, 6]);
    expect(await page.evaluate(() => window.book.next())).toBe(true);
    expect(await shownAt(page, SPREAD)).toEqual(['paper', 'none']);  // the odd last page's blank back
    expect(await page.evaluate(() => window.book.next())).toBe(false);

    // Keys on the focused book, and clicks on a half.
    await page.evaluate(() => window.book.element.focus());
    await page.keyboard.press('Home');
    expect(await page.evaluate(() => window.book.page)).toBe(0);
    await page.keyboard.press('ArrowRight');
    await page.keyboard.press('PageDown');
    expect(await page.evaluate(() => window.book.page)).toBe(3);
    expect(await shownAt(page, SPREAD)).toEqual([3, 4]);
    const left = await page.evaluate(() => {
      const box = window.book.element.querySelector('canvas').getBoundingClientRect();
      const r = window.book.restingRect();
      return { x: box.left + r.x + r.width * 0.25, y: box.top + r.y + r.height / 2 };
    });
    await page.mouse.click(left.x, left.y);
    // A mouse click waits a moment to tell a double-click (which zooms, on still pages too) from a turn.
    expect(await page.evaluate(async () => { await window.book.whenIdle(); return window.book.page; })).toBe(1);

    // Nothing in the strings ran or became markup; destroy empties the container and is final.
    const after = await page.evaluate(async () => {
      const book = window.book;
      const markup = book.element.querySelectorAll('img, b').length;
      book.destroy();
      book.destroy();
      return {
        hacked: window.hacked,
        markup,
        regions: document.getElementById('container').children.length,
        next: await book.next().then(() => 'resolved', (error) => error.message),
        flip: await book.flip(1).then(() => 'resolved', (error) => error.message),
      };
    });
    expect(after).toEqual({ hacked: false, markup: 0, regions: 0, next: 'conecurl: this flipbook was destroyed', flip: 'conecurl: this flipbook was destroyed' });
    expect(uncaught).toEqual([]);
  });

  test('browser (no WebGL2): fallback false rejects with no book left; <cone-flipbook> reports error once and shows the static book, which turns', async ({ page }) => {
    await openReady(page, FIXTURE);
    const bare = await page.evaluate(async () => {
      const container = document.getElementById('container');
      const error = await window.Flipbook.create(container, { pages: [window.makeNumberedPage(0)], fallback: false })
        .then(() => null, (e) => e);
      return { code: error.code, fallback: error.fallback ?? null, children: container.children.length };
    });
    expect(bare).toEqual({ code: 'webgl2-unavailable', fallback: null, children: 0 });

    await page.goto(ELEMENT_FIXTURE);
    await page.waitForFunction(() => document.body.dataset.ready || document.body.dataset.error);
    const element = await page.evaluate(async () => {
      const { StaticBook } = await import('/web/src/book/static-book.js');
      const pages = [0, 1, 2, 3].map((i) => window.pageUrl(i)).join(' ');
      const el = window.makeElement({ pages, display: 'double' });
      const events = [];
      for (const type of ['error', 'ready', 'turned']) el.addEventListener(type, (e) => events.push([type, e.detail.error ? e.detail.error.code : e.detail.page]));
      document.getElementById('stage').append(el);
      const book = await el.whenReady();
      const turned = await el.next();
      return { events, isStatic: book instanceof StaticBook, same: el.book === book, turned, page: el.page,
        failurePanelHidden: el.shadowRoot.querySelector('[part=error]').hidden };
    });
    expect(element).toEqual({
      events: [['error', 'webgl2-unavailable'], ['ready', 0], ['turned', 1]],
      isStatic: true, same: true, turned: true, page: 1, failurePanelHidden: true,
    });
  });
});

test('browser: when the wasm engine cannot load, create rejects with code engine-unavailable and the static fallback shows the pages', async ({ page }) => {
  await openReady(page, FIXTURE);
  await recordEvents(page);
  const result = await page.evaluate(async () => {
    const pages = [0, 1, 2].map((i) => window.makeNumberedPage(i));
    const error = await window.Flipbook.create(document.getElementById('container'), { pages, display: 'double', wasmUrl: '/no/such/engine.wasm' })
      .then(() => null, (e) => e);
    window.book = error.fallback;
    return { code: error.code, message: error.message, isStatic: error.fallback instanceof window.StaticBook,
      errorEvent: window.events.some((e) => e.type === 'error' && e.detail.error === error) };
  });
  expect(result).toMatchObject({ code: 'engine-unavailable', isStatic: true, errorEvent: true });
  expect(result.message).toMatch(/^conecurl: the wasm engine failed to load/);
  expect(await page.evaluate(() => window.book.next())).toBe(true);
  expect(await shownAt(page, SPREAD)).toEqual([1, 2]);
});

/**
 * Holds every request for the engine's .wasm until `release()`: a book created now waits on the engine
 * for as long as the test likes. `requested` resolves once the first request arrives.
 */
async function holdEngine(page) {
  let release;
  const released = new Promise((resolve) => { release = resolve; });
  let requested;
  const asked = new Promise((resolve) => { requested = resolve; });
  await page.route('**/conecurl-engine.wasm', async (route) => {
    requested();
    await released;
    await route.continue();
  });
  return { requested: asked, release };
}

/** Counts the WebGL2 contexts asked for from now on (window.contextsAsked()), on any canvas. */
const countContextsFromNow = (page) => page.evaluate(() => {
  let asked = 0;
  const getContext = HTMLCanvasElement.prototype.getContext;
  HTMLCanvasElement.prototype.getContext = function (type, ...rest) {
    if (type === 'webgl2') asked++;
    return getContext.call(this, type, ...rest);
  };
  window.contextsAsked = () => asked;
});

test('browser: a Flipbook destroyed while the engine still loads never builds a renderer: create() rejects with an AbortError, no WebGL context is asked for, nothing is left in the container', async ({ page }) => {
  const engine = await holdEngine(page);
  await openReady(page, FIXTURE);
  await page.evaluate(() => {
    // A subclass holds the instance create() builds (as <cone-flipbook> does), so it can be destroyed before create() settles.
    class HeldFlipbook extends window.Flipbook {
      constructor(...args) {
        super(...args);
        window.pending = this;
      }
    }
    const pages = [0, 1, 2, 3].map((i) => window.makeNumberedPage(i));
    window.outcome = HeldFlipbook.create(document.getElementById('container'), { pages, display: 'double' })
      .then(() => ({ resolved: true }), (error) => ({ name: error.name, message: error.message, fallback: Boolean(error.fallback) }));
  });
  await engine.requested;  // the book waits on the engine now
  await countContextsFromNow(page);
  await page.evaluate(() => window.pending.destroy());
  engine.release();
  const result = await page.evaluate(async () => {
    const outcome = await window.outcome;
    const { loadEngine } = await import('/web/src/engine.js');
    await loadEngine();  // the engine the book waited on has loaded
    await new Promise((resolve) => requestAnimationFrame(resolve));
    return {
      outcome,
      contexts: window.contextsAsked(),
      surface: window.pending.surface?.kind ?? null,  // what draws it: none
      containerChildren: document.getElementById('container').childElementCount,
      canvases: document.querySelectorAll('canvas').length,
    };
  });
  expect(result.outcome).toEqual({ name: 'AbortError', message: 'conecurl: the book was destroyed before create() finished', fallback: false });
  expect(result).toMatchObject({ contexts: 0, surface: null, containerChildren: 0, canvases: 0 });
});

test('browser: a <cone-flipbook> removed from the document while the engine still loads never builds a renderer, and leaves its box empty', async ({ page }) => {
  const engine = await holdEngine(page);
  await openReady(page, FIXTURE);
  await page.evaluate(async () => {
    await import('/web/src/element.js');
    const element = document.createElement('cone-flipbook');
    element.pages = [0, 1, 2, 3].map((i) => window.makeNumberedPage(i).toDataURL());
    document.getElementById('container').append(element);
    window.element = element;
    window.whenReady = element.whenReady().then(() => 'resolved', (error) => error.message);
  });
  await engine.requested;  // its book waits on the engine now
  await countContextsFromNow(page);
  await page.evaluate(() => window.element.remove());
  expect(await page.evaluate(() => window.whenReady)).toContain('removed from the document');
  engine.release();
  const result = await page.evaluate(async () => {
    const { loadEngine } = await import('/web/src/engine.js');
    await loadEngine();  // the engine the book waited on has loaded: a build still under way goes on from here
    await new Promise((resolve) => requestAnimationFrame(resolve));
    await new Promise((resolve) => requestAnimationFrame(resolve));
    return {
      contexts: window.contextsAsked(),
      book: window.element.book,
      box: window.element.shadowRoot.querySelector('.book').childElementCount,
      canvases: window.element.shadowRoot.querySelectorAll('canvas').length,
    };
  });
  expect(result).toEqual({ contexts: 0, book: null, box: 0, canvases: 0 });
});

/**
 * Loses the book's WebGL context (WEBGL_lose_context) and resolves once it is lost. With `rhoPast`, it
 * loses it in the animation frame where the leaf in flight has turned past that rotation, so the turn is
 * still in flight when it is lost however long the machine stalls between two steps of the test.
 */
function loseContext(page, { rhoPast = null } = {}) {
  return page.evaluate(async (rhoPast) => {
    const canvas = window.book.surface.canvas;
    window.loseExtension = canvas.getContext('webgl2').getExtension('WEBGL_lose_context');  // the book's own context
    const lost = new Promise((resolve) => canvas.addEventListener('webglcontextlost', resolve, { once: true }));
    const flying = () => window.book.surface.book.frame().find((leaf) => !leaf.resting)?.curl.rho ?? 0;
    if (rhoPast !== null) await new Promise((resolve) => requestAnimationFrame(function look() { return flying() > rhoPast ? resolve() : requestAnimationFrame(look); }));
    window.loseExtension.loseContext();
    await lost;
  }, rhoPast);
}

/** Restores it, in a later task (Chrome ignores a restore in the task that lost it), and waits a frame. */
function restoreContext(page) {
  return page.evaluate(async () => {
    const canvas = window.book.surface.canvas;
    await new Promise((resolve) => setTimeout(resolve));  // a later task than the loss, on any machine
    const restored = new Promise((resolve) => canvas.addEventListener('webglcontextrestored', resolve, { once: true }));
    window.loseExtension.restoreContext();
    await restored;
    await new Promise((resolve) => requestAnimationFrame(resolve));
  });
}

/** The progress of the leaf in flight, as its rotation about the spine (0 resting right, pi landed). */
const flyingRho = (page) => page.evaluate(() => window.book.surface.book.frame().find((leaf) => !leaf.resting)?.curl.rho ?? null);
/** The whole pose (cone angle, apex, rotation) of the leaf in flight. */
const flyingPose = (page) => page.evaluate(() => window.book.surface.book.frame().find((leaf) => !leaf.resting)?.curl ?? null);

/** Every cached page image has its texture again, and nothing else is resident. */
const texturesMatchCache = (page) => page.evaluate(() => {
  const { surface: view, residentPages: cached } = window.book;
  return { cached: cached.length, resident: view.renderer.residentPageImages(), missing: cached.filter((i) => !view.renderer.hasPageImage(i)) };
});

test('browser: a WebGL context lost mid-turn pauses the turn; on restore every texture is back and the turn lands; pages loaded while lost show too', async ({ page }) => {
  const uncaught = [];
  page.on('pageerror', (error) => uncaught.push(error.message));
  await openReady(page, FIXTURE);
  await recordEvents(page);
  await openBook(page, { pages: 12, display: 'double', duration: 1000, startPage: 1 });
  await page.evaluate(() => {
    window.turning = window.book.next();
    window.queued = window.book.next();  // asked during the turn: it waits its turn
  });
  await loseContext(page, { rhoPast: 0.3 });
  const pausedAt = await flyingRho(page);
  expect(pausedAt, 'lost with the first turn in flight').toBeGreaterThan(0.3);
  // The container is resized meanwhile: the book lays out and asks for a frame, which must not run the clock.
  await page.evaluate(() => { document.getElementById('container').style.width = '620px'; });
  await page.waitForFunction(() => window.events.some((e) => e.type === 'resize' && e.detail.width === 620));
  // Nothing may move now: 30 frames (half the turn's duration at 60 frames a second) in which a clock
  // that ran would move the leaf; a slow machine gives them more time, so it would move it further.
  await framesPass(page, 30);
  expect(await flyingRho(page), 'the turn does not move while the context is lost').toBe(pausedAt);
  expect(await page.evaluate(() => [window.book.surface.contextLost, window.book.animating,
    window.events.filter((e) => e.type === 'turned').length])).toEqual([true, true, 0]);
  await restoreContext(page);
  expect(await page.evaluate(() => window.book.surface.contextLost)).toBe(false);
  expect(await page.evaluate(() => Promise.all([window.turning, window.queued]))).toEqual([true, true]);
  expect(await page.evaluate(() => window.book.page)).toBe(5);
  expect(await texturesMatchCache(page)).toMatchObject({ missing: [] });
  expect(await shownAt(page, SPREAD)).toEqual([5, 6]);

  // Lost while at rest, the book jumps to pages it has not loaded yet: they load into the lost
  // context, and show once it is back.
  await loseContext(page);
  await page.evaluate(async () => { await window.book.flip(10, { animate: false }); await window.book.whenIdle(); });
  await restoreContext(page);
  const textures = await texturesMatchCache(page);
  expect(textures.missing).toEqual([]);
  expect(textures.resident).toBe(textures.cached);
  expect(await shownAt(page, SPREAD)).toEqual([9, 10]);
  expect(await page.evaluate(() => window.book.prev())).toBe(true);
  expect(await shownAt(page, SPREAD)).toEqual([7, 8]);
  expect(uncaught).toEqual([]);
});

test('browser: a WebGL context lost mid-drag pauses the held page; after restore it catches up with the pointer and the release completes the turn with every page shown', async ({ page }) => {
  await openReady(page, FIXTURE);
  await recordEvents(page);
  await openBook(page, { pages: 8, display: 'double', duration: 400, startPage: 1 });
  const at = (fx, fy) => page.evaluate(([fx, fy]) => window.halfPoint(fx, fy), [fx, fy]);
  const poseAtRest = () => page.waitForFunction(() => window.book.surface.book.holding() && !window.book.surface.book.moving());
  const corner = await at(0.995, 0.99);
  await page.mouse.move(corner.x, corner.y);
  await page.mouse.down();
  const middle = await at(0.75, 0.9);
  await page.mouse.move(middle.x, middle.y, { steps: 4 });
  await poseAtRest();
  const held = await flyingPose(page);
  expect(held.theta).toBeLessThan(Math.PI / 2 - 0.01);  // the corner is curled up
  await loseContext(page);
  const far = await at(0.15, 0.85);
  await page.mouse.move(far.x, far.y, { steps: 4 });  // the pointer goes on while the context is lost
  await framesPass(page, 20);  // frames in which a held pose that followed the pointer would move
  expect(await flyingPose(page), 'the held page waits while the context is lost').toEqual(held);
  await restoreContext(page);
  await poseAtRest();
  expect(await flyingRho(page), 'after the restore it caught up with the pointer, far along').toBeGreaterThan(held.rho + 0.5);
  await page.mouse.up();
  await page.waitForFunction(() => window.events.some((e) => e.type === 'turned'));
  await page.waitForFunction(() => !window.book.animating);
  expect(await page.evaluate(() => window.events.filter((e) => e.type.startsWith('turn')).map((e) => e.type))).toEqual(['turnstart', 'turned']);
  expect(await page.evaluate(() => window.book.page)).toBe(3);
  expect((await texturesMatchCache(page)).missing).toEqual([]);
  expect(await shownAt(page, SPREAD)).toEqual([3, 4]);
});

// Counts what a book holds on to, from before the page's own scripts run: animation frames not yet
// run, event listeners per target, live ResizeObservers, and WebGL objects per context (created and
// not deleted). The test also wraps the engine's Embind constructors to see that all are deleted.
function instrument(page) {
  return page.addInitScript(() => {
    const pendingFrames = new Set();
    const request = window.requestAnimationFrame.bind(window);
    const cancel = window.cancelAnimationFrame.bind(window);
    window.requestAnimationFrame = (callback) => {
      const id = request((time) => { pendingFrames.delete(id); callback(time); });
      pendingFrames.add(id);
      return id;
    };
    window.cancelAnimationFrame = (id) => { pendingFrames.delete(id); cancel(id); };

    const listeners = new Map();  // target -> Set of "type|capture" keys of live listeners
    const capture = (options) => Boolean(typeof options === 'boolean' ? options : options?.capture);
    const add = EventTarget.prototype.addEventListener;
    const remove = EventTarget.prototype.removeEventListener;
    const keys = new WeakMap();  // listener -> unique id, so two listeners of one type count twice
    let nextKey = 1;
    const keyOf = (type, listener, options) => {
      if (!keys.has(listener)) keys.set(listener, nextKey++);
      return `${type}|${capture(options)}|${keys.get(listener)}`;
    };
    EventTarget.prototype.addEventListener = function (type, listener, options) {
      if (listener) {
        if (!listeners.has(this)) listeners.set(this, new Set());
        const key = keyOf(type, listener, options);
        listeners.get(this).add(key);
        if (options?.once) add.call(this, type, () => listeners.get(this)?.delete(key), { once: true });
      }
      return add.call(this, type, listener, options);
    };
    EventTarget.prototype.removeEventListener = function (type, listener, options) {
      if (listener) listeners.get(this)?.delete(keyOf(type, listener, options));
      return remove.call(this, type, listener, options);
    };

    const observers = new Set();
    const NativeResizeObserver = window.ResizeObserver;
    window.ResizeObserver = class extends NativeResizeObserver {
      observe(...args) { observers.add(this); return super.observe(...args); }
      disconnect() { observers.delete(this); return super.disconnect(); }
    };

    const glObjects = new Map();  // context -> Set of live objects
    const proto = WebGL2RenderingContext.prototype;
    for (const kind of ['Texture', 'Buffer', 'Framebuffer', 'Renderbuffer', 'Program', 'Shader', 'VertexArray', 'Query', 'Sampler', 'TransformFeedback']) {
      const create = proto[`create${kind}`];
      const destroy = proto[`delete${kind}`];
      proto[`create${kind}`] = function (...args) {
        const object = create.apply(this, args);
        if (object) {
          if (!glObjects.has(this)) glObjects.set(this, new Set());
          glObjects.get(this).add(object);
        }
        return object;
      };
      proto[`delete${kind}`] = function (object) {
        glObjects.get(this)?.delete(object);
        return destroy.call(this, object);
      };
    }

    window.held = {
      frames: () => pendingFrames.size,
      // Live listeners per target, by a name a test can read; targets with none are left out.
      listeners: (skip = []) => {
        const out = {};
        for (const [target, set] of listeners) {
          if (set.size === 0 || skip.includes(target)) continue;
          const name = target === window ? 'window' : target === document ? 'document'
            : target instanceof MediaQueryList ? `matchMedia ${target.media}`
              : target instanceof Element ? `<${target.localName}${target.className ? `.${target.className}` : ''}>` : target.constructor.name;
          out[name] = (out[name] || 0) + set.size;
        }
        return out;
      },
      observers: () => observers.size,
      glObjects: (context) => glObjects.get(context)?.size ?? 0,
    };
  });
}

/** Wraps the engine's Book and BookRenderer constructors to keep every instance made. */
function trackEmbind(page) {
  return page.evaluate(async () => {
    const { loadEngine } = await import('/web/src/engine.js');
    const engine = await loadEngine();
    window.engine = engine;
    // One Book made and deleted before the baseline: the allocator's first growth of the heap keeps a
    // region header (12 bytes in this build) that belongs to no book. Later books reuse that room.
    engine.Book.create({ pageCount: 2 }).delete();
    window.embindMade = [];
    for (const name of ['Book', 'BookRenderer']) {
      const create = engine[name].create;
      engine[name].create = (...args) => {
        const instance = create.apply(engine[name], args);
        window.embindMade.push(instance);
        return instance;
      };
    }
  });
}

/** What is left after destroy(): see instrument(). */
const leftovers = (page) => page.evaluate(() => ({
  frames: window.held.frames(),
  listeners: window.held.listeners([window.book]),
  observers: window.held.observers(),
  glObjects: window.held.glObjects(window.bookContext),
  contextReleased: window.bookContext.isContextLost(),
  embindLive: window.embindMade.filter((instance) => !instance.isDeleted()).length,
  embindMade: window.embindMade.length,
  targets: Object.keys(window.engine.specialHTMLTargets).filter((key) => key.startsWith('!conecurl')).length,
  containerChildren: document.getElementById('container').children.length,
  heapBytes: window.engine.heapBytesInUse(),
}));

test('browser: calls during a turn queue; destroy() mid-turn leaves no animation frame, listener, observer, GL object, context or wasm object; later calls reject clearly; destroy twice is fine', async ({ page }) => {
  await instrument(page);
  await openReady(page, FIXTURE);
  await trackEmbind(page);
  const baseline = await page.evaluate(() => ({ listeners: window.held.listeners(), heapBytes: window.engine.heapBytesInUse() }));
  await openBook(page, { pages: 10, display: 'double', duration: 800 });
  const during = await page.evaluate(async () => {
    const book = window.book;
    window.bookContext = book.surface.canvas.getContext('webgl2');
    const first = book.next();
    const queued = [book.next(), book.flip(7)];  // asked mid-turn: they wait their turn
    // Checked every animation frame, as the leaf moves: the engine's clock advances at most 0.25 s a
    // frame, so the first turn is still in flight when this sees it past 0.2, however slow the machine.
    await new Promise((resolve) => {
      const check = () => ((book.surface.book.frame().find((leaf) => !leaf.resting)?.curl.rho ?? 0) > 0.2 ? resolve() : requestAnimationFrame(check));
      check();
    });
    const inFlight = {
      animating: book.animating, frames: window.held.frames(), listeners: window.held.listeners([book]),
      observers: window.held.observers(), glObjects: window.held.glObjects(window.bookContext),
    };
    book.destroy();
    const atDestroy = window.held.frames();
    const settled = await Promise.all([first, ...queued]);
    book.destroy();  // again: nothing happens, nothing throws
    const attempt = async (call) => { try { await call(); return 'no error'; } catch (error) { return `${error.name}: ${error.message}`; } };
    return {
      inFlight, atDestroy, settled,
      after: {
        next: await attempt(() => book.next()),
        prev: await attempt(() => book.prev()),
        flip: await attempt(() => book.flip(2)),
        setOptions: await attempt(() => book.setOptions({ lighting: false })),
        previewTurn: await attempt(() => book.previewTurn('forward', 0.5)),
        page: book.page,
        display: book.display,
      },
    };
  });
  // While it lives the book holds frames, listeners (canvas, region, matchMedia), observers and GL objects.
  expect(during.inFlight.animating).toBe(true);
  expect(during.inFlight.frames).toBeGreaterThan(0);
  expect(during.inFlight.listeners).not.toEqual(baseline.listeners);
  expect(during.inFlight.listeners['<canvas>']).toBeGreaterThan(5);
  expect(Object.keys(during.inFlight.listeners).some((name) => name.startsWith('matchMedia'))).toBe(true);
  expect(during.inFlight.observers).toBeGreaterThan(0);
  expect(during.inFlight.glObjects).toBeGreaterThan(10);
  expect(during.atDestroy).toBe(0);
  // The turn in flight and the queued calls settle when the book goes: false for the turns, undefined for flip.
  expect(during.settled).toEqual([false, false, undefined]);
  const destroyed = 'Error: conecurl: this flipbook was destroyed';
  // page and display still answer: where the book was going (three leaves were in flight: spread 3).
  expect(during.after).toEqual({ next: destroyed, prev: destroyed, flip: destroyed, setOptions: destroyed, previewTurn: destroyed, page: 5, display: 'double' });
  await quietWindow(page);  // a late callback (frame, timer, load) would show up now
  const left = await leftovers(page);
  expect(left).toEqual({
    frames: 0, listeners: baseline.listeners, observers: 0, glObjects: 0, contextReleased: true,
    embindLive: 0, embindMade: 2, targets: 0, containerChildren: 0, heapBytes: baseline.heapBytes,
  });
});

test('browser: destroy() mid-drag and while pages load leaves nothing behind either, and the pointer let go later does nothing', async ({ page }) => {
  const uncaught = [];
  page.on('pageerror', (error) => uncaught.push(error.message));
  await instrument(page);
  await openReady(page, FIXTURE);
  await trackEmbind(page);
  const baseline = await page.evaluate(() => ({ listeners: window.held.listeners(), heapBytes: window.engine.heapBytesInUse() }));
  await page.evaluate(async () => {
    // Page 5 onwards load slowly (a page function that waits at a gate the test opens after
    // destroy()): they are still loading at destroy(), however slow the machine.
    let open;
    const gate = new Promise((resolve) => { open = resolve; });
    window.slowPages = { asked: 0, arrived: 0, open };
    const slow = (i) => async () => {
      window.slowPages.asked++;
      await gate;
      window.slowPages.arrived++;
      return window.makeNumberedPage(i);
    };
    const pages = Array.from({ length: 10 }, (_, i) => (i < 5 ? window.makeNumberedPage(i) : slow(i)));
    const book = await window.Flipbook.create(document.getElementById('container'), { pages, display: 'double', startPage: 1, loadWindow: 1 });
    window.book = book;
    window.bookContext = book.surface.canvas.getContext('webgl2');
    book.flip(6, { animate: false });  // the slow pages are wanted now
  });
  const at = (fx, fy) => page.evaluate(([fx, fy]) => window.halfPoint(fx, fy), [fx, fy]);
  const corner = await at(0.995, 0.99);
  const middle = await at(0.7, 0.9);
  await page.mouse.move(corner.x, corner.y);
  await page.mouse.down();
  await page.mouse.move(middle.x, middle.y, { steps: 4 });
  const dragging = await page.evaluate(() => ({ holding: window.book.surface.book.holding(), loading: window.book.progress.pending }));
  expect(dragging.holding).toBe(true);
  expect(dragging.loading).toBeGreaterThan(0);
  expect(await page.evaluate(() => { window.book.destroy(); return window.held.frames(); })).toBe(0);
  await page.mouse.move(corner.x, corner.y, { steps: 2 });
  await page.mouse.up();
  // The slow pages arrive after the book is gone; then what the book would do with them has its window.
  await page.evaluate(() => window.slowPages.open());
  await page.waitForFunction(() => window.slowPages.asked > 0 && window.slowPages.arrived === window.slowPages.asked);
  await quietWindow(page);
  const left = await leftovers(page);
  expect(left).toEqual({
    frames: 0, listeners: baseline.listeners, observers: 0, glObjects: 0, contextReleased: true,
    embindLive: 0, embindMade: 2, targets: 0, containerChildren: 0, heapBytes: baseline.heapBytes,
  });
  expect(uncaught).toEqual([]);
});

test('browser: 200 create/destroy cycles keep the JS heap and the wasm heap flat and release every WebGL context', async ({ page }) => {
  test.setTimeout(240_000);
  const warnings = [];
  page.on('console', (message) => { if (/WebGL|context/i.test(message.text())) warnings.push(message.text()); });
  await openReady(page, FIXTURE);
  const cdp = await page.context().newCDPSession(page);
  await page.evaluate(async () => {
    const { loadEngine } = await import('/web/src/engine.js');
    const engine = await loadEngine();
    const memory = Object.values(engine.asm).find((value) => value instanceof WebAssembly.Memory);
    window.wasmHeap = () => ({ inUse: engine.heapBytesInUse(), size: memory.buffer.byteLength });
    // Each cycle: a book of four canvas pages, loaded, then destroyed. Every tenth has a Blob page
    // too (an ImageBitmap made and closed), is drawn and turns a page first: SwiftShader compiles the
    // shaders at a context's first draw, and releasing a context that took a bitmap waits on the GPU
    // process, each ~0.3 s on two shared cores.
    const blob = await new Promise((resolve) => window.makeNumberedPage(3, 64, 80).toBlob(resolve));
    const canvases = [0, 1, 2, 3].map((i) => window.makeNumberedPage(i, 64, 80));
    let cycle = 0;
    window.cycles = async (count) => {
      for (let i = 0; i < count; i++, cycle++) {
        const full = cycle % 10 === 0;
        const pages = full ? [...canvases.slice(0, 3), blob] : canvases;
        const book = await window.Flipbook.create(document.getElementById('container'), { pages, display: 'double', duration: 50 });
        if (full) {
          book.surface.drawNow();
          await book.next();
        }
        book.destroy();
      }
    };
  });
  const measure = async () => {
    for (let i = 0; i < 3; i++) await cdp.send('HeapProfiler.collectGarbage');
    const { usedSize } = await cdp.send('Runtime.getHeapUsage');
    return { js: usedSize, wasm: await page.evaluate(() => window.wasmHeap()) };
  };
  await page.evaluate(() => window.cycles(20));
  const at20 = await measure();
  await page.evaluate(() => window.cycles(180));
  const at200 = await measure();
  const figures = `JS heap ${at20.js} -> ${at200.js} bytes (${at200.js - at20.js >= 0 ? '+' : ''}${at200.js - at20.js}); `
    + `wasm in use ${at20.wasm.inUse} -> ${at200.wasm.inUse} bytes; wasm memory ${at20.wasm.size} -> ${at200.wasm.size} bytes`;
  test.info().annotations.push({ type: '200 create/destroy cycles', description: figures });
  console.log(`200 create/destroy cycles: ${figures}`);
  expect(at200.js - at20.js, 'JS heap growth from cycle 20 to 200, bytes').toBeLessThan(1_000_000);
  expect(at200.wasm.inUse, 'wasm bytes in use').toBe(at20.wasm.inUse);
  expect(at200.wasm.size, 'wasm memory size').toBe(at20.wasm.size);
  expect(await page.evaluate(() => document.getElementById('container').children.length)).toBe(0);
  // Chrome warns "Too many active WebGL contexts" when contexts pile up unreleased.
  expect(warnings).toEqual([]);
});

test('browser: strings from options, alt text, URLs and error messages are never parsed as HTML: the label, the page text, and <cone-flipbook>\'s error panel show them literally', async ({ page }) => {
  const hostile = '<img src=x onerror="window.pwned=1"><script>window.pwned=2</script>';
  // An <img src=x> made from the hostile string would fail to load and run its onerror. A probe
  // <img src=x> asked for after it fails no sooner: once the probe's error is heard (and a task more),
  // an injected onerror would have run, however slow the machine.
  const addProbe = () => page.evaluate(() => {
    window.probeFailed = () => new Promise((resolve) => {
      const probe = new Image();
      probe.onload = probe.onerror = () => setTimeout(resolve);
      probe.src = 'x';
    });
  });
  await openReady(page, FIXTURE);
  await addProbe();
  const book = await page.evaluate(async (hostile) => {
    window.pwned = 0;
    const pages = [{ src: window.makeNumberedPage(0), alt: hostile }, `/no/such/${hostile}.png`];
    const errors = [];
    const original = window.Flipbook.prototype.dispatchEvent;
    window.Flipbook.prototype.dispatchEvent = function (event) {
      if (event.type === 'pageerror') errors.push(event.detail.error.message);
      return original.call(this, event);
    };
    const failed = new Promise((resolve) => { window.pageFailed = resolve; });
    await window.openBook({ pages, display: 'single', label: hostile, on: { pageerror: () => window.pageFailed() } });
    await failed;  // the 404 page's pageerror, with its URL in the message
    await window.probeFailed();  // an injected onerror would have run by now
    const root = window.book.element;
    return {
      label: root.getAttribute('aria-label'),
      text: Array.from(root.querySelectorAll('p'), (p) => p.textContent),
      elements: root.querySelectorAll('img, script').length,
      documentImages: document.querySelectorAll('img').length,
      pageError: errors[0],
      pwned: window.pwned,
    };
  }, hostile);
  expect(book).toEqual({
    label: hostile, text: [`Page 1: ${hostile}`], elements: 0, documentImages: 0,
    pageError: expect.stringContaining(`'/no/such/${hostile}.png'`), pwned: 0,
  });

  await page.goto(ELEMENT_FIXTURE);
  await page.waitForFunction(() => document.body.dataset.ready);
  await addProbe();
  const panel = await page.evaluate(async (hostile) => {
    window.pwned = 0;
    const element = window.makeElement({ pages: window.pageUrl(0), duration: hostile });
    document.getElementById('stage').append(element);
    await element.whenReady().catch(() => {});  // it rejects: the bad duration
    await window.probeFailed();  // an injected onerror would have run by now
    const shown = element.shadowRoot.querySelector('[part=error]');
    return { text: shown.querySelector('p').textContent, elements: shown.querySelectorAll('img, script').length, pwned: window.pwned };
  }, hostile);
  expect(panel.text).toContain(`"${hostile}"`);
  expect(panel).toMatchObject({ elements: 0, pwned: 0 });
});

test('browser: the renderer refuses bad arguments at the Embind boundary (page index, image size and source, grid rows, leaf index) with a RangeError or TypeError, and still draws after', async ({ page }) => {
  await openReady(page, FIXTURE);
  await openBook(page, { pages: 4, display: 'double', startPage: 1 });
  const refusals = await page.evaluate(() => {
    const view = window.book.surface;
    const renderer = view.renderer;
    const pixel = new ImageData(1, 1);
    const attempt = (call) => { try { call(); return 'no error'; } catch (error) { return `${error.name}: ${error.message}`; } };
    return {
      pageNegative: attempt(() => renderer.setPageImage(-1, pixel, 1, 1)),
      pageFraction: attempt(() => renderer.setPageImage(1.5, pixel, 1, 1)),
      pageString: attempt(() => renderer.setPageImage('2', pixel, 1, 1)),
      widthNaN: attempt(() => renderer.setPageImage(0, pixel, NaN, 1)),
      heightZero: attempt(() => renderer.setPageImage(0, pixel, 1, 0)),
      notAnImage: attempt(() => renderer.setPageImage(0, { width: 1, height: 1 }, 1, 1)),
      noSource: attempt(() => renderer.setPageImage(0, null, 1, 1)),
      stringSource: attempt(() => renderer.setPageImage(0, 'abcd', 1, 1)),
      tooLarge: attempt(() => renderer.setPageImage(0, pixel, renderer.maxTextureSize() + 1, 1)),
      releaseNaN: attempt(() => renderer.releasePageImage(NaN)),
      hasNegative: attempt(() => renderer.hasPageImage(-3)),
      rowsNegative: attempt(() => renderer.setGridRows(-1)),
      rowsTooMany: attempt(() => renderer.setGridRows(513)),
      rowsNaN: attempt(() => renderer.setGridRows(NaN)),
      leafPastFrame: attempt(() => renderer.captureLeaf(view.book, view.book.frame().length)),
      leafNegative: attempt(() => renderer.captureLeaf(view.book, -1)),
      leafString: attempt(() => renderer.captureLeaf(view.book, '0')),
      notABook: attempt(() => renderer.draw({})),
      antialiasString: attempt(() => view.engine.BookRenderer.create('#unused', 'yes')),
      stillResident: [1, 2].map((i) => renderer.hasPageImage(i)),
    };
  });
  expect(refusals).toEqual({
    pageNegative: 'RangeError: conecurl: page must be a whole number from 0 to 1000000',
    pageFraction: 'RangeError: conecurl: page must be a whole number from 0 to 1000000',
    pageString: 'RangeError: conecurl: page must be a whole number from 0 to 1000000',
    widthNaN: 'RangeError: conecurl: image width must be a whole number from 1 to 65536',
    heightZero: 'RangeError: conecurl: image height must be a whole number from 1 to 65536',
    antialiasString: 'TypeError: conecurl: antialias must be true or false',
    notAnImage: 'Error: conecurl: the browser refused to upload the page image',
    noSource: 'TypeError: conecurl: page image must be an ImageBitmap, canvas, image, ImageData or video',
    stringSource: 'TypeError: conecurl: page image must be an ImageBitmap, canvas, image, ImageData or video',
    tooLarge: expect.stringMatching(/^Error: conecurl: page image \d+x1 exceeds MAX_TEXTURE_SIZE \d+$/),
    releaseNaN: 'RangeError: conecurl: page must be a whole number from 0 to 1000000',
    hasNegative: 'RangeError: conecurl: page must be a whole number from 0 to 1000000',
    rowsNegative: 'RangeError: conecurl: rows must be a whole number from 0 to 512',
    rowsTooMany: 'RangeError: conecurl: rows must be a whole number from 0 to 512',
    rowsNaN: 'RangeError: conecurl: rows must be a whole number from 0 to 512',
    leafPastFrame: 'RangeError: conecurl: leaf draw index must be a whole number from 0 to 1',
    leafNegative: 'RangeError: conecurl: leaf draw index must be a whole number from 0 to 1',
    leafString: 'RangeError: conecurl: leaf draw index must be a whole number from 0 to 1',
    notABook: expect.stringMatching(/^BindingError: /),
    stillResident: [true, true],
  });
  // Nothing refused changed the renderer: it draws the same pages, and a good capture still works.
  expect(await shownAt(page, SPREAD)).toEqual([1, 2]);
  expect(await page.evaluate(() => window.book.surface.renderer.captureLeaf(window.book.surface.book, 0).length)).toBeGreaterThan(0);
});
