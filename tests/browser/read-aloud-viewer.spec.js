// Browser tests of the toolbar's Read aloud part (issue 31, web/src/viewer/: toolbar.js, attach-controls.js,
// read-aloud-menu.js): Read aloud and Voice and speed shown only once the book can read aloud, play,
// pause and resume by one button, the book's readaloud* events followed, the popup by keyboard, the
// voices in the page's language first, a choice applied to the reading under way, a phone's width, and
// axe-core. The book is a real Flipbook whose read-aloud API is a fake kept to the contract of
// docs/api.md (readAloud, readingAloud, readAloudVoices, canReadAloud, the ReadAloud object and the
// events): it records its calls and dispatches the events, so the viewer is tested on its own.
import { test, expect } from '@playwright/test';
import AxeBuilder from '@axe-core/playwright';
import { openReady } from './helpers.js';

const FIXTURE = '/tests/browser/fixtures/flipbook-fixture.html';

// The browser's voices as readAloudVoices() gives them, in the browser's order.
const VOICES = [
  { name: 'Amélie', lang: 'fr-FR', default: false, local: true },
  { name: 'Alex', lang: 'en-US', default: true, local: true },
  { name: 'Hans', lang: 'de-DE', default: false, local: false },
  { name: 'Daniel', lang: 'en-GB', default: false, local: true },
  { name: 'Thomas', lang: 'fr-CA', default: false, local: false },
];

/**
 * Run in the page before its scripts: window.installFakeReadAloud(target, settings) gives `target` (a
 * book, or Flipbook.prototype) the read-aloud API of the contract. settings: { can: true | false |
 * 'reject' | 'later' (window.answerCanReadAloud(value) answers), voices, refuse: a message readAloud()
 * rejects with }. window.readAloudCalls lists [name, argument] of every call; window.readAloudListeners
 * counts the book's readaloud* listeners; window.finishReading() ends the reading as its last word would;
 * window.answered settles once the latest canReadAloud() or readAloud() has been answered.
 */
function fakeReadAloud() {
  window.installFakeReadAloud = (target, { can = true, voices = [], refuse = null } = {}) => {
    const calls = [];
    window.readAloudCalls = calls;
    window.readAloudListeners = 0;
    let current = null;
    let answer = null;
    window.answerCanReadAloud = (value) => answer?.(value);
    const answering = (promise) => {
      window.answered = promise.then(() => {}, () => {});
      return promise;
    };
    const fire = (book, type, detail) => book.dispatchEvent(new CustomEvent(type, { detail }));
    function start(book, options) {
      const reading = {
        state: 'reading',
        pause() {
          calls.push(['pause']);
          if (reading.state !== 'reading' && reading.state !== 'waiting') return;
          reading.state = 'paused';
          fire(book, 'readaloudpause', { page: book.page });
        },
        resume() {
          calls.push(['resume']);
          if (reading.state !== 'paused') return;
          reading.state = 'reading';
          fire(book, 'readaloudresume', { page: book.page });
        },
        stop() {
          calls.push(['stop']);
          end('stopped');
        },
        update(changes) {
          calls.push(['update', { ...changes, keys: Object.keys(changes) }]);
        },
      };
      const end = (reason) => {
        if (reading.state === 'ended') return;
        reading.state = 'ended';
        if (current === reading) current = null;
        fire(book, 'readaloudend', { reason, page: book.page });
      };
      window.finishReading = () => end('finished');
      current = reading;
      fire(book, 'readaloudstart', { page: book.page, lang: 'en', voice: options.voice ?? 'Alex' });
      return reading;
    }
    Object.defineProperties(target, {
      readAloud: {
        configurable: true,
        value(options = {}) {
          calls.push(['readAloud', { ...options, keys: Object.keys(options) }]);
          if (refuse) return answering(Promise.reject(new Error(refuse)));
          current?.stop();
          return answering(Promise.resolve(start(this, options)));
        },
      },
      readingAloud: { configurable: true, get: () => current },
      readAloudVoices: { configurable: true, value: () => Promise.resolve(voices.map((voice) => ({ ...voice }))) },
      canReadAloud: {
        configurable: true,
        value() {
          calls.push(['canReadAloud']);
          if (can === 'reject') return answering(Promise.reject(new Error('no speech here')));
          if (can === 'later') return answering(new Promise((resolve) => { answer = resolve; }));
          return answering(Promise.resolve(can));
        },
      },
      // Counts the readaloud* listeners added and removed, as an EventTarget keeps them.
      addEventListener: {
        configurable: true,
        value(type, ...rest) {
          if (type.startsWith('readaloud')) window.readAloudListeners++;
          return EventTarget.prototype.addEventListener.call(this, type, ...rest);
        },
      },
      removeEventListener: {
        configurable: true,
        value(type, ...rest) {
          if (type.startsWith('readaloud')) window.readAloudListeners--;
          return EventTarget.prototype.removeEventListener.call(this, type, ...rest);
        },
      },
    });
  };
}

