// A book's pages as the controller keeps them, whichever surface draws them: which are loading,
// loaded or failed (and why), the images kept for the pages near the open spread (a bounded cache, the
// least recently wanted let go first), their sizes for the screen, and sharper images when zoomed in. A
// page's `placeholder` is drawn while its own image loads (page-placeholders.js), replaced in the same texture.
// Over 350 lines because a page's load is one flow (early load, placeholder, upload, keep, failure) read in one place.
import { loadPage, pageFailure } from './page-loader.js';
import { EarlyLoads, FirstView } from './early-loads.js';
import { PageCache } from './page-residency.js';
import { PagePlaceholders } from './page-placeholders.js';
import { uploadSizeFor } from './texture-upload.js';
import { directionFacts } from '../engine/direction.js';
import { isZoomed, openPages, restingRect, splicePageMap } from '../engine/layout.js';

const TEXTURE_OVERSAMPLE = 1.5;  // images up to this many pixels per device pixel of the page on screen
const REFIT_RATIO = 1.25;        // a kept image is handed over again only when this far off the size wanted

export class PageStore {
  /**
   * @param {Array<object>} entries  the book's page entries (options.js pageEntries)
   * @param {{ loadWindow: number, direction: string }} settings
   * @param {{ surface: () => object, openPages: () => number[], emit: (type: string, detail: object) => void,
   *           onOpenPageLoaded: (index: number) => void,
   *           decorate?: (index: number, image: object) => object }} hooks
   *   decorate: the image handed to the surface for a page (its search marks drawn in: marked-page.js),
   *   or the page's own image; the store keeps the clean one
   */
  constructor(entries, settings, hooks) {
    this.entries = entries;
    this._settings = settings;
    this._hooks = hooks;
    // page -> image, while the surface holds it; only its { width, height, dropped: true } where the
    // surface copied it (a texture) and the image was ours: the decoded pixels are not held twice.
    this._images = new Map();
    this._naturals = new Map();  // page -> size its source holds, where the image kept was decoded smaller
    this._owned = new Set();   // images made here (ImageBitmaps from URLs and Blobs): closed when let go
    this._cache = new PageCache(settings.loadWindow, entries.length);
    this._abort = new AbortController();  // fetches still running when the book is destroyed stop
    this._early = new EarlyLoads(this._abort.signal);  // the opening pages, asked for before the surface exists
    this._placeholders = new PagePlaceholders({  // drawn while their pages load
      surface: () => this._hooks.surface(), early: this._early, signal: this._abort.signal,
      own: (image) => this._owned.add(image), close: (image) => this._closeIfOwned(image), cover: () => this.cover(),
      loadingAt: (entry, index) => {
        const at = this._closed ? -1 : this._indexOf(entry, index);
        return at >= 0 && this._cache.stateOf(at) === 'loading' && !this._images.has(at) ? at : -1;
      },
      shown: () => {
        this._releaseExcess();
        this._tellShown();
      },
    });
    this._shownWaiters = [];  // whenShown()'s: { shown(), resolve }
    this._reloads = new Map();  // page entry -> its reload running now (by entry: indices move as pages are spliced)
    this._firstView = new FirstView();  // its pages on screen load alone, their neighbours after
    this._closed = false;
  }

