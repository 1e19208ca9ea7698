// Types of conecurl/react (react.js): the <Flipbook> component's props, its ref handle, useFlipbook().
import type { CSSProperties, ForwardRefExoticComponent, ReactNode, Ref, RefAttributes } from 'react';
import type { FlipbookEventMap } from './book/flipbook.js';
import type { FlipbookHandle, FlipbookOptionProps, FlipbookState } from './components/framework-props.js';

export type { FlipbookHandle, FlipbookOptionProps, FlipbookState } from './components/framework-props.js';

/** Every book event as a handler prop, given the event itself: onTurned, onTurnStart, onPageError, ... */
export interface FlipbookEventProps {
  onReady?: (event: FlipbookEventMap['ready']) => void;
  onProgress?: (event: FlipbookEventMap['progress']) => void;
  onPageError?: (event: FlipbookEventMap['pageerror']) => void;
  onTurnStart?: (event: FlipbookEventMap['turnstart']) => void;
  onTurned?: (event: FlipbookEventMap['turned']) => void;
  onTurnCancel?: (event: FlipbookEventMap['turncancel']) => void;
  onResize?: (event: FlipbookEventMap['resize']) => void;
  onZoom?: (event: FlipbookEventMap['zoom']) => void;
  onSharpened?: (event: FlipbookEventMap['sharpened']) => void;
  onLink?: (event: FlipbookEventMap['link']) => void;
  /** The pages prop changed and the book applied it (inserted, removed or replaced pages, no new book). */
  onPagesChange?: (event: FlipbookEventMap['pageschange']) => void;
  /** Search results changed, a hit was shown, or the search was cleared. */
  onSearchChange?: (event: FlipbookEventMap['searchchange']) => void;
  onFullscreenChange?: (event: FlipbookEventMap['fullscreenchange']) => void;
  /** download() is about to download; preventDefault() stops it. */
  onDownload?: (event: FlipbookEventMap['download']) => void;
  /** print() is about to print; preventDefault() stops it. */
  onPrint?: (event: FlipbookEventMap['print']) => void;
  /** A reader copied a link to a passage they selected (a PDF book's text layer). */
  onPassageLink?: (event: FlipbookEventMap['passagelink']) => void;
  /** The book shows one page instead of two, or two instead of one (display 'auto' chose again, or the display prop changed). */
  onDisplayChange?: (event: FlipbookEventMap['displaychange']) => void;
  /** A tap or click on the middle of the book, which turns nothing (a reader's bar can come back on it). */
  onMiddleTap?: (event: FlipbookEventMap['middletap']) => void;
  /** Reading aloud started (readAloud()), moved to a page, said a word or began a sentence, paused, resumed or ended. */
  onReadAloudStart?: (event: FlipbookEventMap['readaloudstart']) => void;
  onReadAloudPage?: (event: FlipbookEventMap['readaloudpage']) => void;
  onReadAloudWord?: (event: FlipbookEventMap['readaloudword']) => void;
  onReadAloudSentence?: (event: FlipbookEventMap['readaloudsentence']) => void;
  /** Voices were listed after canReadAloud() answered false: it may answer true now. */
  onReadAloudVoices?: (event: FlipbookEventMap['readaloudvoices']) => void;
  onReadAloudPause?: (event: FlipbookEventMap['readaloudpause']) => void;
  onReadAloudResume?: (event: FlipbookEventMap['readaloudresume']) => void;
  onReadAloudEnd?: (event: FlipbookEventMap['readaloudend']) => void;
  /** The book could not be built, or a prop was refused (a TypeError naming it); without it, the console hears. */
  onError?: (event: CustomEvent<{ error: Error }>) => void;
}

export interface FlipbookProps extends FlipbookOptionProps, FlipbookEventProps {
  /** Controlled: the page to show; a change turns the book there. Pair it with onPageChange. */
  page?: number;
  /** Uncontrolled: the page to open at. */
  defaultPage?: number;
  /** The page shown changed (a turn landed, a jump). */
  onPageChange?: (page: number) => void;
  /** The pages, when `pages` is not given: an <img> is an image page (src, alt), any other element a live HTML page. */
  children?: ReactNode;
  id?: string;
  className?: string;
  /** The box the book fills: width 100% and aspect-ratio 16 / 10 unless given here. */
  style?: CSSProperties;
}

/** The flipbook as a React component; on a server it renders its empty, sized box. */
export declare const Flipbook: ForwardRefExoticComponent<FlipbookProps & RefAttributes<FlipbookHandle>>;

/** State and calls of a <Flipbook ref={flipbook.ref}> placed anywhere in the tree. */
export interface UseFlipbook extends FlipbookState {
  ref: Ref<FlipbookHandle>;
  next(): Promise<boolean>;
  prev(): Promise<boolean>;
  flip(index: number, options?: { animate?: boolean }): Promise<void>;
  setZoom(scale: number): void;
  readonly book: FlipbookHandle['book'];
}
export declare function useFlipbook(): UseFlipbook;
