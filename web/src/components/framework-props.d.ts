// Types shared by conecurl/react and conecurl/vue: the book options a component takes as props, and
// the handle its ref (React) or exposed instance (Vue) gives.
import type { FlipbookOptions } from '../book/flipbook.js';
import type { Flipbook } from '../book/flipbook.js';
import type { StaticBook } from '../book/static-book.js';

/**
 * The book's options as props, except `startPage` (use `page` or `defaultPage`) and `on` (use the
 * event props). `lighting`, `shadows`, `gutter`, `showThrough`, `thickness`, `display`, `minPageWidth`, `sound` and `muted` apply to the running book, and so
 * does a changed `pages` (the pages added, removed or replaced go in live: insertPages, removePages,
 * replacePage; the page shown follows, `pageschange` says so); a change of any other builds a new book
 * in the same box at the page shown.
 */
export type FlipbookOptionProps = Partial<Omit<FlipbookOptions, 'startPage' | 'on'>>;

/** { ready, page, pageCount, display } of a component's book. */
export interface FlipbookState {
  /** The book is built and shows its pages (or its StaticBook fallback does). */
  ready: boolean;
  /** First visible page; before `ready`, the page it will open at. */
  page: number;
  /** 0 before `ready`. */
  pageCount: number;
  display: 'single' | 'double' | null;
}

/** What a component's ref (React) or exposed instance (Vue) gives. Calls made before `ready` wait for it. */
export interface FlipbookHandle extends Readonly<FlipbookState> {
  next(): Promise<boolean>;
  prev(): Promise<boolean>;
  flip(index: number, options?: { animate?: boolean }): Promise<void>;
  /** 1 to 4; setting it zooms about the middle of the book (no effect before `ready`). */
  zoom: number;
  /** The Flipbook (or its StaticBook fallback) underneath; null while it is built. */
  readonly book: Flipbook | StaticBook | null;
  /** Calls `listener(state)` now and whenever it changes; returns the unsubscribe. */
  subscribe(listener: (state: FlipbookState) => void): () => void;
}
