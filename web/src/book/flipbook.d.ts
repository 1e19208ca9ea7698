// Types of Flipbook, the public entry point. Kept beside flipbook.js.
import type { StaticBook } from './static-book.js';
import type { BookView } from '../surfaces/book-view.js';
import type { CanvasSurface } from '../surfaces/canvas-surface.js';

export type PageImage = string | HTMLImageElement | HTMLCanvasElement | ImageBitmap | Blob;
/**
 * A page source: an image, or a function that makes one when the page is first wanted (lazily). The
 * function is told the page's index and the size in device pixels it is drawn at.
 */
export type PageSource = PageImage | ((index: number, size: { width: number; height: number }) => PageImage | Promise<PageImage>);

export interface PageLink {
  /** Where on the page: [x, y, width, height] as fractions of the page, from its top-left corner. */
  rect: [number, number, number, number];
  /** A URL (http, https, mailto or relative) ... */
  href?: string;
  /** ... or a page of this book to turn to. */
  page?: number;
  /** Its name for screen readers and the tooltip; default the URL or "Go to page N". */
  title?: string;
}

export interface PageEntry {
  /** The page's image (give this or `html`). */
  src?: PageSource;
  /**
   * A live HTML page: the element is shown over the page while it lies open (fully interactive) and
   * drawn to the page's texture while it moves (needs the optional dependency modern-screenshot).
   * Any element but an image, canvas or video; strings are never parsed as HTML.
   */
  html?: HTMLElement;
  /** Text of the page for screen readers. */
  alt?: string;
  /** Turns rigidly, like a cover. */
  hard?: boolean;
  /** A sharper image of the page, loaded for the open pages when zoomed in. */
  zoomSrc?: PageImage;
  /** A small image of the page: pageThumbnail() up to 512 px wide draws it (a published document has one a page). */
  thumbSrc?: PageImage;
  /**
   * A small image shown at once while `src` loads (a data: URL costs no request): drawn over the whole page,
   * then replaced by `src` once decoded, with no paper between and no layout change. One that fails is passed over.
   */
  placeholder?: PageImage;
  /** Clickable areas of the page, active while it lies open and flat. */
  links?: PageLink[];
  /** Recorded narration: readAloud() plays it and marks each word at its time, in place of a speech voice. */
  narration?: PageNarration;
}

/** A word of recorded narration: when it is said (seconds into the audio) and where it lies on the page. */
export interface NarrationWord {
  start: number;
  end: number;
  text: string;
  /** [x, y, width, height] as fractions of the page (like a link's); needed where the page is an image, else found in the page's text. */
  rect?: [number, number, number, number];
}

/** A page's recorded narration: its audio file and the times of its words. */
export interface PageNarration {
  /** The audio's URL (any format the browser plays: WAV, MP3, Ogg, AAC...). */
  src: string;
  /** The words with their times, or the URL of a WebVTT file (a cue a word, or <00:01.200> timestamps in a cue) or of a JSON array of them. */
  words: NarrationWord[] | string;
}

/** Something that speaks text: readAloud({ engine }) takes any object with this speak(); the default wraps speechSynthesis. */
export interface SpeechEngine {
  speak(text: string, options: {
    lang: string; rate: number; pitch: number; voice?: string;
    /** Call at each word: its first character's index in `text`, and its length. */
    onWord(charIndex: number, charLength: number): void;
    /** Call as each sentence begins, where the engine knows (from, to: character indices in `text`): it is marked lightly, `data-reading="sentence"`. */
    onSentence?(from: number, to: number): void;
    /** Call once when all of `text` was said. */
    onEnd(): void;
    /** Call when it cannot go on: the reading ends with reason 'error'. */
    onError?(error: Error): void;
  }): { pause(): void; resume(): void; cancel(): void };
}

export interface ReadAloudOptions {
  /** What speaks the pages without narration; default the browser's speechSynthesis. */
  engine?: SpeechEngine;
  /**
   * A voice's name (readAloudVoices() lists them), or a SpeechSynthesisVoice (kept for the language, see
   * `readAloudMemory`); default the one kept for each page's language, else the first of readAloudVoices()'s
   * order for it that is not eSpeak's.
   */
  voice?: string | SpeechSynthesisVoice;
  /** Speed, 0.1 to 10 (default the one kept for the language, else 1); for narration, the audio's playbackRate. */
  rate?: number;
  /** 0 to 2 (default 1). */
  pitch?: number;
  /** BCP 47 language of the speech; default the page's: an HTML page's lang, the document's, the web page's. */
  lang?: string;
  /** A reader's own turn moves the reading to the new page instead of stopping it (default false). */
  follow?: boolean;
}

/** A word being read: its place in the page's words, its text and its rectangles (fractions of the page, one a line). */
export interface ReadAloudWord {
  page: number;
  index: number;
  text: string;
  rects: Array<[number, number, number, number]>;
}

