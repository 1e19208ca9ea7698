// Browser: read-aloud (issue 31) on a speech engine the test drives (readAloud({ engine })): over the
// test PDF, the words of each open page are said and marked in order (data-reading elements over the
// word's glyphs, the same rectangles search() gives), the book turns at the end of the open pages and
// reading goes on at the next page's first word, with the last word drawn into the curling leaf; pause
// and resume; a reader's turn stops it (or, with follow, moves it); stop() and destroy() mid-word leave
// nothing behind; the default engine hands speechSynthesis.speak the page's text and language.
import { test, expect } from '@playwright/test';
import { UTTERANCE_STUB } from './speech-stubs.js';
import { openPdfBook as openPdf, makeDocumentPdf, PAGES } from './document-pdf.js';

let made;
test.beforeAll(async () => { made = await makeDocumentPdf(); });

const openPdfBook = (page, options) => openPdf(page, made, { lighting: false, shadows: false, gutter: false, ...options });

// A speech engine the test drives: each speak() is recorded; window.sayWords(n) says the next n words of
// the latest utterance (onWord at each word's first character), window.finish() ends it (onEnd).
async function installEngine(page) {
  await page.evaluate(() => {
    window.events = [];
    for (const type of ['readaloudstart', 'readaloudpage', 'readaloudword', 'readaloudpause', 'readaloudresume', 'readaloudend', 'turnstart', 'turned']) {
      window.book.addEventListener(type, (e) => window.events.push({ type, ...e.detail }));
    }
    const engine = { calls: [] };
    engine.speak = (text, options) => {
      const call = { text, lang: options.lang, rate: options.rate, pitch: options.pitch, voice: options.voice, paused: false, cancelled: false, said: 0, options };
      call.words = [...text.matchAll(/\S+/g)].map((m) => ({ at: m.index, length: m[0].length, text: m[0] }));
      engine.calls.push(call);
      return { pause() { call.paused = true; }, resume() { call.paused = false; }, cancel() { call.cancelled = true; } };
    };
    window.engine = engine;
    const latest = () => engine.calls[engine.calls.length - 1];
    window.sayWords = (n) => {
      const call = latest();
      for (let k = 0; k < n && call.said < call.words.length; k++, call.said++) {
        const word = call.words[call.said];
        call.options.onWord(word.at, word.length);
      }
      return call.words.slice(0, call.said).map((w) => w.text);
    };
    window.finish = () => latest().options.onEnd();
    window.calls = () => engine.calls.map(({ text, lang, paused, cancelled, said }) => ({ text, lang, paused, cancelled, said }));
  });
}

// The words of page `index` as pdf.js reads its text (the fixture's heading, lines and page number).
const textOf = (index) => [PAGES[index].heading, ...PAGES[index].lines, String(index + 1)].join(' ');
const pageWords = (index) => textOf(index).split(/\s+/);
const reading = (page) => page.evaluate(() => ({ state: window.book.readingAloud?.state ?? null, marks: document.querySelectorAll('[data-reading]').length }));

