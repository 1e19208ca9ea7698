// Browser: events a user can always hear. docs/api.md's own example hears the first view's page
// errors; the `on` option registers listeners before anything happens; pageState() answers later;
// <cone-flipbook> passes a cancelled link back to the book, with WebGL2 and in the static fallback.
import { test, expect } from '@playwright/test';
import { openReady, withoutWebGL2 } from './helpers.js';

const FLIPBOOK_FIXTURE = '/tests/browser/fixtures/flipbook-fixture.html';
const ELEMENT_FIXTURE = '/tests/browser/fixtures/element-fixture.html';

// Eight pages, the third a 404, built as docs/api.md shows; listeners added after create resolved.
async function readmeExample(page) {
  return page.evaluate(async () => {
    const pages = Array.from({ length: 8 }, (_, i) => (i === 2 ? '/no/such/page-2.png' : window.makeNumberedPage(i)));
    const early = [];
    const container = document.getElementById('container');
    const book = await window.Flipbook.create(container, {
      pages, display: 'double', startPage: 1,
      on: { pageerror: (event) => early.push(['on', event.detail.index, event.detail.reason]), ready: () => early.push(['on', 'ready']) },
    });
    const heard = [];
    book.addEventListener('pageerror', (event) => heard.push([event.detail.index, event.detail.reason, event.detail.error.message]));
    book.addEventListener('ready', (event) => heard.push(['ready', event.detail.page]));
    // The held events go out together just after create resolves, ready the last of them.
    await new Promise((resolve) => book.addEventListener('ready', resolve, { once: true }));
    const states = [0, 1, 2, 3, 7].map((i) => {
      const { state, reason, error } = book.pageState(i);
      return [i, state, reason ?? null, error ? error.name : null];
    });
    let outside = null;
    try { book.pageState(8); } catch (error) { outside = `${error.name}: ${error.message}`; }
    book.destroy();
    return { heard, early, states, outside };
  });
}

test('browser: the docs/api.md example hears a page of the first view that failed (pageerror after create resolves), on: listeners too, and pageState() tells it later', async ({ page }) => {
  await openReady(page, FLIPBOOK_FIXTURE);
  const { heard, early, states, outside } = await readmeExample(page);
  expect(heard.map(([index, reason]) => [index, reason])).toEqual([[2, 'http'], ['ready', 1]]);
  expect(heard[0][2]).toContain('/no/such/page-2.png');
  expect(early).toEqual([['on', 2, 'http'], ['on', 'ready']]);
  expect(states).toEqual([
    [0, 'loaded', null, null], [1, 'loaded', null, null], [2, 'failed', 'http', 'PageLoadError'],
    [3, 'loaded', null, null], [7, 'idle', null, null],
  ]);
  expect(outside).toBe('RangeError: conecurl: page must be a page index from 0 to 7, got 8');
});

