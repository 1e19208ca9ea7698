// How a book's parts are wired to it: each part (the page store, zoom, the overlay layers, input, live
// pages, the surface's reports, the size watch, page memory, autoplay, the page sound) is made here with
// the callbacks it needs, one a line, from the controller's port (book-controller.js `_makePort`).
// Parts only some books use (page memory, autoplay, the page sound, live pages) are imported here only
// when an option or a call asks for them: a plain book never downloads them.
import { BookZoom } from './book-zoom.js';
import { watchSize } from './size-watch.js';
import { PageStore } from '../pages/page-store.js';
import { createLinkLayer } from '../layers/link-layer.js';
import { turnsAt } from '../input/turn-area.js';
import { positionOfPage } from '../engine/layout.js';

/**
 * What the parts may ask of the book: the controller makes it once, in `_makePort`.
 * @typedef {object} BookPort
 * @property {HTMLCanvasElement} canvas
 * @property {HTMLElement} root  the book's focusable element
 * @property {object[]} entries  the page entries (live pages change them in place)
 * @property {object} settings  the options in effect (setOptions changes them in place)
 * @property {() => object|null} surface  null before _build() and after destroy()
 * @property {() => object} store  the PageStore
 * @property {() => object} zoom  the BookZoom
 * @property {() => object} turns  the BookTurns
 * @property {() => object|null} html  the HTML pages' layer, once mounted
 * @property {() => boolean} destroyed
 * @property {() => void} alive  throws once the book is destroyed
 * @property {() => boolean} animates  turns animate (WebGL, no reduced motion)
 * @property {() => number} page
 * @property {() => number} pageCount
 * @property {() => number[]} openPages
 * @property {(type: string, detail: object) => void} emit
 * @property {(task: () => void) => void} afterFirstFrame  `task` once the frame drawn now is on screen (not if destroyed first)
 * @property {(index: number) => Promise<void>} flip  the public flip()
 * @property {() => void} showOpenPages  layers laid over the open pages, live region, alt text
 * @property {() => void} layoutLayers
 * @property {() => void} hideLayers
 * @property {() => void} refitSoon  images fitted to the size and zoom once they rest
 * @property {(size: { width: number, height: number }) => void} resized
 * @property {(HtmlPages: Function) => void} attachHtml  mounts the HTML pages' layer
 * @property {(link: object, event: Event) => void} followLink
 * @property {() => void} flushEvents  events held while create() runs go out now
 * @property {() => boolean} isDocument  the book's pages are a document's (a PDF, or a published one)
 * @property {() => object|null} document  the open document (document/pdf-pages.js openPdf, document/published-document.js
 *   openPublished: pageText(), outline(), downloadUrl()), or null
 * @property {HTMLElement} container  the element the book was made in (fullscreen takes it)
 * @property {(layer: object) => void} addLayer  an overlay layer made later (search hits), laid and removed with the others
 * @property {(index: number, image: object) => object} decorate  the image the surface gets for a page (search marks drawn in)
 * @property {(on: boolean) => void} duckSound  a voice reads aloud: the page sound goes quieter (page-sound.js duck)
 */

/** @param {BookPort} book */
export function makeZoom(book) {
  return new BookZoom(book.canvas, {
    surface: book.surface,
    moved: book.layoutLayers,
    changed: (scale) => {
      book.refitSoon();  // sharp pages once it rests
      book.emit('zoom', { scale });
    },
  });
}

/** @param {BookPort} book */
export function makePageStore(book) {
  return new PageStore(book.entries, book.settings, {
    surface: book.surface,
    openPages: book.openPages,
    emit: book.emit,
    // A source may have learned its page's text and links while making it (a PDF page). Not while a
    // leaf moves or is lifted by a hover hint: the landing, or the hint's end, shows them again.
    decorate: book.decorate,  // search marks and the word read aloud drawn into the page's image (document-wiring.js)
    onOpenPageLoaded: (index) => {
      if (!book.surface().animating && book.openPages().includes(index)) book.showOpenPages();
    },
  });
}

