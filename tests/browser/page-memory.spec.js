// Browser: deep links and memory (page-memory.js). hash: true opens at #page=N, writes each turn as
// a history entry, and follows back and forward; rememberPage restores the last page from localStorage.
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';

const FIXTURE = '/tests/browser/fixtures/flipbook-fixture.html';

test('browser: hash: true opens at #page=N, each turn writes #page= as a history entry, back and forward turn the book', async ({ page }) => {
  const problems = await openReady(page, `${FIXTURE}#page=3`);
  const opened = await page.evaluate(async () => {
    await window.openBook({ pages: 8, display: 'single', hash: true, duration: 60 });
    return window.book.page;
  });
  expect(opened).toBe(2);  // #page=3 counts from 1
  await page.evaluate(async () => { await window.book.next(); await window.book.next(); });
  expect(await page.evaluate(() => location.hash)).toBe('#page=5');
  // Navigates and waits until the book has heard it: every navigation here fires popstate, then
  // hashchange, and the book's listeners (added before ours) have run once ours hears hashchange.
  // Then waits for the turn the book started to land at the page expected (bounded only by the test's
  // timeout), and for the book to settle, so that a page left alone is judged after the book reacted.
  const pageAfter = async (navigate, expected) => {
    await page.evaluate(() => { window.addressHeard = new Promise((resolve) => addEventListener('hashchange', resolve, { once: true })); });
    await page.evaluate(navigate);
    await page.evaluate(() => window.addressHeard);
    await page.waitForFunction(({ page: p, hash }) => location.hash === hash && window.book.page === p && !window.book.animating, expected);
    await page.evaluate(() => window.settle());
    return page.evaluate(() => ({ page: window.book.page, hash: location.hash }));
  };
  expect(await pageAfter(() => history.back(), { page: 3, hash: '#page=4' })).toEqual({ page: 3, hash: '#page=4' });
  expect(await pageAfter(() => history.back(), { page: 2, hash: '#page=3' })).toEqual({ page: 2, hash: '#page=3' });
  expect(await pageAfter(() => history.forward(), { page: 3, hash: '#page=4' })).toEqual({ page: 3, hash: '#page=4' });
  expect(await pageAfter(() => { location.hash = '#page=8'; }, { page: 7, hash: '#page=8' })).toEqual({ page: 7, hash: '#page=8' });
  // Turns the address asked for add no entries of their own: back from #page=8 is #page=4 again.
  expect(await pageAfter(() => history.back(), { page: 3, hash: '#page=4' })).toEqual({ page: 3, hash: '#page=4' });
  // A #page past the end, or not a page, is left alone.
  expect(await pageAfter(() => { location.hash = '#page=99'; }, { page: 3, hash: '#page=99' })).toEqual({ page: 3, hash: '#page=99' });
  expect(problems).toEqual([]);
});

test('browser: rememberPage keeps the page in localStorage under its key and a new book opens there; #page= wins over it', async ({ page }) => {
  const problems = await openReady(page, FIXTURE);
  const result = await page.evaluate(async () => {
    localStorage.clear();
    await window.openBook({ pages: 8, display: 'single', rememberPage: 'novel', duration: 60 });
    const first = window.book.page;
    await window.book.flip(5);
    const stored = localStorage.getItem('conecurl:page:novel');
    await window.openBook({ pages: 8, display: 'single', rememberPage: 'novel' });  // destroys the first
    const reopened = window.book.page;
    await window.openBook({ pages: 8, display: 'single', rememberPage: 'another' });
    const otherKey = window.book.page;
    location.hash = '#page=2';
    await window.openBook({ pages: 8, display: 'single', rememberPage: 'novel', hash: true });
    return { first, stored, reopened, otherKey, hashWins: window.book.page };
  });
  expect(result).toEqual({ first: 0, stored: '5', reopened: 5, otherKey: 0, hashWins: 1 });
  expect(problems).toEqual([]);
});