  /** Where page `index` stands: { state, reason?, error? }. */
  pageState(index) { return this._cache.pageState(index); }
  /** Whether `image` is the image kept for page `index`. */
  holds(index, image) { return this._images.get(index) === image; }
  /** Pages whose images are kept (held by the surface), in page order. */
  get residentPages() { return [...this._images.keys()].sort((a, b) => a - b); }
  /** { loaded, total, pending }: pages loaded or failed, the page count, loads running now. */
  get progress() { return this._cache.progress; }
  /** Resolves once no page is loading, the first view's neighbours included (they load once it is drawn). */
  whenIdle() { return this._firstView.whenReleased.then(() => this._cache.whenIdle()); }
  /** Resolves once no page is loading now (before the first view is drawn: its pages on screen). */
  whenLoadsSettle() { return this._cache.whenIdle(); }
  /**
   * Resolves once each of `pages` has a picture on the surface: its image, or its placeholder while the
   * image loads; or once it failed (paper and a pageerror). What a first spread shows before it is sharp.
   */
  whenShown(pages) {
    const shown = () => this._closed || pages.every((page) => ['loaded', 'failed'].includes(this._cache.stateOf(page))
      || this._placeholders.pages().includes(page));
    if (shown()) return Promise.resolve();
    return new Promise((resolve) => this._shownWaiters.push({ shown, resolve }));
  }

  // A page took a picture or its load ended: whenShown()'s waiters that now hold are resolved.
  _tellShown() {
    this._shownWaiters = this._shownWaiters.filter(({ shown, resolve }) => (shown() ? (resolve(), false) : true));
  }

  /** The first view is drawn: the pages near it load from now on (until now only its pages on screen did). */
  releaseFirstView() { this._firstView.release(); this.update(); }

  /** Loads the pages wanted now (on screen, then the open spread's neighbours within loadWindow; only those on
   * screen until the first view is drawn) and lets go of the least recently wanted beyond the cache's capacity. */
  update() {
    if (this._closed) return;
    const onScreen = this._hooks.surface().pagesOnScreen();
    const wanted = this._cache.want(this._viewAt(onScreen, this._hooks.openPages()));
    this._firstView.update(onScreen);
    for (const page of wanted) if (this._cache.stateOf(page) === 'idle' && this._firstView.admits(page)) this._load(page);
    this._early.drop();  // asked for early and not wanted now
    this._releaseExcess();
  }

  // What the cache is told of a view: the pages on screen, the open spread's first and last.
  _viewAt(onScreen, open) {
    return { onScreen, first: open[0], last: open[open.length - 1], loadWindow: this._settings.loadWindow, pageCount: this.entries.length };
  }

  /** Before the surface exists: starts loading what its first update() will want at `position`, sized for a
   * `display` view of a canvas of `size` CSS px (layout.js, as the engine), to fetch and decode meanwhile; a page
   * whose placeholder is a URL once `placeholdersShown` resolves (EarlyLoads.start). */
  prefetch(size, display, position, placeholdersShown = null) {
    const open = openPages(position, this.entries.length, display);
    const { direction, pageAspect } = this._settings;
    const cover = this._coverOf(restingRect(size, { display, direction, pageAspect }), display, 1);
    this._early.start(open.map((page) => [page, this.entries[page]]), cover, placeholdersShown);  // the first view's pages: their neighbours after
  }

  /** A page's size on screen in CSS px at zoom 1 (restingRect is the zoomed picture of both pages). */
  pageCssSize() {
    const surface = this._hooks.surface();
    return this._pageOf(surface.restingRect(), surface.display, surface.zoom);
  }

  // One page's share of `full`, the rect of both pages of a spread (or the one page), at zoom 1.
  _pageOf(full, display, zoom) {
    const [spread, { vertical }] = [display === 'single' ? 1 : 2, directionFacts(this._settings.direction)];
    return { width: full.width / (vertical ? 1 : spread) / zoom, height: full.height / (vertical ? spread : 1) / zoom };
  }

  /**
   * Pixels a page needs: its size on screen in device pixels, times TEXTURE_OVERSAMPLE. Images are
   * sized for the whole book unless asked for the open pages while zoomed in (only those get the extra
   * pixels: memory stays bounded).
   */
  cover({ zoomed = false } = {}) {
    const surface = this._hooks.surface();
    return this._coverOf(surface.restingRect(), surface.display, surface.zoom, zoomed ? surface.zoom : 1);
  }

