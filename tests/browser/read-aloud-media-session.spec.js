// Browser: read-aloud on the system's media controls (issue 37) and behind a hidden page. A reading
// sets the Media Session's handlers (play, pause, stop, next and previous page), its metadata (the
// book's title and cover) and playback state, and clears them all when it ends; calling the handlers
// pauses, resumes, stops and turns the book, reading on from the new page. While the page is hidden
// (screen locked, tab in the background: no animation frames) the reading's turn lands at once.
// Recorded narration adds its audio's position and seekto.
// Chromium has no getter for action handlers: the page records what is set before the book is made.
// The speech is an engine the test drives (readAloud({ engine })), as in read-aloud.spec.js.
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';

const ALTS = ['The paper boat', 'It sailed down the river', 'past the mill', 'under the bridge', 'into the sea', 'The end'];

// The fixture's book of six numbered pages (each with an alt the engine says), double, named by its
// label; navigator.mediaSession.setActionHandler wrapped to record each handler (window.mediaActions).
async function openBook(page) {
  await page.addInitScript(() => {
    window.mediaActions = {};
    const session = navigator.mediaSession;
    const set = session.setActionHandler.bind(session);
    Object.defineProperty(session, 'setActionHandler', {
      configurable: true,
      value: (action, handler) => {
        window.mediaActions[action] = handler;
        set(action, handler);
      },
    });
  });
  await openReady(page, '/tests/browser/fixtures/flipbook-fixture.html');
  await page.evaluate(async (alts) => {
    const pages = alts.map((alt, i) => ({ src: window.makeNumberedPage(i), alt }));
    window.book = await window.Flipbook.create(document.getElementById('container'), {
      pages, display: 'double', duration: 300, label: 'The Paper Boat', lighting: false, shadows: false,
    });
    await window.book.whenIdle();
    window.events = [];
    for (const type of ['readaloudpage', 'readaloudpause', 'readaloudresume', 'readaloudend', 'turnstart', 'turned']) {
      window.book.addEventListener(type, (e) => window.events.push({ type, ...e.detail }));
    }
    // A speech engine the test drives: window.finish() ends the latest utterance.
    const calls = [];
    const waiting = [];
    window.engine = {
      calls,
      speak: (text, options) => {
        const call = { text, options, paused: false, cancelled: false };
        calls.push(call);
        for (const check of waiting.splice(0)) check();
        return { pause() { call.paused = true; }, resume() { call.paused = false; }, cancel() { call.cancelled = true; } };
      },
    };
    window.finish = () => calls[calls.length - 1].options.onEnd();
    // Resolves once the engine has been asked to say `n` texts (a promise: no animation frame needed to see it).
    window.spoken = (n) => new Promise((resolve) => {
      const check = () => (calls.length >= n ? resolve() : waiting.push(check));
      check();
    });
    window.said = () => calls.filter((c) => !c.cancelled).map((c) => c.text);
    // What the media controls see now.
    window.media = () => {
      const { metadata, playbackState } = navigator.mediaSession;
      const handlers = Object.fromEntries(Object.entries(window.mediaActions).map(([action, h]) => [action, typeof h === 'function']));
      return { handlers, playbackState, title: metadata?.title ?? null, artwork: metadata ? metadata.artwork.map((a) => a.src) : null };
    };
  }, ALTS);
}

const pagesRead = (page) => page.evaluate(() => window.events.filter((e) => e.type === 'readaloudpage').map((e) => e.page));

