// Types of conecurl/viewer (viewer.js): attachControls and what it returns.
import type { BookController, ControlParts, ViewerLabels } from './book/flipbook.js';

export type { ControlParts, ViewerLabels };

export interface AttachControlsOptions {
  /** true (default) or the parts to show or hide, as the `controls` option takes them. */
  controls?: boolean | ControlParts;
  /** Texts by key, as the `labels` option takes them. */
  labels?: ViewerLabels;
  /** The book shows a PDF: Download and Print are shown unless hidden. Default false. */
  pdf?: boolean;
}

/** The viewer attached to a book. */
export interface Controls {
  /** The toolbar and its panels, appended to the book's container after the book's element. */
  readonly element: HTMLElement;
  /** The toolbar (role="toolbar"). */
  readonly toolbar: HTMLElement;
  /** The panels' elements by kind, those shown. */
  readonly panels: { thumbnails?: HTMLElement; contents?: HTMLElement; search?: HTMLElement };
  /** Takes the viewer away; the book gets its whole box back. */
  remove(): void;
}

/**
 * Shows the toolbar and its panels with `book` (a Flipbook or StaticBook), in the book's container
 * below it; the book fits itself to the rest of its box. Only the book's public API is used. A
 * TypeError names a bad option.
 */
export function attachControls(book: BookController, options?: AttachControlsOptions): Controls;

/** The English texts, by key. */
export const DEFAULT_LABELS: Readonly<Required<ViewerLabels>>;
/** The toolbar's parts, in their order on it. */
export const CONTROL_PARTS: ReadonlyArray<keyof ControlParts>;