test('browser: readAloud({ engine }) says the open pages\' words in order, marks each over its glyphs, turns at their end and goes on at the next page', async ({ page }) => {
  await openPdfBook(page);
  await installEngine(page);
  await page.evaluate(() => window.book.readAloud({ engine: window.engine, lang: 'en-GB', rate: 1.5 }));
  await page.waitForFunction(() => window.engine.calls.length === 1);
  // The cover lies alone: its text, in the language asked for.
  let calls = await page.evaluate(() => window.calls());
  expect(calls[0].text.split(/\s+/)).toEqual(pageWords(0));
  expect(calls[0].lang).toBe('en-GB');
  // Word by word: each marked where search() finds it, on page 0.
  for (let k = 1; k <= 3; k++) {
    await page.evaluate(() => window.sayWords(1));
    const { word, event, marks, hit } = await page.evaluate(async () => {
      const word = window.book.readingAloud.word;
      const event = window.events.filter((e) => e.type === 'readaloudword').pop();
      const marks = [...document.querySelectorAll('[data-reading]')].map((m) => ({ page: Number(m.dataset.page), box: m.getBoundingClientRect().toJSON() }));
      const hits = await window.book.search(word.text.replace(/[^\p{L}]/gu, ''));
      return { word, event, marks, hit: hits.find((h) => h.page === word.page) };
    });
    expect(word.text).toBe(pageWords(0)[k - 1]);
    expect(event).toMatchObject({ page: 0, index: k - 1, text: word.text });
    expect(marks.length).toBe(word.rects.length);
    expect(marks.every((m) => m.page === 0)).toBe(true);
    // The word's rectangle is search()'s for the same word, to a hair.
    expect(hit).toBeTruthy();
    for (let i = 0; i < 4; i++) expect(Math.abs(word.rects[0][i] - hit.rects[0][i])).toBeLessThan(0.003);
  }
  await page.evaluate(() => window.book.clearSearch());
  // The rest of the cover, then its end: the book turns by itself (one turn), and page 1 is read, then page 2.
  await page.evaluate(() => { window.sayWords(100); window.finish(); });
  await page.waitForFunction(() => window.engine.calls.length === 2);
  calls = await page.evaluate(() => window.calls());
  expect(calls[1].text.split(/\s+/)).toEqual(pageWords(1));
  const turns = await page.evaluate(() => window.events.filter((e) => e.type === 'turnstart' || e.type === 'turned').map((e) => e.type));
  expect(turns).toEqual(['turnstart', 'turned']);
  expect(await page.evaluate(() => window.book.openPages)).toEqual([1, 2]);
  await page.evaluate(() => { window.sayWords(2); });
  expect(await page.evaluate(() => window.book.readingAloud.word)).toMatchObject({ page: 1, index: 1, text: 'One:' });
  await page.evaluate(() => { window.sayWords(100); window.finish(); });
  await page.waitForFunction(() => window.engine.calls.length === 3);
  calls = await page.evaluate(() => window.calls());
  expect(calls[2].text.split(/\s+/)).toEqual(pageWords(2));
  const pagesRead = await page.evaluate(() => window.events.filter((e) => e.type === 'readaloudpage').map((e) => [e.page, e.source]));
  expect(pagesRead).toEqual([[0, 'text'], [1, 'text'], [2, 'text']]);
  // Every word said so far came in order, on its page.
  const said = await page.evaluate(() => window.events.filter((e) => e.type === 'readaloudword').map((e) => `${e.page}:${e.text}`));
  expect(said).toEqual([...pageWords(0).map((w) => `0:${w}`), ...pageWords(1).map((w) => `1:${w}`)]);
  await page.evaluate(() => window.book.readingAloud.stop());
});

test('browser: at the end of the open pages the last word said is drawn into the leaf as it curls, and is gone from the texture once it lands', async ({ page }) => {
  await openPdfBook(page, { startPage: 1 });
  await installEngine(page);
  const blue = () => page.evaluate(() => {
    const view = window.book.surface;
    view.drawNow();
    const { data } = view.readPixels();
    let n = 0;
    for (let i = 0; i < data.length; i += 4) if (data[i + 2] > 220 && data[i + 2] - data[i] > 50 && data[i + 1] > 150) n += 1;
    return n;
  });
  await page.evaluate(() => window.book.readAloud({ engine: window.engine }));
  await page.waitForFunction(() => window.engine.calls.length === 1);
  await page.evaluate(() => { window.sayWords(100); window.finish(); });
  await page.waitForFunction(() => window.engine.calls.length === 2);  // page 2, the right page
  await page.evaluate(() => window.sayWords(1));  // its heading's first word; the engine ends there
  // Flat: the mark is an element over the canvas, not in the page's texture.
  expect(await blue()).toBe(0);
  expect((await reading(page)).marks).toBeGreaterThan(0);
  // The end of page 2: as the leaf carrying page 2 starts to move, its last word said is blue in its texture.
  const atStart = await page.evaluate(() => new Promise((resolve) => {
    window.book.addEventListener('turnstart', () => {
      const view = window.book.surface;
      view.drawNow();
      const { data } = view.readPixels();
      let n = 0;
      for (let i = 0; i < data.length; i += 4) if (data[i + 2] > 220 && data[i + 2] - data[i] > 50 && data[i + 1] > 150) n += 1;
      resolve({ n, marks: document.querySelectorAll('[data-reading]').length });
    }, { once: true });
    window.finish();
  }));
  expect(atStart.n).toBeGreaterThan(20);
  expect(atStart.marks).toBe(0);  // the elements give way while a leaf moves
  await page.waitForFunction(() => window.engine.calls.length === 3);
  await page.evaluate(() => window.book.readingAloud.stop());
  await page.evaluate(() => window.book.whenIdle());
  expect(await blue()).toBe(0);
});