/**
 * Opens a 12-page book with the fake read-aloud API (`fake`: installFakeReadAloud's settings) and the
 * viewer (attachControls with `controls`, or with `viaOption` the book's own `controls` option, the
 * fake on Flipbook.prototype); waits until it rests. `lang`: the container's lang attribute.
 */
async function openReading(page, { controls = true, viaOption = false, lang = null, ...fake } = {}) {
  await page.evaluate(async ({ controls, viaOption, lang, fake }) => {
    window.controls?.remove();
    window.controls = null;
    const container = document.getElementById('container');
    if (lang) container.lang = lang;
    if (viaOption) {
      window.installFakeReadAloud(window.Flipbook.prototype, fake);
      await window.openBook({ pages: 12, display: 'double', controls });
    } else {
      await window.openBook({ pages: 12, display: 'double' });
      window.installFakeReadAloud(window.book, fake);
      const { attachControls } = await import('/web/src/viewer.js');
      window.controls = attachControls(window.book, { controls });
    }
    await window.settle();
  }, { controls, viaOption, lang, fake: { voices: VOICES, ...fake } });
}

/** Resolves once the fake's latest answer (canReadAloud(), readAloud()) has reached the viewer. */
const answered = (page) => page.evaluate(async () => {
  await window.answered;
  await new Promise((resolve) => setTimeout(resolve));  // no time: the tasks the answer queued run first
});
const calls = (page) => page.evaluate(() => window.readAloudCalls);
const lastCall = async (page, name) => (await calls(page)).filter(([called]) => called === name).at(-1);

/** Serious and critical axe-core violations on the page, one line each. */
async function seriousViolations(page) {
  const { violations } = await new AxeBuilder({ page }).analyze();
  return violations.filter((v) => v.impact === 'serious' || v.impact === 'critical')
    .map((v) => `${v.impact} ${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`);
}

let problems = [];
test.beforeEach(async ({ page }) => {
  await page.addInitScript(fakeReadAloud);
  problems = await openReady(page, FIXTURE);
});
test.afterEach(() => {
  expect(problems, 'errors on the page').toEqual([]);
});

test('browser: Read aloud and Voice and speed stay hidden while canReadAloud() is false or rejects, the toolbar as without them, and show once it resolves true', async ({ page }) => {
  const visibleControls = () => page.evaluate(() => [...document.querySelectorAll('[role=toolbar] button, [role=toolbar] input')]
    .filter((c) => c.getClientRects().length > 0).map((c) => c.dataset.control ?? 'page'));
  await openReading(page, { controls: { readAloud: false } });
  await expect(page.locator('[data-control^=readAloud]')).toHaveCount(0);
  const without = await visibleControls();
  expect(without).not.toContain('readAloud');
  for (const can of [false, 'reject']) {
    await openReading(page, { can });
    await page.waitForFunction(() => window.readAloudCalls.some(([name]) => name === 'canReadAloud'));
    await answered(page);
    const toolbar = page.getByRole('toolbar');
    await expect(toolbar.getByRole('button', { name: 'Read aloud' })).toBeHidden();
    await expect(toolbar.getByRole('button', { name: 'Voice and speed' })).toBeHidden();
    expect(await visibleControls(), `canReadAloud ${can}`).toEqual(without);
  }
  await openReading(page, { can: 'later' });
  const toolbar = page.getByRole('toolbar');
  await expect(toolbar.getByRole('button', { name: 'Read aloud' })).toBeHidden();
  await page.evaluate(() => window.answerCanReadAloud(true));
  await expect(toolbar.getByRole('button', { name: 'Read aloud' })).toBeVisible();
  await expect(toolbar.getByRole('button', { name: 'Voice and speed' })).toBeVisible();
  await expect(toolbar.getByRole('button', { name: 'Voice and speed' })).toHaveAttribute('aria-haspopup', 'dialog');
  expect(await visibleControls()).toEqual([...without.slice(0, 5), 'readAloud', 'readAloudSettings', ...without.slice(5)]);
  // Alone in its group (zoom hidden) and absent, it leaves no gap either.
  const gaps = () => page.evaluate(() => [...document.querySelectorAll('[role=toolbar] .conecurl-gap')].filter((g) => g.getClientRects().length > 0).length);
  await openReading(page, { controls: { zoom: false, readAloud: false } });
  const gapsWithout = await gaps();
  await openReading(page, { controls: { zoom: false }, can: false });
  await answered(page);
  expect(await gaps()).toBe(gapsWithout);
  // Through the book's own `controls` option as well.
  await openReading(page, { viaOption: true });
  await expect(page.getByRole('toolbar').getByRole('button', { name: 'Read aloud' })).toBeVisible();
  await openReading(page, { viaOption: true, controls: { readAloud: false } });
  await expect(page.locator('[data-control^=readAloud]')).toHaveCount(0);
});