/** @param {BookPort} book */
export function makeLinkLayer(book) {
  return createLinkLayer(book.root, {
    linksOf: (page) => book.entries[page].links,
    onActivate: book.followLink,
  });
}

/** The edge marks' layer (document/edge-marks.js), imported only for a book that shows them (`edgeMarks`, on with `controls`). */
export async function loadEdgeMarks(settings) {
  return settings.edgeMarks ? (await import('../document/edge-marks.js')).EdgeMarks : null;
}

/**
 * A document's selectable text (text-layer.js, imported only for PDF and published books with `textLayer`), laid in under
 * `before` (the links); its passage button copies a link and says so (`passagelink`). Null for other
 * books, and once destroyed.
 * @param {BookPort} book
 */
export async function loadTextLayer(book, before) {
  if (!book.isDocument() || !book.settings.textLayer) return null;
  const { createTextLayer } = await import('../layers/text-layer.js');
  if (book.destroyed()) return null;
  return createTextLayer(book.root, {
    doc: book.document(),
    canvas: book.canvas,
    before,
    onPassage: (passage) => {
      // The link copied by passage-link.js, imported at the first passage a reader asks for.
      import('../document/passage-link.js').then(({ sharePassage }) => sharePassage(passage))
        .then((detail) => { if (!book.destroyed()) book.emit('passagelink', detail); });
    },
  });
}

/** The HTML pages' layer (html-pages.js, loaded only for books that have them). @param {BookPort} book */
export function makeHtmlPages(HtmlPages, book) {
  return new HtmlPages(book.root, book.entries, {
    direction: book.settings.direction,
    turnArea: book.settings.turnArea,
    canvas: book.canvas,
    zoom: () => book.zoom().scale,
    pageSize: () => book.store().pageCssSize(),
    changed: (index) => book.store().refresh(index),
    pagesOnScreen: () => book.surface()?.pagesOnScreen() ?? [],
    // A video's new frame drawn into the page's image: upload it again, if the page is still kept.
    // (The snapshot already has the page's texture size: no cover to work out, no layout read a frame.)
    redrawn: (index, canvas) => {
      if (book.store().holds(index, canvas)) book.surface().setPageImage(index, book.store().presented(index, canvas));
    },
  });
}

/** insertPages, removePages, replacePage (live-pages.js, imported on the first call). @param {BookPort} book */
export async function makeLivePages(book) {
  const { LivePages } = await import('./live-pages.js');
  return new LivePages({
    entries: book.entries,
    store: book.store(),
    hardCovers: book.settings.hardCovers,
    surface: book.surface,
    html: book.html,
    attachHtml: book.attachHtml,
    page: book.page,
    isDocument: book.isDocument,
    alive: book.alive,
    shown: book.showOpenPages,
    emit: book.emit,
    flushEvents: book.flushEvents,
  });
}

/** What the surface reports while the book lives. @param {BookPort} book */
export function followSurface(book) {
  const surface = book.surface();
  // While leaves move, the pages they show change (turns that waited start late): the surface says when.
  surface.onPagesChanged = () => {
    if (!book.destroyed()) book.store().update();
  };
  // After a lost context, pages whose images the store closed once uploaded are decoded again.
  surface.onImagesLost = (pages) => {
    if (!book.destroyed()) book.store().reloadLost(pages);
  };
}

/**
 * The input modules (book-input.js, imported now: the book attaches them once its first spread shows),
 * told what they may do; input after destroy() is dropped. Null once destroyed. @param {BookPort} book
 */