test('browser: pause() holds the engine and the turn, resume() goes on; readaloudpause and readaloudresume say so', async ({ page }) => {
  await openPdfBook(page);
  await installEngine(page);
  await page.evaluate(() => window.book.readAloud({ engine: window.engine }));
  await page.waitForFunction(() => window.engine.calls.length === 1);
  await page.evaluate(() => window.sayWords(2));
  await page.evaluate(() => window.book.readingAloud.pause());
  expect(await page.evaluate(() => [window.book.readingAloud.state, window.calls()[0].paused])).toEqual(['paused', true]);
  await page.evaluate(() => window.book.readingAloud.resume());
  expect(await page.evaluate(() => [window.book.readingAloud.state, window.calls()[0].paused])).toEqual(['reading', false]);
  // Paused just as the page ends (an engine may end while pausing): no turn until resume().
  await page.evaluate(() => { window.sayWords(100); window.book.readingAloud.pause(); window.finish(); });
  await page.evaluate(() => window.book.whenIdle());
  expect(await page.evaluate(() => [window.book.page, window.book.animating, window.engine.calls.length])).toEqual([0, false, 1]);
  await page.evaluate(() => window.book.readingAloud.resume());
  await page.waitForFunction(() => window.engine.calls.length === 2);
  expect(await page.evaluate(() => window.book.openPages)).toEqual([1, 2]);
  const kinds = await page.evaluate(() => window.events.filter((e) => e.type === 'readaloudpause' || e.type === 'readaloudresume').map((e) => e.type));
  expect(kinds).toEqual(['readaloudpause', 'readaloudresume', 'readaloudpause', 'readaloudresume']);
  await page.evaluate(() => window.book.readingAloud.stop());
});

test('browser: a reader\'s own turn stops the reading at once; with follow: true the reading goes on at the new page', async ({ page }) => {
  await openPdfBook(page);
  await installEngine(page);
  await page.evaluate(() => window.book.readAloud({ engine: window.engine }));
  await page.waitForFunction(() => window.engine.calls.length === 1);
  await page.evaluate(() => window.sayWords(2));
  // next(), as a key or a button would: the speech is cancelled and the mark goes with the turn's start.
  const stopped = await page.evaluate(async () => {
    const turning = window.book.next();
    const right = { state: window.book.readingAloud?.state ?? null, cancelled: window.calls()[0].cancelled, marks: document.querySelectorAll('[data-reading]').length };
    await turning;
    return { right, end: window.events.filter((e) => e.type === 'readaloudend') };
  });
  expect(stopped.right).toEqual({ state: null, cancelled: true, marks: 0 });
  expect(stopped.end).toEqual([{ type: 'readaloudend', reason: 'turned', page: 0 }]);
  // A word the cancelled engine still reports changes nothing.
  await page.evaluate(() => window.sayWords(1));
  expect(await page.evaluate(() => window.events.filter((e) => e.type === 'readaloudword').length)).toBe(2);
  // follow: true: flip(5) riffles away; the reading waits, then reads pages 5 and 6 from their first word.
  await page.evaluate(() => window.book.readAloud({ engine: window.engine, follow: true }));
  await page.waitForFunction(() => window.engine.calls.length === 2);
  await page.evaluate(() => window.sayWords(1));
  await page.evaluate(() => window.book.flip(5));
  await page.waitForFunction(() => window.engine.calls.length === 3);
  const followed = await page.evaluate(() => ({ calls: window.calls(), state: window.book.readingAloud.state, open: window.book.openPages }));
  expect(followed.calls[1].cancelled).toBe(true);
  expect(followed.open).toEqual([5, 6]);
  expect(followed.calls[2].text).toBe(followed.calls[2].text.trim() ? followed.calls[2].text : 'x');
  expect(followed.calls[2].text.split(/\s+/)).toEqual(pageWords(5));
  expect(followed.state).toBe('reading');
  await page.evaluate(() => window.book.readingAloud.stop());
});

test('browser: with follow: true, a drag let go short of the spine (turnstart, then turncancel) goes on at the word it was on', async ({ page }) => {
  await openPdfBook(page, { startPage: 1 });
  await installEngine(page);
  await page.evaluate(() => window.book.readAloud({ engine: window.engine, follow: true }));
  await page.waitForFunction(() => window.engine.calls.length === 1);
  await page.evaluate(() => window.sayWords(4));  // "Chapter One: Zebras The"
  // What the drag module tells the book as a reader takes hold of a corner and lets it fall back.
  const held = await page.evaluate(() => {
    window.book.dispatchEvent(new CustomEvent('turnstart', { detail: { direction: 'forward', page: 1, drag: true } }));
    return { state: window.book.readingAloud.state, cancelled: window.calls()[0].cancelled, marks: document.querySelectorAll('[data-reading]').length };
  });
  expect(held).toEqual({ state: 'waiting', cancelled: true, marks: 0 });
  await page.evaluate(() => window.book.dispatchEvent(new CustomEvent('turncancel', { detail: { page: 1 } })));
  await page.waitForFunction(() => window.engine.calls.length === 2);
  const again = await page.evaluate(() => ({ text: window.calls()[1].text, state: window.book.readingAloud.state }));
  expect(again.state).toBe('reading');
  expect(again.text.split(/\s+/)).toEqual(pageWords(1).slice(3));  // from "The", the word it was on
  await page.evaluate(() => window.book.readingAloud.stop());
});

