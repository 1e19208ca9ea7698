// Types of <cone-flipbook> (element.js): the element class, its events, and its tag in
// HTMLElementTagNameMap so document.querySelector('cone-flipbook') is typed.
import type { Flipbook, FlipbookCreateError, FlipbookEventMap, PageEntry, PagesChangeDetail, PageSource } from './book/flipbook.js';
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
 * The Flipbook as an element. Attributes (all optional except the pages): pages (URLs separated by
 * spaces; else the child elements: an <img> an image page, alt text kept, any other element a live
 * HTML page shown through a named slot), display, direction, start-page, duration, schedule, center,
 * hard-covers, lighting, shadows, gutter ("true"/"false"), thickness ("true"/"false"/a number),
 * antialias ("auto"/"true"/"false"),
 * load-window, wasm-url, pdf, pdf-worker-src.
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
  /**
   * Every option is a property too (frameworks that set properties, such as Svelte and Angular): the
   * pages as an array (over the pages attribute and the child elements; a string sets the attribute),
   * a PDF as a URL or its bytes; the others read their attribute, parsed, and writing one sets the
   * attribute (null removes it) with the attribute's effect (live, or a rebuild at the current page).
   */
  get pages(): PageSource[] | (PageEntry | PageSource)[] | string[] | undefined;
  set pages(value: (PageEntry | PageSource | HTMLElement)[] | string | null | undefined);
  get pdf(): string | ArrayBuffer | Uint8Array | undefined;
  set pdf(value: string | ArrayBuffer | Uint8Array | null | undefined);
  direction: 'ltr' | 'rtl' | 'vertical' | undefined;
  startPage: number | undefined;
  duration: number | undefined;
  schedule: 'paper' | 'smooth' | undefined;
  center: boolean | undefined;
  hardCovers: boolean | undefined;
  lighting: boolean | undefined;
  shadows: boolean | undefined;
  gutter: boolean | undefined;
  thickness: boolean | number | undefined;
  antialias: boolean | 'auto' | undefined;
  loadWindow: number | undefined;
  hash: boolean | undefined;
  autoplay: boolean | { interval: number } | undefined;
  sound: boolean | undefined;
  muted: boolean | undefined;
  rememberPage: string | undefined;
  wasmUrl: string | undefined;
  pdfWorkerSrc: string | undefined;
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