test('browser: while a book reads aloud the Media Session has its title, cover and handlers, they pause, resume, turn (reading on from the new page) and stop it, and all is cleared when it ends', async ({ page }) => {
  await openBook(page);
  await page.evaluate(() => window.book.readAloud({ engine: window.engine }));
  await page.evaluate(() => window.spoken(1));
  // The cover as a blob URL of its image (a canvas here), once it is drawn.
  await page.waitForFunction(() => navigator.mediaSession.metadata?.artwork.length === 1);
  let media = await page.evaluate(() => window.media());
  expect(media).toMatchObject({
    title: 'The Paper Boat', playbackState: 'playing',
    handlers: { play: true, pause: true, stop: true, nexttrack: true, previoustrack: true },
  });
  expect(media.handlers.seekto ?? false).toBe(false);  // speech: nothing to seek in
  expect(media.artwork[0]).toMatch(/^blob:/);
  const cover = await page.evaluate(async (src) => {
    const image = await createImageBitmap(await (await fetch(src)).blob());
    return { width: image.width, height: image.height };
  }, media.artwork[0]);
  expect(cover).toEqual({ width: 512, height: 640 });  // page 0 (320 x 400) drawn 512 wide

  // Pause and play: the engine held and let go, readaloudpause and readaloudresume, the state follows.
  await page.evaluate(() => window.mediaActions.pause());
  expect(await page.evaluate(() => ({ state: window.book.readingAloud.state, paused: window.engine.calls[0].paused, playback: navigator.mediaSession.playbackState })))
    .toEqual({ state: 'paused', paused: true, playback: 'paused' });
  await page.evaluate(() => window.mediaActions.play());
  expect(await page.evaluate(() => ({ state: window.book.readingAloud.state, paused: window.engine.calls[0].paused, playback: navigator.mediaSession.playbackState })))
    .toEqual({ state: 'reading', paused: false, playback: 'playing' });

  // Next page: the book turns (the reading was not started with follow) and reads on from page 1.
  await page.evaluate(() => window.mediaActions.nexttrack());
  await page.evaluate(() => window.spoken(2));
  expect(await pagesRead(page)).toEqual([0, 1]);
  expect(await page.evaluate(() => window.book.openPages)).toEqual([1, 2]);
  expect(await page.evaluate(() => window.engine.calls[1].text)).toBe(ALTS[1]);
  expect(await page.evaluate(() => window.book.readingAloud.state)).toBe('reading');
  // Previous page: back to the cover, read again.
  await page.evaluate(() => window.mediaActions.previoustrack());
  await page.evaluate(() => window.spoken(3));
  expect(await pagesRead(page)).toEqual([0, 1, 0]);
  expect(await page.evaluate(() => ({ open: window.book.openPages, text: window.engine.calls[2].text }))).toEqual({ open: [0], text: ALTS[0] });
  expect(await page.evaluate(() => window.events.some((e) => e.type === 'readaloudend'))).toBe(false);

  // Stop: readaloudend 'stopped', every handler cleared, no metadata, no state.
  await page.evaluate(() => window.mediaActions.stop());
  expect(await page.evaluate(() => window.events.filter((e) => e.type === 'readaloudend').map((e) => e.reason))).toEqual(['stopped']);
  media = await page.evaluate(() => window.media());
  expect(media).toMatchObject({ title: null, artwork: null, playbackState: 'none' });
  expect(Object.values(media.handlers).every((set) => !set)).toBe(true);
  expect(await page.evaluate(() => window.book.readingAloud)).toBeNull();

  // A reading the book's destroy() ends clears them too.
  await page.evaluate(() => window.book.readAloud({ engine: window.engine }));
  await page.evaluate(() => window.spoken(4));
  expect((await page.evaluate(() => window.media())).handlers.pause).toBe(true);
  await page.evaluate(() => window.book.destroy());
  media = await page.evaluate(() => window.media());
  expect(media).toMatchObject({ title: null, playbackState: 'none' });
  expect(Object.values(media.handlers).every((set) => !set)).toBe(true);
});

test('browser: while the page is hidden (no animation frames run) a reading at the end of the open pages turns the book at once, without a moving leaf, and reads on', async ({ page }) => {
  await openBook(page);
  await page.evaluate(() => window.book.readAloud({ engine: window.engine }));
  await page.evaluate(() => window.spoken(1));
  // Hidden, as a locked screen or a background tab has it: visibilityState 'hidden', and animation
  // frames held (they never run) until the page shows again.
  await page.evaluate(() => {
    window.hiddenFrames = [];
    window.showingFrames = window.requestAnimationFrame;
    window.requestAnimationFrame = (callback) => window.hiddenFrames.push(callback);
    Object.defineProperty(document, 'visibilityState', { configurable: true, get: () => 'hidden' });
    Object.defineProperty(document, 'hidden', { configurable: true, get: () => true });
    document.dispatchEvent(new Event('visibilitychange'));
  });
  // The cover said: the book jumps to pages 1 and 2 (turned, no turnstart) and reads page 1, then 2,
  // then jumps on to 3 and 4.
  await page.evaluate(() => window.finish());
  await page.evaluate(() => window.spoken(2));
  expect(await page.evaluate(() => ({ open: window.book.openPages, animating: window.book.animating }))).toEqual({ open: [1, 2], animating: false });
  await page.evaluate(() => window.finish());
  await page.evaluate(() => window.spoken(3));
  await page.evaluate(() => window.finish());
  await page.evaluate(() => window.spoken(4));
  expect(await page.evaluate(() => window.book.openPages)).toEqual([3, 4]);
  expect(await page.evaluate(() => window.said())).toEqual(ALTS.slice(0, 4));
  expect(await pagesRead(page)).toEqual([0, 1, 2, 3]);
  expect(await page.evaluate(() => window.events.filter((e) => e.type === 'turnstart' || e.type === 'turned').map((e) => `${e.type} ${e.page}`)))
    .toEqual(['turned 1', 'turned 3']);
  expect(await page.evaluate(() => window.book.readingAloud.state)).toBe('reading');
  // Shown again: the frames held run, and the reading stops cleanly.
  await page.evaluate(() => {
    delete document.visibilityState;
    delete document.hidden;
    window.requestAnimationFrame = window.showingFrames;
    for (const callback of window.hiddenFrames.splice(0)) window.requestAnimationFrame(callback);
    document.dispatchEvent(new Event('visibilitychange'));
    window.book.readingAloud.stop();
  });
  expect(await page.evaluate(() => window.events.filter((e) => e.type === 'readaloudend').map((e) => e.reason))).toEqual(['stopped']);
});

