// Browser (phone): the viewer on the phone screens (issue 28), with the demo's PDF book and its toolbar:
// the toolbar fits (the controls its width cannot hold in the More menu, each working from there), every
// target 44x44 CSS px, the sheets inside the screen and scrolling inside themselves, a search hit shown
// clear of the sheet, reading mode by the Fullscreen API and by Read, and the reference images. Counted
// and measured; needs Chromium and the demo's PDF (pdf-lib, pdf.js).
import { test, expect } from '@playwright/test';
import { PHONES, touchscreen } from './phone.js';

/** Opens the demo with its PDF book and toolbar (the toolbar in view); `window.book` is the book. */
async function openDemoPdf(page) {
  await page.goto('/web/demo/');
  await page.waitForFunction(() => document.body.dataset.ready || document.body.dataset.error, null, { timeout: 120_000 });
  await page.selectOption('#source', 'pdf');
  await page.waitForFunction(() => /of 12$/.test(document.querySelector('#where').textContent)
    && document.querySelector('[role=toolbar]'), null, { timeout: 120_000 });
  await page.evaluate(async () => {
    window.book = window.conecurlDemo.book;
    await window.book.whenIdle();
  });
  await page.waitForFunction(() => !window.book.animating);
}

/** The toolbar's state: its widths, the controls shown and those in the More menu, which lie off the screen. */
const toolbarFit = (page) => page.evaluate(() => {
  const bar = document.querySelector('[role=toolbar]');
  const name = (c) => c.dataset.control ?? 'page';
  const shown = [...bar.querySelectorAll('button, input')].filter((c) => c.getClientRects().length > 0);
  return {
    scrollWidth: bar.scrollWidth,
    clientWidth: bar.clientWidth,
    documentWidth: document.documentElement.scrollWidth,
    shown: shown.map(name),
    outside: shown.filter((c) => {
      const r = c.getBoundingClientRect();
      return r.left < -0.5 || r.right > innerWidth + 0.5;
    }).map(name),
    menu: [...document.querySelectorAll('[role=menu] [role=menuitem]')].filter((item) => !item.hidden).map(name),
  };
});

// Every control in toolbar order, as the PDF book shows them (the More button's items by their buttons' names).
const TOOLBAR_ORDER = ['previous', 'page', 'next', 'zoomOut', 'zoomIn', 'thumbnails', 'contents', 'search', 'download', 'print', 'fullscreen'];

test('browser (phone): the PDF book\'s toolbar fits the screen: every control inside it, no sideways scroll, and the More menu holds exactly the controls not shown, in toolbar order', async ({ page }, testInfo) => {
  await openDemoPdf(page);
  const fit = await toolbarFit(page);
  console.log(`${testInfo.project.name}: toolbar ${fit.scrollWidth} of ${fit.clientWidth} px; shown ${fit.shown.join(' ')}; in More: ${fit.menu.join(' ') || '-'}`);
  expect(fit.scrollWidth).toBeLessThanOrEqual(fit.clientWidth);
  expect(fit.documentWidth).toBeLessThanOrEqual(PHONES[testInfo.project.name].width);
  expect(fit.outside).toEqual([]);
  const notShown = TOOLBAR_ORDER.filter((part) => !fit.shown.includes(part));
  expect(fit.menu).toEqual(notShown);
  expect(fit.shown.includes('more')).toBe(notShown.length > 0);
  for (const stays of ['previous', 'page', 'next']) expect(fit.shown).toContain(stays);
  if (testInfo.project.name === 'phone-small') expect(fit.menu.length).toBeGreaterThan(0);
});

