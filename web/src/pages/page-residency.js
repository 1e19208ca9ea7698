// Which pages keep a texture: the bounded page cache of Flipbook as plain functions (no DOM, no GL),
// so the policy is tested on its own and GPU memory does not grow with the length of the book.

import { MAX_TURNS_IN_FLIGHT, splicePageMap, splicedPage } from '../engine/layout.js';

export { MAX_TURNS_IN_FLIGHT };  // turns the book can have in flight at once (the engine's constant)

/**
 * Most page textures a book keeps: the pages within `loadWindow` of the open spread plus a little
 * history, and never fewer than can be on screen at once (two resting pages and both sides of every
 * leaf in flight). It depends on `loadWindow` only, never on the page count.
 */
export function textureCapacity(loadWindow) {
  return Math.max(2 * loadWindow + 4, 2 + 2 * MAX_TURNS_IN_FLIGHT);
}

/**
 * Pages wanted now, most wanted first: those on screen, then the open spread's neighbours outward
 * (the next page before the previous one at each distance), up to `capacity` pages; the pages on
 * screen are always all in. `first`/`last` are the open spread's pages at the settled position.
 */
export function wantedPages({ onScreen, first, last, loadWindow, pageCount, capacity }) {
  const wanted = [...new Set(onScreen)];
  const seen = new Set(wanted);
  const add = (page) => {
    if (wanted.length < capacity && page >= 0 && page < pageCount && !seen.has(page)) {
      seen.add(page);
      wanted.push(page);
    }
  };
  // Stops at the book's ends and at capacity: a loadWindow of a billion pages costs no more than the book.
  for (let distance = 0; distance <= loadWindow && wanted.length < capacity; distance++) {
    if (last + distance >= pageCount && first - distance < 0) break;
    add(last + distance);
    add(first - distance);
  }
  return wanted;
}

/**
 * Resident pages to release so that at most `capacity` stay: never a wanted one; of the others, the
 * longest unwanted first. `lastWanted` maps each resident page to when it was last wanted.
 */
export function pagesToRelease({ resident, wanted, lastWanted, capacity }) {
  const excess = resident.length - capacity;
  if (excess <= 0) return [];
  const wantedSet = new Set(wanted);
  return resident
    .filter((page) => !wantedSet.has(page))
    .sort((a, b) => (lastWanted.get(a) ?? -Infinity) - (lastWanted.get(b) ?? -Infinity))
    .slice(0, excess);
}

/**
 * One book's cache bookkeeping (Flipbook's textures, StaticBook's images): each page's load state,
 * the loads in flight, which pages are wanted now and when each was last wanted, so that the least
 * recently wanted goes first.
 */
export class PageCache {
  constructor(loadWindow, pageCount) {
    this.capacity = textureCapacity(loadWindow);
    this.wanted = new Set();
    this.loadsInFlight = 0;
    this._lastWanted = new Map();  // page -> tick of the update that last wanted it
    this._clock = 0;
    this._states = new Array(pageCount).fill('idle');  // idle | loading | loaded | failed
    this._failures = new Map();    // page -> { reason, error } while it stands failed
    this._settled = 0;             // pages loaded or failed
    this._idleWaiters = [];
  }

  /** 'idle', 'loading', 'loaded' or 'failed'. */
  stateOf(page) { return this._states[page]; }

  /** Sets a page's state (a load started, landed, failed with `failure` { reason, error }, or was let go: 'idle'). */
  setState(page, state, failure = null) {
    const settled = (s) => s === 'loaded' || s === 'failed';
    this._settled += (settled(state) ? 1 : 0) - (settled(this._states[page]) ? 1 : 0);
    this._states[page] = state;
    if (state === 'failed') this._failures.set(page, failure ?? { reason: 'upload', error: new Error('page failed') });
    else this._failures.delete(page);
  }

  /** Where a page stands, for the books' pageState(): its state, and why it failed. */
  pageState(page) {
    if (!Number.isInteger(page) || page < 0 || page >= this._states.length) {
      throw new RangeError(`conecurl: page must be a page index from 0 to ${this._states.length - 1}, got ${String(page)}`);
    }
    return { state: this._states[page], ...this._failures.get(page) };
  }

  /** A load of `page` starts. */
  startLoad(page) {
    this.setState(page, 'loading');
    this.loadsInFlight++;
  }

  /** A load ended (its page's state set already): the `progress` event's detail. */
  endLoad() {
    this.loadsInFlight--;
    if (this.loadsInFlight === 0) this.releaseWaiters();
    return this.progress;
  }

  /** { loaded, total, pending }: pages loaded or failed, the page count, loads running now. */
  get progress() {
    return { loaded: this._settled, total: this._states.length, pending: this.loadsInFlight };
  }

  /** Resolves once no page is loading. */
  whenIdle() {
    if (this.loadsInFlight === 0) return Promise.resolve();
    return new Promise((resolve) => this._idleWaiters.push(resolve));
  }

  /** Lets every whenIdle() resolve now (the book is destroyed). */
  releaseWaiters() {
    for (const resolve of this._idleWaiters.splice(0)) resolve();
  }

  /** `removed` pages at `at` gave way to `inserted` new ones (idle): states and wants renumbered. */
  splice(at, removed, inserted) {
    const gone = this._states.slice(at, at + removed);
    this._settled -= gone.filter((s) => s === 'loaded' || s === 'failed').length;
    // Concatenated, not spliced with spread arguments: a million pages inserted at once fit no call's arguments.
    this._states = [...this._states.slice(0, at), ...new Array(inserted).fill('idle'), ...this._states.slice(at + removed)];
    this._failures = splicePageMap(this._failures, at, removed, inserted);
    this._lastWanted = splicePageMap(this._lastWanted, at, removed, inserted);
    this.wanted = new Set([...this.wanted].map((page) => splicedPage(page, at, removed, inserted)).filter((page) => page >= 0));
  }

  /** Records and returns the pages wanted now ({ onScreen, first, last, loadWindow, pageCount }). */
  want(view) {
    const pages = wantedPages({ ...view, capacity: this.capacity });
    this._clock++;
    this.wanted = new Set(pages);
    for (const page of pages) this._lastWanted.set(page, this._clock);
    return pages;
  }

  /** The pages of `resident` to let go now (and forget), least recently wanted first. */
  release(resident) {
    const pages = pagesToRelease({ resident, wanted: this.wanted, lastWanted: this._lastWanted, capacity: this.capacity });
    for (const page of pages) this._lastWanted.delete(page);
    return pages;
  }
}