test('browser: Read aloud calls readAloud() with the popup\'s voice and speed; the same button pauses and resumes, its name (Read aloud, Pause reading) and its lit state following', async ({ page }) => {
  await openReading(page);
  const toolbar = page.getByRole('toolbar');
  const read = toolbar.locator('[data-control=readAloud]');
  await expect(read).toBeVisible();
  await expect(read).toHaveAttribute('data-on', 'false');
  await expect(read).toHaveAccessibleName('Read aloud');
  // Nothing chosen: the browser's default voice (no voice given), speed 1.
  await read.click();
  expect(await lastCall(page, 'readAloud')).toEqual(['readAloud', { rate: 1, keys: ['rate'] }]);
  await expect(read).toHaveAttribute('data-on', 'true');
  await expect(read).toHaveAccessibleName('Pause reading');
  await expect(read).toHaveAttribute('title', 'Pause reading');
  await read.click();
  expect(await lastCall(page, 'pause')).toEqual(['pause']);
  await expect(read).toHaveAttribute('data-on', 'false');
  await expect(read).toHaveAccessibleName('Read aloud');
  expect(await page.evaluate(() => window.book.readingAloud.state)).toBe('paused');
  await read.click();
  expect(await lastCall(page, 'resume')).toEqual(['resume']);
  await expect(read).toHaveAttribute('data-on', 'true');
  await page.evaluate(() => window.finishReading());
  await expect(read).toHaveAttribute('data-on', 'false');
  // A voice and a speed chosen: the next reading is given them.
  await toolbar.getByRole('button', { name: 'Voice and speed' }).click();
  const popup = page.getByRole('dialog', { name: 'Voice and speed' });
  await expect(popup).toBeVisible();
  await popup.getByLabel('Voice').selectOption('Daniel');
  await popup.getByLabel('Speed').selectOption('1.5');
  expect(await lastCall(page, 'update')).toBeUndefined();  // nothing was reading
  await page.keyboard.press('Escape');
  await expect(popup).toBeHidden();
  await read.click();
  expect(await lastCall(page, 'readAloud')).toEqual(['readAloud', { voice: 'Daniel', rate: 1.5, keys: ['voice', 'rate'] }]);
  await expect(read).toHaveAttribute('data-on', 'true');
});

test('browser: the button follows the host\'s reading: readAloud(), pause(), resume(), stop() and the reading\'s end, called outside the viewer', async ({ page }) => {
  await openReading(page);
  const read = page.locator('[role=toolbar] [data-control=readAloud]');
  await expect(read).toBeVisible();
  await page.evaluate(() => window.book.readAloud({ rate: 2 }));
  await expect(read).toHaveAttribute('data-on', 'true');
  await expect(read).toHaveAccessibleName('Pause reading');
  await page.evaluate(() => window.book.readingAloud.pause());
  await expect(read).toHaveAttribute('data-on', 'false');
  await expect(read).toHaveAccessibleName('Read aloud');
  await page.evaluate(() => window.book.readingAloud.resume());
  await expect(read).toHaveAttribute('data-on', 'true');
  // The host's reading is paused by the viewer's button.
  await read.click();
  expect(await lastCall(page, 'pause')).toEqual(['pause']);
  await expect(read).toHaveAttribute('data-on', 'false');
  await page.evaluate(() => window.book.readingAloud.stop());
  await expect(read).toHaveAccessibleName('Read aloud');
  expect(await page.evaluate(() => window.book.readingAloud)).toBeNull();
  // Stopped, a press starts a new reading (not a resume).
  await read.click();
  expect((await calls(page)).filter(([name]) => name === 'readAloud')).toHaveLength(2);
  await expect(read).toHaveAttribute('data-on', 'true');
});