/** Why a reading ended: all read to the book's end, stop(), a reader's turn, pages changed, the book destroyed, or an error. */
export type ReadAloudEndReason = 'finished' | 'stopped' | 'turned' | 'pageschange' | 'destroyed' | 'error';

/** A reading aloud, as readAloud() resolves with it and `readingAloud` holds it until it ends. */
export interface ReadAloud {
  /** 'waiting': a reader's turn in flight, with `follow`. */
  readonly state: 'reading' | 'paused' | 'waiting' | 'ended';
  /** The page being read. */
  readonly page: number;
  /** The word said now, or null (a voice that reports no words marks only its sentence). */
  readonly word: ReadAloudWord | null;
  /** The sentence said now (its first and last word's indices, its rectangles one a line), where the engine says when each begins; or null. */
  readonly sentence: { page: number; from: number; to: number; rects: Array<[number, number, number, number]> } | null;
  /** The <audio> element playing recorded narration now (null while a speech engine speaks). */
  readonly audio: HTMLAudioElement | null;
  pause(): void;
  resume(): void;
  /** Stops: the speech or audio stops, the mark goes, `readaloudend` with reason 'stopped'. */
  stop(): void;
  /**
   * A new voice, rate or pitch at once: narration changes speed as it plays; speech starts again at the
   * sentence being said (at the word, for an engine that tells no sentences). A TypeError or RangeError names a bad change (as readAloud() checks it).
   */
  update(changes: { voice?: string; rate?: number; pitch?: number }): void;
  /** Resolves with `readaloudend`'s detail when the reading ends. */
  readonly finished: Promise<{ reason: ReadAloudEndReason; page: number; error?: Error }>;
}

/** A voice of the browser's speech synthesis. */
export interface ReadAloudVoice {
  name: string;
  lang: string;
  default: boolean;
  local: boolean;
  /** The browser's own identifier of the voice (SpeechSynthesisVoice.voiceURI; '' where it gives none). */
  voiceURI: string;
}