test('browser (phone): each control in the More menu works from there (panels open as sheets, zoom, download and print asked of the book)', async ({ page }, testInfo) => {
  await openDemoPdf(page);
  const { menu } = await toolbarFit(page);
  test.skip(menu.length === 0, `${testInfo.project.name}: every control fits the toolbar`);
  await page.evaluate(() => {
    window.asked = [];
    for (const type of ['download', 'print']) window.book.addEventListener(type, (e) => { e.preventDefault(); window.asked.push(type); });
  });
  const more = page.getByRole('button', { name: 'More' });
  for (const part of menu.filter((p) => p !== 'fullscreen')) {
    if (part === 'zoomOut') await page.evaluate(() => { window.book.zoom = 2; });  // Zoom out is disabled at 1
    await more.click();
    await expect(more).toHaveAttribute('aria-expanded', 'true');
    const item = page.locator(`[role=menu] [role=menuitem][data-control="${part}"]`);
    await expect(item).toBeVisible();
    await item.click();
    await expect(page.getByRole('menu')).toBeHidden();
    const label = { thumbnails: 'Thumbnails', contents: 'Contents', search: 'Search' }[part];
    if (label) {
      const sheet = page.getByRole('dialog', { name: label });
      await expect(sheet).toBeVisible();
      await sheet.getByRole('button', { name: 'Close' }).click();
      await expect(sheet).toBeHidden();
      await expect(more).toBeFocused();  // the panel's button is in the menu: focus goes back to More
    } else if (part === 'zoomIn') {
      await page.waitForFunction(() => window.book.zoom === 1.5);
      await page.evaluate(() => { window.book.zoom = 1; });
    } else if (part === 'zoomOut') {
      await page.waitForFunction(() => window.book.zoom === 1.5);
      await page.evaluate(() => { window.book.zoom = 1; });
    } else {
      await page.waitForFunction((type) => window.asked.includes(type), part);
    }
  }
});

test('browser (phone): every target is at least 44x44 CSS px: toolbar controls, More and its items, panel items and close buttons', async ({ page }) => {
  await openDemoPdf(page);
  const small = (selector) => page.evaluate((selector) => [...document.querySelectorAll(selector)]
    .filter((c) => c.getClientRects().length > 0)
    .map((c) => ({ c, r: c.getBoundingClientRect() }))
    .filter(({ r }) => r.width < 44 - 0.01 || r.height < 44 - 0.01)
    .map(({ c, r }) => `${c.dataset.control ?? c.getAttribute('aria-label') ?? c.textContent.trim()} ${r.width.toFixed(1)}x${r.height.toFixed(1)}`), selector);
  let counted = 0;
  const count = (selector) => page.evaluate((s) => [...document.querySelectorAll(s)].filter((c) => c.getClientRects().length > 0).length, selector);
  expect(await small('[role=toolbar] button, [role=toolbar] input')).toEqual([]);
  counted += await count('[role=toolbar] button, [role=toolbar] input');
  const more = page.getByRole('button', { name: 'More' });
  if (await more.isVisible()) {
    await more.click();
    expect(await small('[role=menu] [role=menuitem]')).toEqual([]);
    counted += await count('[role=menu] [role=menuitem]');
    await page.keyboard.press('Escape');
  }
  for (const name of ['Thumbnails', 'Contents', 'Search']) {
    await openPanel(page, name);
    const sheet = page.getByRole('dialog', { name });
    if (name === 'Thumbnails') await expect(sheet.locator('canvas').first()).toBeVisible();
    if (name === 'Contents') await expect(sheet.getByRole('button', { name: 'Cover' })).toBeVisible();
    if (name === 'Search') {
      await sheet.getByRole('searchbox').fill('gutter');
      await sheet.getByRole('searchbox').press('Enter');
      await expect(sheet.locator('.conecurl-results button').first()).toBeVisible();
    }
    expect(await small('[role=dialog]:not([hidden]) button, [role=dialog]:not([hidden]) input'), name).toEqual([]);
    counted += await count('[role=dialog]:not([hidden]) button, [role=dialog]:not([hidden]) input');
    await sheet.getByRole('button', { name: 'Close' }).click();
  }
  expect(counted).toBeGreaterThan(20);
});

/** Opens panel `name` by its toolbar button or, when that is in the More menu, from there. */
async function openPanel(page, name) {
  const direct = page.getByRole('toolbar').getByRole('button', { name, exact: true });
  if (await direct.isVisible()) await direct.click();
  else {
    await page.getByRole('button', { name: 'More' }).click();
    await page.getByRole('menuitem', { name }).click();
  }
  await expect(page.getByRole('dialog', { name })).toBeVisible();
}

