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
    // Spreads, as these tests count pages in twos (640x400 is too narrow for display 'auto' to choose them).
    await window.openBook({ pages: sources, display: 'double', ...options });
    await window.settle();
  }, { pages, options });
}

/** Resolves once the book's next `turned` has been heard and it rests, after `act` ran. */
async function turnedAfter(page, act) {
  await page.evaluate(() => {  // the listener in place before `act` (an evaluate left pending may run after it)
    window.landed = false;
    window.book.addEventListener('turned', () => window.settle().then(() => { window.landed = true; }), { once: true });
  });
  await act();
  await page.waitForFunction(() => window.landed);
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
  expect(loaded).toEqual([]);  // not even the option tables: options.js checks only the options' shape
});

test('browser: a controls part or label key the viewer does not know rejects create() with a TypeError naming it, and leaves no toolbar', async ({ page }) => {
  await openReady(page, FIXTURE);
  const errors = await page.evaluate(async () => {
    const pages = Array.from({ length: 4 }, (_, i) => () => window.makeNumberedPage(i, 160, 200));
    const attempt = (options) => window.Flipbook.create(document.getElementById('container'), { pages, ...options })
      .then(() => 'built', (error) => `${error.name}: ${error.message}`);
    return [await attempt({ controls: { share: false } }), await attempt({ controls: true, labels: { nextPage: 'Suivant' } }),
      await attempt({ controls: 'yes' })];
  });
  expect(errors[0]).toMatch(/^TypeError: .*'controls' must be .*previous, next, page/);
  expect(errors[1]).toMatch(/^TypeError: .*'labels' must be .*toolbar, previous, next/);
  expect(errors[2]).toMatch(/^TypeError: .*option 'controls' must be true, false or an object/);
  await expect(page.getByRole('toolbar')).toHaveCount(0);
});

test('browser: the Thumbnails panel of a 1000-page book holds only the rows near its scroll position (counted), marks the open pages, and a press riffles there', async ({ page }, testInfo) => {
  await openViewer(page, 1000, { controls: true });
  // From the press to the first thumbnail image in the panel (reported, not asserted).
  const firstThumbnailMs = await page.evaluate(() => new Promise((resolve) => {
    const viewer = document.querySelector('.conecurl-viewer');
    const start = performance.now();
    const seen = new MutationObserver(() => {
      if (viewer.querySelector('.conecurl-panel canvas, .conecurl-panel img')) {
        seen.disconnect();
        resolve(performance.now() - start);
      }
    });
    seen.observe(viewer, { childList: true, subtree: true });
    viewer.querySelector('[data-control="thumbnails"]').click();
  }));
  testInfo.annotations.push({ type: 'time to first thumbnails (1000 pages)', description: `${firstThumbnailMs.toFixed(0)} ms` });
  console.log(`viewer: first thumbnails of a 1000-page book after ${firstThumbnailMs.toFixed(0)} ms`);
  const panel = page.getByRole('dialog', { name: 'Thumbnails' });
  await expect(panel.getByRole('button', { name: 'Page 1', exact: true })).toHaveAttribute('aria-current', 'page');
  const held = () => page.evaluate(() => {
    const panel = document.querySelector('.conecurl-panel:not([hidden])');
    return { images: panel.querySelectorAll('img, canvas').length, buttons: panel.querySelectorAll('.conecurl-thumb').length };
  });
  // Thumbnails are drawn as they come into view: wait for those in view, then count.
  await expect(panel.locator('canvas').first()).toBeVisible();
  const atTop = await held();
  expect(atTop.buttons).toBeGreaterThan(0);
  expect(atTop.buttons).toBeLessThan(150);
  expect(atTop.images).toBeLessThan(150);
  // Scrolled to the middle: the rows there are made, those at the top are gone.
  await panel.locator('.conecurl-panel-body').evaluate((body) => { body.scrollTop = body.scrollHeight / 2; });
  const middle = panel.getByRole('button', { name: 'Page 500', exact: true });
  await expect(middle).toBeVisible();
  await expect(middle.locator('canvas')).toHaveCount(1);
  await expect(panel.getByRole('button', { name: 'Page 1', exact: true })).toHaveCount(0);
  const inMiddle = await held();
  expect(inMiddle.buttons).toBeLessThan(150);
  expect(inMiddle.images).toBeLessThan(150);
  testInfo.annotations.push({ type: 'elements held (1000 pages)', description: `top: ${JSON.stringify(atTop)}, middle: ${JSON.stringify(inMiddle)}` });
  console.log(`viewer: thumbnails panel holds ${JSON.stringify(atTop)} at the top, ${JSON.stringify(inMiddle)} in the middle`);
  // A press far away riffles there (one turnstart with riffle: true), and the mark follows.
  await page.evaluate(() => {  // in place before the press (an evaluate left pending may run after it)
    window.book.addEventListener('turnstart', (event) => { window.riffled = Boolean(event.detail.riffle); }, { once: true });
  });
  await turnedAfter(page, () => middle.click());
  expect(await page.evaluate(() => window.riffled)).toBe(true);
  expect(await openPages(page)).toContain(499);
  await expect(middle).toHaveAttribute('aria-current', 'page');
});

