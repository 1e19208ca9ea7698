// Browser tests of the viewer over a real PDF (tests/browser/document-pdf.js: fonts, headings,
// bookmarks): the Contents panel is the PDF's outline and marks the section read; the Search panel
// searches, steps through the hits by Enter, Shift+Enter and its buttons, announces "n of N", shows a
// hit on its page and ends the search when closed; Download, Print and Fullscreen call the book;
// <cone-flipbook controls> and its `controls` property. Needs the document API (docapi) and Chromium.
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';
import { BOOKMARKS, makeDocumentPdf } from './document-pdf.js';

let made;
test.beforeAll(async () => { made = await makeDocumentPdf(); });

/** Opens the fixture with a book of the test PDF and the toolbar in `window.book`; waits until it rests. */
async function openPdfViewer(page, options = {}) {
  await openReady(page, '/tests/browser/fixtures/pdf-fixture.html');
  await page.evaluate(async ({ base64, options }) => {
    window.pdfBytes = window.bytesFromBase64(base64);
    window.book = await window.Flipbook.create(window.container, {
      pdf: window.pdfBytes, display: 'double', duration: 300, controls: true, ...options,
    });
    await window.book.whenIdle();
  }, { base64: made.base64, options });
}

/** Resolves once the book's next `turned` has been heard, after `act` ran. */
async function turnedAfter(page, act) {
  await page.evaluate(() => {  // the listener in place before `act` (an evaluate left pending may run after it)
    window.landed = false;
    window.book.addEventListener('turned', () => { window.landed = true; }, { once: true });
  });
  await act();
  await page.waitForFunction(() => window.landed);
}

const flat = (entries) => entries.flatMap((entry) => [entry, ...flat(entry.children ?? [])]);

test('browser: a PDF book\'s toolbar has Download and Print; its Contents panel is the PDF\'s bookmarks, an entry opens its page and is marked', async ({ page }) => {
  await openPdfViewer(page);
  const toolbar = page.getByRole('toolbar');
  await expect(toolbar.getByRole('button', { name: 'Download' })).toHaveCount(1);
  await expect(toolbar.getByRole('button', { name: 'Print' })).toHaveCount(1);
  await toolbar.getByRole('button', { name: 'Contents' }).click();
  const panel = page.getByRole('dialog', { name: 'Contents' });
  await expect(panel.locator('.conecurl-tree button')).toHaveCount(flat(BOOKMARKS).length);  // once outline() resolved
  const titles = await panel.locator('.conecurl-tree button > span:first-child').allTextContents();
  expect(titles).toEqual(flat(BOOKMARKS).map((entry) => entry.title));
  const section = flat(BOOKMARKS).find((entry) => entry.title === 'Section 2.1');
  await turnedAfter(page, () => panel.getByRole('button', { name: 'Section 2.1' }).click());
  expect(await page.evaluate(() => window.book.openPages)).toContain(section.page);
  await expect(panel.getByRole('button', { name: 'Section 2.1' })).toHaveAttribute('aria-current', 'location');
});

test('browser: the Search panel finds the hits, steps through them (Enter, Shift+Enter, buttons), says "n of N", shows each on its page, and closing ends the search', async ({ page }) => {
  await openPdfViewer(page);
  const expected = await page.evaluate(async () => (await window.book.search('zebra')).map((hit) => ({ page: hit.page, snippet: hit.snippet })));
  await page.evaluate(() => window.book.clearSearch());
  expect(expected.length).toBeGreaterThan(1);
  await page.getByRole('button', { name: 'Search', exact: true }).click();
  const panel = page.getByRole('dialog', { name: 'Search' });
  const field = panel.getByRole('searchbox', { name: 'Search the book' });
  await expect(field).toBeFocused();
  const status = panel.getByRole('status');
  await expect(status).toHaveAttribute('aria-live', 'polite');
  await field.fill('ZÉBRA');  // case and diacritics are the book's to fold
  await field.press('Enter');
  await expect(status).toHaveText(`1 of ${expected.length}`);
  const results = panel.locator('.conecurl-results button');
  await expect(results).toHaveCount(expected.length);
  for (const [i, hit] of expected.entries()) {
    await expect(results.nth(i)).toContainText(`Page ${hit.page + 1}`);
    await expect(results.nth(i)).toContainText(hit.snippet);
  }
  // Each hit chosen is shown: the book comes to rest with its page open, the hit marked over it. (Each
  // step waits for that, as a reader would: showHit() while an earlier one's turn is under way is the
  // document API's to order.)
  const shown = async (n) => {
    await expect(status).toHaveText(`${n + 1} of ${expected.length}`);
    await expect(results.nth(n)).toHaveAttribute('aria-current', 'true');
    await page.waitForFunction((want) => !window.book.animating && window.book.openPages.includes(want), expected[n].page);
  };
  await shown(0);
  await expect(page.locator('[data-search-hit]').first()).toBeAttached();
  await field.press('Enter');
  await shown(1);
  await field.press('Shift+Enter');
  await shown(0);
  await panel.getByRole('button', { name: 'Previous result' }).click();  // wraps round to the last
  const last = expected.length - 1;
  await shown(last);
  await panel.getByRole('button', { name: 'Next result' }).click();
  await shown(0);
  await results.nth(last).click();
  await shown(last);
  // A hit shown by other means (a tick on the book's edge) becomes the current one here.
  await page.evaluate(async () => {
    const hits = await window.book.search('zebra');
    window.book.showHit(hits[1]);
  });
  await expect(status).toHaveText(`2 of ${expected.length}`);
  await expect(results.nth(1)).toHaveAttribute('aria-current', 'true');
  // A search ended by other means empties the panel.
  await page.evaluate(() => window.book.clearSearch());
  await expect(results).toHaveCount(0);
  await expect(status).toHaveText('');
  // Nothing found: said so.
  await field.fill('okapi');
  await field.press('Enter');
  await expect(status).toHaveText('No results');
  await expect(results).toHaveCount(0);
  // Closing the panel ends the search: its marks go.
  await field.fill('zebra');
  await field.press('Enter');
  await expect(status).toHaveText(`1 of ${expected.length}`);
  // The listener is in place before the key (an evaluate left pending may run after it).
  await page.evaluate(() => {
    window.cleared = null;
    window.book.addEventListener('searchchange', (event) => { if (event.detail.query === '') window.cleared = event.detail.hits.length; });
  });
  await page.keyboard.press('Escape');
  await page.waitForFunction(() => window.cleared !== null);
  expect(await page.evaluate(() => window.cleared)).toBe(0);
  await expect(page.locator('[data-search-hit]')).toHaveCount(0);
});