test('browser: stop() and destroy() mid-word leave nothing behind: engine cancelled, no mark, no listener, readaloudend said once', async ({ page }) => {
  await openPdfBook(page, { sound: true });
  await installEngine(page);
  await page.evaluate(() => window.book.readAloud({ engine: window.engine }));
  await page.waitForFunction(() => window.engine.calls.length === 1);
  await page.evaluate(() => window.sayWords(3));
  expect(await page.evaluate(() => window.book.sound.ducked)).toBe(true);  // the page sound under the voice
  expect((await reading(page)).marks).toBeGreaterThan(0);
  await page.evaluate(() => window.book.readingAloud.stop());
  const after = await page.evaluate(async () => {
    window.sayWords(2);         // the cancelled engine goes on talking: nothing hears it
    window.finish();
    await window.book.next();   // a turn no longer concerns the reading
    await window.book.whenIdle();
    return {
      calls: window.calls().map((c) => c.cancelled),
      reading: window.book.readingAloud,
      marks: document.querySelectorAll('[data-reading]').length,
      ducked: window.book.sound.ducked,
      ends: window.events.filter((e) => e.type === 'readaloudend').map((e) => e.reason),
      words: window.events.filter((e) => e.type === 'readaloudword').length,
    };
  });
  expect(after).toEqual({ calls: [true], reading: null, marks: 0, ducked: false, ends: ['stopped'], words: 3 });
  // destroy() mid-word: readaloudend (reason 'destroyed') still reaches the listener, then nothing.
  await page.evaluate(() => window.book.readAloud({ engine: window.engine }));
  await page.waitForFunction(() => window.engine.calls.length === 2);
  await page.evaluate(() => window.sayWords(2));
  const destroyed = await page.evaluate(() => {
    window.book.destroy();
    window.sayWords(2);
    window.finish();
    return {
      cancelled: window.calls()[1].cancelled,
      ends: window.events.filter((e) => e.type === 'readaloudend').map((e) => e.reason),
      marks: document.querySelectorAll('[data-reading], .conecurl-reading').length,
    };
  });
  expect(destroyed).toEqual({ cancelled: true, ends: ['stopped', 'destroyed'], marks: 0 });
});

test('browser: the default engine hands speechSynthesis.speak the page\'s text a sentence an utterance, with its language, voice and rate, and marks words at its boundary events', async ({ page }) => {
  // The browser's speech synthesis replaced, before the page loads, by one that records what it is given.
  await page.addInitScript({ path: UTTERANCE_STUB });
  await page.addInitScript(() => {
    const voices = [{ name: 'Test Voice', lang: 'en-US', default: true, localService: true, voiceURI: 'test-voice' },
      { name: 'Voix', lang: 'fr-FR', default: false, localService: true, voiceURI: 'voix' }];
    const spoken = [];
    const synth = new EventTarget();
    Object.assign(synth, {
      spoken,
      getVoices: () => voices,
      speak: (utterance) => spoken.push(utterance),
      pause() { this.paused = true; },
      resume() { this.paused = false; },
      cancel() { this.cancelled = (this.cancelled ?? 0) + 1; },
    });
    Object.defineProperty(window, 'speechSynthesis', { value: synth, configurable: true });
  });
  await openPdfBook(page);
  await installEngine(page);
  const result = await page.evaluate(async () => {
    const document = window.document;
    document.documentElement.lang = 'en-AU';
    const voices = await window.book.readAloudVoices();
    const can = await window.book.canReadAloud();
    await window.book.readAloud({ voice: 'Voix', rate: 0.75 });
    const { spoken } = window.speechSynthesis;
    const next = async (n) => { while (spoken.length < n) await new Promise((resolve) => requestAnimationFrame(resolve)); };
    // Each sentence ended in turn until the book turned and page 1's first is said; the second sentence's
    // boundary event marks a word counted from the page's start.
    let word = null;
    for (let i = 0; window.book.readingAloud.page === 0; i++) {
      await next(i + 1);
      if (window.book.readingAloud.page !== 0) break;
      if (i === 1) {
        spoken[1].dispatchEvent(Object.assign(new Event('boundary'), { name: 'word', charIndex: spoken[1].text.search(/\s/) + 1, charLength: 4 }));
        word = window.book.readingAloud.word;
      }
      spoken[i].dispatchEvent(new Event('end'));
      await next(i + 2);
    }
    const first = spoken[0];
    return { voices, can, texts: spoken.map((u) => u.text.trim()), lang: first.lang, voice: first.voice?.name, rate: first.rate, word };
  });
  expect(result.voices).toEqual([{ name: 'Test Voice', lang: 'en-US', default: true, local: true, voiceURI: 'test-voice' }, { name: 'Voix', lang: 'fr-FR', default: false, local: true, voiceURI: 'voix' }]);
  expect(result.can).toBe(true);
  // Page 0's lines (its heading, a sentence a line, its number), one utterance each; then page 1's heading.
  expect(result.texts).toEqual([PAGES[0].heading, ...PAGES[0].lines, '1', PAGES[1].heading]);
  expect(result.lang).toBe('en-AU');  // the page's: the PDF says none, the web page says en-AU
  expect(result).toMatchObject({ voice: 'Voix', rate: 0.75 });
  expect(result.word).toMatchObject({ page: 0, index: 2, text: pageWords(0)[2] });
  // A voice the browser does not have is a clear error.
  const error = await page.evaluate(() => window.book.readAloud({ voice: 'Nobody' }).then(() => null, (e) => e.message));
  expect(error).toMatch(/no voice named 'Nobody'.*'Test Voice', 'Voix'/);
});