test('browser: a readAloud() that rejects (no voice) leaves the button at Read aloud, not pressed, and nothing on the page broken', async ({ page }) => {
  await openReading(page, { refuse: 'conecurl: readAloud() found no voice for en' });
  const read = page.locator('[role=toolbar] [data-control=readAloud]');
  await expect(read).toBeVisible();
  await read.click();
  await page.waitForFunction(() => window.readAloudCalls.some(([name]) => name === 'readAloud'));
  await answered(page);
  await expect(read).toHaveAttribute('data-on', 'false');
  await expect(read).toHaveAccessibleName('Read aloud');
  await read.click();  // and again: the same
  await expect(read).toHaveAttribute('data-on', 'false');
});

test('browser: the Voice and speed popup by keyboard: Enter opens it on Voice, Tab and Shift+Tab go between the selects, Escape closes it and gives focus back to its button', async ({ page }) => {
  await openReading(page);
  const toolbar = page.getByRole('toolbar');
  const settings = toolbar.getByRole('button', { name: 'Voice and speed' });
  await expect(settings).toBeVisible();
  await page.evaluate(() => window.book.element.focus());
  await page.keyboard.press('Tab');  // into the toolbar, then along it by arrows
  for (let i = 0; i < 10 && !(await settings.evaluate((b) => b === document.activeElement)); i++) await page.keyboard.press('ArrowRight');
  await expect(settings).toBeFocused();
  await expect(settings).toHaveAttribute('aria-expanded', 'false');
  await page.keyboard.press('Enter');
  const popup = page.getByRole('dialog', { name: 'Voice and speed' });
  await expect(popup).toBeVisible();
  await expect(settings).toHaveAttribute('aria-expanded', 'true');
  await expect(settings).toHaveAttribute('aria-controls', await popup.getAttribute('id'));
  const voice = popup.getByRole('combobox', { name: 'Voice' });
  const speed = popup.getByRole('combobox', { name: 'Speed' });
  await expect(voice).toBeFocused();
  expect(await voice.evaluate((select) => getComputedStyle(select).outlineStyle)).toBe('solid');  // :focus-visible
  await page.keyboard.press('Tab');
  await expect(speed).toBeFocused();
  await page.keyboard.press('Tab');  // round to the first
  await expect(voice).toBeFocused();
  await page.keyboard.press('Shift+Tab');
  await expect(speed).toBeFocused();
  await expect(speed).toHaveValue('1');
  expect(await speed.locator('option').allTextContents()).toEqual(['0.5\u00d7', '0.75\u00d7', '1\u00d7', '1.25\u00d7', '1.5\u00d7', '2\u00d7']);
  await page.keyboard.press('Escape');
  await expect(popup).toBeHidden();
  await expect(settings).toBeFocused();
  await expect(settings).toHaveAttribute('aria-expanded', 'false');
  // A press outside closes it too; the button again closes it.
  await settings.click();
  await expect(popup).toBeVisible();
  await page.mouse.click(5, 5);
  await expect(popup).toBeHidden();
  await settings.click();
  await expect(popup).toBeVisible();
  await settings.click();
  await expect(popup).toBeHidden();
});

test('browser: the voices are listed as "name (lang)" after Browser\'s default, those of the page\'s language first; a book in a French container lists French first; no voices: Speed alone', async ({ page }) => {
  const listed = async () => {
    await page.getByRole('toolbar').getByRole('button', { name: 'Voice and speed' }).click();
    const popup = page.getByRole('dialog', { name: 'Voice and speed' });
    await expect(popup).toBeVisible();
    return popup;
  };
  await openReading(page);  // the fixture's <html lang="en">
  let popup = await listed();
  expect(await popup.getByLabel('Voice').locator('option').allTextContents()).toEqual([
    'Browser\'s default', 'Alex (en-US)', 'Daniel (en-GB)', 'Hans (de-DE)', 'Thomas (fr-CA)', 'Amélie (fr-FR)',
  ]);
  await expect(popup.getByLabel('Voice')).toHaveValue('');
  await openReading(page, { lang: 'fr-FR' });
  popup = await listed();
  expect(await popup.getByLabel('Voice').locator('option').allTextContents()).toEqual([
    'Browser\'s default', 'Amélie (fr-FR)', 'Thomas (fr-CA)', 'Hans (de-DE)', 'Daniel (en-GB)', 'Alex (en-US)',
  ]);
  await openReading(page, { voices: [] });  // a narrated book in a browser without voices
  popup = await listed();
  await expect(popup.getByRole('combobox')).toHaveCount(1);
  await expect(popup.getByRole('combobox', { name: 'Speed' })).toBeFocused();
});