const OUTLINE = [
  { title: 'Cover', page: 0 },
  { title: 'Part one', page: 3, children: [{ title: 'Chapter A', page: 5 }, { title: 'Chapter B', page: 8 }] },
  { title: 'Part two', page: 10 },
];

test('browser: the Contents panel shows outline() as a tree of buttons named by their titles; an entry turns there and the section being read is marked', async ({ page }) => {
  await openViewer(page, 12, { controls: true, outline: OUTLINE });
  await page.getByRole('button', { name: 'Contents', exact: true }).click();
  const panel = page.getByRole('dialog', { name: 'Contents' });
  // The panel lies beside the book, not over it: the book fits itself to the rest of its box.
  await page.waitForFunction(() => {
    const panel = document.querySelector('.conecurl-panel:not([hidden])').getBoundingClientRect();
    const canvas = window.book.surface.canvas.getBoundingClientRect();
    return canvas.left >= panel.right - 0.5 && Math.abs(canvas.width - window.book.surface.canvas.clientWidth) < 1;
  });
  for (const title of ['Cover', 'Part one', 'Chapter A', 'Chapter B', 'Part two']) {
    await expect(panel.getByRole('button', { name: title, exact: true })).toHaveCount(1);
  }
  // Nested: the chapters are in a list inside Part one's item.
  await expect(panel.locator('li:has(> button:has-text("Part one")) ul button')).toHaveCount(2);
  await expect(panel.getByRole('button', { name: 'Cover' })).toHaveAttribute('aria-current', 'location');
  await turnedAfter(page, () => panel.getByRole('button', { name: 'Chapter B' }).click());
  expect(await openPages(page)).toContain(8);
  await expect(panel.getByRole('button', { name: 'Chapter B' })).toHaveAttribute('aria-current', 'location');
  await expect(panel.locator('[aria-current]')).toHaveCount(1);
  // Turning by other means moves the mark as well.
  await turnedAfter(page, () => page.evaluate(() => window.book.flip(3)));
  await expect(panel.getByRole('button', { name: 'Part one' })).toHaveAttribute('aria-current', 'location');
});

test('browser: axe-core finds no serious or critical violation with the toolbar, and with each panel open', async ({ page }) => {
  await openViewer(page, 40, { controls: { download: true, print: true }, outline: OUTLINE });
  expect(await seriousViolations(page), 'toolbar').toEqual([]);
  for (const name of ['Thumbnails', 'Contents', 'Search']) {
    await page.getByRole('button', { name, exact: true }).click();
    const panel = page.getByRole('dialog', { name });
    await expect(panel).toBeVisible();
    if (name === 'Thumbnails') await expect(panel.locator('canvas').first()).toBeVisible();
    if (name === 'Contents') await expect(panel.getByRole('button', { name: 'Cover' })).toBeVisible();
    expect(await seriousViolations(page), `${name} panel`).toEqual([]);
  }
});

test('browser: the toolbar, reference image (viewer-toolbar.png: every part, on a book 860 px wide)', async ({ page }) => {
  await page.setViewportSize({ width: 900, height: 600 });
  await page.evaluate(() => { document.getElementById('container').style.width = '860px'; });
  await openViewer(page, 12, { controls: { download: true, print: true } });
  await page.evaluate(() => document.activeElement?.blur());
  await expect(page.locator('.conecurl-viewer')).toHaveScreenshot('viewer-toolbar.png', { maxDiffPixelRatio: 0.005, threshold: 0.1 });
});

