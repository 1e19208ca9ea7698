// Types of <cone-flipbook> (element.js): the element class, its events, and its tag in
// HTMLElementTagNameMap so document.querySelector('cone-flipbook') is typed.
import type { Flipbook, FlipbookCreateError, FlipbookEventMap, FlipbookOptions, PageEntry, PagesChangeDetail, PageSource } from './book/flipbook.js';
import type { StaticBook } from './book/static-book.js';

export interface ConeFlipbookEventMap extends Omit<HTMLElementEventMap, 'error' | keyof FlipbookEventMap>,
  Omit<FlipbookEventMap, 'error'> {
  /**
   * The book could not be built (a bad attribute: a TypeError naming it) or a live change was
   * refused; or there is no WebGL2 or engine (`code` says which), and a StaticBook shows the pages.
   */
  error: CustomEvent<{ error: Error | FlipbookCreateError }>;
}

/**
 * The Flipbook as an element. Every option is an attribute (all optional except the pages), its name
 * in kebab case, except `on` (listen on the element: it dispatches every book event): pages (URLs
 * separated by spaces; else the child elements: an <img> an image page, alt text kept, any other
 * element a live HTML page shown through a named slot), display, min-page-width, direction, start-page, duration,
 * schedule, center, hard-covers, lighting, shadows, gutter, show-through (0 to 1), hash, sound, muted, fallback
 * ("true"/"false"), thickness ("true"/"false"/a number), autoplay ("true"/"false"/the milliseconds
 * between turns), antialias ("auto"/"true"/"false"), resolution ("auto"/"full"/a number), turn-area ("page"/"edges"/"corners"/"none"),
 * label (the book's name for screen readers), load-window, remember-page, read-aloud-memory (a key, or "false"), wasm-url, pdf, pdf-worker-src, src (a published book.json: the document option; not named document, which would shadow the global document in inline event handlers),
 * outline (the table of contents as JSON; the property also keeps the array), download (a URL), edge-marks ("true"/"false").
 * controls (bare or "true": the toolbar; its parts as an object through the property), labels (the
 * toolbar's texts as a JSON object, or an object through the property),
 * text-layer ("true"/"false": a PDF's selectable text).
 * lighting, shadows, gutter, show-through, thickness, display, min-page-width, sound and muted apply to the running book; a change of
 * any other builds a new book at the page shown.
 */
