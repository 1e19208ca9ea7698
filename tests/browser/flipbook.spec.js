// Browser: the Flipbook class (first slice of the component): option checking, loading events,
// navigation events, a failed page that leaves the book working, and destroy.
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';

const FIXTURE = '/tests/browser/fixtures/flipbook-fixture.html';

test('browser: Flipbook.create refuses bad options with a TypeError naming the option', async ({ page }) => {
  await openReady(page, FIXTURE);
  const errors = await page.evaluate(async () => {
    const container = document.getElementById('container');
    const pages = [window.makeNumberedPage(0), window.makeNumberedPage(1)];
    const cases = [
      { pages, colour: 'red' },
      { pages, display: 'triple' },
      { pages: [] },
      { pages, startPage: 5 },
      { pages, duration: -1 },
      { pages: [pages[0], 42] },
      { pages, lighting: 'yes' },
    ];
    const out = [];
    for (const options of cases) {
      try { await window.Flipbook.create(container, options); out.push('no error'); } catch (e) { out.push(`${e.name}: ${e.message}`); }
    }
    return out;
  });
  const names = ["'colour'", "'display'", "'pages'", "'startPage'", "'duration'", "'pages[1]'", "'lighting'"];
  errors.forEach((message, i) => {
    expect(message).toMatch(/^TypeError: conecurl: /);
    expect(message).toContain(names[i]);
  });
});

test('browser: Flipbook loads lazily with progress and ready, turns with turnstart/turned, and flips', async ({ page }) => {
  await openReady(page, FIXTURE);
  const log = await page.evaluate(async () => {
    const events = [];
    const pages = Array.from({ length: 30 }, (_, i) => window.makeNumberedPage(i));
    const container = document.getElementById('container');
    // Listeners go on before create() resolves: record from a subclass-free wrapper via the prototype.
    const original = window.Flipbook.prototype.dispatchEvent;
    window.Flipbook.prototype.dispatchEvent = function (event) {
      events.push([event.type, JSON.stringify(event.detail)]);
      return original.call(this, event);
    };
    const book = await window.Flipbook.create(container, { pages, display: 'double', duration: 300 });
    const resident = book.surface.renderer.residentPageImages();
    await book.next();
    await book.flip(20, { animate: false });
    const at20 = book.page;
    await book.flip(17);
    return { events, resident, at20, final: book.page, count: book.pageCount };
  });
  expect(log.count).toBe(30);
  const types = log.events.map(([type]) => type);
  expect(types.filter((t) => t === 'progress').length).toBeGreaterThan(3);
  expect(types).toContain('ready');
  expect(types.indexOf('turnstart')).toBeGreaterThan(types.indexOf('ready'));
  expect(log.events.find(([t]) => t === 'turned')[1]).toBe('{"page":1}');
  // Only the pages near the open spread are resident, not all 30.
  expect(log.resident).toBeLessThanOrEqual(10);
  expect(log.at20).toBe(19);  // page 20 sits on the right of spread 10, which starts with page 19
  expect(log.final).toBe(17);
});

test('browser: a page that fails to load shows a placeholder and a pageerror; the book keeps turning', async ({ page }) => {
  await openReady(page, FIXTURE);
  const result = await page.evaluate(async () => {
    const container = document.getElementById('container');
    const pages = [window.makeNumberedPage(0), '/no/such/page.png', '/tests/browser/references/curl-t0-00.png', window.makeNumberedPage(3)];
    const errors = [];
    const original = window.Flipbook.prototype.dispatchEvent;
    window.Flipbook.prototype.dispatchEvent = function (event) {
      if (event.type === 'pageerror') errors.push({ index: event.detail.index, message: event.detail.error.message });
      return original.call(this, event);
    };
    const book = await window.Flipbook.create(container, { pages, display: 'double', duration: 200 });
    const turned = await book.next();
    book.surface.drawNow();
    const pixels = book.surface.readPixels();
    const at = (x, y) => { const i = (y * pixels.width + x) * 4; return Array.from(pixels.data.slice(i, i + 3)); };
    return { errors, turned, page: book.page, left: at(110, 300), rightLoaded: book.surface.renderer.hasPageImage(2) };
  });
  expect(result.errors).toHaveLength(1);
  expect(result.errors[0].index).toBe(1);
  expect(result.errors[0].message).toContain('/no/such/page.png');
  expect(result.turned).toBe(true);
  expect(result.page).toBe(1);
  // The failed page 1 on the left is plain paper (near white), not a blank canvas.
  for (const channel of result.left) expect(channel).toBeGreaterThan(200);
  expect(result.rightLoaded).toBe(true);  // a URL page loads
});

test('browser: destroy removes the canvas, is idempotent, and later calls fail clearly', async ({ page }) => {
  await openReady(page, FIXTURE);
  const result = await page.evaluate(async () => {
    const container = document.getElementById('container');
    const book = await window.Flipbook.create(container, { pages: [window.makeNumberedPage(0), window.makeNumberedPage(1)] });
    book.destroy();
    book.destroy();
    let message = '';
    try { await book.next(); } catch (e) { message = e.message; }
    return { canvases: container.querySelectorAll('canvas').length, message };
  });
  expect(result.canvases).toBe(0);
  expect(result.message).toContain('destroyed');
});

test('browser: antialias \'auto\' leaves multisampling off on a software rasterizer (SwiftShader here) and true or false is obeyed; a bad value is a TypeError', async ({ page }) => {
  await openReady(page, FIXTURE);
  const result = await page.evaluate(async () => {
    const container = document.getElementById('container');
    const pages = [window.makeNumberedPage(0), window.makeNumberedPage(1)];
    const probe = document.createElement('canvas').getContext('webgl2');
    const info = probe.getExtension('WEBGL_debug_renderer_info');
    const rendererName = probe.getParameter(info.UNMASKED_RENDERER_WEBGL);
    probe.getExtension('WEBGL_lose_context').loseContext();
    const antialiased = async (options) => {
      const book = await window.Flipbook.create(container, { pages, ...options });
      const canvas = book.element.querySelector('canvas');
      const attributes = canvas.getContext('webgl2').getContextAttributes();  // the book's own context
      book.destroy();
      return attributes.antialias;
    };
    let bad;
    try { await window.Flipbook.create(container, { pages, antialias: 'yes' }); } catch (e) { bad = `${e.name}: ${e.message}`; }
    return { rendererName, auto: await antialiased({}), on: await antialiased({ antialias: true }), off: await antialiased({ antialias: false }), bad };
  });
  expect(result.rendererName).toMatch(/SwiftShader/i);
  expect(result.auto).toBe(false);
  expect(result.on).toBe(true);
  expect(result.off).toBe(false);
  expect(result.bad).toBe("TypeError: conecurl: option 'antialias' must be 'auto', true or false, got \"yes\"");
});