  _coverOf(full, display, zoom, magnified = 1) {
    const { width, height } = this._pageOf(full, display, zoom);
    const scale = (globalThis.devicePixelRatio || 1) * TEXTURE_OVERSAMPLE * magnified;
    return { width: Math.ceil(width * scale), height: Math.ceil(height * scale) };
  }

  /** Page `index` changed (an HTML page's content): its kept image made again, a failed page loaded again if wanted. */
  refresh(index) {
    const state = this._closed ? 'closed' : this._cache.stateOf(index);
    if (state === 'failed') {
      this._cache.setState(index, 'idle');
      this.update();
      return this.whenIdle();
    }
    return state === 'loaded' ? this._reload(index, this.cover(), this.entries[index].src, false, { force: true }) : Promise.resolve();
  }

  /**
   * The surface lost these pages' images (a WebGL context restored, and their images were closed after
   * upload): they are decoded again from their sources. The pages show plain paper until then.
   */
  reloadLost(pages) {
    if (this._closed) return;
    for (const index of pages) {
      if (this._images.has(index)) this._reload(index, this.cover(), this.entries[index].src, false, { force: true });
    }
  }

  /**
   * The size on screen or the zoom changed: kept images far off the size now wanted are handed to the
   * surface again, and zoomed-in open pages get a sharper source where they have one.
   */
  refit() {
    if (this._closed) return;
    const surface = this._hooks.surface();
    const maxTextureSize = surface.maxTextureSize;
    const open = new Set(this._hooks.openPages());
    for (const [index, image] of this._images) {
      const sharp = open.has(index) && isZoomed(surface.zoom);
      const cover = this.cover({ zoomed: sharp });
      const uploaded = surface.pageImageSize(index);
      const kept = { width: image.naturalWidth || image.width, height: image.naturalHeight || image.height };
      const natural = this._naturals.get(index) ?? kept;  // what the source holds
      const wanted = uploadSizeFor(natural.width, natural.height, { cover, maxTextureSize });
      const ratio = wanted.width / uploaded.width;
      const entry = this.entries[index];
      if (ratio > REFIT_RATIO && wanted.width > kept.width * REFIT_RATIO) {
        this._reload(index, cover, entry.src, sharp);  // the source holds more than was decoded: decode it again
      } else if (ratio > REFIT_RATIO || ratio < 1 / REFIT_RATIO) {
        if (image.dropped) this._reload(index, cover, entry.src, sharp);  // ours, closed after upload: decode again
        else surface.setPageImage(index, this.presented(index, image), { cover });
      }
      // Zoomed in past what the source holds: a sharper source, where the page has one.
      const sharper = typeof entry.src === 'function' ? entry.src : entry.zoomSrc;  // a function is told `cover`
      if (sharp && sharper && wanted.width < cover.width / REFIT_RATIO && wanted.width < maxTextureSize) {
        this._reload(index, cover, sharper, true);
      }
    }
  }

  /**
   * The entries were spliced (live-pages.js): `removed` pages at `at` gave way to `inserted` new ones.
   * The removed pages' images are let go (the surface drops its copies itself); the others keep theirs,
   * renumbered. Loads under way find their page by its entry when they land.
   */
  splice(at, removed, inserted) {
    for (const [page, image] of this._images) if (page >= at && page < at + removed) this._closeIfOwned(image);
    this._placeholders.splice(at, removed, inserted);
    this._images = splicePageMap(this._images, at, removed, inserted);
    this._naturals = splicePageMap(this._naturals, at, removed, inserted);
    this._cache.splice(at, removed, inserted);
  }

  /**
   * Page `index` has a new entry (replacePage): a page shown keeps its present image until the new one
   * is uploaded over it (or shows paper if it fails); any other is loaded anew when wanted.
   */
  replace(index) {
    this._naturals.delete(index);
    if (this._images.has(index)) {
      this._reload(index, this.cover(), this.entries[index].src, false, { force: true, replacing: true });
      return;
    }
    this._placeholders.release(index);  // the old entry's, while it loaded
    this._cache.setState(index, 'idle');  // a load under way finds its entry gone and is dropped
    this.update();
  }