/** The open sheet's rect, its body's scroll sizes, and the viewport. */
const sheetBox = (page, name) => page.getByRole('dialog', { name }).evaluate((sheet) => {
  const scroller = sheet.querySelector('.conecurl-panel-body');
  return { rect: sheet.getBoundingClientRect().toJSON(), scrollHeight: scroller.scrollHeight, clientHeight: scroller.clientHeight,
    viewport: { width: innerWidth, height: innerHeight } };
});
const inside = (r, v) => r.left >= -0.5 && r.top >= -0.5 && r.right <= v.width + 0.5 && r.bottom <= v.height + 0.5;

test('browser (phone): each sheet (thumbnails, contents, search) lies inside the screen and scrolls inside itself', async ({ page }, testInfo) => {
  await openDemoPdf(page);
  for (const name of ['Thumbnails', 'Contents', 'Search']) {
    await openPanel(page, name);
    const sheet = page.getByRole('dialog', { name });
    if (name === 'Thumbnails') await expect(sheet.locator('canvas').first()).toBeVisible();
    if (name === 'Contents') await expect(sheet.getByRole('button', { name: 'Made with conecurl' })).toHaveCount(1);
    if (name === 'Search') {
      await sheet.getByRole('searchbox').fill('the');
      await sheet.getByRole('searchbox').press('Enter');
      await expect(sheet.locator('.conecurl-results button').nth(10)).toHaveCount(1);
    }
    const box = await sheetBox(page, name);
    expect(inside(box.rect, box.viewport), `${name}: ${JSON.stringify(box.rect)}`).toBe(true);
    expect(box.rect.height).toBeLessThanOrEqual(box.viewport.height * (testInfo.project.name === 'phone-landscape' ? 1 : 0.45) + 0.5);
    // Long content scrolls inside the sheet: 12 thumbnails, 12 entries and dozens of results are longer than it.
    expect(box.scrollHeight, name).toBeGreaterThan(box.clientHeight);
    await sheet.locator('.conecurl-panel-body').evaluate((body) => { body.scrollTop = body.scrollHeight; });
    expect(await sheet.locator('.conecurl-panel-body').evaluate((body) => body.scrollTop)).toBeGreaterThan(0);
    expect(await page.evaluate(() => document.documentElement.scrollWidth)).toBeLessThanOrEqual(box.viewport.width);
    await sheet.getByRole('button', { name: 'Close' }).click();
  }
});

test('browser (phone): a search hit shown with the search sheet open lies on the screen, clear of the sheet', async ({ page }) => {
  await openDemoPdf(page);
  // The hit lowest on its page: the hardest one to keep clear of a bottom sheet.
  const { index, total } = await page.evaluate(async () => {
    const hits = await window.book.search('gutter');
    window.book.clearSearch();
    let lowest = 0;
    hits.forEach((hit, i) => { if (hit.rects[0][1] > hits[lowest].rects[0][1]) lowest = i; });
    return { index: lowest, total: hits.length };
  });
  expect(total).toBeGreaterThan(1);
  await openPanel(page, 'Search');
  const sheet = page.getByRole('dialog', { name: 'Search' });
  await sheet.getByRole('searchbox').fill('gutter');
  await sheet.getByRole('searchbox').press('Enter');
  await expect(sheet.locator('.conecurl-results button')).toHaveCount(total);
  await sheet.locator('.conecurl-results button').nth(index).click();
  await expect(sheet.locator('.conecurl-results button').nth(index)).toHaveAttribute('aria-current', 'true');
  await page.waitForFunction(() => !window.book.animating && document.querySelector('[data-search-hit][data-current]'));
  const seen = await page.evaluate(() => ({
    hits: [...document.querySelectorAll('[data-search-hit][data-current]')].map((m) => m.getBoundingClientRect().toJSON()),
    sheet: document.querySelector('[role=dialog]:not([hidden])').getBoundingClientRect().toJSON(),
    viewport: { width: innerWidth, height: innerHeight },
  }));
  for (const hit of seen.hits) {
    expect(inside(hit, seen.viewport), JSON.stringify(hit)).toBe(true);
    const overlaps = hit.left < seen.sheet.right && hit.right > seen.sheet.left && hit.top < seen.sheet.bottom && hit.bottom > seen.sheet.top;
    expect(overlaps, `hit ${JSON.stringify(hit)} under the sheet ${JSON.stringify(seen.sheet)}`).toBe(false);
  }
});