export interface FlipbookOptions {
  /**
   * The pages, first to last; at least one. A URL is loaded with CORS. An HTMLElement (not an image,
   * canvas or video) is a live HTML page, as `{ html: element }`. Give this, `pdf` or `document`.
   */
  pages?: Array<PageSource | HTMLElement | PageEntry>;
  /**
   * Where a press may turn a page: anywhere on it ('page'), a band along its free edge ('edges'), its
   * two free corners ('corners'), or nowhere ('none': keys, buttons and code still turn). Default
   * 'edges' when the book has HTML pages (a press on their content stays theirs) or a PDF's text
   * layer (a press on text selects it), else 'page'.
   */
  turnArea?: 'page' | 'edges' | 'corners' | 'none';
  /**
   * A PDF (URL or bytes) instead of `pages`: shown through pdf.js (the optional dependency pdfjs-dist,
   * imported only then), each page rendered when wanted at the size the canvas needs, its text as its
   * alt text, the page shape from the PDF's first page. The bytes are copied; yours stay usable.
   */
  pdf?: string | ArrayBuffer | Uint8Array;
  /** URL of pdf.js's worker module, where `import.meta.resolve('pdfjs-dist/build/pdf.worker.min.mjs')` cannot find it. */
  pdfWorkerSrc?: string;
  /**
   * A published document instead of `pages`: the URL of its book.json (what `conecurl publish` writes,
   * or a host's own pipeline: docs/publish.md). Its page images are the pages (with their zoomSrc,
   * thumbSrc, alt and links); search, the text layer and outline() read its text and outline files,
   * with no pdf.js; its title is the label unless `label` is given; download() fetches its PDF.
   */
  document?: string | URL;
  /**
   * 'auto' (default) shows two pages where each page of the spread would be at least `minPageWidth`
   * CSS px wide (across the turn), else one; it chooses again as the container resizes (`displaychange`).
   */
  display?: 'single' | 'double' | 'auto';
  /**
   * With display 'auto': the narrowest page (CSS px, across the turn) shown two at a time; default 300.
   * Changes live through setOptions.
   */
  minPageWidth?: number;
  /** 'ltr' (default), 'rtl' (spine on the right), 'vertical' (spine at the top, a calendar). */
  direction?: 'ltr' | 'rtl' | 'vertical';
  /** Page to open at; default 0. */
  startPage?: number;
  /** Milliseconds per turn; default 1000. */
  duration?: number;
  /**
   * Keep #page=N (N from 1) in the address: a link to it opens the book there, each turn adds a history
   * entry, and the back and forward buttons turn the book. Default false; one book per page should use it.
   */
  hash?: boolean;
  /** Remember the page in localStorage under this key and open there next time (#page=N wins). */
  rememberPage?: string;
  /**
   * Where read-aloud keeps the reader's voice and speed, per language (readAloud()'s, update()'s, the
   * toolbar's Voice and speed popup's): a localStorage key, default 'conecurl-read-aloud'; false keeps nothing.
   */
  readAloudMemory?: string | false;
  /**
   * Turn on its own every `interval` ms (true: 4000), waiting while the pointer is over the book,
   * while it has focus and while the tab is hidden; stop at the last page unless `loop`. Default false.
   */
  autoplay?: boolean | { interval?: number; loop?: boolean };
  /**
   * A page sound, synthesised with Web Audio (no audio files): a paper rustle whose loudness and
   * brightness follow the turning leaf's angular speed, and a soft tap as it lands; hard leaves sound
   * heavier. Its AudioContext is made on the first user gesture on the book (or one that turns it);
   * silent while `muted`, under prefers-reduced-motion and on still pages. Default false; live.
   */
  sound?: boolean;
  /** Silences the page sound (no AudioContext is made while muted). Default false; live, and `book.muted`. */
  muted?: boolean;
  /**
   * The curl's schedule: 'paper' (default; the paper's three phases, Nuon's constants exactly) or
   * 'smooth' (the same key poses joined with continuous slopes: no jolt at t = 0.15 and 0.4).
   */
  schedule?: 'paper' | 'smooth';
  /**
   * A closed book sits in the middle of its frame: the front cover alone on the right (the back cover
   * alone on the left) is centred, and the book slides to the open position as the cover turns, as
   * part of the same animation. Default true; false keeps the spine in the middle always.
   */
  center?: boolean;
  /** The first and last pages turn rigidly; default false. */
  hardCovers?: boolean;
  lighting?: boolean;
  shadows?: boolean;
  gutter?: boolean;
  /**
   * How much of a page's print shows through the blank back of its leaf as it turns in single display
   * (a phone), mirrored, as thin paper held to the light shows it: 0 (none) to 1. Default 0.1. A hard
   * cover's back stays board. WebGL only. Changes live through setOptions.
   */
  showThrough?: number;
  /**
   * The stacks of leaves under the open pages show their edges (fore-edge, head, tail), as deep as
   * the leaves on each side; hard covers show a board. true (default): a leaf 0.004 of the page width
   * thick; a number from 0 to 0.02: that thickness; false (or 0): no stacks. WebGL only: the 2D
   * fallback draws none. Changes live through setOptions.
   */
  thickness?: boolean | number;
  /**
   * Pages loaded on each side of the open spread; default 4. At most max(2 * loadWindow + 4, 14)
   * page textures are kept, however many pages the book has.
   */
  loadWindow?: number;
  /** The book's accessible name (aria-label of its region); default 'Book'. */
  label?: string;
  /** Where the engine's .wasm is served, if not next to its JS. */
  wasmUrl?: string;
  /**
   * Without WebGL2 (or when the engine cannot load), show the pages as still images: create() still
   * rejects, and the error's `fallback` is a working StaticBook in the container. Default true.
   */
  fallback?: boolean;
  /**
   * Multisampled edges, smooth where a curling page meets the background. 'auto' (default) is true
   * unless the browser's WebGL2 runs on a software rasterizer (no GPU: SwiftShader, llvmpipe), where
   * it costs about a third of each frame's time.
   */
  antialias?: 'auto' | boolean;
  /**
   * How sharp frames with moving leaves are drawn (a resting book is always drawn at the screen's full
   * device pixel ratio). 'auto' (default): while a leaf moves, frames that come late (a 60 Hz screen's
   * frame missed) lower the drawing's scale, down to 1.5 device pixels per CSS pixel, kept only if frames
   * then come sooner; frames on time raise it again; on a screen of ratio 1.5 or less nothing changes. 'full': always the screen's ratio.
   * A number: that many device pixels per CSS pixel while leaves move (at most the screen's). Live.
   */
  resolution?: 'auto' | 'full' | number;
  /**
   * Listeners by event name, registered before anything happens. Without them, events of the first
   * view (its page errors, progress, ready) are still heard: what happens while create() runs is
   * delivered just after it resolves, to listeners added right after `await Flipbook.create(...)`.
   */
  on?: { [K in keyof FlipbookEventMap]?: (event: FlipbookEventMap[K]) => void };
  /**
   * A PDF book's text, selectable over its flat pages (pdf.js's TextLayer, loaded only then): a
   * reader selects and copies it with mouse or touch, a screen reader reads it in order, a press on it
   * selects and never turns, and a selection offers "Copy link to this passage" (`passagelink`).
   * Default true (PDF books only; with it, `turnArea` defaults to 'edges').
   */
  textLayer?: boolean;
  // docapi (issue 23)
  /**
   * The table of contents of an image or HTML book, as outline() gives it (pages from 0); on a PDF
   * book it takes the place of the PDF's bookmarks. A bad entry is a TypeError naming it.
   */
  outline?: OutlineEntry[];
  /** The URL download() (and the toolbar's Download button) downloads; a PDF book defaults to its PDF. */
  download?: string;
  // edgemarks (issue 23)
  /**
   * Marks on the book's edge: the page blocks' fore-edge carries a coloured index tab for each
   * top-level entry of `outline()` and a tick for each page with a search hit (`searchchange`), drawn
   * at the leaves they belong to, moving from one block to the other as leaves turn. At rest each tab
   * and tick has a button over it, named by its title, that riffles there. Needs the WebGL book and
   * `thickness` (a StaticBook draws no blocks). Default: true when `controls` is on, else false.
   */
  edgeMarks?: boolean;
  // viewer (issue 23)
  /**
   * A toolbar below the book (role="toolbar"; the book fits the rest of its box): previous and next
   * page, a page field ("3 of 12", a number typed and Enter opens it), zoom out and in, the Thumbnails,
   * Contents and Search panels, Download (a PDF, or the `download` URL), Print (a PDF) and Fullscreen.
   * true shows them all; an object hides those set false (`{ search: false }`). Its module is loaded
   * only when this is set (conecurl/viewer's attachControls). Default false.
   */
  controls?: boolean | ControlParts;
  /** The toolbar's and panels' texts by key, for translation (docs/api.md lists the keys and defaults). */
  labels?: ViewerLabels;
}