export async function attachBookInput(book) {
  const { attachInput } = await import('../input/book-input.js');
  if (book.destroyed()) return null;
  const zoom = book.zoom();
  const { settings } = book;
  return attachInput({
    canvas: book.canvas,
    element: book.root,
    surface: book.surface(),
    direction: settings.direction,
  }, {
    zoom: () => zoom.scale,
    zoomed: () => zoom.zoomed,
    zoomAbout: (scale, x, y) => { if (!book.destroyed()) zoom.about(scale, x, y); },
    zoomAboutCentre: (scale) => { if (!book.destroyed()) zoom.aboutCentre(scale); },
    panBy: (dx, dy) => zoom.panBy(dx, dy),
    turn: (direction) => { if (!book.destroyed()) book.turns().turn(direction).catch(() => {}); },
    jump: (end) => { book.flip(end === 'first' ? 0 : book.pageCount() - 1).catch(() => {}); },  // Home, End: a riffle
    // Whether a press at a viewport point may turn a page there (the `turnArea` option).
    turnsFrom: (clientX, clientY) => {
      const box = book.canvas.getBoundingClientRect();
      return turnsAt(settings.turnArea, () => book.surface().openPagePlaces(), settings.direction, clientX - box.left, clientY - box.top);
    },
    dragStarted: (direction) => {
      book.hideLayers();
      book.emit('turnstart', { direction, page: book.page(), drag: true });
      book.store().update();
    },
    dragEnded: (completed) => {
      if (book.destroyed()) return;
      book.store().update();
      if (completed) {
        book.turns().landed();
      } else {
        book.showOpenPages();
        book.emit('turncancel', { page: book.page() });
      }
    },
    // A tap or click on the middle third of the book (input-taps.js): `middletap`, at CSS px from the book element's corner.
    middleTapped: (clientX, clientY) => {
      if (book.destroyed()) return;
      const box = book.root.getBoundingClientRect();
      book.emit('middletap', { x: clientX - box.left, y: clientY - box.top });
    },
    // A corner lifts as the mouse hovers it: the live layers give way to the page's texture.
    hintStarted: book.hideLayers,
    // A corner lifted by hovering fell back: the open pages are those from before it again.
    hintEnded: () => { if (!book.destroyed()) book.showOpenPages(); },
  });
}

/** The element's size and pixel ratio, from `initial` on (size-watch.js); returns the stop. @param {BookPort} book */
export function watchBookSize(book, initial) {
  return watchSize(book.root, initial, (size) => {
    if (!book.destroyed()) book.resized(size);
  });
}

/**
 * The modules of what follows the book that its options ask for, imported now (`hash`, `rememberPage`:
 * page-memory.js; `autoplay`: autoplay.js; `sound`: page-sound.js); null for each not asked for, and no
 * wait at all when none is. Page memory is needed before the first view (where the book opens).
 */
export function loadCompanions(settings) {
  const wanted = {
    memory: settings.hash || settings.rememberPage ? () => import('./page-memory.js') : null,
    autoplay: settings.autoplay ? () => import('./autoplay.js') : null,
    sound: settings.sound ? () => import('./page-sound.js') : null,
  };
  if (!Object.values(wanted).some(Boolean)) return NO_COMPANIONS;
  return Promise.all(Object.values(wanted).map((load) => load?.() ?? null))
    .then(([memory, autoplay, sound]) => ({ memory, autoplay, sound }));
}
const NO_COMPANIONS = Object.freeze({ memory: null, autoplay: null, sound: null });

/** The page the book opens at: the address's or the remembered page when asked for, else `startPage`. */
export function openingPageOf(companions, settings, pageCount) {
  return companions.memory ? companions.memory.openingPage(settings, pageCount) : settings.startPage;
}

/**
 * The pages the first view shows at page `opening` in `display`, and their neighbours, asked for before the
 * surface is made (a WebGL context, the longest step of a first view): their fetch and decode run meanwhile,
 * sized for the canvas as it is laid out now; the store's first update() takes them up. A page whose placeholder
 * is a URL asks for its own image once `placeholdersShown` resolves (the poster's painted). @param {BookPort} book
 */
export function prefetchOpening(book, display, opening, placeholdersShown = null) {
  const size = { width: book.canvas.clientWidth, height: book.canvas.clientHeight };
  book.store().prefetch(size, display, positionOfPage(opening, book.pageCount(), display), placeholdersShown);
}

