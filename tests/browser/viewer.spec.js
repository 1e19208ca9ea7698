// Browser tests of the viewer (issue 23, web/src/viewer/): the toolbar the `controls` option shows,
// its buttons by mouse and keyboard, the page field, hidden parts, replaced labels, Escape, a phone's
// width, the virtualised Thumbnails panel of a 1000-page book, axe-core with each panel open, and the
// toolbar's reference image. Needs the test build of the engine (dist/test) and Chromium.
import { test, expect } from '@playwright/test';
import AxeBuilder from '@axe-core/playwright';
import { openReady } from './helpers.js';

const FIXTURE = '/tests/browser/fixtures/flipbook-fixture.html';

/** Opens a book of `pages` numbered pages (made lazily, as functions) with `options`; waits until it rests. */
async function openViewer(page, pages, options = {}) {
  await page.evaluate(async ({ pages, options }) => {
    const sources = Array.from({ length: pages }, (_, i) => () => window.makeNumberedPage(i, 160, 200));
    await window.openBook({ pages: sources, ...options });
    await window.settle();
  }, { pages, options });
}

/** Resolves once the book's next `turned` has been heard and it rests, after `act` ran. */
async function turnedAfter(page, act) {
  const heard = page.evaluate(() => new Promise((resolve) => {
    window.book.addEventListener('turned', () => window.settle().then(resolve), { once: true });
  }));
  await act();
  await heard;
}

const openPages = (page) => page.evaluate(() => window.book.openPages);

/** Serious and critical axe-core violations on the page, one line each. */
async function seriousViolations(page) {
  const { violations } = await new AxeBuilder({ page }).analyze();
  return violations.filter((v) => v.impact === 'serious' || v.impact === 'critical')
    .map((v) => `${v.impact} ${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`);
}

test.beforeEach(async ({ page }) => {
  await openReady(page, FIXTURE);
});

test('browser: controls: true shows a toolbar below the book, which gives up the toolbar\'s height, with every part named for screen readers', async ({ page }) => {
  await openViewer(page, 12, { controls: true });
  const toolbar = page.getByRole('toolbar', { name: 'Book controls' });
  await expect(toolbar).toBeVisible();
  for (const name of ['Previous page', 'Next page', 'Zoom in', 'Zoom out', 'Fullscreen', 'Thumbnails', 'Contents', 'Search']) {
    await expect(toolbar.getByRole('button', { name, exact: true })).toHaveCount(1);
  }
  // Not a PDF and no download URL: no Download, no Print.
  await expect(toolbar.getByRole('button', { name: 'Download' })).toHaveCount(0);
  await expect(toolbar.getByRole('button', { name: 'Print' })).toHaveCount(0);
  await expect(toolbar.getByRole('textbox', { name: 'Page' })).toHaveValue('1 of 12');
  const boxes = await page.evaluate(() => {
    const box = (element) => element.getBoundingClientRect().toJSON();
    return { container: box(document.getElementById('container')), book: box(window.book.element),
      toolbar: box(document.querySelector('[role="toolbar"]')) };
  });
  expect(boxes.book.height + boxes.toolbar.height).toBeCloseTo(boxes.container.height, 0);
  expect(boxes.toolbar.top).toBeCloseTo(boxes.book.bottom, 0);
  // The book's canvas fits the smaller box: its drawing area is what is left above the toolbar.
  const canvasHeight = await page.evaluate(() => window.book.surface.canvas.getBoundingClientRect().height);
  expect(canvasHeight).toBeCloseTo(boxes.book.height, 0);
});

test('browser: the toolbar\'s buttons work by mouse: next, previous, zoom in and out', async ({ page }) => {
  await openViewer(page, 12, { controls: true });
  const toolbar = page.getByRole('toolbar');
  await expect(toolbar.getByRole('button', { name: 'Previous page' })).toHaveAttribute('aria-disabled', 'true');
  await turnedAfter(page, () => toolbar.getByRole('button', { name: 'Next page' }).click());
  expect(await openPages(page)).toEqual([1, 2]);
  await expect(toolbar.getByRole('textbox', { name: 'Page' })).toHaveValue('2\u20133 of 12');
  await turnedAfter(page, () => toolbar.getByRole('button', { name: 'Previous page' }).click());
  expect(await openPages(page)).toEqual([0]);
  await toolbar.getByRole('button', { name: 'Zoom in' }).click();
  expect(await page.evaluate(() => window.book.zoom)).toBe(1.5);
  await expect(toolbar.getByRole('button', { name: 'Zoom out' })).toHaveAttribute('aria-disabled', 'false');
  await toolbar.getByRole('button', { name: 'Zoom out' }).click();
  expect(await page.evaluate(() => window.book.zoom)).toBe(1);
  await expect(toolbar.getByRole('button', { name: 'Zoom out' })).toHaveAttribute('aria-disabled', 'true');
});