/** An entry of a book's table of contents: outline() and the `outline` option. */
export interface OutlineEntry {
  title: string;
  /** The page it opens, from 0. */
  page: number;
  /** Entries under it (always an array from outline(); optional in the option). */
  children?: OutlineEntry[];
}

/** A place where search() found its text. */
export interface SearchHit {
  /** The page, from 0. */
  page: number;
  /** About 40 characters around the hit, with an ellipsis where the page's text was cut. */
  snippet: string;
  /** The hit's rectangles, one per line it spans: [x, y, width, height] as fractions of its page, from the top-left. */
  rects: Array<[number, number, number, number]>;
}

/** What `searchchange` tells: the query, its hits in page order, and the hit shown now. */
export interface SearchChangeDetail {
  /** The text searched for; '' once cleared. */
  query: string;
  hits: SearchHit[];
  current: SearchHit | null;
}

/** The toolbar's parts (the `controls` option): each shown unless false. */
export interface ControlParts {
  previous?: boolean;
  next?: boolean;
  /** The page field. */
  page?: boolean;
  /** Zoom out and zoom in. */
  zoom?: boolean;
  fullscreen?: boolean;
  thumbnails?: boolean;
  contents?: boolean;
  search?: boolean;
  /** Default: shown for a PDF book or a `download` URL. */
  download?: boolean;
  /** Default: shown for a PDF book. */
  print?: boolean;
  /** Read aloud (play and pause) and Voice and speed: shown once the book's `canReadAloud()` resolves true. */
  readAloud?: boolean;
  /**
   * Keep offline, a More menu item: fetches every file of the site through the service worker that
   * controls the page (a published site's sw.js), its size shown before. Default: off; shown with
   * `true` only while such a worker controls the page (a published site's reader sets it).
   */
  keepOffline?: boolean;
}

/** The viewer's texts (the `labels` option); `{n}` and `{total}` are filled in with numbers. */
export interface ViewerLabels {
  /** The toolbar's name: 'Book controls'. */
  toolbar?: string;
  previous?: string;
  next?: string;
  /** The page field's name: 'Page'. */
  page?: string;
  /** The page field's text: '{n} of {total}'. */
  pageOf?: string;
  zoomIn?: string;
  zoomOut?: string;
  fullscreen?: string;
  thumbnails?: string;
  contents?: string;
  search?: string;
  download?: string;
  print?: string;
  /** A panel's close button: 'Close'. */
  close?: string;
  /** A thumbnail's name: 'Page {n}'. */
  thumbnail?: string;
  noContents?: string;
  /** The search field's name: 'Search the book'. */
  searchField?: string;
  previousHit?: string;
  nextHit?: string;
  /** Said by the live region as a hit is shown: '{n} of {total}'. */
  hitOf?: string;
  noHits?: string;
  searching?: string;
  /** A result's page: 'Page {n}'. */
  hitPage?: string;
  /** The toolbar's menu button holding the controls that do not fit: 'More'. */
  more?: string;
  /** On a phone, or where there is no Fullscreen API: the button that gives the book the whole screen: 'Read'. */
  read?: string;
  /** The reading bar's button that leaves reading mode: 'Exit reading'. */
  exitReading?: string;
  /** The button that starts reading aloud, or resumes it: 'Read aloud'. */
  readAloud?: string;
  /** That button while the book reads aloud: 'Pause reading'. */
  pauseReading?: string;
  /** The button of the voice and speed popup, and the popup's name: 'Voice and speed'. */
  readAloudSettings?: string;
  /** The popup's voice select: 'Voice'. */
  voice?: string;
  /** The popup's speed select: 'Speed'. */
  speed?: string;
  /** The voice select's first choice, no voice named: "Browser's default". */
  defaultVoice?: string;
  /** The popup's language select, shown over more than 300 voices (one language's listed at a time): 'Language'. */
  voiceLanguage?: string;
  /** The More menu's item, the size of what it will fetch filled in: 'Keep offline ({size})'. */
  keepOffline?: string;
  /** Said as it fetches: 'Keeping offline: {percent}% of {size}'. */
  keepingOffline?: string;
  /** Said once every file is kept, and the item's name then: 'Kept offline'. */
  keptOffline?: string;
  /** Said when a fetch failed: 'Keeping offline stopped: the network failed. Try again online.' */
  keepOfflineFailed?: string;
}

