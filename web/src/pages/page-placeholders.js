// A page's `placeholder` (issue 38): a small image the surface draws over the whole page while the page's own
// image loads, replaced by that image in the same texture. Apart from page-store.js, which asks it through a port.
import { loadPage } from './page-loader.js';
import { splicePageMap } from '../engine/layout.js';

export class PagePlaceholders {
  /**
   * @param {{ surface: () => object, early: object, signal: AbortSignal, own: (image: object) => void,
   *           close: (image: object) => void, loadingAt: (entry: object, index: number) => number,
   *           cover: () => object, shown: () => void }} port
   *   early: the store's EarlyLoads; own/close: an image made here is the store's to close; loadingAt: where
   *   `entry`'s page is now if it still loads with no image kept, else -1; shown: a placeholder took a texture
   */
  constructor(port) {
    this._port = port;
    // page -> its placeholder image, held by the surface while the page's own image loads (one texture a
    // page: the image replaces it). Counted with the kept images against the cache's capacity.
    this._images = new Map();
  }

  /** The pages showing their placeholder. */
  pages() { return [...this._images.keys()]; }

  /**
   * Page `index`'s `placeholder` (entry.placeholder), loaded beside its own image (or taken from the early
   * loads) and handed to the surface at its own small size (the surface draws any page image over the whole
   * page: the layout comes from the page, never from the image) if the page still loads without its image
   * (`swap.landed` false). A placeholder that fails is passed over: the page loads as without one.
   */
  async show(entry, index, swap) {
    const port = this._port;
    const early = port.early.takePlaceholder(entry);  // decoded while the surface was made
    let loaded;
    try {
      loaded = await (early ?? loadPage(entry.placeholder, { index, signal: port.signal }));
    } catch {
      return;
    }
    const { image, owned } = loaded;
    if (owned) port.own(image);
    index = swap.landed ? -1 : port.loadingAt(entry, index);
    if (index < 0) {
      port.close(image);
      return;
    }
    try {
      port.surface().setPageImage(index, image, { cover: port.cover() });
    } catch {
      port.close(image);
      return;
    }
    this.drop(index);
    this._images.set(index, image);
    port.shown();
  }

  /** Page `index`'s placeholder image is let go (its texture replaced by the page's image, or released by the caller); whether it had one. */
  drop(index) {
    if (!this._images.has(index)) return false;
    this._port.close(this._images.get(index));
    this._images.delete(index);
    return true;
  }

  /** A page that will not show its image (it failed, or is let go) gives back its placeholder's texture too. */
  release(index) {
    if (this.drop(index)) this._port.surface().releasePageImage(index);
  }

  /** The pages were spliced: the removed pages' placeholders go (the surface drops its copies), the others follow theirs. */
  splice(at, removed, inserted) {
    for (const [page, image] of this._images) if (page >= at && page < at + removed) this._port.close(image);
    this._images = splicePageMap(this._images, at, removed, inserted);
  }

  /** The book is destroyed (the store closes the images it owns). */
  clear() { this._images.clear(); }
}
