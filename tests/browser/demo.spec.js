// Browser: the demo page served by `npm start` loads without errors, shows the book (a Flipbook), turns
// pages with its buttons, the keyboard and a corner drag, and opens frozen at an exact frame with ?t=;
// on a phone it fits the screen's width with a one-page book.
import { test, expect } from '@playwright/test';
import AxeBuilder from '@axe-core/playwright';
import { openReady } from './helpers.js';

// A desktop screen: the demo's book box there is wide enough for display 'auto' to open two pages of
// 300 CSS px or more (at the suite's 800x600 it would open one).
test.use({ viewport: { width: 1280, height: 800 } });

test('browser: demo loads with no console error and shows the cover', async ({ page }) => {
  const problems = await openReady(page, '/web/demo/');
  expect(problems).toEqual([]);
  await expect(page.locator('#where')).toHaveText('Page 1 of 40');
  await expect(page.locator('#readout')).toContainText('θ 90.0°');
});

test('browser: demo Next and Prev buttons turn a leaf each way and settle', async ({ page }) => {
  await openReady(page, '/web/demo/');
  await page.selectOption('#speed', '0.5');
  await page.click('#next');
  await expect(page.locator('body')).toHaveAttribute('data-state', 'open', { timeout: 30_000 });
  await expect(page.locator('#where')).toHaveText('Pages 2–3 of 40');
  await page.click('#next');
  await expect(page.locator('#where')).toHaveText('Pages 4–5 of 40', { timeout: 30_000 });
  await page.click('#prev');
  await expect(page.locator('#where')).toHaveText('Pages 2–3 of 40', { timeout: 30_000 });
  await expect(page.locator('body')).toHaveAttribute('data-state', 'open', { timeout: 30_000 });
});

test('browser: demo "Jump to page" riffles to the page asked for (one turnstart with riffle: true)', async ({ page }) => {
  await openReady(page, '/web/demo/');
  await page.evaluate(() => {
    window.starts = [];
    window.conecurlDemo.book.addEventListener('turnstart', (e) => window.starts.push(e.detail));
  });
  await page.fill('#jump-page', '30');
  await page.click('#jump button');
  await expect(page.locator('#where')).toHaveText('Pages 30–31 of 40', { timeout: 30_000 });
  expect(await page.evaluate(() => window.starts.map((s) => s.riffle))).toEqual([true]);
});

test('browser: demo Thickness and Sound toggles change the running book live', async ({ page }) => {
  await openReady(page, '/web/demo/');
  await page.evaluate(() => { window.firstBook = window.conecurlDemo.book; });
  expect(await page.evaluate(() => window.conecurlDemo.book.options.thickness)).toBe(true);
  await page.uncheck('#thickness');
  await page.check('#sound');
  expect(await page.evaluate(() => [window.conecurlDemo.book.options.thickness, window.conecurlDemo.book.options.sound])).toEqual([false, true]);
  // A gesture on the book starts the sound: its status leaves 'waiting'.
  await page.click('#next');
  await page.locator('#book canvas').click({ position: { x: 10, y: 10 } });
  await expect.poll(() => page.evaluate(() => window.conecurlDemo.book.sound.state), { timeout: 30_000 }).not.toBe('waiting');
  expect(await page.evaluate(() => window.conecurlDemo.book === window.firstBook)).toBe(true);  // no rebuild
});

test('browser: demo turns with the arrow keys when the book has focus', async ({ page }) => {
  await openReady(page, '/web/demo/?page=9');
  await page.selectOption('#speed', '0.5');
  await expect(page.locator('#where')).toHaveText('Pages 10–11 of 40');
  await page.focus('#book [aria-roledescription="book"]');
  // SwiftShader under a loaded CI machine draws few frames a second; each advances at most 0.25 s.
  await page.keyboard.press('ArrowRight');
  await expect(page.locator('#where')).toHaveText('Pages 12–13 of 40', { timeout: 30_000 });
  await page.keyboard.press('ArrowLeft');
  await expect(page.locator('#where')).toHaveText('Pages 10–11 of 40', { timeout: 30_000 });
});

test('browser: demo ?t=0.25 opens frozen at that frame with the schedule read out', async ({ page }) => {
  await openReady(page, '/web/demo/?page=3&t=0.25');
  await expect(page.locator('#readout')).toContainText('t 0.250');
  await expect(page.locator('#readout')).toContainText('ρ 45.0°');
});

