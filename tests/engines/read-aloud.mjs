// Cross-engine journeys of read-aloud on the engine's own voices: Firefox's from speech-dispatcher and
// espeak-ng (speech.mjs gives it a configuration of the suite's own), WebKitGTK's from its own synthesiser.
import assert from 'node:assert/strict';

export { speechEnvironment } from './speech.mjs';

const HTML = '/tests/browser/fixtures/html-fixture.html';

// A page of 300-odd words: sentences of a short story, in order, so a word's place says where the voice is.
export const LONG_PAGE = Array.from({ length: 16 }, (_, i) => `Sentence ${i + 1} of the first page tells how the paper boat went on down the long river past the mill.`).join(' ');
export const SHORT_PAGES = ['The boat came to the sea at last.', 'A gull sat on it. It did not sink.', 'The wind took it home.', 'The end.'];

/**
 * Opens a double-page book of HTML pages (a long one alone, then short ones two by two: both open pages
 * are said before a turn) and records read-aloud's events, and each mark as it is laid, in window.log.
 */
export function openStoryBook({ long, short }) {
  const pages = [long, ...short].map((text) => {
    const page = window.makeTextPage(text);
    page.style.fontSize = '8px';  // the long page's words all lie on the page
    return page;
  });
  return window.Flipbook.create(window.container, { pages, display: 'double', duration: 300 }).then(async (book) => {
    window.book = book;
    await book.whenIdle();
    window.log = [];
    const marked = () => Array.from(document.querySelectorAll('[data-reading]'), (m) => m.dataset.page);
    for (const type of ['readaloudstart', 'readaloudpage', 'readaloudword', 'readaloudend', 'turned']) {
      book.addEventListener(type, (e) => window.log.push({ type, page: e.detail?.page, reason: e.detail?.reason, marks: marked() }));
    }
    // Every [data-reading] mark laid over a page, as it comes, with the sentence and word said then.
    new MutationObserver(() => {
      const marks = marked();
      const { sentence = null, word = null } = book.readingAloud ?? {};
      if (marks.length > 0) window.log.push({ type: 'mark', page: Number(marks[0]), sentence: sentence && [sentence.from, sentence.to], word: word?.index ?? null });
    }).observe(book.element, { childList: true, subtree: true });
    return book.pageCount;
  });
}

/**
 * What a whole reading of the story book (openStoryBook) must have done, from its window.log: ended
 * 'finished' on page 4, said each page once in order, turned at the end of the open pages, laid a mark
 * over each page while it was said, and gone through the long page's words in order to its last.
 */
export function checkReading(log) {
  const end = log.find((e) => e.type === 'readaloudend');
  assert.deepEqual(end && { page: end.page, reason: end.reason }, { page: 4, reason: 'finished' }, JSON.stringify(log.filter((e) => e.type !== 'mark')));
  assert.deepEqual(log.filter((e) => e.type === 'readaloudpage').map((e) => e.page), [0, 1, 2, 3, 4], 'each page is said once, in order');
  assert.deepEqual(log.filter((e) => e.type === 'turned').map((e) => e.page), [1, 3], 'the book turned at the end of the open pages');
  for (const page of [0, 1, 2, 3, 4]) {
    assert.ok(log.some((e) => e.type === 'mark' && e.page === page), `a [data-reading] mark lay over page ${page} while it was said`);
  }
  // The long page's marks go through its words in order, to its last (the voice said it all).
  const onFirst = log.filter((e) => e.type === 'mark' && e.page === 0).map((e) => e.word ?? e.sentence[0]);
  assert.deepEqual(onFirst, [...onFirst].sort((a, b) => a - b), 'the marks move forward through the page');
  const lastSaid = log.filter((e) => e.type === 'mark' && e.page === 0).map((e) => Math.max(e.word ?? -1, e.sentence?.[1] ?? -1));
  assert.equal(Math.max(...lastSaid), LONG_PAGE.split(/\s+/).length - 1, 'the long page was said to its last word');
}

/** Defines the read-aloud journeys on engineSuite's context: { engine, url, open, evaluate, journey, heard, browser }. */
export function readAloudJourneys(context) {
  const { open, evaluate, journey } = context;

  journey('read-aloud on the engine\'s own voice: a 300-word page said to its end with each word or sentence marked as it is said, both open pages said, the book turning at the end of the open pages, to readaloudend', async () => {
    await open(HTML);
    assert.equal(await evaluate(openStoryBook, { long: LONG_PAGE, short: SHORT_PAGES }), 5);
    // Asked once, at once, as the reader's toolbar asks: the voices may come after the page asks.
    const first = await evaluate(async () => {
      const can = await window.book.canReadAloud();
      const voices = await window.book.readAloudVoices();
      return { can, voices: voices.length, chosen: voices[0]?.name ?? null };
    });
    assert.equal(first.can, true, 'canReadAloud() answers true the first time it is asked');
    assert.ok(first.voices > 0, `the engine lists its voices (${first.voices})`);
    const started = Date.now();
    await evaluate(() => { window.book.readAloud({ rate: 3 }).catch((e) => window.log.push({ type: 'rejected', error: String(e) })); });
    await context.browser.waitFor(() => window.log.some((e) => e.type === 'readaloudend' || e.type === 'rejected'));
    const log = await evaluate(() => window.log);
    const marks = log.filter((e) => e.type === 'mark');
    console.log(`# ${context.engine}: ${first.voices} voices (the first in the book's order: ${first.chosen}); the story read aloud at rate 3 in `
      + `${((Date.now() - started) / 1000).toFixed(1)} s; ${marks.length} marks laid, ${marks.filter((e) => e.word !== null).length} of them with a word said`);
    checkReading(log);
    assert.deepEqual(await evaluate(() => [window.book.readingAloud, document.querySelectorAll('[data-reading]').length]), [null, 0], 'nothing left marked');
  });
}
