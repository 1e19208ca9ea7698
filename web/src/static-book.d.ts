// Types of StaticBook, the book without WebGL2 (static-book.js). Kept beside static-book.js.
import type { FlipbookEventMap, FlipbookOptions, PageState } from './flipbook.js';

/**
 * The open pages as still images on a 2D canvas: what Flipbook.create leaves in the container when
 * WebGL2 or the engine is unavailable (the rejection's `fallback`), or a book of its own. The same
 * options, members, keys, clicks, taps, swipes, links, events (no `turncancel`, `zoom` or `sharpened`:
 * nothing is dragged or magnified) and screen-reader support as Flipbook; turns cut straight to the
 * next spread.
 */
export class StaticBook extends EventTarget {
  /** Rejects with a TypeError naming a bad option; resolves once the open pages loaded or failed. */
  static create(container: HTMLElement, options: FlipbookOptions): Promise<StaticBook>;
  readonly pageCount: number;
  /** Where page `index` stands now (RangeError for an index outside the book). */
  pageState(index: number): PageState;
  /** Always false: still pages never move. */
  readonly animating: boolean;
  /** Pages whose images are loaded and kept, in page order. */
  readonly residentPages: number[];
  readonly page: number;
  readonly display: 'single' | 'double';
  readonly element: HTMLElement;
  /**
   * Always 1: still pages are not magnified by the book (the browser's pinch-zoom works on them).
   * Setting it checks the value (RangeError outside 1..4) and changes nothing.
   */
  zoom: number;
  /** True when it turned (at once), false at the end of the book. Rejects after destroy(). */
  next(): Promise<boolean>;
  prev(): Promise<boolean>;
  /** Checks its arguments like Flipbook's; a static book has no turn frames, so it returns false. */
  previewTurn(direction: 'forward' | 'backward', t: number): boolean;
  flip(index: number, options?: { animate?: boolean }): Promise<void>;
  /** Accepts (and checks) lighting, shadows and gutter; flat still pages show none of them. */
  setOptions(options: Pick<FlipbookOptions, 'lighting' | 'shadows' | 'gutter'>): void;
  /** Where the open pages lie on its canvas, in CSS px (both places of a spread in double). */
  restingRect(): { x: number; y: number; width: number; height: number };
  destroy(): void;
  addEventListener<K extends keyof FlipbookEventMap>(type: K, listener: (event: FlipbookEventMap[K]) => void,
    options?: boolean | AddEventListenerOptions): void;
  addEventListener(type: string, listener: EventListenerOrEventListenerObject | null,
    options?: boolean | AddEventListenerOptions): void;
}

/** The engine Book's positions in plain JS (StaticBook needs no wasm): the last position. */
export function lastPosition(pageCount: number, display: 'single' | 'double'): number;
/** The position (spread or page) that shows `page`. */
export function positionOfPage(page: number, pageCount: number, display: 'single' | 'double'): number;
/** The first visible page at a position. */
export function firstVisiblePage(position: number, pageCount: number, display: 'single' | 'double'): number;
/** The pages lying open at a position: -1 for a blank back, undefined where no leaf lies. */
export function spreadAt(position: number, pageCount: number, display: 'single' | 'double'): { turned?: number; unturned?: number };
