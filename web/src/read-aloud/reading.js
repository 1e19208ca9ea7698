// One reading aloud: the loop that says the open pages' words in order (a speech engine for text,
// the audio file for recorded narration), marks each word as it is said, turns the book at the end of
// the open pages and goes on at the next page's first word; and what a reader's own turn does to it.
// Made by book-reader.js; the object a host holds is this class's instance (`book.readingAloud`).
import { wordAt } from './page-script.js';
import { playNarration } from './narration-player.js';

/** A page with nothing to say (no text, no alt) is passed over after this pause. */
export const SKIP_PAUSE_MS = 700;

// A pause that can itself be paused: what a page with nothing to say plays.
function silence(ms, onEnd) {
  let left = ms;
  let since = performance.now();
  let timer = setTimeout(onEnd, left);
  return {
    pause() {
      clearTimeout(timer);
      left -= performance.now() - since;
    },
    resume() {
      since = performance.now();
      timer = setTimeout(onEnd, Math.max(0, left));
    },
    cancel() { clearTimeout(timer); },
  };
}

// Word rects ([x, y, w, h] fractions of the page) joined into one a line: rects in reading order whose
// heights overlap by half are one line, from the leftmost to the rightmost.
function lineRects(rects) {
  const lines = [];
  for (const [x, y, w, h] of rects) {
    const line = lines[lines.length - 1];
    const overlap = line ? Math.min(line[1] + line[3], y + h) - Math.max(line[1], y) : 0;
    if (line && overlap > 0.5 * Math.min(line[3], h)) {
      const [left, top] = [Math.min(line[0], x), Math.min(line[1], y)];
      const [right, bottom] = [Math.max(line[0] + line[2], x + w), Math.max(line[1] + line[3], y + h)];
      line.splice(0, 4, left, top, right - left, bottom - top);
    } else {
      lines.push([x, y, w, h]);
    }
  }
  return lines;
}

export class Reading {
  /**
   * @param {object} book  what a reading needs of the book (book-reader.js): openPages(), pageCount(),
   *   emit(type, detail), on(type, listener) -> off, script(page), checkUpdate(changes), turn(), show(page) -> Promise, showWord(word|null),
   *   curlMarks({ word, sentence }|null) -> Promise, ended(reading)
   * @param {{ engine: object|null, voice?: string, rate: number, pitch: number, lang?: string, follow: boolean }} settings
   * @param {object} control  filled in with end(reason): how its maker ends it (the book destroyed)
   */
  constructor(book, settings, control) {
    this._book = book;
    this._settings = settings;
    this._state = 'reading';
    this._page = book.openPages()[0];
    this._word = null;
    this._sentence = null;  // the sentence said now: { page, from, to, rects } (word indices, rects a line each)
    this._speaker = null;   // what says the page now: { pause, resume, cancel, audio? }
    this._runs = 0;         // each (re)start of the loop; an older loop stops at its next step
    this._held = null;      // while paused: the promise the loop waits on, and its release
    this._own = null;       // our own turn in flight: { started: boolean }
    this._heldAt = null;    // where a reader's drag found the reading: { page, index }, to go on there if it falls back
    this._onCancel = null;  // resolves the page being said when the loop moves on (_silence)
    this._announced = -1;   // the page `readaloudpage` last told of: told once a page, not at each restart
    this.finished = new Promise((resolve) => { this._finish = resolve; });
    control.end = (reason) => this._end(reason);
    this._off = [
      book.on('turnstart', () => this._onTurnStart()),
      book.on('turned', () => this._onTurned()),
      book.on('turncancel', () => this._onTurnCancel()),
      book.on('pageschange', () => this._end('pageschange')),
      book.on('displaychange', () => this._onDisplayChange()),
    ];
  }

  /** 'reading', 'paused', 'waiting' (a reader's turn in flight, with `follow`) or 'ended'. */
  get state() { return this._state; }
  /** The page being read. */
  get page() { return this._page; }
  /** The word said now: { page, index, text, rects } (rects: [x, y, w, h] fractions of the page), or null. */
  get word() { return this._word ? { ...this._word, rects: this._word.rects.map((r) => r.slice()) } : null; }
  /**
   * The sentence said now, where the engine says when each begins (the browser's voices): { page, from,
   * to, rects } (its first and last word's indices; rects: [x, y, w, h] fractions of the page, one a line), or null.
   */
  get sentence() { return this._sentence ? { ...this._sentence, rects: this._sentence.rects.map((r) => r.slice()) } : null; }
  /** The <audio> element playing recorded narration now, or null (speech). */
  get audio() { return this._speaker?.audio ?? null; }

