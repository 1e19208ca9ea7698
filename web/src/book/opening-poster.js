// The first view's poster over one book (layers/first-view-poster.js lays it), through its life: shown once the
// book knows its size, the opening pages' own images held until it has painted, and gone when the surface covers it.
import { afterFrames } from '../surfaces/after-first-frame.js';
import { posterStillFits, showFirstViewPoster } from '../layers/first-view-poster.js';

// How many animation frames the book waits at most for its poster to be told painted before it makes its
// context, and after its surface is made the opening pages' own images (first-view-poster.js resolves at once
// where it cannot be painted: a hidden page, an element not rendered or off screen). Its paint is in the first
// of them; it only bounds a case not foreseen.
const POSTER_PAINT_LATEST_FRAMES = 10;
const paintBound = (task) => afterFrames(POSTER_PAINT_LATEST_FRAMES, task);

export class OpeningPoster {
  /** @param {(schedule: Function, task: Function) => void} defer  the book's (cancelled when it is destroyed) */
  constructor(defer) {
    this._defer = defer;
    this._poster = null;
    // A page the poster shows asks for its own image once this resolves (EarlyLoads.start): on a slow network the
    // small pictures come first, and the page's largest contentful paint (the poster's image) waits on no big one.
    this.placeholdersShown = new Promise((resolve) => { this._showPlaceholders = resolve; });
  }

  /**
   * Lays the poster (showFirstViewPoster's arguments) and resolves once it has painted, or after the frames'
   * bound, or at once where it has nothing to show. Awaited before the context is made (a long block of the
   * main thread where WebGL runs in software): the cover shows first, and the pages' own images are asked for
   * before that block.
   */
  show(canvas, book, size, opening) {
    this._poster = showFirstViewPoster(canvas, book, size, opening);
    if (!this._poster) {
      this._showPlaceholders();
      return Promise.resolve();
    }
    this._poster.whenPainted.then(this._showPlaceholders);
    return new Promise((resolve) => {
      this._poster.whenPainted.then(resolve);
      this._defer(paintBound, resolve);
    });
  }

  /** The surface is made: the opening pages' images wait no longer than the frames' bound from now. */
  surfaceMade() { this._defer(paintBound, this._showPlaceholders); }

  /** The surface covers the poster now; it goes once its images have painted too (each is the page's largest
   * contentful paint where the canvas is none): first-view-poster.js removeOncePainted. */
  retire() {
    const poster = this._poster;
    poster?.removeOncePainted().then(() => { if (this._poster === poster) this._poster = null; });
  }

  /** Removes it where the surface's open pages (openPagePlaces) lie elsewhere: zoomed, or other pages open. */
  fit(places) { if (this._poster && !posterStillFits(this._poster, places)) this.remove(); }

  remove() {
    this._poster?.remove();
    this._poster = null;
  }
}