export class ConeFlipbookElement extends HTMLElement {
  static readonly observedAttributes: string[];
  /**
   * The Flipbook inside once it is ready (a StaticBook without WebGL2 or the engine); null before,
   * after a failure and after destroy().
   */
  readonly book: Flipbook | StaticBook | null;
  /** First visible page; before `ready`, the page the book will open at. */
  readonly page: number;
  /** 0 until `ready`. */
  readonly pageCount: number;
  /** Pages shown side by side; null until `ready`. Setting it sets the display attribute (applied live). */
  get display(): 'single' | 'double' | null;
  set display(value: 'single' | 'double' | 'auto' | null | undefined);
  /** With display 'auto', the narrowest page shown two at a time, CSS px (the min-page-width attribute, applied live). */
  minPageWidth: FlipbookOptions['minPageWidth'];
  /**
   * Every option with an attribute is a property too (frameworks that set properties, such as Svelte
   * and Angular). A value no attribute can hold is kept as given, read back as given and wins over the
   * attribute: the pages as an array (over the child elements too), a PDF's bytes, an autoplay object;
   * it builds a new book. Any other value (a string, number or boolean) sets the attribute (null
   * removes it), with the attribute's effect (live, or a new book at the page shown), and reads back
   * parsed; undefined when neither is set.
   */
  get pages(): FlipbookOptions['pages'];
  set pages(value: FlipbookOptions['pages'] | string | null);
  get pdf(): FlipbookOptions['pdf'];
  set pdf(value: FlipbookOptions['pdf'] | null);
  direction: FlipbookOptions['direction'];
  startPage: FlipbookOptions['startPage'];
  duration: FlipbookOptions['duration'];
  schedule: FlipbookOptions['schedule'];
  center: FlipbookOptions['center'];
  hardCovers: FlipbookOptions['hardCovers'];
  lighting: FlipbookOptions['lighting'];
  shadows: FlipbookOptions['shadows'];
  gutter: FlipbookOptions['gutter'];
  showThrough: FlipbookOptions['showThrough'];
  thickness: FlipbookOptions['thickness'];
  antialias: FlipbookOptions['antialias'];
  resolution: FlipbookOptions['resolution'];
  loadWindow: FlipbookOptions['loadWindow'];
  hash: FlipbookOptions['hash'];
  /** `{ interval: 3000 }` is kept as given; true, false or a number of milliseconds set the attribute. */
  get autoplay(): FlipbookOptions['autoplay'];
  set autoplay(value: FlipbookOptions['autoplay'] | number | null);
  sound: FlipbookOptions['sound'];
  muted: FlipbookOptions['muted'];
  rememberPage: FlipbookOptions['rememberPage'];
  readAloudMemory: FlipbookOptions['readAloudMemory'];
  /** Where a press may turn a page (the turn-area attribute). */
  turnArea: FlipbookOptions['turnArea'];
  /** The book's name for screen readers (the label attribute); default 'Book'. */
  label: FlipbookOptions['label'];
  /** false: no still pages without WebGL2 or the engine, only the error (the fallback attribute). */
  fallback: FlipbookOptions['fallback'];
  wasmUrl: FlipbookOptions['wasmUrl'];
  pdfWorkerSrc: FlipbookOptions['pdfWorkerSrc'];
  /**
   * A published document's book.json URL (the src attribute; Flipbook's `document` option): its pages are
   * the book. Not named `document`, which would shadow the global document in inline event handlers.
   */
  src: FlipbookOptions['document'];
  /** The table of contents: an array is kept as given; a string is its JSON (the outline attribute). */
  get outline(): FlipbookOptions['outline'];
  set outline(value: FlipbookOptions['outline'] | string | null);
  /** The URL download() and the Download button fetch (the download attribute). */
  download: FlipbookOptions['download'];
  /** Tabs and ticks on the book's fore-edge (the edge-marks attribute); default: on with controls. */
  edgeMarks: FlipbookOptions['edgeMarks'];
  /** The toolbar: true or false set the attribute; `{ search: false }` is kept as given. */
  get controls(): FlipbookOptions['controls'];
  set controls(value: FlipbookOptions['controls'] | null);
  /** The toolbar's texts: an object is kept as given; a string is written to the attribute (JSON). */
  get labels(): FlipbookOptions['labels'];
  set labels(value: FlipbookOptions['labels'] | string | null);
  /** A PDF book's selectable text over its flat pages (the text-layer attribute); default true. */
  textLayer: FlipbookOptions['textLayer'];
  /**
   * Waits for the book being built (the StaticBook fallback without WebGL2 or the engine); rejects
   * with its error, or at once if not in the document or destroyed.
   */
  whenReady(): Promise<Flipbook | StaticBook>;
  /** Wait for the book like whenReady(), then turn. */
  next(): Promise<boolean>;
  prev(): Promise<boolean>;
  flip(index: number, options?: { animate?: boolean }): Promise<void>;
  /** Wait for the book like whenReady(), then change its pages live (see Flipbook.insertPages). */
  insertPages(at: number, pages: Array<PageSource | HTMLElement | PageEntry>): Promise<PagesChangeDetail>;
  removePages(from: number, count?: number): Promise<PagesChangeDetail>;
  replacePage(index: number, page: PageSource | HTMLElement | PageEntry): Promise<PagesChangeDetail>;
  /** Destroys the book now; the element rebuilds only when put in the document again. */
  destroy(): void;
  addEventListener<K extends keyof ConeFlipbookEventMap>(type: K,
    listener: (this: ConeFlipbookElement, event: ConeFlipbookEventMap[K]) => unknown,
    options?: boolean | AddEventListenerOptions): void;
  addEventListener(type: string, listener: EventListenerOrEventListenerObject,
    options?: boolean | AddEventListenerOptions): void;
  removeEventListener<K extends keyof ConeFlipbookEventMap>(type: K,
    listener: (this: ConeFlipbookElement, event: ConeFlipbookEventMap[K]) => unknown,
    options?: boolean | EventListenerOptions): void;
  removeEventListener(type: string, listener: EventListenerOrEventListenerObject,
    options?: boolean | EventListenerOptions): void;
}

declare global {
  interface HTMLElementTagNameMap {
    'cone-flipbook': ConeFlipbookElement;
  }
}