test('browser: where speech synthesis has no voice, readAloud() rejects with an error that says what to do, and canReadAloud() is false', async ({ page }) => {
  await page.addInitScript(() => {
    const synth = new EventTarget();
    Object.assign(synth, { getVoices: () => [], speak() { throw new Error('no voice to speak with'); }, cancel() {}, pause() {}, resume() {} });
    Object.defineProperty(window, 'speechSynthesis', { value: synth, configurable: true });
  });
  await openPdfBook(page);
  const result = await page.evaluate(async () => ({
    can: await window.book.canReadAloud(),
    error: await window.book.readAloud().then(() => null, (e) => e.message),
    reading: window.book.readingAloud,
    bad: await window.book.readAloud({ rate: 20 }).then(() => null, (e) => e.message),
  }));
  expect(result.can).toBe(false);
  expect(result.error).toMatch(/readAloud\(\) found no voice.*narration.*engine/);
  expect(result.reading).toBeNull();
  expect(result.bad).toMatch(/'rate' must be a number from 0.1 to 10, got 20/);
});

// A speechSynthesis as Firefox's (speech-dispatcher) lists its voices: none at first, all of them some
// seconds after the first getVoices(), with `voiceschanged` (Firefox ESR 153 with eSpeak's 13,000-odd: 1.9 s).
function lateVoices(afterMs) {
  const synth = new EventTarget();
  let listed = null;
  const voices = [{ name: 'eSpeak English', lang: 'en-US', default: true, localService: true, voiceURI: 'urn:moz-tts:speechd:en' }];
  Object.assign(synth, {
    getVoices() {
      listed ??= setTimeout(() => { listed = true; synth.dispatchEvent(new Event('voiceschanged')); }, afterMs);
      return listed === true ? voices : [];
    },
    speak() {}, cancel() {}, pause() {}, resume() {},
  });
  Object.defineProperty(window, 'speechSynthesis', { value: synth, configurable: true });
}

test('browser: voices listed seconds late (as Firefox lists speech-dispatcher\'s): canReadAloud() is true the first time it is asked, and readAloudVoices() asked meanwhile waits for the same list', async ({ page }) => {
  await page.addInitScript(lateVoices, 2500);
  await openPdfBook(page);
  const result = await page.evaluate(async () => {
    const [can, voices] = await Promise.all([window.book.canReadAloud(), window.book.readAloudVoices()]);
    return { can, voices: voices.map((v) => v.name) };
  });
  expect(result).toEqual({ can: true, voices: ['eSpeak English'] });
});

// A speechSynthesis as WebKitGTK 2.50's with its own voices: each utterance starts and ends in tasks of its
// own, reports no word boundaries, and its `end` comes from inside the synthesiser's reset, which forgets an
// utterance spoken before it returns (in that task, microtasks included): that one starts, and never ends.
function webkitSpeech() {
  const synth = new EventTarget();
  let resetting = false;
  Object.assign(synth, {
    said: [],
    forgotten: [],
    speaking: false,
    getVoices: () => [{ name: 'kal', lang: 'en-US', default: true, localService: true, voiceURI: '' }],
    speak(utterance) {
      const forgotten = resetting;
      (forgotten ? synth.forgotten : synth.said).push(utterance.text);
      synth.speaking = true;
      setTimeout(() => {
        utterance.dispatchEvent(new Event('start'));
        if (forgotten) return;
        setTimeout(() => {
          resetting = true;
          synth.speaking = false;
          utterance.dispatchEvent(new Event('end'));
          // The reset returns once this task's script is done: its microtasks too (a long chain of them).
          let hops = 100;
          const hop = () => { if (hops-- > 0) queueMicrotask(hop); else resetting = false; };
          queueMicrotask(hop);
        });
      });
    },
    cancel() {}, pause() {}, resume() {},
  });
  Object.defineProperty(window, 'speechSynthesis', { value: synth, configurable: true });
}