  /** What the surface is handed for page `index` whose image is `image`: the image with its marks, if any. */
  presented(index, image) {
    return this._hooks.decorate?.(index, image) ?? image;
  }

  /**
   * Page `index`'s marks changed (search hits): its image is handed to the surface again, marked or
   * clean, at the size it has now; one closed after upload is loaded again. Resolves when done.
   */
  remark(index) {
    if (this._closed || this._cache.stateOf(index) !== 'loaded') return Promise.resolve();
    const image = this._images.get(index);
    const surface = this._hooks.surface();
    if (image && !image.dropped) {
      surface.setPageImage(index, this.presented(index, image), { cover: surface.pageImageSize(index) ?? this.cover() });
      return Promise.resolve();
    }
    return this._reload(index, this.cover(), this.entries[index].src, false, { force: true });
  }

  /** The book is destroyed: loads stop, owned images are closed, waiters released. */
  close() {
    if (this._closed) return;
    this._closed = true;
    this._abort.abort();
    this._early.drop();
    for (const image of this._owned) image.close?.();
    this._owned.clear();
    this._images.clear();
    this._placeholders.clear();
    this._cache.releaseWaiters();
    this._firstView.release();
    this._tellShown();
  }

  _releaseExcess() {
    for (const page of this._cache.release([...this._images.keys(), ...this._placeholders.pages()])) {
      this._hooks.surface().releasePageImage(page);
      if (this._placeholders.drop(page)) continue;  // still loading: its image is kept or dropped when it lands
      this._closeIfOwned(this._images.get(page));
      this._images.delete(page);
      this._naturals.delete(page);
      this._cache.setState(page, 'idle');
    }
  }

  // Where `entry` is now (pages may have been spliced while it loaded); -1 if it left the book.
  _indexOf(entry, index) {
    return this.entries[index] === entry ? index : this.entries.indexOf(entry);
  }

  async _load(index) {
    this._cache.startLoad(index);
    const entry = this.entries[index];
    const swap = { landed: false };  // the page's own image is in hand: its placeholder is not drawn any more
    try {
      // A function makes its page only when the page is wanted (drawn, fetched or rendered on
      // demand), told the size in device pixels the page is drawn at. Asked for early (prefetch), taken up.
      const cover = this.cover();
      const inHand = this._early.landed(entry);  // fetched and decoded while the surface was made
      const early = this._early.take(entry, cover);
      if (entry.placeholder !== undefined && !inHand) this._placeholders.show(entry, index, swap);
      const { image, owned, natural } = (early && await early)
        ?? await loadPage(entry.src, { index, size: cover, signal: this._abort.signal });
      swap.landed = true;
      if (owned) this._owned.add(image);
      index = this._closed ? -1 : this._indexOf(entry, index);
      if (index < 0 || this._cache.stateOf(index) !== 'loading'
          || (!this._cache.wanted.has(index) && this._images.size >= this._cache.capacity)) {
        // Destroyed, removed or replaced, or no longer wanted and no room: not worth keeping.
        this._closeIfOwned(image);
        if (index >= 0 && this._cache.stateOf(index) === 'loading') {
          this._placeholders.release(index);
          this._cache.setState(index, 'idle');
        }
        return;
      }
      // Over the placeholder's texture, if it has one: the placeholder stays drawn until this replaces it.
      await this._hooks.surface().queuePageImage(index, this.presented(index, image), { cover: this.cover() });  // mid-turn: in bands over frames
      if (this._closed) return;
      index = this._indexOf(entry, index);  // the surface renumbered its texture along with the page
      if (index < 0) {
        this._closeIfOwned(image);
        return;
      }
      this._placeholders.drop(index);
      this._keep(index, image);
      this._keepNatural(index, natural);
      this._cache.setState(index, 'loaded');
      this._releaseExcess();
      this._hooks.onOpenPageLoaded(index);
    } catch (error) {
      swap.landed = true;
      index = this._closed ? -1 : this._indexOf(entry, index);
      if (index < 0 || this._cache.stateOf(index) !== 'loading') return;
      // The page keeps (or goes back to) the plain paper placeholder; the book keeps working. `reason` says
      // why: 'http', 'network', 'cors', 'decode' or 'source' (PageLoadError), or 'upload'.
      this._placeholders.release(index);
      const failure = pageFailure(error);
      this._cache.setState(index, 'failed', failure);
      this._hooks.emit('pageerror', { index, ...failure });
    } finally {
      const progress = this._cache.endLoad();
      this._tellShown();
      if (!this._closed) this._hooks.emit('progress', progress);
    }
  }

