// The opening pages, asked for before the book's surface exists: making it (a WebGL context) is the longest
// step of a first view, and their fetch and off-thread decode run meanwhile. PageStore takes them up, and
// their neighbours wait until they are drawn (FirstView).
import { loadPage } from './page-loader.js';
import { MAX_IMAGE_SIZE, naturalSize, uploadSizeFor } from './texture-upload.js';

const SAME_SIZE = 0.99;  // within 1 % of the size wanted is that size (as texture-upload.js)

// Only a fetch and a decode off the main thread are started early: a page function may draw on the main
// thread, which is busy making the context then (and a function is told its size, which the surface knows best).
const isEncoded = (source) => typeof source === 'string' || (typeof Blob !== 'undefined' && source instanceof Blob);

const closeOwned = ({ image, owned }) => { if (owned) image.close?.(); };

/**
 * The first view's pages on screen load alone; their neighbours once the book has drawn them and lets
 * go (release()), so that on a slow network the first spread shares its bandwidth with no page it does not
 * show. Until then every page on screen is admitted: one a turn brings in before the release too.
 */
export class FirstView {
  constructor() {
    this._onScreen = null;  // the pages on screen at the store's latest update
    this._released = false;
    this.whenReleased = new Promise((resolve) => { this._resolve = resolve; });
  }

  /** The store's update: `onScreen` its pages on screen. */
  update(onScreen) { if (!this._released) this._onScreen = new Set(onScreen); }

  /** Whether `page` may load now. */
  admits(page) { return this._released || !this._onScreen || this._onScreen.has(page); }

  /** The neighbours may load from now on (the first view is drawn, or the book is destroyed). */
  release() {
    this._released = true;
    this._resolve();
  }
}

export class EarlyLoads {
  /** @param {AbortSignal} signal  the store's: fetches stop when the book is destroyed */
  constructor(signal) {
    this._signal = signal;
    this._loads = new Map();  // page entry -> loadPage's promise
    this._placeholders = new Map();  // page entry -> loadPage's promise of its placeholder, ready for the surface's first frame
    this._landed = new Set();  // page entries whose early load has settled
  }

  /** Starts loading each page of `pages` ([index, entry]) whose source is a URL or a Blob, decoded to cover `cover`,
   * and its placeholder where it has one (a URL or a Blob). A page whose placeholder is a URL (the book's poster
   * shows it: first-view-poster.js) asks for its own image only once `placeholdersShown` (a promise) resolves. */
  start(pages, cover, placeholdersShown = null) {
    for (const [index, entry] of pages) {
      if (isEncoded(entry.placeholder) && !this._placeholders.has(entry)) {
        const load = loadPage(entry.placeholder, { index, signal: this._signal });
        load.catch(() => {});  // a placeholder that fails is passed over by the store
        this._placeholders.set(entry, load);
      }
      if (!isEncoded(entry.src) || this._loads.has(entry)) continue;
      const ask = () => loadPage(entry.src, { index, size: cover, signal: this._signal });
      const load = placeholdersShown && typeof entry.placeholder === 'string' ? placeholdersShown.then(ask) : ask();
      const landed = () => { if (this._loads.get(entry) === load) this._landed.add(entry); };
      load.then(landed, landed);  // a failure is reported by the load that takes it up
      this._loads.set(entry, load);
    }
  }

  /**
   * The early load of `entry` as loadPage resolves (or rejects), or null where none was started. Taken
   * synchronously: the store's next update() finds it gone. An image decoded smaller than `cover` now
   * wants (the surface lays the page out larger than guessed) is let go, and null is returned: loaded anew.
   */
  take(entry, cover) {
    const load = this._loads.get(entry);
    if (!load) return null;
    this._loads.delete(entry);
    this._landed.delete(entry);
    return load.then((result) => {
      const have = naturalSize(result.image);
      const from = result.natural ?? have;
      const wanted = uploadSizeFor(from.width, from.height, { cover, maxTextureSize: MAX_IMAGE_SIZE });
      if (have.width >= wanted.width * SAME_SIZE && have.height >= wanted.height * SAME_SIZE) return result;
      closeOwned(result);
      return null;
    });
  }

  /** Whether `entry`'s early load has settled already (its image is in hand: no placeholder is worth drawing). */
  landed(entry) { return this._landed.has(entry); }

  /** The early load of `entry`'s placeholder as loadPage resolves (or rejects), or null; taken synchronously. */
  takePlaceholder(entry) {
    const load = this._placeholders.get(entry) ?? null;
    this._placeholders.delete(entry);
    return load;
  }

  /** Loads not taken are let go: their images closed as they land. */
  drop() {
    for (const load of [...this._loads.values(), ...this._placeholders.values()]) load.then(closeOwned, () => {});
    this._loads.clear();
    this._placeholders.clear();
    this._landed.clear();
  }
}
