// Browser: read-aloud that holds on real voices' ways (issue 37), on a speechSynthesis the test plays: a
// voice that goes silent mid-sentence (Chrome's network voices after ~15 s) is caught by the watchdog; a
// long sentence is said a clause at a time, each told by readaloudsentence; readaloudpage is told once a
// page; a display switch plans again from the word being read; voices listed late bring the Read button.
import { test, expect } from '@playwright/test';
import { UTTERANCE_STUB } from './speech-stubs.js';

// A speechSynthesis with one voice ('kal') that says each utterance in tasks of its own (start, then end)
// and reports no words, except that the utterances whose text is in window.stalls start and then say
// nothing more, no `end`, no `error` (each stall used once). What it was given: synth.said.
function playedSpeech() {
  const synth = new EventTarget();
  window.stalls = [];
  Object.assign(synth, {
    said: [],
    cancels: 0,
    getVoices: () => [{ name: 'kal', lang: 'en-US', default: true, localService: true, voiceURI: 'kal' }],
    speak(utterance) {
      synth.said.push(utterance.text);
      const stall = window.stalls.indexOf(utterance.text.trim());
      if (stall >= 0) window.stalls.splice(stall, 1);
      setTimeout(() => {
        utterance.dispatchEvent(new Event('start'));
        if (stall < 0) setTimeout(() => utterance.dispatchEvent(new Event('end')));
      });
    },
    cancel() { synth.cancels += 1; },
    pause() {},
    resume() {},
  });
  Object.defineProperty(window, 'speechSynthesis', { value: synth, configurable: true });
}

/** A book of text pages (html-fixture's makeTextPage), its read-aloud events logged in window.log. */
async function openTextBook(page, texts, options = {}) {
  await page.addInitScript({ path: UTTERANCE_STUB });
  await page.addInitScript(playedSpeech);
  await page.goto('/tests/browser/fixtures/html-fixture.html');
  await page.waitForFunction(() => document.body.dataset.ready);
  await page.evaluate(async ({ texts, options }) => {
    window.pageElements = texts.map((t) => window.makeTextPage(t));
    window.book = await window.Flipbook.create(window.container, { pages: window.pageElements, display: 'double', duration: 300, ...options });
    await window.book.whenIdle();
    window.log = [];
    for (const type of ['readaloudpage', 'readaloudsentence', 'turned', 'readaloudend', 'displaychange']) {
      window.book.addEventListener(type, (e) => window.log.push({ type, ...e.detail, error: e.detail.error?.message }));
    }
  }, { texts, options });
}

const ended = (page) => page.waitForFunction(() => window.log.some((e) => e.type === 'readaloudend'), null, { timeout: 60_000 })
  .then(() => page.evaluate(() => ({ log: window.log, said: window.speechSynthesis.said.map((t) => t.trim()), reading: window.book.readingAloud })));

test('browser: a voice that goes silent mid-sentence with no event (as Chrome\'s network voices do) is caught by the watchdog, the sentence said again from its start, and the reading ends finished', async ({ page }) => {
  test.setTimeout(120_000);
  await openTextBook(page, ['The cat sat. It was warm.', 'A dog came by. It barked.']);
  await page.evaluate(() => { window.stalls = ['It was warm.']; window.book.readAloud(); });
  const { log, said } = await ended(page);
  expect(said, JSON.stringify(log)).toEqual(['The cat sat.', 'It was warm.', 'It was warm.', 'A dog came by.', 'It barked.']);
  expect(log.filter((e) => e.type === 'readaloudend')).toEqual([{ type: 'readaloudend', reason: 'finished', page: 1 }]);
  expect(await page.evaluate(() => window.speechSynthesis.cancels)).toBeGreaterThanOrEqual(1);
});