  _keepNatural(index, natural) { if (natural) this._naturals.set(index, natural); else this._naturals.delete(index); }

  // Loads a page's image again at the size `cover` asks for: its source decoded larger, `zoomSrc`, or
  // its function called again (a PDF page rendered anew). The page keeps its present image until the
  // new one is ready; `sharpened` is told when it came for the zoomed view.
  // `replacing`: the page's entry is new (replacePage): if its image fails, the old one goes too.
  async _reload(index, cover, source, zoomed, { force = false, replacing = false } = {}) {
    const entry = this.entries[index];
    const running = this._reloads.get(entry);
    if (running) {
      if (!force) return running;
      await running.catch(() => {});  // content changed during the reload: once more after it
      index = this._indexOf(entry, index);
      if (index < 0 || this._closed) return undefined;
    }
    const reload = this._reloadNow(entry, index, cover, source, zoomed, replacing);
    this._reloads.set(entry, reload);
    return reload;
  }

  async _reloadNow(entry, index, cover, source, zoomed, replacing) {
    try {
      const { image, owned, natural } = await loadPage(source, { index, size: cover, signal: this._abort.signal });
      if (owned) this._owned.add(image);
      index = this._closed ? -1 : this._indexOf(entry, index);
      if (index < 0 || !this._images.has(index)) {
        this._closeIfOwned(image);
        return;
      }
      const surface = this._hooks.surface();
      const previous = this._images.get(index);
      surface.setPageImage(index, this.presented(index, image), { cover });
      this._keep(index, image);
      if (source === entry.src) this._keepNatural(index, natural);
      if (previous !== image) this._closeIfOwned(previous);
      if (zoomed) this._hooks.emit('sharpened', { index, width: surface.pageImageSize(index).width });
    } catch (error) {
      index = this._closed ? -1 : this._indexOf(entry, index);
      if (index < 0) return;
      if (replacing && this._images.has(index)) this._fail(index, error);
      else this._hooks.emit('pageerror', { index, ...pageFailure(error) });
    } finally {
      this._reloads.delete(entry);
    }
  }

  // A replaced page whose new image failed: its old image goes, it shows paper and stands failed.
  _fail(index, error) {
    this._hooks.surface().releasePageImage(index);
    this._closeIfOwned(this._images.get(index));
    this._images.delete(index);
    const failure = pageFailure(error);
    this._cache.setState(index, 'failed', failure);
    this._hooks.emit('pageerror', { index, ...failure });
  }

  // What is kept of a page's image once the surface holds it: the image, or where the surface made its
  // own copy and the image is ours (an ImageBitmap decoded here), only its size: it is closed now.
  _keep(index, image) {
    if (this._hooks.surface().copiesImages && this._owned.has(image)) {
      this._images.set(index, { width: image.width, height: image.height, dropped: true });
      this._closeIfOwned(image);
    } else {
      this._images.set(index, image);
    }
  }

  _closeIfOwned(image) { if (image && this._owned.delete(image)) image.close?.(); }
}
