// Read-aloud as a book has it (`readAloud()`, `readingAloud`):
// the options checked, the voice found, each page's script made, the word marked over the flat page
// (layers/reading-mark.js) or drawn into a curling one, the page sound ducked while a voice speaks.
// Imported at a book's first readAloud() (book/book-read-aloud.js).
import { Reading } from './reading.js';
import { pageScript } from './page-script.js';
import { speechEngine, speechVoices } from './speech-engine.js';
import { choosingEngine, keepChoice, voiceMemory } from '../engine/voice-choice.js';
import { showInMediaSession } from './media-session.js';
import { createReadingMarkLayer } from '../layers/reading-mark.js';
import { describeValue } from '../engine/describe-value.js';
import { pageLanguage } from '../engine/language.js';

const OPTION_KEYS = ['engine', 'voice', 'rate', 'pitch', 'lang', 'follow'];
const RANGES = { rate: [0.1, 10], pitch: [0, 2] };
const COVER_WIDTH = 512;  // the cover's thumbnail for the media controls, in pixels, where it has no URL

/** readAloud()'s options checked, defaults filled in; a TypeError or RangeError names what is wrong (and `call`). */
export function checkReadOptions(options = {}, call = 'readAloud()') {
  if (options === null || typeof options !== 'object') throw new TypeError(`conecurl: ${call} takes an options object, got ${describeValue(options)}`);
  const unknown = Object.keys(options).find((key) => !OPTION_KEYS.includes(key));
  if (unknown !== undefined) throw new TypeError(`conecurl: ${call} has no option '${unknown}' (allowed: ${OPTION_KEYS.join(', ')})`);
  const { engine = null, voice, rate = 1, pitch = 1, lang, follow = false } = options;
  if (engine !== null && typeof engine?.speak !== 'function') {
    throw new TypeError(`conecurl: ${call} 'engine' must have speak(text, { lang, rate, pitch, voice, onWord, onEnd }) returning { pause, resume, cancel }; got ${describeValue(engine)}`);
  }
  if (voice !== undefined && !(typeof voice === 'string' && voice !== '') && !(typeof voice === 'object' && voice !== null && typeof voice.name === 'string')) {
    throw new TypeError(`conecurl: ${call} 'voice' must be a voice's name (readAloudVoices() lists them) or a SpeechSynthesisVoice; got ${describeValue(voice)}`);
  }
  for (const [name, value] of [['rate', rate], ['pitch', pitch]]) {
    const [low, high] = RANGES[name];
    if (!(Number.isFinite(value) && value >= low && value <= high)) throw new RangeError(`conecurl: ${call} '${name}' must be a number from ${low} to ${high}, got ${describeValue(value)}`);
  }
  if (lang !== undefined && !(typeof lang === 'string' && lang !== '')) throw new TypeError(`conecurl: ${call} 'lang' must be a language tag such as 'en-GB', got ${describeValue(lang)}`);
  if (typeof follow !== 'boolean') throw new TypeError(`conecurl: ${call} 'follow' must be true or false, got ${describeValue(follow)}`);
  return { engine, voice: typeof voice === 'object' ? voice.name : voice, voiceObject: typeof voice === 'object' ? voice : null, rate, pitch, lang, follow };
}

const UPDATE_KEYS = ['voice', 'rate', 'pitch'];

/** A reading's update() checked: only voice, rate and pitch, each as readAloud() takes it. */
export function checkUpdate(changes) {
  if (changes === null || typeof changes !== 'object') throw new TypeError(`conecurl: update() takes { voice, rate, pitch }, got ${describeValue(changes)}`);
  const unknown = Object.keys(changes).find((key) => !UPDATE_KEYS.includes(key));
  if (unknown !== undefined) throw new TypeError(`conecurl: update() has no option '${unknown}' (allowed: ${UPDATE_KEYS.join(', ')})`);
  const given = Object.fromEntries(Object.entries(changes).filter(([, value]) => value !== undefined));
  const checked = checkReadOptions(given, 'update()');
  // A voice given as undefined goes back to the default one.
  return Object.fromEntries(Object.keys(changes).map((key) => [key, checked[key]]));
}