/**
 * The first view: its pages on screen load alone and are drawn; their neighbours once that frame is on screen
 * (on a slow network the first spread shares its bandwidth with no page it does not show, and nothing started
 * in the drawing task delays its frame). `afterShown()` (a promise: what the book builds once its first spread
 * is on screen) runs as soon as each page on screen shows a picture, its placeholder or its image. Resolves once
 * those pages have loaded or failed and are drawn, and afterShown's has; not after the neighbours (whenIdle()). @param {BookPort} book
 */
export async function loadFirstView(book, afterShown = async () => {}) {
  const store = book.store();
  const after = store.whenShown(book.surface().pagesOnScreen()).then(afterShown);
  after.catch(() => {});  // a failure is thrown below, where it is awaited
  await store.whenLoadsSettle();
  try {
    book.surface().drawNow?.();  // the first spread on screen now, before anything else is fetched
  } catch {
    // A context lost meanwhile draws once it is back; the neighbours load all the same.
  }
  book.afterFirstFrame(() => store.releaseFirstView());
  await after;
}

/**
 * What the book builds once its first spread shows, imported at once (none of it is needed to show the
 * first spread, so none of it is fetched before): its input (`input`, attached), the edge marks
 * (`edgeMarks`) and a document's text layer (`text`, under `before`). Each a promise; a failure is thrown where it is awaited.
 * @param {BookPort} book
 */
export function loadLateParts(book, before) {
  const parts = { input: attachBookInput(book), edgeMarks: loadEdgeMarks(book.settings), text: loadTextLayer(book, before) };
  for (const loading of Object.values(parts)) Promise.resolve(loading).catch(() => {});
  return parts;
}

/**
 * What follows the book (`controller`, through its public API) from beside it: the address and the
 * remembered page, autoplay, the page sound, from the modules loadCompanions() imported. Returns the
 * sound (page-sound.js, or a stand-in until `sound` is first set) and the stop of all three.
 * @param {BookPort} book
 */
export function startCompanions(controller, book, { memory, autoplay, sound }) {
  const { settings, root } = book;
  const stopFollowingPage = memory ? memory.followPage(controller, settings) : null;  // #page=N and the remembered page
  const autoplaying = autoplay?.autoplaySettings(settings.autoplay);
  const stopAutoplay = autoplaying ? autoplay.startAutoplay(controller, root, autoplaying) : null;
  const pageSound = soundOf(controller, book, sound);
  return {
    sound: pageSound,
    stop() {
      stopFollowingPage?.();
      stopAutoplay?.();
      pageSound.stop();
    },
  };
}

// The page sound: page-sound.js when loaded; until then (sound off at create) a stand-in that imports it
// once setOptions({ sound: true }) asks, and says what it would: off, muted, silent or waiting.
function soundOf(controller, book, module) {
  const start = (pageSound) => pageSound.startPageSound(controller, book.root, { animates: book.animates });
  let sound = module ? start(module) : null;
  let stopped = false;
  let loading = null;
  let ducked = false;
  return {
    /** A voice reads aloud (on) or stopped: the page sound goes quieter meanwhile. */
    duck(on) {
      ducked = on;
      sound?.duck(on);
    },
    update() {
      if (sound) return sound.update();
      if (book.settings.sound && !loading) {
        loading = import('./page-sound.js').then((pageSound) => {
          if (stopped) return;
          sound = start(pageSound);
          sound.duck(ducked);
        });
      }
      return undefined;
    },
    stop() {
      stopped = true;
      sound?.stop();
    },
    get status() {
      if (sound) return sound.status;
      const { sound: on, muted } = book.settings;
      const state = !on ? 'off' : muted ? 'muted' : !book.animates() ? 'silent' : 'waiting';
      return Object.freeze({ state, gain: 0, target: 0, speed: 0, taps: 0, ducked, level: 0 });
    },
  };
}