test('browser: a voice or speed chosen while reading changes the reading under way at once (update()), the reading not restarted', async ({ page }) => {
  await openReading(page);
  const toolbar = page.getByRole('toolbar');
  const read = toolbar.locator('[data-control=readAloud]');
  await expect(read).toBeVisible();
  await read.click();
  await expect(read).toHaveAttribute('data-on', 'true');
  await toolbar.getByRole('button', { name: 'Voice and speed' }).click();
  const popup = page.getByRole('dialog', { name: 'Voice and speed' });
  await popup.getByLabel('Speed').selectOption('1.25');
  expect(await lastCall(page, 'update')).toEqual(['update', { rate: 1.25, keys: ['rate'] }]);
  await popup.getByLabel('Voice').selectOption('Hans');
  expect(await lastCall(page, 'update')).toEqual(['update', { voice: 'Hans', keys: ['voice'] }]);
  await popup.getByLabel('Voice').selectOption('');  // back to the browser's default: voice given as undefined
  expect(await lastCall(page, 'update')).toEqual(['update', { keys: ['voice'] }]);
  expect((await calls(page)).filter(([name]) => name === 'readAloud' || name === 'stop')).toHaveLength(1);
  await expect(read).toHaveAttribute('data-on', 'true');
  // Paused, a choice still goes to the reading (it resumes with it).
  await page.keyboard.press('Escape');
  await read.click();
  await expect(read).toHaveAttribute('data-on', 'false');
  await toolbar.getByRole('button', { name: 'Voice and speed' }).click();
  await popup.getByLabel('Speed').selectOption('0.75');
  expect(await lastCall(page, 'update')).toEqual(['update', { rate: 0.75, keys: ['rate'] }]);
});

test('browser: remove() takes the popup and its readaloud* listeners away', async ({ page }) => {
  await openReading(page);
  await expect(page.locator('[role=toolbar] [data-control=readAloud]')).toBeVisible();
  expect(await page.evaluate(() => window.readAloudListeners)).toBe(5);  // start, pause, resume, end, and voices (listed late)
  await page.getByRole('toolbar').getByRole('button', { name: 'Voice and speed' }).click();
  await expect(page.getByRole('dialog', { name: 'Voice and speed' })).toBeVisible();
  await page.evaluate(() => window.controls.remove());
  expect(await page.evaluate(() => window.readAloudListeners)).toBe(0);
  await expect(page.getByRole('dialog')).toHaveCount(0);
  await page.evaluate(() => window.book.readAloud());  // the book reads on without its viewer
  expect(await page.evaluate(() => window.book.readingAloud.state)).toBe('reading');
});

test('browser: axe-core finds no serious or critical violation on the toolbar with the Voice and speed popup open, while reading', async ({ page }, testInfo) => {
  await openReading(page);
  const toolbar = page.getByRole('toolbar');
  await toolbar.locator('[data-control=readAloud]').click();
  await expect(toolbar.locator('[data-control=readAloud]')).toHaveAttribute('data-on', 'true');
  await toolbar.getByRole('button', { name: 'Voice and speed' }).click();
  const popup = page.getByRole('dialog', { name: 'Voice and speed' });
  await expect(popup).toBeVisible();
  expect(await seriousViolations(page)).toEqual([]);
  // Placed above the toolbar, inside the screen, by its button.
  const [box, bar, button] = await Promise.all([popup.boundingBox(), toolbar.boundingBox(),
    toolbar.getByRole('button', { name: 'Voice and speed' }).boundingBox()]);
  expect(box.y + box.height).toBeLessThanOrEqual(bar.y + 0.5);
  expect(box.x).toBeGreaterThanOrEqual(0);
  expect(box.x + box.width).toBeLessThanOrEqual(800);
  expect(Math.abs(box.x - button.x)).toBeLessThanOrEqual(1);
  await page.screenshot({ path: testInfo.outputPath('read-aloud-800x600.png') });  // looked at by hand
});