/** Where a page stands: not wanted yet ('idle'), loading, loaded, or failed (with why, as `pageerror` said). */
export interface PageState {
  state: 'idle' | 'loading' | 'loaded' | 'failed';
  reason?: PageErrorReason;
  error?: Error;
}

/** Why a page could not be shown (`pageerror`'s `reason`). */
export type PageErrorReason = 'http' | 'network' | 'cors' | 'decode' | 'source' | 'upload';

/**
 * What Flipbook.create rejects with when the book cannot be drawn with WebGL2. A bad option is a
 * plain TypeError instead.
 */
export interface FlipbookCreateError extends Error {
  /** 'webgl2-unavailable': no WebGL2 context; 'engine-unavailable': the wasm engine failed to load. */
  code?: 'webgl2-unavailable' | 'engine-unavailable';
  /** The static book now in the container (not with `fallback: false`, or if it failed too). */
  fallback?: StaticBook;
  /** Why the fallback could not be built either, if it could not. */
  fallbackError?: Error;
}

/** What insertPages, removePages and replacePage changed: the `pageschange` event's detail, and what they resolve with. */
export interface PagesChangeDetail {
  change: 'insert' | 'remove' | 'replace';
  /** The first page inserted, removed or replaced. */
  at: number;
  count: number;
  pageCount: number;
  /** The first visible page now: the page the reader had in view, renumbered (a removed one: the page that took its place). */
  page: number;
}

