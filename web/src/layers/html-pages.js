// HTML pages: live DOM where the reader interacts, a texture where the page moves. An overlay layer
// that shows each open HTML page's element over its place while the book rests (inputs, links, video,
// selection, focus all live), hides it while a leaf moves, and rasterises it to the page's texture
// (modern-screenshot, an optional dependency imported only for books with HTML pages; of the three
// measured by scripts/bench/html-snapshots.mjs the closest to the browser's own rendering, and flat in
// memory over 200 books), again whenever its content changes.
import { PAPER } from '../engine/layout.js';
import { freeEdge } from '../engine/direction.js';
import { turnGrips } from '../input/turn-area.js';

const REFRESH_DELAY_MS = 150;  // a page's texture is made again once its content has rested this long
const SNAPSHOT_TIMEOUT_MS = 10000;  // a page the rasteriser cannot draw by then fails (pageerror), the book goes on
// Changes no mutation reports: form values, and images or videos in the page that finished loading
// (listened to in the capture phase: load events do not bubble). Web fonts: document.fonts.
const CHANGE_EVENTS = ['input', 'change', 'load', 'loadeddata'];
const OFFSCREEN = 'translate(-100000px, 0)';
// What a grip hands to the canvas: presses, moves and clicks that turn, and zoom gestures.
const FORWARDED = ['pointerdown', 'pointermove', 'pointerup', 'pointercancel', 'click', 'dblclick', 'wheel'];
const EVENT_CLASS = { click: 'MouseEvent', dblclick: 'MouseEvent', wheel: 'WheelEvent' };

async function importRasteriser() {
  try {
    return await import('modern-screenshot');
  } catch (error) {
    throw new Error('conecurl: HTML pages need the optional dependency modern-screenshot (npm install modern-screenshot) '
      + `to draw them while they turn; it could not be loaded: ${error && error.message ? error.message : error}`);
  }
}

export class HtmlPages {
  /**
   * @param {HTMLElement} root  the book's element: the layer goes in it, over the canvas
   * @param {Array<object>} entries  the book's page entries; those with `html` get a `src` that rasterises them
   * @param {{ direction: string, turnArea: string, canvas: HTMLCanvasElement, zoom: () => number,
   *           pageSize: () => { width: number, height: number }, changed: (index: number) => void,
   *           pagesOnScreen: () => number[], redrawn: (index: number, canvas: HTMLCanvasElement) => void }} book
   */
  constructor(root, entries, book) {
    this._book = book;
    // A press on a grip (the turn area over live content) is the canvas's: the same event, sent there.
    this._forward = (event) => {
      event.stopPropagation();
      if (event.cancelable) event.preventDefault();
      const Class = globalThis[EVENT_CLASS[event.type] ?? 'PointerEvent'];
      book.canvas.dispatchEvent(new Class(event.type, event));
    };
    this._layer = document.createElement('div');
    this._layer.className = 'conecurl-html-pages';
    this._layer.style.cssText = 'position:absolute;inset:0;overflow:hidden;pointer-events:none';
    // Right after the canvas (positioned, book-shell.js, in `root`), so above it and below the links, which come later.
    book.canvas.after(this._layer);
    this._pages = new Map();  // page index -> { element, sheet, content, home, observer, grips, canvas, videos }
    this._dirty = new Set();
    this._timer = 0;
    this._moving = false;     // a leaf moves: the live pages are hidden, their textures show
    this._removed = false;
    this._size = null;        // the pages' CSS size at zoom 1, as last laid out
    // A web font that arrives later changes how every page looks.
    this._fontsLoaded = () => { for (const index of this._pages.keys()) this._changed(index); };
    document.fonts?.addEventListener?.('loadingdone', this._fontsLoaded);
    this._host = root.getRootNode().host ?? null;  // <cone-flipbook>: its children stay its own, slotted
    entries.forEach((entry, index) => this._adopt(index, entry));
  }

  /**
   * The book's pages were spliced on the live book (live-pages.js): the removed pages' elements go back
   * where they came from, later pages take their new indices, and `entries` (the new pages at `at`)
   * that are HTML pages are mounted.
   */
  splice(at, removed, entries) {
    for (const [index, page] of this._pages) if (index >= at && index < at + removed) this._unmount(page);
    const shift = entries.length - removed;
    const moved = new Map();
    for (const [index, page] of this._pages) {
      if (index >= at && index < at + removed) continue;
      if (index >= at + removed) this._renumber(page, index + shift);
      moved.set(page.index, page);
    }
    this._pages = moved;
    this._dirty = new Set([...this._dirty].filter((i) => i < at || i >= at + removed).map((i) => (i < at ? i : i + shift)));
    entries.forEach((entry, i) => this._adopt(at + i, entry));
  }

  // An HTML page entry becomes page `index`: its element is mounted, its `src` rasterises it.
  _adopt(index, entry) {
    if (!entry.html) return;
    const page = this._mount(index, entry.html, this._host);
    this._pages.set(index, page);
    // By the page, not the index it had: pages inserted or removed before it renumber it while it loads.
    entry.src = (_, size) => this.snapshot(page.index, size);
  }