/** Presses Fullscreen (or Read) on the toolbar, or in the More menu where it went: a real click, a user gesture. */
async function pressReading(page, label) {
  const direct = page.getByRole('toolbar').getByRole('button', { name: label, exact: true });
  if (await direct.isVisible()) await direct.click();
  else {
    await page.getByRole('button', { name: 'More' }).click();
    await page.getByRole('menuitem', { name: label }).click();
  }
}

/** The book's box, the viewport, and the bar's state in reading mode. */
const readingState = (page) => page.evaluate(() => {
  const viewer = document.querySelector('.conecurl-viewer');
  return {
    book: window.book.element.getBoundingClientRect().toJSON(),
    container: window.book.element.parentElement.getBoundingClientRect().toJSON(),
    viewport: { width: innerWidth, height: innerHeight },
    reading: viewer.hasAttribute('data-reading'),
    barHidden: getComputedStyle(viewer).visibility === 'hidden',
    fullscreen: Boolean(document.fullscreenElement),
    documentWidth: document.documentElement.scrollWidth,
  };
});

for (const road of ['fullscreen', 'read']) {
  test(`browser (phone): reading mode by ${road === 'read' ? 'Read (no Fullscreen API)' : 'the Fullscreen API'}: the book's box is the screen, the bar hides, a middle tap shows it, Exit restores everything`, async ({ page }, testInfo) => {
    if (road === 'read') {
      await page.addInitScript(() => Object.defineProperty(Document.prototype, 'fullscreenEnabled', { get: () => false }));
    }
    await openDemoPdf(page);
    const before = await readingState(page);
    const styleBefore = await page.evaluate(() => window.book.element.parentElement.getAttribute('style'));
    if (road === 'read') await expect(page.getByRole('button', { name: 'Fullscreen' })).toHaveCount(0);
    await pressReading(page, road === 'read' ? 'Read' : 'Fullscreen');
    await page.waitForFunction((road) => document.querySelector('.conecurl-viewer[data-reading]')
      && (road === 'read' || document.fullscreenElement), road);
    const viewport = PHONES[testInfo.project.name];
    // The book's box is the whole screen (the bar lies over its foot), with the bar shown at first.
    await expect.poll(async () => {
      const { book } = await readingState(page);
      return [book.left, book.top, book.width, book.height].map(Math.round);
    }).toEqual([0, 0, viewport.width, viewport.height]);
    const exit = page.getByRole('button', { name: 'Exit reading' });
    await expect(exit).toBeVisible();
    expect((await readingState(page)).fullscreen).toBe(road === 'fullscreen');
    // A turn hides the bar; a middle tap shows it, another hides it.
    await page.evaluate(() => window.book.next());
    await expect(exit).toBeHidden();
    // A finger's tap on the middle of the open page (CDP touch), which the book says as `middletap`:
    // down the page's middle, the first point clear of a link (page 2 is the brochure's contents).
    const touch = await touchscreen(page);
    const middletap = async () => touch.tap(await page.evaluate(() => {
      const canvas = window.book.element.querySelector('canvas').getBoundingClientRect();
      const [place] = window.book.openPagePlaces();
      const x = canvas.left + place.x + place.width / 2;
      for (let f = 0.1; f < 0.7; f += 0.02) {
        const y = canvas.top + place.y + f * place.height;
        if (!document.elementFromPoint(x, y)?.closest('a')) return { x, y };
      }
      throw new Error('no point clear of a link down the middle of the page');
    }));
    await middletap();
    await expect(exit).toBeVisible();
    await middletap();
    await expect(exit).toBeHidden();
    await middletap();
    await expect(exit).toBeVisible();
    // The bar lies at the screen's foot once it has slid in.
    await expect.poll(() => page.getByRole('toolbar').evaluate((element) => Math.round(element.getBoundingClientRect().bottom))).toBe(viewport.height);
    expect((await toolbarFit(page)).scrollWidth).toBeLessThanOrEqual((await toolbarFit(page)).clientWidth);
    await exit.click();
    await page.waitForFunction(() => !document.querySelector('.conecurl-viewer[data-reading]') && !document.fullscreenElement);
    const after = await readingState(page);
    expect(await page.evaluate(() => window.book.element.parentElement.getAttribute('style') ?? '')).toBe(styleBefore ?? '');
    await expect.poll(async () => (await readingState(page)).book.height).toBeCloseTo(before.book.height, 0);
    expect(after.container.width).toBeCloseTo(before.container.width, 0);
    expect(after.documentWidth).toBeLessThanOrEqual(viewport.width);
    await expect(page.getByRole('toolbar').getByRole('button', { name: 'Exit reading' })).toBeHidden();
  });
}