export interface FlipbookEventMap {
  /** The first view is on screen (its pages on screen loaded or failed, and drawn); its neighbours load after. */
  ready: CustomEvent<{ page: number }>;
  /** After each page load settles: pages ready now (loaded or failed), the page count, loads still running. */
  progress: CustomEvent<{ loaded: number; total: number; pending: number }>;
  /**
   * A turn begins: from next()/prev()/flip(), a click, tap, swipe or key, or a drag (`drag: true`); a
   * flip() to a page more than two leaves away riffles, several leaves at once, with one turnstart
   * (`riffle: true`) and one `turned` when they land.
   */
  turnstart: CustomEvent<{ direction: 'forward' | 'backward'; page: number; drag?: boolean; riffle?: boolean }>;
  turned: CustomEvent<{ page: number }>;
  /** The view's magnification changed (1 to 4). */
  zoom: CustomEvent<{ scale: number }>;
  /** A link in a page was clicked or activated; preventDefault() stops its navigation or flip. */
  link: CustomEvent<{ page: number; href: string; toPage?: number }>;
  /** An open page got a sharper texture for the zoomed view (its zoomSrc, or its function called again). */
  sharpened: CustomEvent<{ index: number; width: number }>;
  /**
   * Pages were inserted, removed or replaced on the live book (insertPages, removePages, replacePage):
   * `count` pages at `at`; `pageCount` and `page` (the first visible page) as they are now.
   */
  pageschange: CustomEvent<PagesChangeDetail>;
  /** A dragged page was let go short of the spine and fell back: the book stays at `page`. */
  turncancel: CustomEvent<{ page: number }>;
  /**
   * A page could not be shown; it stays plain paper and the book keeps working. `error` is a
   * PageLoadError (message names the page, its URL and the cause) except for 'upload'.
   */
  pageerror: CustomEvent<{ index: number; error: Error; reason: PageErrorReason }>;
  /** The container's size (CSS px) or devicePixelRatio changed and the book was laid out again. */
  resize: CustomEvent<{ width: number; height: number; display: 'single' | 'double' }>;
  /**
   * The book cannot be drawn (no WebGL2, no engine): dispatched by the instance being built, just
   * before create() rejects with the same error. Subclasses (such as <cone-flipbook>) hear it.
   */
  error: CustomEvent<{ error: FlipbookCreateError }>;
  // docapi (issue 23)
  /** search() found its hits, showHit() showed one, or clearSearch() ended it (query '', no hits). */
  searchchange: CustomEvent<SearchChangeDetail>;
  /** The book's container entered or left fullscreen (toggleFullscreen(), or the browser's Escape). */
  fullscreenchange: CustomEvent<{ fullscreen: boolean }>;
  /** download() is about to download `url`; cancelable: preventDefault() stops it (download() resolves false). */
  download: CustomEvent<{ url: string }>;
  /** print() is about to print `pages`; cancelable: preventDefault() stops it (print() resolves false). */
  print: CustomEvent<{ pages: number[] }>;
  /**
   * A reader used "Copy link to this passage" on text selected on `page` (a PDF book's text layer):
   * `url` is this document's address with #page=N&text=... (N from 1), which opens a book with
   * `hash: true` at that page and marks the passage; `copied` says whether it reached the clipboard.
   */
  passagelink: CustomEvent<{ page: number; text: string; url: string; copied: boolean }>;
  // phone (issue 28)
  /** The display in effect changed: display 'auto' chose again (a resize, a rotation) or setOptions changed it. */
  displaychange: CustomEvent<{ display: 'single' | 'double'; previous: 'single' | 'double' }>;
  /**
   * A tap or click on the middle third of the book (of the page in single display; the band within a
   * sixth of the spread's width either side of the spine in double), which turns nothing: x, y in CSS
   * px from the book element's top-left corner. Not for a double tap or click, a drag, a swipe, nor
   * while zoomed in; whatever `turnArea` is.
   */
  middletap: CustomEvent<{ x: number; y: number }>;
  // read-aloud (issue 31)
  /** readAloud() started reading at `page`, in `lang` (null: each page's) with `voice` (null: the default). */
  readaloudstart: CustomEvent<{ page: number; lang: string | null; voice: string | null }>;
  /** Reading reached `page`: it plays its recorded narration, says its text or alt, or passes over it ('none'). */
  readaloudpage: CustomEvent<{ page: number; source: 'narration' | 'text' | 'alt' | 'none' }>;
  /** A word is being said: marked on its page (`data-reading` over the flat page, in its image while it turns). */
  readaloudword: CustomEvent<ReadAloudWord>;
  /** A sentence (a long one's clause) begins: marked on its page (`data-reading="sentence"`), the word mark on top where the voice reports words. */
  readaloudsentence: CustomEvent<{ page: number; from: number; to: number; text: string; rects: Array<[number, number, number, number]> }>;
  /** The browser listed its voices after `canReadAloud()` had answered false: it may answer true now. */
  readaloudvoices: CustomEvent<{ count: number }>;
  readaloudpause: CustomEvent<{ page: number }>;
  readaloudresume: CustomEvent<{ page: number }>;
  /** The reading ended, and why. */
  readaloudend: CustomEvent<{ reason: ReadAloudEndReason; page: number; error?: Error }>;
}

/** What the page sound (the `sound` option) is doing. */
export interface PageSoundStatus {
  /**
   * 'off' (sound false), 'muted', 'silent' (reduced motion or still pages), 'waiting' (for a user
   * gesture: no AudioContext yet), else the AudioContext's state: 'running', 'suspended' or 'closed'.
   */
  state: 'off' | 'muted' | 'silent' | 'waiting' | 'running' | 'suspended' | 'closed';
  /** The rustle's gain now, as its GainNode has it (0 without an AudioContext). */
  gain: number;
  /** The gain the rustle is heading for, from the last frame's speed. */
  target: number;
  /** The fastest leaf's angular speed in the last frame heard, rad/s. */
  speed: number;
  /** Landing taps played so far. */
  taps: number;
  /** A voice is reading aloud: the whole page sound is lowered under it (to 0.3 of its level). */
  ducked: boolean;
  /** The whole sound's level now, as its master GainNode has it: 1, gliding to 0.3 while ducked (0 without an AudioContext). */
  level: number;
}

/** A leaf lying open at the settled position, and where it lies on the canvas (CSS px from its top-left). */
export interface PagePlace {
  /** The page it shows; -1 for a leaf's blank back. */
  page: number;
  /** It lies on the turned side (left in ltr, right in rtl, top in vertical); its free edge is outward. */
  turned: boolean;
  x: number;
  y: number;
  width: number;
  height: number;
}

/**
 * What every book is (book-controller.js): Flipbook draws it with WebGL2, StaticBook on a 2D canvas.
 * Same members, input, loading, links, zoom and events on both.
 */