  /** Starts at the first open page. */
  start() {
    this._book.emit('readaloudstart', { page: this._page, lang: this._settings.lang ?? null, voice: this._settings.voice ?? null });
    this._run(this._page, 0);
  }

  pause() {
    if (this._state !== 'reading') return;
    this._state = 'paused';
    let release;
    this._held = { wait: new Promise((resolve) => { release = resolve; }), release };
    this._speaker?.pause();
    this._book.emit('readaloudpause', { page: this._page });
  }

  resume() {
    if (this._state !== 'paused') return;
    this._state = 'reading';
    const held = this._held;
    this._held = null;
    this._speaker?.resume();
    held.release();
    this._book.emit('readaloudresume', { page: this._page });
  }

  /** Stops reading: the speech or the audio stops, the mark goes, `readaloudend` with reason 'stopped'. */
  stop() { this._end('stopped'); }

  /**
   * New voice, rate or pitch, now: narration changes its speed as it plays; speech starts again at the
   * sentence being said (at the word, where the engine tells no sentences).
   */
  update(changes) {
    const checked = this._book.checkUpdate(changes);  // a TypeError or RangeError names a bad one
    if (this._state === 'ended') return;
    Object.assign(this._settings, checked);
    if (this._speaker?.audio) {
      this._speaker.audio.playbackRate = this._settings.rate;
    } else if (this._speaker && this._state !== 'waiting') {
      // Speech starts again at the sentence being said (at the word, for an engine that tells no sentences).
      const sentence = this._sentence?.page === this._page ? this._sentence.from : null;
      this._run(this._page, sentence ?? (this._at()?.page === this._page ? this._at().index : 0));
    }
  }

  // ---- the loop --------------------------------------------------------------------------------

  // Reads from word `from` of `page` (an open page) to the end of the open pages, turns, and on.
  async _run(page, from) {
    const run = ++this._runs;
    this._silence();
    const gone = () => run !== this._runs;
    try {
      let pages = this._book.openPages();
      let at = Math.max(0, pages.indexOf(page));
      for (;;) {
        for (; at < pages.length; at++) {
          const script = await this._book.script(pages[at]);
          if (gone()) return;
          this._page = pages[at];
          if (this._page !== this._announced) {
            this._announced = this._page;
            this._book.emit('readaloudpage', { page: this._page, source: script.kind });
          }
          await this._say(script, from, gone);
          if (gone()) return;
          from = 0;
        }
        const last = pages[pages.length - 1];
        if (last >= this._book.pageCount() - 1) return this._end('finished');
        if (this._held) await this._held.wait;
        if (gone()) return;
        // The last word and sentence said stay marked on the leaf as it curls: drawn into its page's image.
        await this._book.curlMarks({ word: this._word, sentence: this._sentence });
        if (gone()) return;
        this._own = { started: false };
        const turned = await this._book.turn().catch(() => false);
        this._own = null;
        if (gone()) return;
        await this._book.curlMarks(null);
        if (!turned) return this._end('finished');
        pages = this._book.openPages();
        at = 0;
      }
    } catch (error) {
      if (!gone()) this._end('error', error);
    }
  }

  // Says one page's script from word `from`; resolves when it is said (or the loop moved on).
  async _say(script, from, gone) {
    if (this._held) await this._held.wait;
    if (gone()) return;
    const { words } = script;
    const { engine, rate, pitch, voice } = this._settings;
    await new Promise((resolve, reject) => {
      let mine = null;
      // A speaker cancelled (the loop moved on) may still call back: only the one speaking now counts.
      const done = () => {
        if (this._speaker === mine) this._speaker = null;
        resolve();
      };
      const failed = (error) => {
        if (this._speaker === mine) this._speaker = null;
        if (gone()) resolve(); else reject(error);
      };
      const said = (index) => { if (!gone() && index >= 0) this._mark(script, index); };
      this._onCancel = resolve;  // a cancelled page resolves: the loop sees it is gone
      if (script.kind === 'narration') {
        mine = playNarration(script.audio, words, { from, rate, onWord: said, onEnd: done, onError: failed });
      } else if (words.length === 0 || !engine || from >= words.length) {
        mine = silence(SKIP_PAUSE_MS, done);
      } else {
        const offset = words[from].start;
        mine = engine.speak(script.text.slice(offset), {
          lang: this._settings.lang ?? script.lang, rate, pitch, voice,
          onSentence: (start, end) => { if (!gone()) this._markSentence(script, start + offset, end + offset); },
          onWord: (charIndex) => said(wordAt(words, charIndex + offset)),
          onEnd: done,
          onError: failed,
        });
      }
      this._speaker = mine;
      if (this._state === 'paused') mine?.pause();
    });
  }