test('browser: on a voice as WebKitGTK\'s (end fired inside its reset, no word boundaries), both open pages are said to readaloudend, each sentence marked with data-reading="sentence" over its words as it begins', async ({ page }) => {
  await page.addInitScript({ path: UTTERANCE_STUB });
  await page.addInitScript(webkitSpeech);
  await page.goto('/tests/browser/fixtures/html-fixture.html');
  await page.waitForFunction(() => document.body.dataset.ready);
  const texts = ['The cat sat. It was warm.', 'A dog came by. It barked.', 'The cat ran.', 'The dog sat. The end.'];
  await page.evaluate(async (texts) => {
    window.pageElements = texts.map((t) => window.makeTextPage(t));
    window.book = await window.Flipbook.create(window.container, { pages: window.pageElements, display: 'double', duration: 300 });
    await window.book.whenIdle();
    window.log = [];
    for (const type of ['readaloudpage', 'turned', 'readaloudend']) {
      window.book.addEventListener(type, (e) => window.log.push({ type, page: e.detail.page, reason: e.detail.reason }));
    }
    new MutationObserver(() => {
      const marks = [...document.querySelectorAll('[data-reading="sentence"]')];
      const sentence = window.book.readingAloud?.sentence;
      if (marks.length === 0 || !sentence) return;
      // The mark's box against its first word's, in the page's element.
      const text = window.pageElements[sentence.page].querySelector('p').firstChild;
      const words = [...text.textContent.matchAll(/\S+/g)];
      const range = document.createRange();
      range.setStart(text, words[sentence.from].index);
      range.setEnd(text, words[sentence.from].index + words[sentence.from][0].length);
      const word = range.getBoundingClientRect();
      const mark = marks[0].getBoundingClientRect();
      const covers = mark.left <= word.left + 0.5 && mark.right >= word.right - 0.5 && mark.top <= word.top + 0.5 && mark.bottom >= word.bottom - 0.5;
      window.log.push({ type: 'sentence', page: sentence.page, words: words.slice(sentence.from, sentence.to + 1).map((w) => w[0]).join(' '), covers, marks: marks.length });
    }).observe(window.book.element, { childList: true, subtree: true });
    window.book.readAloud();
  }, texts);
  await page.waitForFunction(() => window.log.some((e) => e.type === 'readaloudend'), null, { timeout: 30_000 })
    .catch(async (error) => { throw new Error(`${error.message}: ${JSON.stringify(await page.evaluate(() => [window.log, window.speechSynthesis.said, window.speechSynthesis.forgotten]))}`); });
  const { log, said, forgotten } = await page.evaluate(() => ({ log: window.log, said: window.speechSynthesis.said, forgotten: window.speechSynthesis.forgotten }));
  expect(forgotten).toEqual([]);
  expect(said.map((t) => t.trim())).toEqual(texts.flatMap((t) => t.split(/(?<=\.) /)));
  expect(log.filter((e) => e.type !== 'sentence')).toEqual([
    { type: 'readaloudpage', page: 0 }, { type: 'turned', page: 1 }, { type: 'readaloudpage', page: 1 }, { type: 'readaloudpage', page: 2 },
    { type: 'turned', page: 3 }, { type: 'readaloudpage', page: 3 }, { type: 'readaloudend', page: 3, reason: 'finished' },
  ]);
  const sentences = log.filter((e) => e.type === 'sentence');
  expect(sentences.map((e) => [e.page, e.words])).toEqual(texts.flatMap((t, page) => t.split(/(?<=\.) /).map((sentence) => [page, sentence])));
  expect(sentences.every((e) => e.covers && e.marks === 1)).toBe(true);
});