export class BookController extends EventTarget {
  readonly pageCount: number;
  /** Where page `index` stands now (RangeError for an index outside the book). */
  pageState(index: number): PageState;
  /** A leaf is moving or waiting to (turns in flight, a held page); false after destroy(). */
  readonly animating: boolean;
  /** Pages whose images are loaded and kept (page textures), in page order; never more than the cache's capacity. */
  readonly residentPages: number[];
  /** Where the open pages lie on the canvas, in CSS pixels from its top-left (both places of a spread in double). */
  restingRect(): { x: number; y: number; width: number; height: number };
  /** Each leaf lying open at the settled position, turned side first, as the engine (or layout.js) places it; zoom included. */
  openPagePlaces(): PagePlace[];
  /** The pages open at the settled position, as the live region announces them (one, or two in double). */
  readonly openPages: number[];
  /** Pages loaded or failed so far, the page count, and loads running now (what `progress` said last). */
  readonly progress: { loaded: number; total: number; pending: number };
  /** The options in effect, defaults filled in (a frozen copy). */
  readonly options: Readonly<Required<Omit<FlipbookOptions, 'pdf' | 'pdfWorkerSrc' | 'document' | 'wasmUrl' | 'rememberPage' | 'on' | 'outline' | 'download' | 'labels'>>> & FlipbookOptions;
  /**
   * What draws the book, for tools and tests (reading pixels, counting frames): a BookView (WebGL2) or
   * a CanvasSurface (still pages); null after destroy(). Drive the book through its own members.
   */
  readonly surface: BookView | CanvasSurface | null;
  /** Resolves once no page is loading, the first view's neighbours included (and no click waits to tell a double-click). */
  whenIdle(): Promise<void>;
  /** First visible page at the settled position; after destroy(), the page the book was left at. */
  readonly page: number;
  /** Follows the container's aspect when the option is 'auto'; after destroy(), as it was last. */
  readonly display: 'single' | 'double';
  /**
   * The element the book made in its container: focusable (tabindex 0), role "region" with
   * aria-roledescription "book"; holds the canvas, the live region and the pages' alt text.
   */
  readonly element: HTMLElement;
  /**
   * Resolve true when the turn has landed, false if the book cannot turn that way (or was destroyed
   * before it landed). Called during a turn they start another leaf or wait their turn. After
   * destroy() they reject with an Error.
   */
  next(): Promise<boolean>;
  prev(): Promise<boolean>;
  /**
   * Shows, frozen, the exact frame of the next ('forward') or previous ('backward') turn at progress t
   * in [0, 1] (scrubbers, figures); false at the end of the book. TypeError/RangeError for bad input.
   */
  previewTurn(direction: 'forward' | 'backward', t: number): boolean;
  /**
   * View magnification, 1 (the whole book) to 4; setting it zooms about the middle of the book
   * (RangeError outside 1..4). While above 1, clicks, swipes, drags and arrow keys do not turn pages;
   * next(), prev() and flip() zoom back out first. Still pages (StaticBook) zoom the same way.
   */
  zoom: number;
  /**
   * Turns to page `index`: leaf by leaf when it is one or two leaves away, and when it is more than two
   * leaves away by a riffle (several leaves at once, one `turnstart` with `riffle: true`, then
   * `turned`); jumps with animate: false, under prefers-reduced-motion and on still pages (StaticBook).
   * RangeError if out of range, TypeError for bad options. A later flip() takes over: an animated flip
   * still under way stops turning and resolves.
   */
  flip(index: number, options?: { animate?: boolean }): Promise<void>;
  /**
   * Inserts `pages` (as the `pages` option takes them) before page `at` (0 to pageCount: pageCount adds
   * them after the last) on the live book, with no rebuild. Waits for leaves in flight to land (and
   * for changes asked before it), then applies: the page in view stays in view (renumbered), untouched
   * pages keep their textures, `pageschange` fires. Rejects with a TypeError or RangeError naming a bad
   * argument, and with an Error on a PDF book (its pages are the PDF's).
   */
  insertPages(at: number, pages: Array<PageSource | HTMLElement | PageEntry>): Promise<PagesChangeDetail>;
  /** Removes `count` pages (default 1) from page `from` on, as insertPages applies; a book keeps at least one page. Removing the page in view shows the page that took its place. */
  removePages(from: number, count?: number): Promise<PagesChangeDetail>;
  /** Puts `page` in the place of page `index`, as insertPages applies; a page on screen shows its old image until the new one is ready. */
  replacePage(index: number, page: PageSource | HTMLElement | PageEntry): Promise<PagesChangeDetail>;
  /** Switches the effects, the thickness, the resolution, the display (and minPageWidth) or the sound on a live book (same page); any other option is a TypeError (it needs a new book). */
  setOptions(options: Pick<FlipbookOptions, 'lighting' | 'shadows' | 'gutter' | 'showThrough' | 'thickness' | 'resolution' | 'display' | 'minPageWidth' | 'sound' | 'muted'>): void;
  /** The page sound is muted (the `muted` option); setting it is setOptions({ muted }) (TypeError unless a boolean). */
  muted: boolean;
  /** What the page sound is doing, a snapshot for tools and tests; null after destroy(). */
  readonly sound: PageSoundStatus | null;
  /**
   * Stops everything at once, mid-turn or mid-drag too: no animation frame, listener, observer, GL
   * object or wasm object is left, the WebGL context is released, page loads are aborted. Turns in
   * flight resolve false; later calls reject (or throw) an Error. Idempotent. Called while create() still
   * builds the book (an instance a subclass holds, as <cone-flipbook> does), it stops the build there: no
   * renderer or WebGL context is made after it, nothing is left in the container, and create() rejects
   * with an AbortError (a DOMException).
   */
  // docapi (issue 23): the document API
  /** The table of contents: the `outline` option, else a PDF's bookmarks (destinations resolved), else []. */
  outline(): Promise<OutlineEntry[]>;
  /**
   * Every place `text` occurs, case and diacritics folded (é = E), in page order: a PDF's text (read
   * once, in the background after the book opens) and HTML pages' text. Rejects with an AbortError when
   * `signal` aborts, a TypeError for a text that is not a string. Fires `searchchange`.
   */
  search(text: string, options?: { signal?: AbortSignal }): Promise<SearchHit[]>;
  /**
   * Turns to the hit's page (riffling when far) and marks it as the current hit; the other hits on the
   * open pages are marked too. Resolves once the page lies open. Fires `searchchange`.
   */
  showHit(hit: SearchHit): Promise<void>;
  /** Ends the search: every mark goes; `searchchange` with query '' and no hits. */
  clearSearch(): void;
  /**
   * Page `index` drawn `width` pixels wide (and `height` high, else in its own shape), from its source
   * (pdf.js for a PDF page), never touching the book's textures; three at a time. Rejects with an Error
   * for a page that cannot be drawn, a RangeError/TypeError for bad arguments.
   */
  pageThumbnail(index: number, size: { width: number; height?: number }): Promise<HTMLCanvasElement>;
  /** The book's container is the fullscreen element. */
  readonly fullscreen: boolean;
  /** Enters (true), leaves (false) or toggles fullscreen on the book's container; resolves with `fullscreen`. */
  toggleFullscreen(force?: boolean): Promise<boolean>;
  /** Downloads the `download` URL or the PDF unless a `download` listener prevents it; resolves whether it did (false with nothing to download). */
  download(): Promise<boolean>;
  /** Prints every page (drawn to images in a hidden frame) unless a `print` listener prevents it; resolves whether it did. */
  print(): Promise<boolean>;
  // read-aloud (issue 31)
  /**
   * Reads the book aloud from the open page, word by word (recorded narration where a page has it, else
   * the engine: the browser's speech synthesis), marking each word, turning at the end of the open pages.
   * A reading already running stops first. Rejects with an Error where nothing can read (no voice and no
   * narration), a TypeError or RangeError for a bad option.
   */
  readAloud(options?: ReadAloudOptions): Promise<ReadAloud>;
  /** The reading aloud now, or null. */
  readonly readingAloud: ReadAloud | null;
  /**
   * The browser's speech voices ([] where it has none; waits briefly for them to be listed), for the
   * book's language: its voices first, grouped by region (the reader's regions from navigator.languages,
   * then the book's, then the others A to Z), local before network and eSpeak's last within a region;
   * the other languages' after, by tag.
   */
  readAloudVoices(): Promise<ReadAloudVoice[]>;
  /** The language page `index` (default: the first open page) is read aloud in: an HTML page's own, the document's, else the book element's. RangeError outside the book. */
  pageLanguage(index?: number): string;
  /** Whether readAloud() can read this book: a page has narration, or the browser has a voice. */
  canReadAloud(): Promise<boolean>;
  destroy(): void;
  addEventListener<K extends keyof FlipbookEventMap>(type: K, listener: (event: FlipbookEventMap[K]) => void,
    options?: boolean | AddEventListenerOptions): void;
  addEventListener(type: string, listener: EventListenerOrEventListenerObject | null,
    options?: boolean | AddEventListenerOptions): void;
}

export class Flipbook extends BookController {
  /**
   * Resolves once the first view is on screen: its pages on screen loaded or failed, and drawn. Their
   * neighbours within loadWindow load after it (await whenIdle() for them). Rejects with a TypeError naming a bad option (nothing is left in the container), or with a
   * FlipbookCreateError when WebGL2 or the engine is unavailable (its `fallback` shows the pages), or with
   * an AbortError (a DOMException) when the book was destroyed before it finished (nothing is left either).
   */
  static create(container: HTMLElement, options: FlipbookOptions): Promise<Flipbook>;
}