test('browser: demo switches display and direction without errors', async ({ page }) => {
  const problems = await openReady(page, '/web/demo/?page=4');
  for (const [id, value] of [['display', 'single'], ['direction', 'rtl'], ['direction', 'vertical'], ['display', 'double']]) {
    await page.selectOption(`#${id}`, value);
    // The book has the new setting (display: live; direction: a new book), its pages loaded and a frame drawn.
    await page.waitForFunction(([id, value]) => window.conecurlDemo.book.options[id] === value, [id, value]);
    await page.evaluate(async () => {
      await window.conecurlDemo.book.whenIdle();
      await new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve)));
    });
  }
  await expect(page.locator('#where')).toContainText('of 40');
  expect(problems).toEqual([]);
});

test('browser: demo switches the schedule to smooth: the plot and readout follow it and the book turns with it', async ({ page }) => {
  const problems = await openReady(page, '/web/demo/?t=0.07');
  const paper = await page.locator('#readout').textContent();
  await page.selectOption('#schedule', 'smooth');
  await page.waitForFunction(() => window.conecurlDemo.book.options.schedule === 'smooth');
  const smooth = await page.locator('#readout').textContent();
  expect(paper).toMatch(/^t 0\.070/);
  expect(smooth).toMatch(/^t 0\.070/);
  expect(smooth).not.toBe(paper);  // another theta and Ay between the key poses
  await page.click('#next');
  await expect(page.locator('#where')).toContainText('Pages 2–3 of 40', { timeout: 30_000 });
  expect(problems).toEqual([]);
});

test('browser: demo book turns when its corner is dragged across the spine', async ({ page }) => {
  await openReady(page, '/web/demo/?page=9');
  await page.selectOption('#speed', '0.5');
  const box = await page.locator('#book canvas').boundingBox();
  const rect = await page.evaluate(() => window.conecurlDemo.book.restingRect());
  const from = { x: box.x + rect.x + rect.width - 3, y: box.y + rect.y + rect.height - 3 };
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  for (let i = 1; i <= 12; i++) await page.mouse.move(from.x - (i / 12) * rect.width * 0.8, from.y - i * 4);
  await page.mouse.up();
  await expect(page.locator('#where')).toHaveText('Pages 12–13 of 40', { timeout: 30_000 });
});

test('browser: demo shows its PDF example through pdf.js, and the contents links turn to their pages', async ({ page }) => {
  await page.setViewportSize({ width: 1440, height: 900 });  // a spread of the PDF's pages, each 300 CSS px or more, beside its toolbar
  const problems = await openReady(page, '/web/demo/');
  await page.selectOption('#source', 'pdf');
  await expect(page.locator('#where')).toHaveText('Page 1 of 12', { timeout: 30_000 });
  // The PDF book is shown as a document: with the toolbar (controls: true), Download and Print too.
  await expect(page.getByRole('toolbar', { name: 'Book controls' }).getByRole('button', { name: 'Print' })).toBeVisible();
  await page.click('#next');
  await expect(page.locator('#where')).toHaveText('Pages 2–3 of 12', { timeout: 30_000 });
  const contentsLinks = page.locator('#book .conecurl-links a');
  await expect(contentsLinks).toHaveCount(9, { timeout: 30_000 });
  await contentsLinks.nth(4).click();  // "5. Cones, not cylinders", on page 7
  await expect(page.locator('#where')).toHaveText('Pages 6–7 of 12', { timeout: 30_000 });
  expect(problems).toEqual([]);
});