test('browser: the on option is checked: an unknown event name or a listener that is not a function is a TypeError naming it', async ({ page }) => {
  await openReady(page, FLIPBOOK_FIXTURE);
  const errors = await page.evaluate(async () => {
    const attempt = async (on) => {
      try { await window.Flipbook.create(document.getElementById('container'), { pages: [window.makeNumberedPage(0)], on }); return 'no error'; }
      catch (error) { return `${error.name}: ${error.message}`; }
    };
    return [await attempt({ turnd: () => {} }), await attempt({ turned: 'log' }), await attempt([])];
  });
  for (const message of errors) expect(message).toMatch(/^TypeError: conecurl: .*\bon\b.*an object of listeners by event name \(ready, progress, pageerror/);
});

async function elementLinkCancel(page) {
  return page.evaluate(async () => {
    const element = window.makeElement({ pages: [0, 1, 2].map((i) => window.pageUrl(i)).join(' ') });
    document.getElementById('stage').append(element);
    const book = await element.whenReady();
    const forwarded = [];
    element.addEventListener('link', (event) => {
      forwarded.push({ cancelable: event.cancelable, href: event.detail.href });
      event.preventDefault();
    });
    // The book's own link event, as its link layer dispatches it when a reader follows a link.
    const original = new CustomEvent('link', { cancelable: true, detail: { page: 1, href: 'https://example.com/' } });
    const proceed = book.dispatchEvent(original);
    element.remove();
    return { forwarded, proceed, prevented: original.defaultPrevented, fallback: book.constructor.name };
  });
}

test('browser: <cone-flipbook> re-dispatches link as a cancelable copy, and preventDefault() on the element cancels the book\'s link', async ({ page }) => {
  await openReady(page, ELEMENT_FIXTURE);
  const result = await elementLinkCancel(page);
  expect(result).toEqual({ forwarded: [{ cancelable: true, href: 'https://example.com/' }], proceed: false, prevented: true, fallback: 'HostedFlipbook' });
});

test.describe('without WebGL2', () => {
  test.beforeEach(async ({ page }) => { await withoutWebGL2(page); });

  test('browser (no WebGL2): <cone-flipbook> forwards the static fallback\'s link, cancelable, and cancelling it cancels the fallback\'s', async ({ page }) => {
    await page.goto(ELEMENT_FIXTURE);
    await page.waitForFunction(() => document.body.dataset.ready);
    const result = await elementLinkCancel(page);
    expect(result).toEqual({ forwarded: [{ cancelable: true, href: 'https://example.com/' }], proceed: false, prevented: true, fallback: 'StaticBook' });
  });

  test('browser (no WebGL2): the static fallback holds its first view\'s pageerror until listeners can be added, and answers pageState()', async ({ page }) => {
    await page.goto(FLIPBOOK_FIXTURE);
    await page.waitForFunction(() => document.body.dataset.ready);
    const result = await page.evaluate(async () => {
      const pages = Array.from({ length: 8 }, (_, i) => (i === 2 ? '/no/such/page-2.png' : window.makeNumberedPage(i)));
      const { StaticBook } = await import('/web/src/book/static-book.js');
      const book = await StaticBook.create(document.getElementById('container'), { pages, display: 'double', startPage: 1 });
      const heard = [];
      book.addEventListener('pageerror', (event) => heard.push([event.detail.index, event.detail.reason]));
      // The held events go out together just after create resolves, ready the last of them.
      await new Promise((resolve) => book.addEventListener('ready', resolve, { once: true }));
      const state = book.pageState(2);
      book.destroy();
      return { heard, state: [state.state, state.reason] };
    });
    expect(result).toEqual({ heard: [[2, 'http']], state: ['failed', 'http'] });
  });
});

test('browser: the public read-only state (animating, residentPages, restingRect) says what the book is doing, with no private field read', async ({ page }) => {
  await openReady(page, FLIPBOOK_FIXTURE);
  const result = await page.evaluate(async () => {
    const book = await window.Flipbook.create(document.getElementById('container'), {
      pages: Array.from({ length: 30 }, (_, i) => window.makeNumberedPage(i)), display: 'double', duration: 300, loadWindow: 2, startPage: 9,
    });
    const atRest = book.animating;
    const turning = book.next();
    const during = book.animating;
    await turning;
    const resident = book.residentPages;
    const loaded = resident.every((i) => book.pageState(i).state === 'loaded');
    const rect = book.restingRect();
    const canvasWidth = book.element.querySelector('canvas').clientWidth;
    book.destroy();
    return { atRest, during, after: book.animating, resident, loaded, rect, canvasWidth };
  });
  expect(result).toMatchObject({ atRest: false, during: true, after: false, loaded: true });
  expect(result.resident).toEqual(expect.arrayContaining([11, 12]));
  expect(result.resident.length).toBeLessThanOrEqual(14);
  expect(result.resident).toEqual([...result.resident].sort((a, b) => a - b));
  expect(result.rect.width).toBeGreaterThan(0);
  expect(result.rect.x + result.rect.width).toBeLessThanOrEqual(result.canvasWidth + 0.5);
});