// A book of numbered image pages (tests/browser/fixtures/test-pages.js) whose pages 0, 1 and 3 carry recorded
// narration made in the page by web/demo/story-voice.js (a short generated WAV and its word times, each
// word given a place on its page); page 1's word times come as a WebVTT file; page 2 has only an alt.
async function openNarratedBook(page) {
  // No speech voice here: the narrated pages play, the page without narration is passed over.
  await page.addInitScript(() => {
    const synth = new EventTarget();
    Object.assign(synth, { getVoices: () => [], speak() { throw new Error('no voice'); }, cancel() {}, pause() {}, resume() {} });
    Object.defineProperty(window, 'speechSynthesis', { value: synth, configurable: true });
  });
  await page.goto('/tests/browser/fixtures/flipbook-fixture.html');
  await page.waitForFunction(() => document.body.dataset.ready);
  await page.evaluate(async () => {
    const { narrate, wordTimesVtt } = await import('/web/demo/story-voice.js');
    const lines = { 0: 'Once upon a time', 1: 'a paper boat set sail', 3: 'The end.' };
    const placed = (words) => words.map((w, i) => ({ ...w, rect: [0.1 + 0.2 * (i % 4), 0.2 + 0.1 * Math.floor(i / 4), 0.15, 0.06] }));
    const pages = Array.from({ length: 4 }, (_, i) => {
      const entry = { src: window.makeNumberedPage(i) };
      if (!lines[i]) return { ...entry, alt: 'A picture without words' };
      const said = narrate(lines[i].split(' '), { seed: i + 1 });
      const src = URL.createObjectURL(new Blob([said.wav], { type: 'audio/wav' }));
      const words = placed(said.words);
      if (i !== 1) return { ...entry, narration: { src, words } };
      // Page 1: a WebVTT file, a cue a word, each giving its place as JSON.
      const vtt = wordTimesVtt(words).replace(/^(\d\d:[\d:.]+ --> [\d:.]+)\n(.+)$/gm, (whole, timing, text) => {
        const word = words.find((w) => w.text === text);
        return `${timing}\n${JSON.stringify({ text, rect: word.rect })}`;
      });
      return { ...entry, narration: { src, words: URL.createObjectURL(new Blob([vtt], { type: 'text/vtt' })) } };
    });
    window.narrated = { lines, pages };
    window.book = await window.Flipbook.create(document.getElementById('container'), { pages, display: 'double', duration: 300 });
    await window.book.whenIdle();
    // The reading starts from a click, as a reader's would (the browser plays audio after a gesture).
    const button = document.createElement('button');
    button.id = 'read';
    button.textContent = 'Read';
    button.addEventListener('click', () => { window.started = window.book.readAloud().catch((e) => e); });
    document.body.append(button);
    window.log = [];
    let audio = null;
    window.book.addEventListener('readaloudword', (e) => {
      const reading = window.book.readingAloud;
      if (reading.audio && reading.audio !== audio) {
        audio = reading.audio;
        const page = e.detail.page;
        audio.addEventListener('ended', () => window.log.push({ type: 'ended', page }));
      }
      window.log.push({ type: 'word', page: e.detail.page, text: e.detail.text, index: e.detail.index, time: reading.audio.currentTime,
        marks: document.querySelectorAll('[data-reading]').length });
    });
    for (const type of ['readaloudpage', 'turnstart', 'turned', 'readaloudend']) {
      window.book.addEventListener(type, (e) => window.log.push({ type, ...e.detail, ...(type === 'turnstart' ? { audioEnded: audio?.ended } : {}) }));
    }
  });
}

test('browser: recorded narration (a generated WAV, its word times, one page\'s as WebVTT) plays, marks each word at its time by the audio\'s currentTime, and turns when the audio ends', async ({ page }) => {
  test.setTimeout(180_000);
  await openNarratedBook(page);
  expect(await page.evaluate(() => window.book.canReadAloud())).toBe(true);  // no voice, but narration
  await page.click('#read');
  await page.waitForFunction(() => window.log.some((e) => e.type === 'readaloudend'));
  const { log, lines, times } = await page.evaluate(async () => {
    const { narrate } = await import('/web/demo/story-voice.js');
    const { lines } = window.narrated;
    const times = Object.fromEntries(Object.entries(lines).map(([i, line]) => [i, narrate(line.split(' '), { seed: Number(i) + 1 }).words]));
    return { log: window.log, lines, times };
  });
  expect(log.filter((e) => e.type === 'readaloudend')).toEqual([{ type: 'readaloudend', reason: 'finished', page: 3 }]);
  // Every word of each narrated page, in order, each marked no sooner than its time in the audio.
  for (const [index, line] of Object.entries(lines)) {
    const words = log.filter((e) => e.type === 'word' && e.page === Number(index));
    expect(words.map((w) => w.text)).toEqual(line.split(' '));
    words.forEach((w, k) => {
      expect(w.time).toBeGreaterThanOrEqual(times[index][k].start);
      expect(w.marks).toBe(1);  // one rect a word, laid over the page while it lies flat
    });
  }
  // The pages in order, what each read; the turn after the audio of the open pages ended.
  expect(log.filter((e) => e.type === 'readaloudpage').map((e) => [e.page, e.source]))
    .toEqual([[0, 'narration'], [1, 'narration'], [2, 'alt'], [3, 'narration']]);
  // (The book hears the audio's `ended` before this test's listener does: the turn starts in between.)
  const order = log.filter((e) => ['ended', 'turnstart', 'turned'].includes(e.type))
    .map((e) => (e.type === 'ended' ? `ended ${e.page}` : e.type === 'turnstart' ? `turnstart after an ended audio: ${e.audioEnded}` : e.type));
  expect(order.filter((e) => !e.startsWith('ended'))).toEqual(['turnstart after an ended audio: true', 'turned', 'turnstart after an ended audio: true', 'turned']);
  expect(order.filter((e) => e.startsWith('ended'))).toEqual(['ended 0', 'ended 1', 'ended 3']);
  expect(log.findIndex((e) => e.type === 'turnstart')).toBeGreaterThan(log.findLastIndex((e) => e.type === 'word' && e.page === 0));
});