export class BookReader {
  /**
   * @param {EventTarget} controller  the book, for its events
   * @param {import('../book/book-wiring.js').BookPort} book
   * @param {(index: number) => Promise<object|null>} pageText  a document page's text record (null for other books)
   */
  constructor(controller, book, pageText) {
    this._controller = controller;
    this._book = book;
    this._pageText = pageText;
    this._current = null;
    this._curl = null;  // the marks drawn into their page's image while a leaf turns: { page, marks }
    this._layer = null;
    this._end = null;   // ends the reading now (Reading's control)
  }

  /** The reading now, or null. */
  get current() { return this._current; }

  /** Starts reading at the open page (a reading already running stops first); resolves with the reading. */
  async start(options) {
    const settings = checkReadOptions(options);
    this._current?.stop();
    // The voice and speed remembered for the language read, where not given; those given kept (voice-choice.js).
    const memory = voiceMemory(this._book.settings.readAloudMemory);
    const langAt = (page) => settings.lang ?? langOf(this._book.entries[page] ?? {}, this._book);
    if (!settings.engine) settings.engine = await this._speech(settings, memory);
    keepChoice(memory, langAt(this._book.openPages().find((page) => page >= 0) ?? 0), options, settings);
    this._book.alive();
    this._current?.stop();  // one started meanwhile
    this._layer ??= this._makeLayer();
    const book = this._book;
    const control = {};
    let endMediaSession = () => {};
    const reading = new Reading({
      openPages: () => book.openPages().filter((page) => page >= 0),
      pageCount: book.pageCount,
      emit: book.emit,
      on: (type, listener) => {
        this._controller.addEventListener(type, listener);
        return () => this._controller.removeEventListener(type, listener);
      },
      script: (page) => this._script(page),
      checkUpdate: (changes) => keepChoice(memory, langAt(reading.page), checkUpdate(changes)),
      turn: () => this._turn('forward'),
      showWord: () => this._layer.update(),
      show: (page) => book.turns().flip(page, false),  // the page being read, shown at once (a display switch)
      curlMarks: (marks) => this._curlMarks(marks),
      ended: (ended) => {
        endMediaSession();
        if (this._current !== ended) return;
        this._current = null;
        this._end = null;
        book.duckSound(false);
      },
    }, settings, control);
    this._current = reading;
    this._end = control.end;
    book.duckSound(true);
    endMediaSession = this._mediaSession(reading, settings);
    reading.start();
    return reading;
  }

  /**
   * The marks page `index`'s image gets while a leaf turns (page-store.js `decorate`): [], or the sentence's
   * ({ rect, sentence: true }, one a line) and the word's ({ rect, reading: true }).
   */
  marksOn(index) {
    return this._curl?.page === index ? this._curl.marks.map((mark) => ({ ...mark, rect: mark.rect.slice() })) : [];
  }

  /** The book goes: the reading ends (`readaloudend` with reason 'destroyed'), the mark goes. */
  stop() {
    this._end?.('destroyed');
    this._layer?.remove();
  }

  // The engine for speech: the browser's, when it has a voice; null where a narrated book can do
  // without (its pages without narration are passed over); an Error where nothing could read.
  // `memory`: the voices remembered by language, for a reading that names none (voice-choice.js).
  async _speech(settings, memory) {
    if (settings.voiceObject) return speechEngine();
    const voices = await speechVoices();
    if (voices.length === 0) {
      if (this._book.entries.some((entry) => entry.narration)) return null;
      throw new Error('conecurl: readAloud() found no voice: this browser\'s speech synthesis has none. '
        + 'Install a speech voice, give the pages recorded narration (a page\'s `narration`), or pass an `engine`');
    }
    if (settings.voice !== undefined && !voices.some((v) => v.name === settings.voice || v.voice.voiceURI === settings.voice)) {
      const names = voices.slice(0, 5).map((v) => `'${v.name}'`).join(', ');
      throw new RangeError(`conecurl: readAloud() has no voice named '${settings.voice}' (this browser has ${voices.length}: ${names}${voices.length > 5 ? ', ...' : ''})`);
    }
    return choosingEngine(speechEngine(), voices, memory);
  }