test('browser: Download and Print call the book (their cancelable events heard), Fullscreen enters and leaves with aria-pressed', async ({ page }) => {
  await openPdfViewer(page);
  await page.evaluate(() => {
    window.heard = [];
    for (const type of ['download', 'print']) {
      window.book.addEventListener(type, (event) => { window.heard.push(type); event.preventDefault(); });
    }
  });
  const toolbar = page.getByRole('toolbar');
  // download is heard once the PDF's bytes are at hand (it may come after a Print clicked at once): wait for each.
  await toolbar.getByRole('button', { name: 'Download' }).click();
  await page.waitForFunction(() => window.heard.length === 1);
  await toolbar.getByRole('button', { name: 'Print' }).click();
  await page.waitForFunction(() => window.heard.length === 2);
  expect(await page.evaluate(() => window.heard)).toEqual(['download', 'print']);
  const fullscreen = toolbar.getByRole('button', { name: 'Fullscreen' });
  await fullscreen.click();
  await page.waitForFunction(() => window.book.fullscreen);
  await expect(fullscreen).toHaveAttribute('aria-pressed', 'true');
  // The toolbar went fullscreen with the book (it is in the book's container).
  expect(await page.evaluate(() => document.fullscreenElement.contains(document.querySelector('[role="toolbar"]')))).toBe(true);
  await fullscreen.click();
  await page.waitForFunction(() => !window.book.fullscreen);
  await expect(fullscreen).toHaveAttribute('aria-pressed', 'false');
});

test('browser: <cone-flipbook controls> shows the toolbar; the controls property takes the parts as an object, labels as an object', async ({ page }) => {
  await openReady(page, '/tests/browser/fixtures/pdf-fixture.html');
  await page.evaluate(async (base64) => {
    const element = document.createElement('cone-flipbook');
    element.style.cssText = 'display:block;width:640px;height:400px';
    element.setAttribute('controls', '');
    element.pdf = window.bytesFromBase64(base64);
    document.body.append(element);
    window.element = element;
    await element.whenReady();
  }, made.base64);
  await expect(page.getByRole('toolbar', { name: 'Book controls' })).toBeVisible();
  await expect(page.getByRole('button', { name: 'Search', exact: true })).toHaveCount(1);
  expect(await page.evaluate(() => window.element.controls)).toBe(true);
  await page.evaluate(async () => {
    window.element.controls = { search: false };
    window.element.labels = { next: 'Page suivante' };
    await window.element.whenReady();
  });
  await expect(page.getByRole('button', { name: 'Search', exact: true })).toHaveCount(0);
  await expect(page.getByRole('button', { name: 'Page suivante' })).toHaveCount(1);
  expect(await page.evaluate(() => window.element.controls)).toEqual({ search: false });
  await page.evaluate(async () => {
    window.element.controls = false;
    await window.element.whenReady();
  });
  await expect(page.getByRole('toolbar')).toHaveCount(0);
});

test('browser: the demo\'s PDF book has the toolbar, and its Contents panel lists the brochure\'s bookmarks; one turns there', async ({ page }) => {
  await openReady(page, '/web/demo/');
  await page.selectOption('#source', 'pdf');
  await expect(page.locator('#where')).toHaveText('Page 1 of 12', { timeout: 30_000 });
  await page.getByRole('toolbar', { name: 'Book controls' }).getByRole('button', { name: 'Contents' }).click();
  const panel = page.getByRole('dialog', { name: 'Contents' });
  await expect(panel.locator('.conecurl-tree button')).toHaveCount(12);
  await panel.getByRole('button', { name: 'Light on paper' }).click();
  // Page 8 lies open (alone or in a spread: the open panel leaves the book less width, display 'auto').
  await page.waitForFunction(() => !window.conecurlDemo.book.animating && window.conecurlDemo.book.openPages.includes(7));
  await expect(panel.getByRole('button', { name: 'Light on paper' })).toHaveAttribute('aria-current', 'location');
});