test('browser: demo shows its picture book that reads itself: every page has narration whose WAV decodes to its length, and every word\'s box covers its ink', async ({ page }) => {
  await page.setViewportSize({ width: 1440, height: 900 });  // a spread of two 300 CSS px pages beside the toolbar
  const problems = await openReady(page, '/web/demo/');
  await page.selectOption('#source', 'story');
  await expect(page.locator('#where')).toHaveText('Page 1 of 8', { timeout: 30_000 });
  await expect(page.getByRole('toolbar', { name: 'Book controls' })).toBeVisible();  // controls: true
  await page.evaluate(() => window.conecurlDemo.book.whenIdle());
  const pages = await page.evaluate(async () => {
    const context = new OfflineAudioContext(1, 1, 22050);
    const entries = window.conecurlDemo.storyPages();
    const out = [];
    for (const entry of entries) {
      const { src, words } = entry.narration;
      const bytes = new Uint8Array(await (await fetch(src)).arrayBuffer());
      const view = new DataView(bytes.buffer);
      const expected = view.getUint32(40, true) / 2 / view.getUint32(24, true);  // data bytes / 2 / rate
      const audio = await context.decodeAudioData(bytes.buffer.slice(0));
      const canvas = entry.src();
      const g = canvas.getContext('2d');
      const inked = words.map(({ rect: [x, y, w, h] }) => {
        const box = [Math.floor(x * canvas.width), Math.floor(y * canvas.height), Math.ceil(w * canvas.width), Math.ceil(h * canvas.height)];
        const { data } = g.getImageData(...box);
        let dark = 0;
        for (let i = 0; i < data.length; i += 4) if (data[i] + data[i + 1] + data[i + 2] < 3 * 90) dark++;
        return dark / (data.length / 4);
      });
      out.push({ src, alt: entry.alt, expected, decoded: audio.duration, channels: audio.numberOfChannels, words, inked,
        aspect: canvas.width / canvas.height });
    }
    return out;
  });
  expect(pages.length).toBe(8);
  expect(pages[0].words.map((w) => w.text).join(' ')).toBe('The Little Paper Boat');  // the cover reads its title
  for (const [index, entry] of pages.entries()) {
    expect(entry.src, `page ${index + 1}`).toMatch(/^blob:/);
    expect(entry.channels).toBe(1);
    expect(Math.abs(entry.decoded - entry.expected), `page ${index + 1}: ${entry.decoded} s decoded, ${entry.expected} s in the WAV`).toBeLessThan(0.01);
    expect(entry.words.length).toBeGreaterThan(0);
    expect(entry.aspect).toBeCloseTo(0.8, 5);
    let before = 0;
    entry.words.forEach((word, i) => {
      const [x, y, w, h] = word.rect;
      const where = `page ${index + 1}, "${word.text}"`;
      expect(word.start, where).toBeGreaterThanOrEqual(before);
      expect(word.end, where).toBeGreaterThan(word.start);
      expect(word.end, where).toBeLessThanOrEqual(entry.expected);
      before = word.end;
      expect(Math.min(x, y, w, h), `${where}: ${word.rect}`).toBeGreaterThan(0);
      expect(Math.max(x + w, y + h), `${where}: ${word.rect}`).toBeLessThan(1);
      expect(entry.inked[i], `${where}: dark ink in its box`).toBeGreaterThan(0.08);
    });
    // The words are the page's text, in order (as its alt text says it, the covers with a label before).
    expect(entry.alt.endsWith(entry.words.map((w) => w.text).join(' '))).toBe(true);
  }
  await page.click('#next');
  await expect(page.locator('#where')).toHaveText('Pages 2–3 of 8', { timeout: 30_000 });
  expect(problems).toEqual([]);
});

test('browser: demo "Read aloud" on the picture book plays the cover\'s narration, marks its words, turns by itself and reads on; Stop stops it', async ({ page }) => {
  test.setTimeout(180_000);
  const problems = await openReady(page, '/web/demo/');
  await page.selectOption('#source', 'story');  // recorded narration: no speech voice needed
  await expect(page.locator('#where')).toHaveText(/ of 8$/, { timeout: 30_000 });
  await page.evaluate(() => {
    window.heard = [];
    const { book } = window.conecurlDemo;
    for (const type of ['readaloudstart', 'readaloudpage', 'readaloudword', 'turned', 'readaloudend']) {
      book.addEventListener(type, (e) => window.heard.push({ type, page: e.detail.page, text: e.detail.text, reason: e.detail.reason,
        marks: document.querySelectorAll('[data-reading]').length }));
    }
  });
  await expect(page.locator('#read-aloud')).toHaveText('Read aloud');
  await page.click('#read-aloud');
  await expect(page.locator('#read-aloud')).toHaveText('Stop');
  // The cover's title, word by word, each marked; then the book turns itself and page 1 is read.
  await page.waitForFunction(() => window.heard.some((e) => e.type === 'readaloudword' && e.page === 1), null, { timeout: 60_000 });
  const heard = await page.evaluate(() => window.heard);
  expect(heard.filter((e) => e.type === 'readaloudword' && e.page === 0).map((e) => e.text)).toEqual(['The', 'Little', 'Paper', 'Boat']);
  expect(heard.filter((e) => e.type === 'readaloudword').every((e) => e.marks > 0)).toBe(true);
  expect(heard.filter((e) => e.type !== 'readaloudword').map((e) => `${e.type} ${e.page}`).slice(0, 4))
    .toEqual(['readaloudstart 0', 'readaloudpage 0', 'turned 1', 'readaloudpage 1']);
  await page.click('#read-aloud');
  await expect(page.locator('#read-aloud')).toHaveText('Read aloud');
  expect(await page.evaluate(() => window.heard.filter((e) => e.type === 'readaloudend').map((e) => e.reason))).toEqual(['stopped']);
  expect(await page.locator('[data-reading]').count()).toBe(0);
  expect(problems).toEqual([]);
});