test('browser: a voice that stalls twice in a row ends the reading with reason \'error\' and an error naming the voice; it is never left reading', async ({ page }) => {
  test.setTimeout(120_000);
  await openTextBook(page, ['The cat sat. It was warm.', 'A dog came by. It barked.']);
  await page.evaluate(() => { window.stalls = ['It was warm.', 'It was warm.']; window.book.readAloud(); });
  const { log, said, reading } = await ended(page);
  expect(said).toEqual(['The cat sat.', 'It was warm.', 'It was warm.']);
  const end = log.find((e) => e.type === 'readaloudend');
  expect(end).toMatchObject({ reason: 'error', page: 0 });
  expect(end.error).toMatch(/voice 'kal' stopped mid-sentence twice in a row/);
  expect(reading).toBeNull();
});

test('browser: a sentence longer than 200 characters is said a clause at a time, each told by readaloudsentence (its words, in order) and marked as it begins', async ({ page }) => {
  const long = 'This sentence goes on and on, with many clauses and commas in it; it runs past the limit of two hundred characters, '
    + 'because some writers write like this: long, winding, and full of turns, which a voice says in one breath until it stops.';
  await openTextBook(page, [`Short. ${long}`, 'The end.']);
  await page.evaluate(() => window.book.readAloud());
  const { log, said } = await ended(page);
  expect(long.length).toBeGreaterThan(200);
  expect(said.every((text) => text.length <= 200)).toBe(true);
  expect(said.slice(1, -1).join(' ')).toBe(long);
  expect(said.length).toBeGreaterThan(3);
  const sentences = log.filter((e) => e.type === 'readaloudsentence');
  expect(sentences.map((e) => e.text)).toEqual(said);
  expect(sentences.every((e) => e.rects.length >= 1 && e.to >= e.from)).toBe(true);
  // Each piece's words follow the last one's, through both pages.
  expect(sentences.map((e) => [e.page, e.from])).toEqual([[0, 0], ...sentences.slice(1, -1).map((e) => [0, e.from]), [1, 0]]);
  for (let i = 2; i < sentences.length - 1; i++) expect(sentences[i].from).toBe(sentences[i - 1].to + 1);
});

test('browser: readaloudpage is told once a page: an update() mid-page says the sentence again without telling the page again', async ({ page }) => {
  await openTextBook(page, ['One. Two. Three.', 'Four.']);
  await page.evaluate(() => {
    window.stalls = [];
    window.book.addEventListener('readaloudsentence', (e) => { if (e.detail.text === 'Two.' && !window.updated) { window.updated = true; window.book.readingAloud.update({ rate: 1.5 }); } });
    window.book.readAloud();
  });
  const { log, said } = await ended(page);
  expect(said).toEqual(['One.', 'Two.', 'Two.', 'Three.', 'Four.']);
  expect(log.filter((e) => e.type === 'readaloudpage').map((e) => e.page)).toEqual([0, 1]);
});

test('browser: update() mid-sentence, on a voice that reports words, says that sentence again from its start (not from the word)', async ({ page }) => {
  await openTextBook(page, ['One. Two words here. Three.', 'Four.']);
  const texts = await page.evaluate(() => new Promise((resolve) => {
    const said = [];
    // An engine that begins the page's second sentence, says its second word, and holds there.
    const engine = { speak(text, { onSentence, onWord }) {
      said.push(text);
      const at = text.indexOf('Two words');
      if (said.length === 1) {
        setTimeout(() => {
          onSentence(at, at + 'Two words here. '.length);
          onWord(at + 4, 5);
          window.book.readingAloud.update({ rate: 2 });
        });
      } else {
        resolve(said);
      }
      return { pause() {}, resume() {}, cancel() {} };
    } };
    window.book.readAloud({ engine });
  }));
  expect(texts).toEqual(['One. Two words here. Three.', 'Two words here. Three.']);
});