test('browser: a narrated page\'s mark follows the audio when it is paused and seeked, and stop() silences and lets the audio go', async ({ page }) => {
  test.setTimeout(180_000);
  await openNarratedBook(page);
  await page.click('#read');
  await page.waitForFunction(() => window.log.some((e) => e.type === 'word' && e.page === 0));
  const seeked = await page.evaluate(async () => {
    const reading = window.book.readingAloud;
    reading.pause();
    const { audio } = reading;
    const words = window.narrated.pages[0].narration.words;
    audio.currentTime = (words[3].start + words[3].end) / 2;
    await new Promise((resolve) => audio.addEventListener('seeked', resolve, { once: true }));
    const after = { state: reading.state, paused: audio.paused, word: reading.word.text, index: reading.word.index };
    audio.currentTime = words[1].start + 0.01;  // back: the mark goes back with it
    await new Promise((resolve) => audio.addEventListener('seeked', resolve, { once: true }));
    const back = reading.word.text;
    reading.stop();
    return { after, back, audioPaused: audio.paused, src: audio.getAttribute('src'), marks: document.querySelectorAll('[data-reading]').length, reading: window.book.readingAloud };
  });
  expect(seeked).toEqual({ after: { state: 'paused', paused: true, word: 'time', index: 3 }, back: 'upon', audioPaused: true, src: null, marks: 0, reading: null });
});

test('browser: live HTML pages are read from their text, in their own language, each word marked over its place in the element', async ({ page }) => {
  await page.goto('/tests/browser/fixtures/html-fixture.html');
  await page.waitForFunction(() => document.body.dataset.ready);
  await page.evaluate(async () => {
    const french = window.makeTextPage('Le café est chaud.');
    french.lang = 'fr-FR';
    const pages = [window.makeTextPage('The cat sat on the mat.'), french, window.makeNumberedPage(2), window.makeNumberedPage(3)];
    window.book = await window.Flipbook.create(window.container, { pages, display: 'single', duration: 300 });
    await window.book.whenIdle();
  });
  await installEngine(page);
  await page.evaluate(() => window.book.readAloud({ engine: window.engine }));
  await page.waitForFunction(() => window.engine.calls.length === 1);
  const first = await page.evaluate(() => {
    window.sayWords(2);  // "The cat": the mark lies over "cat" in the page's element
    const mark = document.querySelector('[data-reading]').getBoundingClientRect();
    const range = document.createRange();
    const text = document.querySelector('.html-page p').firstChild;  // page 0's paragraph
    range.setStart(text, 4);
    range.setEnd(text, 7);
    const word = range.getBoundingClientRect();
    return { call: window.calls()[0], mark: mark.toJSON(), word: word.toJSON() };
  });
  expect(first.call.text.trim()).toBe('The cat sat on the mat.');
  expect(first.call.lang).toBe('en');  // the web page's <html lang="en">
  // The mark covers the word (a pixel or two of padding around it).
  expect(first.mark.left).toBeLessThanOrEqual(first.word.left + 0.5);
  expect(first.mark.right).toBeGreaterThanOrEqual(first.word.right - 0.5);
  expect(first.mark.top).toBeLessThanOrEqual(first.word.top + 0.5);
  expect(first.mark.bottom).toBeGreaterThanOrEqual(first.word.bottom - 0.5);
  expect(first.mark.width).toBeLessThan(first.word.width + 8);
  await page.evaluate(() => { window.sayWords(100); window.finish(); });
  await page.waitForFunction(() => window.engine.calls.length === 2);
  const second = await page.evaluate(() => window.calls()[1]);
  expect(second.text.trim()).toBe('Le café est chaud.');
  expect(second.lang).toBe('fr-FR');
  // Pages 2 and 3 are images without alt or text: passed over after a short pause each, to the end.
  await page.evaluate(() => {
    window.ending = window.book.readingAloud.finished;
    window.sayWords(100);
    window.finish();
  });
  const end = await page.evaluate(() => window.ending);
  expect(end).toEqual({ reason: 'finished', page: 3 });
  const pages = await page.evaluate(() => window.events.filter((e) => e.type === 'readaloudpage').map((e) => [e.page, e.source]));
  expect(pages).toEqual([[0, 'text'], [1, 'text'], [2, 'none'], [3, 'none']]);
  expect(await page.evaluate(() => window.engine.calls.length)).toBe(2);
});