test('browser: demo "Read aloud" on the PDF brochure reads with the browser\'s voice: speechSynthesis.speak gets the cover\'s first line (a sentence an utterance) in the page\'s language, and the toolbar shows its Read button', async ({ page }) => {
  // A browser with one voice (this machine's Chromium has none): speak() records what it is given.
  await page.addInitScript(() => {
    const synth = new EventTarget();
    const voice = { name: 'Demo Voice', lang: 'en-GB', default: true, localService: true, voiceURI: 'demo' };
    Object.assign(synth, { spoken: [], getVoices: () => [voice], speak(u) { this.spoken.push(u); }, cancel() {}, pause() {}, resume() {} });
    Object.defineProperty(window, 'speechSynthesis', { value: synth, configurable: true });
    window.SpeechSynthesisUtterance = class extends EventTarget {
      constructor(text) {
        super();
        Object.assign(this, { text, lang: '', rate: 1, pitch: 1, voice: null });
      }
    };
  });
  await page.setViewportSize({ width: 1440, height: 900 });
  const problems = await openReady(page, '/web/demo/');
  await page.selectOption('#source', 'pdf');
  await expect(page.locator('#where')).toHaveText(/ of 12$/, { timeout: 30_000 });
  await expect(page.locator('[role=toolbar] [data-control=readAloud]')).toBeVisible();
  await page.click('#read-aloud');
  await page.waitForFunction(() => window.speechSynthesis.spoken.length === 1, null, { timeout: 30_000 });
  const spoken = await page.evaluate(() => ({ text: window.speechSynthesis.spoken[0].text, lang: window.speechSynthesis.spoken[0].lang }));
  // Read a sentence an utterance, and a PDF's line is a sentence: the cover's title first (this stub
  // never ends an utterance, so nothing follows it).
  expect(spoken.text.trim()).toBe('Turning Pages');
  expect(spoken.lang).toBe(await page.evaluate(() => document.documentElement.lang));
  await expect(page.locator('#read-aloud')).toHaveText('Stop');
  await page.click('#read-aloud');
  await expect(page.locator('#read-aloud')).toHaveText('Read aloud');
  expect(problems).toEqual([]);
});

test('browser: the demo passes axe-core with no serious or critical violation (contrast, names matching visible text, ...)', async ({ page }) => {
  await openReady(page, '/web/demo/');  // the demo says it is ready once the plot and the readout are drawn
  await page.evaluate(() => window.conecurlDemo.book.whenIdle());  // and the book's pages
  const { violations } = await new AxeBuilder({ page }).analyze();
  const serious = violations.filter((v) => v.impact === 'serious' || v.impact === 'critical')
    .map((v) => `${v.impact} ${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`);
  expect(serious).toEqual([]);
});

// Phones (issue 22): nothing overflows sideways, the book takes the width and shows one page (display
// 'auto' in a book taller than wide), and every control lies on the screen, tall enough for a finger.
for (const width of [360, 390, 430]) {
  test.describe(`a ${width}x844 phone`, () => {
    test.use({ viewport: { width, height: 844 }, deviceScaleFactor: 1, hasTouch: true, isMobile: true });

    test(`browser: demo fits a ${width} px wide phone: no sideways scroll, a single page across the width, controls on screen`, async ({ page }) => {
      const problems = await openReady(page, '/web/demo/');
      expect(await page.evaluate(() => document.documentElement.scrollWidth)).toBe(width);
      const book = await page.locator('#book canvas').boundingBox();
      expect(book.width).toBeGreaterThanOrEqual(0.9 * width);
      expect(await page.evaluate(() => window.conecurlDemo.book.display)).toBe('single');
      await expect(page.locator('#where')).toHaveText('Page 1 of 40');

      const controls = page.locator('.nav button, .nav input, .controls select, .controls input, .controls output, #plot');
      expect(await controls.count()).toBeGreaterThan(12);
      for (const control of await controls.all()) {
        const box = await control.boundingBox();
        const name = await control.evaluate((e) => e.id || e.textContent.trim() || e.tagName);
        expect(box.x, `${name} starts on screen`).toBeGreaterThanOrEqual(0);
        expect(box.x + box.width, `${name} ends on screen`).toBeLessThanOrEqual(width);
      }
      for (const control of await page.locator('.nav button, .nav input, .controls select').all()) {
        expect((await control.boundingBox()).height, 'a finger-sized target').toBeGreaterThanOrEqual(40);
      }

      // One page a tap.
      await page.selectOption('#speed', '0.5');
      await page.locator('#next').tap();
      await expect(page.locator('#where')).toHaveText('Page 2 of 40', { timeout: 30_000 });
      expect(problems).toEqual([]);
    });
  });
}