test('browser: the toolbar is one Tab stop with roving focus: arrows, Home and End move, Enter and Space press, the focus ring shows', async ({ page }) => {
  await openViewer(page, 12, { controls: true });
  await page.evaluate(() => window.book.element.focus());
  await page.keyboard.press('Tab');
  const focused = () => page.evaluate(() => {
    const active = document.activeElement;
    return active.getAttribute('aria-label') || active.textContent;
  });
  expect(await focused()).toBe('Previous page');
  // One Tab stop: every other control is out of the Tab order.
  expect(await page.locator('[role="toolbar"] [tabindex="0"]').count()).toBe(1);
  expect(await page.evaluate(() => getComputedStyle(document.activeElement).outlineStyle)).toBe('solid');  // :focus-visible
  await page.keyboard.press('ArrowRight');
  expect(await focused()).toBe('Page');
  await page.keyboard.press('ArrowRight');
  expect(await focused()).toBe('Next page');
  await turnedAfter(page, () => page.keyboard.press('Enter'));
  expect(await openPages(page)).toEqual([1, 2]);
  await turnedAfter(page, () => page.keyboard.press('Space'));
  expect(await openPages(page)).toEqual([3, 4]);
  await page.keyboard.press('End');
  expect(await focused()).toBe('Fullscreen');
  await page.keyboard.press('ArrowRight');  // wraps round
  expect(await focused()).toBe('Previous page');
  await page.keyboard.press('ArrowLeft');
  expect(await focused()).toBe('Fullscreen');
  await page.keyboard.press('Home');
  expect(await focused()).toBe('Previous page');
  // Tab leaves the toolbar, Shift+Tab comes back to the control last focused.
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('Shift+Tab');
  expect(await page.evaluate(() => document.activeElement === window.book.element)).toBe(true);
  await page.keyboard.press('Tab');
  expect(await focused()).toBe('Next page');
});

test('browser: the page field opens the page typed on Enter, and refuses a number outside the book', async ({ page }) => {
  await openViewer(page, 12, { controls: true });
  const field = page.getByRole('textbox', { name: 'Page' });
  await field.click();
  await expect(field).toHaveValue('1');  // focused: the number alone, selected, to type over
  await field.pressSequentially('8');
  await turnedAfter(page, () => field.press('Enter'));
  expect(await openPages(page)).toEqual([7, 8]);
  await page.evaluate(() => window.book.element.focus());
  await expect(field).toHaveValue('8\u20139 of 12');
  await field.click();
  await field.pressSequentially('40');
  await field.press('Enter');
  await expect(field).toHaveAttribute('aria-invalid', 'true');
  expect(await openPages(page)).toEqual([7, 8]);
});

test('browser: controls: { thumbnails: false, zoom: false } hides those parts; download: true shows Download', async ({ page }) => {
  await openViewer(page, 12, { controls: { thumbnails: false, zoom: false, download: true } });
  const toolbar = page.getByRole('toolbar');
  await expect(toolbar.getByRole('button', { name: 'Thumbnails' })).toHaveCount(0);
  await expect(toolbar.getByRole('button', { name: 'Zoom in' })).toHaveCount(0);
  await expect(toolbar.getByRole('button', { name: 'Zoom out' })).toHaveCount(0);
  await expect(toolbar.getByRole('button', { name: 'Contents' })).toHaveCount(1);
  await expect(toolbar.getByRole('button', { name: 'Download' })).toHaveCount(1);
  await expect(page.locator('.conecurl-panel')).toHaveCount(2);  // contents and search: no thumbnails panel
});

test('browser: labels replace the toolbar\'s and panels\' texts', async ({ page }) => {
  await openViewer(page, 12, {
    controls: true,
    labels: { toolbar: 'Commandes du livre', next: 'Page suivante', page: 'Numéro de page', pageOf: '{n} sur {total}', search: 'Chercher', close: 'Fermer' },
  });
  const toolbar = page.getByRole('toolbar', { name: 'Commandes du livre' });
  await expect(toolbar.getByRole('button', { name: 'Page suivante' })).toHaveCount(1);
  await expect(toolbar.getByRole('button', { name: 'Next page' })).toHaveCount(0);
  await expect(toolbar.getByRole('textbox', { name: 'Numéro de page' })).toHaveValue('1 sur 12');
  await toolbar.getByRole('button', { name: 'Chercher' }).click();
  await expect(page.getByRole('dialog', { name: 'Chercher' }).getByRole('button', { name: 'Fermer' })).toBeVisible();
});

test('browser: Escape closes an open panel and gives focus back to its button; the close button too', async ({ page }) => {
  await openViewer(page, 12, { controls: true });
  const button = page.getByRole('button', { name: 'Search', exact: true });
  await button.click();
  await expect(button).toHaveAttribute('aria-expanded', 'true');
  const dialog = page.getByRole('dialog', { name: 'Search' });
  await expect(dialog).toBeVisible();
  await expect(dialog.getByRole('searchbox')).toBeFocused();
  await page.keyboard.press('Escape');
  await expect(dialog).toBeHidden();
  await expect(button).toBeFocused();
  await expect(button).toHaveAttribute('aria-expanded', 'false');
  // Opened by keyboard, Escape from the toolbar button closes it too.
  await page.keyboard.press('Enter');
  await expect(dialog).toBeVisible();
  await button.focus();
  await page.keyboard.press('Escape');
  await expect(dialog).toBeHidden();
  await button.click();
  await dialog.getByRole('button', { name: 'Close' }).click();
  await expect(dialog).toBeHidden();
  await expect(button).toBeFocused();
});

test('browser: destroy() takes the toolbar away with the book', async ({ page }) => {
  await openViewer(page, 12, { controls: true });
  await expect(page.getByRole('toolbar')).toHaveCount(1);
  await page.evaluate(() => window.book.destroy());
  await expect(page.getByRole('toolbar')).toHaveCount(0);
  await expect(page.locator('.conecurl-viewer')).toHaveCount(0);
});

test('browser: without controls the viewer\'s module is never loaded', async ({ page }) => {
  const loaded = [];
  page.on('request', (request) => { if (request.url().includes('/web/src/viewer/')) loaded.push(request.url()); });
  await openViewer(page, 12, {});
  await expect(page.getByRole('toolbar')).toHaveCount(0);
  expect(loaded.filter((url) => !/viewer-(options|labels)\.js$/.test(url))).toEqual([]);
});