  _mark(script, index) {
    if (this._state === 'ended') return;
    const word = script.words[index];
    this._word = { page: script.page, index, text: word.text, rects: word.rects };
    this._book.showWord(this._word);
    this._book.emit('readaloudword', { page: script.page, index, text: word.text, rects: word.rects.map((r) => r.slice()) });
  }

  // The sentence from character `start` to `end` of the script is being said: marked, and the word said
  // before it is no longer.
  _markSentence(script, start, end) {
    if (this._state === 'ended') return;
    const from = wordAt(script.words, start);
    if (from < 0) return;
    let to = from;
    while (to + 1 < script.words.length && script.words[to + 1].start < end) to++;
    const words = script.words.slice(from, to + 1);
    this._sentence = { page: script.page, from, to, rects: lineRects(words.flatMap((w) => w.rects)) };
    this._word = null;
    this._book.showWord(null);
    this._book.emit('readaloudsentence', { page: script.page, from, to, text: words.map((w) => w.text).join(' '),
      rects: this._sentence.rects.map((r) => r.slice()) });
  }

  // Where the voice is: the word said, else the first word of the sentence said ({ page, index }), or null.
  _at() {
    if (this._word) return this._word;
    return this._sentence && { page: this._sentence.page, index: this._sentence.from };
  }

  // What says the page now stops, and its page's promise resolves.
  _silence() {
    const speaker = this._speaker;
    this._speaker = null;
    speaker?.cancel();
    this._onCancel?.();
    this._onCancel = null;
  }

  // The display switched (a phone rotated, display 'auto'): other pages are open; planned again from the
  // word being read, on its page where it is still open, else from the first open page.
  _onDisplayChange() {
    if (this._state !== 'reading' && this._state !== 'paused') return;
    if (this._own) return;  // our own turn in flight: the loop reads the open pages when it lands
    const at = this._at() ?? { page: this._page, index: 0 };
    if (this._book.openPages().includes(at.page)) {
      this._run(at.page, at.index);
      return;
    }
    // The page being read is no longer open (a spread became one page): shown at once, read on there.
    const run = ++this._runs;
    this._silence();
    this._own = { started: true };
    Promise.resolve(this._book.show(at.page)).catch(() => {}).then(() => {
      this._own = null;
      if (run === this._runs && this._state !== 'ended') this._run(at.page, at.index);
    });
  }

  // ---- a reader's turns ------------------------------------------------------------------------

  _onTurnStart() {
    if (this._own && !this._own.started) {
      this._own.started = true;
      return;
    }
    this._readerTurned(false);
  }

  _onTurned() {
    if (this._own) return;  // our own turn's landing: the loop goes on
    if (this._state === 'waiting') {
      this._state = this._held ? 'paused' : 'reading';
      this._run(this._book.openPages()[0], 0);
    } else {
      this._readerTurned(true);  // a jump: no turnstart came first
    }
  }

  _onTurnCancel() {
    if (this._state !== 'waiting') return;
    this._state = this._held ? 'paused' : 'reading';
    const { page, index } = this._heldAt;
    this._run(page, index);  // a drag let go: on at the word it was on
  }

  // A reader turned (a drag, a key, flip()): reading stops, or with `follow` waits to go on at the new page.
  _readerTurned(landed) {
    if (this._state === 'ended') return;
    if (!this._settings.follow) {
      this._end('turned');
      return;
    }
    this._runs++;
    this._silence();
    this._heldAt = { page: this._at()?.page ?? this._page, index: this._at()?.index ?? 0 };
    this._word = null;
    this._sentence = null;
    this._book.showWord(null);
    if (landed) {
      this._run(this._book.openPages()[0], 0);
    } else {
      this._state = 'waiting';
    }
  }

  _end(reason, error) {
    if (this._state === 'ended') return;
    this._state = 'ended';
    this._runs++;
    this._silence();
    this._held?.release();
    this._held = null;
    this._word = null;
    this._sentence = null;
    for (const off of this._off) off();
    this._book.showWord(null);
    this._book.curlMarks(null).catch(() => {});
    const detail = { reason, page: this._page, ...(error ? { error } : {}) };
    this._book.ended(this);
    this._book.emit('readaloudend', detail);
    this._finish(detail);
  }
}