  // The reading on lock screens, headphones and media keys (media-session.js): next and previous turn
  // the book and read on from the new page, as `follow` has a reader's turn do, whatever its own says.
  _mediaSession(reading, settings) {
    return showInMediaSession(reading, {
      title: titleOf(this._book),
      cover: () => this._cover(),
      on: (type, listener) => this._on(type, listener),
      turn: (direction) => {
        if (reading.state === 'ended') return;
        const follow = settings.follow;
        settings.follow = true;
        this._turn(direction).catch(() => {}).finally(() => { settings.follow = follow; });
      },
    });
  }

  // One leaf turned for the reading (or a media key): animated, but at once while the page is hidden
  // (screen locked, tab in the background), where no animation frame runs and a moving leaf never lands.
  // Resolves whether it turned.
  async _turn(direction) {
    const book = this._book;
    if (globalThis.document?.visibilityState !== 'hidden') return book.turns().turn(direction);
    const open = book.openPages().filter((page) => page >= 0);
    const page = direction === 'forward' ? Math.max(...open) + 1 : Math.min(...open) - 1;
    if (page < 0 || page >= book.pageCount()) return false;
    await book.turns().flip(page, false);  // a jump: `turned`, no `turnstart`
    return true;
  }

  // The cover's image for the media controls: page 0's URL where it is one, else its thumbnail as a
  // blob URL (media-session.js lets it go); none for an HTML page.
  async _cover() {
    const entry = this._book.entries[0];
    if (!entry || entry.html) return null;
    const source = entry.thumbSrc ?? entry.src;
    if (typeof source === 'string') return new URL(source, globalThis.document.baseURI).href;
    if (typeof HTMLImageElement !== 'undefined' && source instanceof HTMLImageElement && source.currentSrc) return source.currentSrc;
    const canvas = await this._controller.pageThumbnail(0, { width: COVER_WIDTH });
    const blob = await new Promise((resolve) => canvas.toBlob(resolve, 'image/png'));
    return blob ? URL.createObjectURL(blob) : null;
  }

  // Listens to the book's `type` events; returns the way to stop.
  _on(type, listener) {
    this._controller.addEventListener(type, listener);
    return () => this._controller.removeEventListener(type, listener);
  }

  _makeLayer() {
    const layer = createReadingMarkLayer(this._book.root, () => {
      const { sentence = null, word = null } = this._current ?? {};
      return [sentence && { ...sentence, sentence: true }, word].filter((mark) => mark && mark.rects.length > 0);
    });
    this._book.addLayer(layer);
    this._book.layoutLayers();
    return layer;
  }

  async _script(page) {
    const book = this._book;
    const entry = book.entries[page];
    return pageScript(page, {
      entry,
      record: () => this._pageText(page),
      lang: langOf(entry, book),
    });
  }

  // The word and the sentence drawn into (or, null, taken out of) their page's image for a turn; resolves
  // once handed over.
  async _curlMarks(marks) {
    const before = this._curl;
    const { word = null, sentence = null } = marks ?? {};
    const page = word?.page ?? sentence?.page;
    const rects = [...(sentence && sentence.page === page ? sentence.rects.map((rect) => ({ rect, sentence: true })) : []),
      ...(word ? word.rects.map((rect) => ({ rect, reading: true })) : [])];
    this._curl = rects.length > 0 ? { page, marks: rects } : null;
    const pages = new Set([before?.page, this._curl?.page].filter((p) => p !== undefined));
    if (this._book.destroyed()) return;
    await Promise.all([...pages].map((p) => this._book.store().remark(p).catch(() => {})));
  }
}

// The book's name on the media controls: its label (a PDF's or a published document's title unless one
// was given), else, where the label is its default 'Book' (book/options.js), the web page's title.
function titleOf(book) {
  const { label } = book.settings;
  return (label !== 'Book' && label) || globalThis.document?.title || label;
}

// A page's language (engine/language.js pageLanguage).
function langOf(entry, book) {
  return pageLanguage(entry, book.document()?.lang, book.root);
}