  /**
   * Of `pages`, the HTML pages whose content changed since their texture was made; a page holding a
   * canvas or video (moving pictures no mutation reports) always counts as changed.
   */
  staleAmong(pages) {
    return pages.filter((page) => this._dirty.has(page)
      || (this._pages.has(page) && this._pages.get(page).element.querySelector('canvas, video') !== null));
  }

  /** Shows the open HTML pages live over their places (CSS px of the root); the others go out of sight. */
  place(places) {
    this._moving = false;  // at rest: a playing video is live again
    if (this._dirty.size > 0) this._scheduleRefresh();  // changes made while leaves moved
    const zoom = this._book.zoom();
    this._resize(this._book.pageSize());
    const open = new Map(places.filter((place) => this._pages.has(place.page)).map((place) => [place.page, place]));
    for (const [index, page] of this._pages) {
      const place = open.get(index);
      if (!place) {
        this._conceal(page);
        continue;
      }
      page.sheet.style.transform = `translate(${place.x}px, ${place.y}px) scale(${zoom})`;
      this._layGrips(page, turnGrips(this._book.turnArea, this._size.width, this._size.height,
        freeEdge(this._book.direction, place.turned)));
      page.sheet.inert = false;
      page.sheet.removeAttribute('aria-hidden');
    }
  }

  /** A leaf moves: every page shows as its texture, and the videos playing on them go on playing there. */
  hide() {
    for (const page of this._pages.values()) this._conceal(page);
    if (!this._moving) {
      this._moving = true;
      if ([...this._pages.values()].some((page) => page.videos.length > 0)) this._followVideos();
    }
  }

  // While leaves move, each frame of a playing <video> on a page on screen is drawn into that page's
  // snapshot where the video lies, and the texture is updated from it: one draw and one upload a frame.
  _followVideos() {
    const step = () => {
      if (!this._moving || this._removed) return;
      const onScreen = new Set(this._book.pagesOnScreen());
      for (const [index, page] of this._pages) {
        if (!page.canvas || !onScreen.has(index)) continue;
        const playing = page.videos.filter(({ video }) => !video.paused && !video.ended && video.readyState >= 2);
        if (playing.length === 0) continue;
        this._drawVideos(page, playing);
        this._book.redrawn(index, page.canvas);
      }
      requestAnimationFrame(step);
    };
    requestAnimationFrame(step);
  }

  /** The book is destroyed: each element goes back where it came from. */
  remove() {
    this._removed = true;
    clearTimeout(this._timer);
    document.fonts?.removeEventListener?.('loadingdone', this._fontsLoaded);
    for (const page of this._pages.values()) this._unmount(page);
    this._pages.clear();
    this._layer.remove();
  }

  // A page leaves: its element goes back where it came from, its sheet goes.
  _unmount(page) {
    page.observer.disconnect();
    for (const type of CHANGE_EVENTS) page.element.removeEventListener(type, page.onInput, true);
    if (page.slotted) page.element.removeAttribute('slot');
    else if (page.home.parent) page.home.parent.insertBefore(page.element, page.home.next?.parentNode === page.home.parent ? page.home.next : null);
    else page.element.remove();
    page.sheet.remove();
  }

  _renumber(page, index) {
    page.index = index;
    page.sheet.dataset.page = String(index);
    if (page.slot) page.element.slot = page.slot.name = `conecurl-page-${index}`;
  }

  /** The page's content drawn at `size` device pixels: a canvas for its texture. */
  async snapshot(index, size) {
    const page = this._pages.get(index);
    this._dirty.delete(index);
    this._resize(this._book.pageSize());
    // A slotted child is drawn itself (a clone of the slot would hold nothing); a moved one with its box.
    const target = page.slotted ? page.element : page.content;
    const late = page.late;
    page.late = null;
    if (late) return this._taken(page, target, late);
    const { domToCanvas } = await importRasteriser();
    const { width, height } = this._size;
    // Videos are left to us (the rasteriser can wait for ever on a stream): their frames are drawn in.
    // Scaled so that the canvas is the texture's size, and never under a pixel high.
    const scale = Math.max(size.width / width, 1 / height);
    const drawing = domToCanvas(target, { width, height, scale, backgroundColor: PAPER,
      filter: (node) => node.localName !== 'video' });
    let timedOut = false;
    let timer = 0;
    const timeUp = new Promise((resolve, reject) => {
      timer = setTimeout(() => {
        timedOut = true;
        reject(new Error(`conecurl: drawing HTML page ${index} took longer than ${SNAPSHOT_TIMEOUT_MS / 1000} s`));
      }, SNAPSHOT_TIMEOUT_MS);
    });
    // A drawing that comes after the time limit still lands (a busy machine): the failed page loads again
    // and takes it, unless the content changed meanwhile (then it is drawn anew).
    drawing.then((canvas) => {
      if (!timedOut || this._removed || this._pages.get(page.index) !== page || this._dirty.has(page.index)) return;
      page.late = canvas;
      this._book.changed(page.index);
    }, () => {});
    const canvas = await Promise.race([drawing, timeUp]).finally(() => clearTimeout(timer));
    return this._taken(page, target, canvas);
  }