test('browser: at every width from 320 to 800 px nothing scrolls sideways: the controls that do not fit are in the More menu, exactly those, in toolbar order', async ({ page }) => {
  await page.evaluate(() => Object.assign(document.getElementById('container').style, { width: '100%', height: '500px', margin: '0' }));
  await page.evaluate(() => { document.body.style.margin = '0'; });
  await openViewer(page, 12, { controls: { download: true, print: true } });
  const order = ['previous', 'page', 'next', 'zoomOut', 'zoomIn', 'thumbnails', 'contents', 'search', 'download', 'print', 'fullscreen'];
  const seen = [];
  for (let width = 320; width <= 800; width += 40) {
    await page.setViewportSize({ width, height: 600 });
    await page.waitForFunction((w) => document.querySelector('[role=toolbar]').clientWidth <= w, width);
    // The ResizeObserver's fit runs before the next frame: wait for one (the state it leaves, not a time).
    await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
    const fit = await page.evaluate(() => {
      const bar = document.querySelector('[role=toolbar]');
      const name = (c) => c.dataset.control ?? 'page';
      const shown = [...bar.querySelectorAll('button, input')].filter((c) => c.getClientRects().length > 0);
      return {
        overflow: bar.scrollWidth - bar.clientWidth, documentWidth: document.documentElement.scrollWidth,
        outside: shown.filter((c) => c.getBoundingClientRect().right > innerWidth + 0.5).map(name),
        shown: shown.map(name),
        menu: [...document.querySelectorAll('[role=menu] [role=menuitem]')].filter((i) => !i.hidden).map(name),
      };
    });
    seen.push(`${width}: ${fit.menu.join(' ') || '-'}`);
    expect(fit.overflow, `${width} px`).toBeLessThanOrEqual(0);
    expect(fit.documentWidth, `${width} px`).toBeLessThanOrEqual(width);
    expect(fit.outside, `${width} px`).toEqual([]);
    expect(fit.menu, `${width} px`).toEqual(order.filter((part) => !fit.shown.includes(part)));
    expect(fit.shown.includes('more'), `${width} px`).toBe(fit.menu.length > 0);
  }
  console.log(`in More by width: ${seen.join('; ')}`);
  expect(seen[0]).not.toMatch(/: -$/);       // 320 px: some controls are in the menu
  expect(seen.at(-1)).toMatch(/: -$/);       // 800 px: every control fits
});

test('browser: the More menu by keyboard: a menu button in the roving focus; Enter opens it, arrows, Home and End move, Escape closes it back to More, Enter on an item presses it, a click outside closes it', async ({ page }) => {
  await page.setViewportSize({ width: 360, height: 600 });
  await page.evaluate(() => Object.assign(document.getElementById('container').style, { width: '340px', height: '500px' }));
  await openViewer(page, 12, { controls: { download: true, print: true }, outline: OUTLINE, labels: { more: 'Plus' } });
  const more = page.getByRole('button', { name: 'Plus' });
  await expect(more).toHaveAttribute('aria-haspopup', 'menu');
  await expect(more).toHaveAttribute('aria-expanded', 'false');
  await page.getByRole('button', { name: 'Previous page' }).focus();
  await page.keyboard.press('End');
  await expect(more).toBeFocused();  // the last control of the roving focus
  await page.keyboard.press('Enter');
  const menu = page.getByRole('menu', { name: 'Plus' });
  await expect(menu).toBeVisible();
  await expect(more).toHaveAttribute('aria-expanded', 'true');
  const items = menu.getByRole('menuitem');
  const names = await items.evaluateAll((list) => list.filter((i) => !i.hidden).map((i) => i.textContent));
  expect(names.length).toBeGreaterThan(1);
  await expect(items.filter({ hasText: names[0] })).toBeFocused();
  await page.keyboard.press('ArrowDown');
  await expect(items.filter({ hasText: names[1] })).toBeFocused();
  await page.keyboard.press('End');
  await expect(items.filter({ hasText: names.at(-1) })).toBeFocused();
  await page.keyboard.press('ArrowDown');  // wraps round
  await expect(items.filter({ hasText: names[0] })).toBeFocused();
  await page.keyboard.press('ArrowUp');
  await expect(items.filter({ hasText: names.at(-1) })).toBeFocused();
  await page.keyboard.press('Home');
  await expect(items.filter({ hasText: names[0] })).toBeFocused();
  await page.keyboard.press('Escape');
  await expect(menu).toBeHidden();
  await expect(more).toBeFocused();
  await expect(more).toHaveAttribute('aria-expanded', 'false');
  // Contents from the menu by Enter: its panel opens; closed, focus comes back to More.
  expect(names).toContain('Contents');
  await page.keyboard.press('ArrowDown');  // opens the menu at its first item
  await expect(menu).toBeVisible();
  for (let i = 0; i < names.indexOf('Contents'); i++) await page.keyboard.press('ArrowDown');
  await expect(items.filter({ hasText: 'Contents' })).toBeFocused();
  await page.keyboard.press('Enter');
  const panel = page.getByRole('dialog', { name: 'Contents' });
  await expect(panel).toBeVisible();
  await expect(menu).toBeHidden();
  await panel.getByRole('button', { name: 'Cover' }).focus();
  await page.keyboard.press('Escape');
  await expect(panel).toBeHidden();
  await expect(more).toBeFocused();
  // A click outside closes it.
  await more.click();
  await expect(menu).toBeVisible();
  await page.mouse.click(5, 5);
  await expect(menu).toBeHidden();
  expect(await seriousViolations(page)).toEqual([]);
});