test('browser: recorded narration puts its audio\'s position in the Media Session and seekto moves the audio and the word marked; the reading\'s end clears both', async ({ page }) => {
  // No speech voice: the narrated cover plays; setPositionState recorded as setActionHandler is.
  await page.addInitScript(() => {
    const synth = new EventTarget();
    Object.assign(synth, { getVoices: () => [], speak() { throw new Error('no voice'); }, cancel() {}, pause() {}, resume() {} });
    Object.defineProperty(window, 'speechSynthesis', { value: synth, configurable: true });
    window.positions = [];
    const session = navigator.mediaSession;
    const set = session.setPositionState.bind(session);
    Object.defineProperty(session, 'setPositionState', { configurable: true, value: (state) => { window.positions.push(state ?? null); set(state); } });
  });
  await openBook(page);
  await page.evaluate(async () => {
    const { narrate } = await import('/web/demo/story-voice.js');
    const said = narrate('Once upon a time there was a paper boat'.split(' '), { seed: 1 });
    const src = URL.createObjectURL(new Blob([said.wav], { type: 'audio/wav' }));
    const words = said.words.map((w, i) => ({ ...w, rect: [0.1 + 0.2 * (i % 4), 0.2 + 0.1 * Math.floor(i / 4), 0.15, 0.06] }));
    const pages = [{ src: window.makeNumberedPage(0), narration: { src, words } }, window.makeNumberedPage(1), window.makeNumberedPage(2)];
    window.book.destroy();
    window.book = await window.Flipbook.create(document.getElementById('container'), { pages, display: 'double', duration: 300 });
    await window.book.whenIdle();
    window.narrationWords = words;
    window.firstWord = new Promise((resolve) => window.book.addEventListener('readaloudword', resolve, { once: true }));
    // From a click, as a reader's would be (the browser plays audio after a gesture).
    const button = document.createElement('button');
    button.id = 'read';
    button.textContent = 'Read';
    button.addEventListener('click', () => { window.book.readAloud(); });
    document.body.append(button);
  });
  await page.click('#read');
  await page.evaluate(() => window.firstWord);
  await page.evaluate(() => window.mediaActions.pause());
  const paused = await page.evaluate(() => ({ seekto: typeof window.mediaActions.seekto, state: navigator.mediaSession.playbackState, last: window.positions.at(-1), duration: window.book.readingAloud.audio.duration }));
  expect(paused.seekto).toBe('function');
  expect(paused.state).toBe('paused');
  expect(paused.last).toMatchObject({ duration: paused.duration, playbackRate: 1 });
  // seekto: the audio goes to the fourth word's time, and that word is marked.
  const seeked = await page.evaluate(async () => {
    const reading = window.book.readingAloud;
    const { audio } = reading;
    const time = (window.narrationWords[3].start + window.narrationWords[3].end) / 2;
    const done = new Promise((resolve) => audio.addEventListener('seeked', resolve, { once: true }));
    window.mediaActions.seekto({ action: 'seekto', seekTime: time });
    await done;
    return { word: reading.word.index, time, position: window.positions.at(-1)?.position, current: audio.currentTime };
  });
  expect(seeked.word).toBe(3);
  expect(Math.abs(seeked.current - seeked.time)).toBeLessThan(0.01);
  expect(Math.abs(seeked.position - seeked.time)).toBeLessThan(0.01);
  // Stopped: seekto cleared, the position cleared.
  await page.evaluate(() => window.mediaActions.stop());
  expect(await page.evaluate(() => ({ seekto: window.mediaActions.seekto, last: window.positions.at(-1), state: navigator.mediaSession.playbackState })))
    .toEqual({ seekto: null, last: null, state: 'none' });
});