  // The page's snapshot made: where its videos lie is measured and their frames drawn in.
  _taken(page, target, canvas) {
    // Where its videos lie, in the page's CSS px: their frames are drawn there now and while the page moves.
    const box = target.getBoundingClientRect();
    const unscale = this._size.width / Math.max(1, box.width);
    page.videos = [...page.element.querySelectorAll('video')].map((video) => {
      const r = video.getBoundingClientRect();
      return { video, rect: { x: (r.left - box.left) * unscale, y: (r.top - box.top) * unscale, width: r.width * unscale, height: r.height * unscale } };
    });
    page.canvas = canvas;
    this._drawVideos(page, page.videos.filter(({ video }) => video.readyState >= 2));
    return canvas;
  }

  _mount(index, element, host) {
    const sheet = document.createElement('div');
    sheet.className = 'conecurl-html-page';
    sheet.dataset.page = String(index);
    sheet.dataset.turnArea = this._book.turnArea;
    sheet.style.cssText = `position:absolute;left:0;top:0;transform-origin:0 0;overflow:hidden;pointer-events:auto;background:${PAPER}`;
    const content = document.createElement('div');
    content.style.cssText = 'width:100%;height:100%;overflow:hidden;box-sizing:border-box';
    sheet.append(content);
    const home = { parent: element.parentNode, next: element.nextSibling };
    const slotted = host !== null && element.parentNode === host;
    let slot = null;
    if (slotted) {
      // A child of <cone-flipbook> stays in the document's tree (its styles apply) and shows through a slot.
      slot = document.createElement('slot');
      slot.name = `conecurl-page-${index}`;
      element.slot = slot.name;
      content.append(slot);
    } else {
      content.append(element);
    }
    // By `page.index`, not `index`: pages spliced in before it move it.
    const onInput = () => this._changed(page.index);
    for (const type of CHANGE_EVENTS) element.addEventListener(type, onInput, true);
    const observer = new MutationObserver(() => this._changed(page.index));
    observer.observe(element, { subtree: true, childList: true, attributes: true, characterData: true });
    const page = { index, element, sheet, content, home, observer, onInput, slotted, slot, grips: [], gripKey: '', canvas: null, videos: [], late: null };
    this._conceal(page);
    this._layer.append(sheet);
    return page;
  }

  _drawVideos(page, videos) {
    const g = page.canvas.getContext('2d');
    const scale = page.canvas.width / this._size.width;
    for (const { video, rect } of videos) g.drawImage(video, rect.x * scale, rect.y * scale, rect.width * scale, rect.height * scale);
  }

  // Transparent boxes over the content's turn area (its free edge or corners): presses there turn.
  _layGrips(page, rects) {
    const key = JSON.stringify(rects);
    if (page.gripKey === key) return;
    page.gripKey = key;
    for (const grip of page.grips.splice(0)) grip.remove();
    for (const { x, y, width, height } of rects) {
      const grip = document.createElement('div');
      grip.className = 'conecurl-turn-grip';
      grip.style.cssText = `position:absolute;left:${x}px;top:${y}px;width:${width}px;height:${height}px;touch-action:none`;
      for (const type of FORWARDED) grip.addEventListener(type, this._forward, type === 'wheel' ? { passive: false } : undefined);
      page.grips.push(grip);
      page.sheet.append(grip);
    }
  }

  _conceal(page) {
    page.sheet.style.transform = OFFSCREEN;  // laid out still, so it can be drawn to its texture
    page.sheet.inert = true;
    page.sheet.setAttribute('aria-hidden', 'true');
  }

  // Every sheet is the page's CSS size at zoom 1 (a zoom scales it, never reflows it).
  _resize(pageSize) {
    // At least a pixel each way: a book squeezed to a few pixels still draws its pages (a 0 px sheet
    // made a canvas with no pixels, a pageerror).
    const size = { width: Math.max(1, pageSize.width), height: Math.max(1, pageSize.height) };
    if (this._size && size.width === this._size.width && size.height === this._size.height) return;
    const first = this._size === null;
    this._size = size;
    for (const page of this._pages.values()) {
      page.sheet.style.width = `${size.width}px`;
      page.sheet.style.height = `${size.height}px`;
    }
    if (!first) for (const index of this._pages.keys()) this._changed(index);  // the content reflowed
  }

  // Content changed: its texture is made again once it has rested, and never during turning frames
  // (while leaves move the page stays marked, and is drawn when the book lands or before it next moves).
  _changed(index) {
    this._dirty.add(index);
    if (this._pages.has(index)) this._pages.get(index).late = null;
    this._scheduleRefresh();
  }

  _scheduleRefresh() {
    clearTimeout(this._timer);
    this._timer = setTimeout(() => {
      if (this._moving || this._removed) return;
      for (const page of [...this._dirty]) this._book.changed(page);
    }, REFRESH_DELAY_MS);
  }
}