test.describe('a phone', () => {
  // Not isMobile: the fixture has no viewport meta, so a mobile browser would lay it out 980 px wide.
  test.use({ viewport: { width: 320, height: 568 }, deviceScaleFactor: 1, hasTouch: true });

  test('browser: on a narrow phone Read aloud and Voice and speed move into More and work from there; the popup opens by More, inside the screen, its selects 44 px high', async ({ page }, testInfo) => {
    await page.evaluate(() => Object.assign(document.getElementById('container').style, { width: '100%', height: '460px' }));
    await openReading(page);
    await page.waitForFunction(() => window.readAloudCalls.some(([name]) => name === 'canReadAloud'));
    const toolbar = page.getByRole('toolbar');
    const more = toolbar.getByRole('button', { name: 'More' });
    const menu = page.getByRole('menu', { name: 'More' });
    const item = (control) => menu.locator(`[data-control=${control}]`);
    await more.click();
    await expect(item('readAloud')).toBeVisible();
    await expect(item('readAloudSettings')).toBeVisible();
    await expect(toolbar.locator('[data-control=readAloud]')).toBeHidden();
    await expect(item('readAloud')).toHaveText('Read aloud');
    await item('readAloud').click();
    expect(await lastCall(page, 'readAloud')).toEqual(['readAloud', { rate: 1, keys: ['rate'] }]);
    await more.click();
    await expect(item('readAloud')).toHaveText('Pause reading');
    await expect(item('readAloud')).toHaveAttribute('data-on', 'true');
    await item('readAloudSettings').click();
    const popup = page.getByRole('dialog', { name: 'Voice and speed' });
    await expect(popup).toBeVisible();
    await expect(popup.getByRole('combobox', { name: 'Voice' })).toBeFocused();
    const box = await popup.boundingBox();
    expect(box.x).toBeGreaterThanOrEqual(0);
    expect(box.y).toBeGreaterThanOrEqual(0);
    expect(box.x + box.width).toBeLessThanOrEqual(320);
    for (const select of await popup.getByRole('combobox').all()) expect((await select.boundingBox()).height).toBeGreaterThanOrEqual(44);
    await popup.getByRole('combobox', { name: 'Speed' }).selectOption('2');
    expect(await lastCall(page, 'update')).toEqual(['update', { rate: 2, keys: ['rate'] }]);
    await page.keyboard.press('Escape');
    await expect(popup).toBeHidden();
    await expect(more).toBeFocused();
    // Pause from the menu.
    await more.click();
    await item('readAloud').click();
    expect(await lastCall(page, 'pause')).toEqual(['pause']);
    await more.click();
    await expect(item('readAloud')).toHaveText('Read aloud');
    await page.keyboard.press('Escape');
  });

  test.describe('390x844', () => {
    test.use({ viewport: { width: 390, height: 844 } });

    test('browser: on a 390 px phone the popup opens above the toolbar, inside the screen, its selects 44 px high', async ({ page }, testInfo) => {
      await page.evaluate(() => Object.assign(document.getElementById('container').style, { width: '100%', height: '600px' }));
      await openReading(page);
      const toolbar = page.getByRole('toolbar');
      await page.waitForFunction(() => window.readAloudCalls.some(([name]) => name === 'canReadAloud'));
      const settings = toolbar.locator('[data-control=readAloudSettings]');
      const inMenu = await settings.isHidden();
      if (inMenu) {
        await toolbar.getByRole('button', { name: 'More' }).click();
        await page.getByRole('menu').locator('[data-control=readAloudSettings]').click();
      } else {
        await settings.click();
      }
      const popup = page.getByRole('dialog', { name: 'Voice and speed' });
      await expect(popup).toBeVisible();
      const [box, bar] = await Promise.all([popup.boundingBox(), toolbar.boundingBox()]);
      expect(box.x).toBeGreaterThanOrEqual(0);
      expect(box.x + box.width).toBeLessThanOrEqual(390);
      expect(box.y + box.height).toBeLessThanOrEqual(bar.y + 0.5);
      for (const select of await popup.getByRole('combobox').all()) expect((await select.boundingBox()).height).toBeGreaterThanOrEqual(44);
      expect(await seriousViolations(page)).toEqual([]);
      await page.screenshot({ path: testInfo.outputPath('read-aloud-390x844.png') });  // looked at by hand
    });
  });
});
