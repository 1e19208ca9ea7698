// Types of Flipbook, the public entry point. Kept beside flipbook.js.

export type PageSource = string | HTMLImageElement | HTMLCanvasElement | ImageBitmap | Blob;

export interface PageEntry {
  src: PageSource;
  /** Text of the page for screen readers. */
  alt?: string;
  /** Turns rigidly, like a cover. */
  hard?: boolean;
}

export interface FlipbookOptions {
  /** The pages, first to last; at least one. A URL is loaded with CORS. */
  pages: Array<PageSource | PageEntry>;
  /** 'auto' (default) shows two pages when the container is wider than 1.2x its height. */
  display?: 'single' | 'double' | 'auto';
  /** 'ltr' (default), 'rtl' (spine on the right), 'vertical' (spine at the top, a calendar). */
  direction?: 'ltr' | 'rtl' | 'vertical';
  /** Page to open at; default 0. */
  startPage?: number;
  /** Milliseconds per turn; default 1000. */
  duration?: number;
  /** The first and last pages turn rigidly; default false. */
  hardCovers?: boolean;
  lighting?: boolean;
  shadows?: boolean;
  gutter?: boolean;
  /**
   * Pages loaded on each side of the open spread; default 4. At most max(2 * loadWindow + 4, 14)
   * page textures are kept, however many pages the book has.
   */
  loadWindow?: number;
  /** The book's accessible name (aria-label of its region); default 'Book'. */
  label?: string;
  /** Where the engine's .wasm is served, if not next to its JS. */
  wasmUrl?: string;
}

export interface FlipbookEventMap {
  ready: CustomEvent<{ page: number }>;
  /** After each page load settles: pages ready now (loaded or failed), the page count, loads still running. */
  progress: CustomEvent<{ loaded: number; total: number; pending: number }>;
  /** A turn begins: from next()/prev()/flip(), a click, tap, swipe or key, or a drag (`drag: true`). */
  turnstart: CustomEvent<{ direction: 'forward' | 'backward'; page: number; drag?: boolean }>;
  turned: CustomEvent<{ page: number }>;
  /** A dragged page was let go short of the spine and fell back: the book stays at `page`. */
  turncancel: CustomEvent<{ page: number }>;
  pageerror: CustomEvent<{ index: number; error: Error }>;
  /** The container's size (CSS px) or devicePixelRatio changed and the book was laid out again. */
  resize: CustomEvent<{ width: number; height: number; display: 'single' | 'double' }>;
}

export class Flipbook extends EventTarget {
  /** Rejects with a TypeError naming a bad option, or an Error if WebGL2 is unavailable. */
  static create(container: HTMLElement, options: FlipbookOptions): Promise<Flipbook>;
  readonly pageCount: number;
  /** First visible page at the settled position; after destroy(), the page the book was left at. */
  readonly page: number;
  /** Follows the container's aspect when the option is 'auto'; after destroy(), as it was last. */
  readonly display: 'single' | 'double';
  /**
   * The element the book made in its container: focusable (tabindex 0), role "region" with
   * aria-roledescription "book"; holds the canvas, the live region and the pages' alt text.
   */
  readonly element: HTMLElement;
  /** Resolve true when the turn has landed, false if the book cannot turn that way. */
  next(): Promise<boolean>;
  prev(): Promise<boolean>;
  /**
   * Turns leaf by leaf to page `index` (or jumps with animate: false, or under
   * prefers-reduced-motion); RangeError if out of range. A later flip() takes over: an animated
   * flip still under way stops turning and resolves.
   */
  flip(index: number, options?: { animate?: boolean }): Promise<void>;
  /** Switches the effects on a live book; any other option is a TypeError (it needs a new book). */
  setOptions(options: Pick<FlipbookOptions, 'lighting' | 'shadows' | 'gutter'>): void;
  /** Releases the canvas, the GL context, the wasm objects and the loaded pages; idempotent. */
  destroy(): void;
  addEventListener<K extends keyof FlipbookEventMap>(type: K, listener: (event: FlipbookEventMap[K]) => void,
    options?: boolean | AddEventListenerOptions): void;
  addEventListener(type: string, listener: EventListenerOrEventListenerObject | null,
    options?: boolean | AddEventListenerOptions): void;
}