test('browser (phone): Escape leaves reading mode, and so does the browser leaving fullscreen', async ({ page }) => {
  await openDemoPdf(page);
  const enter = async () => {
    await pressReading(page, 'Fullscreen');
    await page.waitForFunction(() => document.querySelector('.conecurl-viewer[data-reading]') && document.fullscreenElement);
  };
  await enter();
  await page.keyboard.press('Escape');
  await page.waitForFunction(() => !document.querySelector('.conecurl-viewer[data-reading]') && !document.fullscreenElement);
  await enter();
  await page.evaluate(() => document.exitFullscreen());
  await page.waitForFunction(() => !document.querySelector('.conecurl-viewer[data-reading]'));
});

test.describe('reference images', () => {
  test.beforeEach(({}, testInfo) => {
    test.skip(testInfo.project.name === 'phone-small', 'references on the portrait and landscape phones');
  });
  const shot = (page, name, testInfo) => expect(page).toHaveScreenshot(`${testInfo.project.name}-viewer-${name}.png`, { maxDiffPixelRatio: 0.01, threshold: 0.2 });

  test('browser (phone): the PDF with its toolbar, reference image', async ({ page }, testInfo) => {
    await openDemoPdf(page);
    await page.getByRole('toolbar').evaluate((bar) => bar.scrollIntoView({ block: 'end' }));
    await shot(page, 'toolbar', testInfo);
  });

  test('browser (phone): the search sheet open with a hit shown, reference image', async ({ page }, testInfo) => {
    await openDemoPdf(page);
    await openPanel(page, 'Search');
    const sheet = page.getByRole('dialog', { name: 'Search' });
    await sheet.getByRole('searchbox').fill('gutter');
    await sheet.getByRole('searchbox').press('Enter');
    await page.waitForFunction(() => !window.book.animating && document.querySelector('[data-search-hit][data-current]'));
    await page.evaluate(() => document.activeElement?.blur());
    await shot(page, 'search-sheet', testInfo);
  });

  test('browser (phone): the More menu open, reference image', async ({ page }, testInfo) => {
    test.skip(testInfo.project.name === 'phone-landscape', 'at 844 px every control fits: no More button');
    await openDemoPdf(page);
    await page.getByRole('toolbar').evaluate((bar) => bar.scrollIntoView({ block: 'end' }));
    await page.getByRole('button', { name: 'More' }).click();
    await expect(page.getByRole('menu')).toBeVisible();
    await shot(page, 'more-menu', testInfo);
  });

  test('browser (phone): reading mode with its bar, reference image', async ({ page }, testInfo) => {
    await openDemoPdf(page);
    await pressReading(page, 'Fullscreen');
    await page.waitForFunction(() => document.querySelector('.conecurl-viewer[data-reading]') && document.fullscreenElement);
    await page.waitForFunction(() => !window.book.animating);
    await page.evaluate(() => window.book.whenIdle());
    await page.evaluate(() => document.activeElement?.blur());
    await shot(page, 'reading', testInfo);
  });
});