test('browser: a display switch mid-reading (a phone turned upright) shows the page being read and reads on from its word there', async ({ page }) => {
  await openTextBook(page, ['One. Two.', 'Three.', 'Four. Five. Six.', 'Seven.'], { startPage: 1 });
  await page.evaluate(() => {
    window.book.addEventListener('readaloudsentence', (e) => { if (e.detail.text === 'Five.' && !window.switched) { window.switched = true; window.book.setOptions({ display: 'single' }); } });
    window.book.readAloud();
  });
  const { log, said } = await ended(page);
  // Open: pages 1 and 2. At "Five." (page 2) the book shows one page, page 1: page 2 is shown at once and
  // read on from "Five.", then the book turns to page 3.
  expect(said).toEqual(['Three.', 'Four.', 'Five.', 'Five.', 'Six.', 'Seven.']);
  expect(log.filter((e) => e.type === 'readaloudpage').map((e) => e.page)).toEqual([1, 2, 3]);
  expect(log.filter((e) => e.type === 'turned').map((e) => e.page)).toEqual([2, 3]);
  expect(log.find((e) => e.type === 'readaloudend')).toMatchObject({ reason: 'finished', page: 3 });
  expect(log.filter((e) => e.type === 'displaychange').map((e) => e.display)).toEqual(['single']);
});

test('browser: on a voice without word events the sentence said last is drawn into the leaf as it curls (its light blue in the texture), and is gone once the leaf lands', async ({ page }) => {
  await openTextBook(page, ['The cat sat. It was warm.', 'A dog came by. It barked.', 'The end.'], { lighting: false, shadows: false, gutter: false });
  // Pixels of the sentence mark's blue (SENTENCE_FILL multiplied over white paper), read from the canvas.
  const bluish = () => {
    const view = window.book.surface;
    view.drawNow();
    const { data } = view.readPixels();
    let n = 0;
    for (let i = 0; i < data.length; i += 4) if (data[i + 2] > 235 && data[i + 2] - data[i] > 18 && data[i + 1] > 220 && data[i + 1] < 250) n += 1;
    return n;
  };
  const atStart = await page.evaluate((source) => new Promise((resolve) => {
    const count = new Function(`return (${source})()`);
    window.book.addEventListener('turnstart', () => resolve({ n: count(), marks: document.querySelectorAll('[data-reading]').length }), { once: true });
    window.book.readAloud();
  }), bluish.toString());
  expect(atStart.n).toBeGreaterThan(20);
  expect(atStart.marks).toBe(0);  // the elements give way while a leaf moves
  await page.waitForFunction(() => window.log.some((e) => e.type === 'turned'));
  await page.evaluate(() => { window.book.readingAloud?.stop(); return window.book.whenIdle(); });
  expect(await page.evaluate((source) => new Function(`return (${source})()`)(), bluish.toString())).toBe(0);
});

test('browser: voices listed after canReadAloud() answered false bring readaloudvoices, and the toolbar\'s Read button appears then', async ({ page }) => {
  test.setTimeout(120_000);
  // None at first; listed when the test says so (after the book's wait for them gave up).
  await page.addInitScript(() => {
    const synth = new EventTarget();
    let voices = [];
    window.listVoices = () => {
      voices = [{ name: 'late', lang: 'en-US', default: true, localService: true, voiceURI: 'late' }];
      synth.dispatchEvent(new Event('voiceschanged'));
    };
    Object.assign(synth, { getVoices: () => voices, speak() {}, cancel() {}, pause() {}, resume() {} });
    Object.defineProperty(window, 'speechSynthesis', { value: synth, configurable: true });
  });
  await page.goto('/tests/browser/fixtures/flipbook-fixture.html');
  await page.waitForFunction(() => document.body.dataset.ready);
  const can = await page.evaluate(async () => {
    await window.openBook({ pages: 6, display: 'double', controls: true });
    window.heard = [];
    window.book.addEventListener('readaloudvoices', (e) => window.heard.push(e.detail));
    return window.book.canReadAloud();
  });
  expect(can).toBe(false);
  const readButton = page.locator('[role=toolbar] button[data-control="readAloud"]');
  await expect(readButton).toBeHidden();
  await page.evaluate(() => window.listVoices());
  await expect(readButton).toBeVisible();
  expect(await page.evaluate(async () => [window.heard, await window.book.canReadAloud()])).toEqual([[{ count: 1 }], true]);
});