test('browser: the toolbar fitting itself again to a new width keeps the focus: More stays focused, and a control that moves into the menu gives focus to More', async ({ page }) => {
  await page.setViewportSize({ width: 360, height: 600 });
  await page.evaluate(() => Object.assign(document.getElementById('container').style, { width: '340px', height: '500px' }));
  await openViewer(page, 12, { controls: { download: true, print: true }, outline: OUTLINE, labels: { more: 'Plus' } });
  const more = page.getByRole('button', { name: 'Plus' });
  // The toolbar's ResizeObserver fits it in the frame after its width changed: two frames later it has.
  const resize = (width) => page.evaluate(async (width) => {
    document.getElementById('container').style.width = `${width}px`;
    for (let i = 0; i < 2; i++) await new Promise((resolve) => requestAnimationFrame(resolve));
  }, width);
  await more.focus();
  await resize(330);
  await expect(more).toBeVisible();
  expect(await more.evaluate((button) => button === document.activeElement)).toBe(true);
  // A control still on the toolbar keeps the focus; one that moves into the menu hands it to More.
  const toolbar = page.getByRole('toolbar');
  const zoomIn = toolbar.getByRole('button', { name: 'Zoom in' });
  await resize(500);
  await expect(zoomIn).toBeVisible();
  await zoomIn.focus();
  await resize(480);
  expect(await zoomIn.evaluate((button) => button === document.activeElement)).toBe(true);
  await resize(260);
  await expect(zoomIn).toBeHidden();
  expect(await more.evaluate((button) => button === document.activeElement)).toBe(true);
});

test.describe('a 390x844 phone', () => {
  // Not isMobile: the fixture has no viewport meta, so a mobile browser would lay it out 980 px wide.
  test.use({ viewport: { width: 390, height: 844 }, deviceScaleFactor: 1, hasTouch: true });

  test('browser: on a phone\'s width the toolbar fits, shows icons only (names kept), and a panel opens as a sheet fixed to the screen\'s foot', async ({ page }, testInfo) => {
    await page.evaluate(() => Object.assign(document.getElementById('container').style, { width: '100%', height: '600px' }));
    await openViewer(page, 12, { controls: true });
    const toolbar = page.getByRole('toolbar');
    const fit = await toolbar.evaluate((element) => {
      const box = element.getBoundingClientRect();
      const controls = [...element.querySelectorAll('button, input')].map((c) => c.getBoundingClientRect());
      const texts = [...element.querySelectorAll('button span')].map((span) => span.getBoundingClientRect().width);
      return {
        overflow: element.scrollWidth - element.clientWidth,
        right: box.right,
        allInside: controls.every((c) => c.left >= box.left - 0.5 && c.right <= box.right + 0.5),
        widestText: Math.max(...texts),
        icons: element.querySelectorAll('button svg').length,
        buttons: element.querySelectorAll('button').length,
      };
    });
    expect(fit.overflow).toBe(0);
    expect(fit.right).toBeLessThanOrEqual(390);
    expect(fit.allInside).toBe(true);
    expect(fit.widestText).toBeLessThanOrEqual(1);  // the texts are only for screen readers
    expect(fit.icons).toBe(fit.buttons);
    await expect(toolbar.getByRole('button', { name: 'Thumbnails' })).toHaveCount(1);
    await toolbar.getByRole('button', { name: 'Search', exact: true }).click();
    // A touch screen (pointer: coarse): the sheet is fixed to the screen's foot, 45% of its height
    // (tests/browser/viewer.phone.spec.js checks the phones' sheets further).
    const sheet = await page.getByRole('dialog', { name: 'Search' }).evaluate((element) => element.getBoundingClientRect().toJSON());
    expect(sheet.width).toBeCloseTo(390, 0);
    expect(sheet.bottom).toBeCloseTo(844, 0);
    expect(sheet.height).toBeCloseTo(844 * 0.45, 0);
    await page.screenshot({ path: testInfo.outputPath('phone.png') });  // looked at by hand
  });
});
