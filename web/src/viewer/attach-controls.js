// attachControls(book, options): the viewer for a book, built on its public API alone (the `controls`
// option calls this; conecurl/viewer exports it). A toolbar below the book (the book's box gives up
// its height), the panels over the book's side (on a phone, sheets fixed to the screen), reading mode,
// all in the book's container so fullscreen takes them. What the first view does not show (the panels'
// contents, read-aloud's Voice and speed popup) is imported once the book's first view is ready or asks.
import { MAX_ZOOM } from '../engine/layout.js';
import { languageOf } from '../engine/language.js';
import { viewerLabels } from './viewer-labels.js';
import { checkViewerOptions, shownParts } from './viewer-options.js';
import { installViewerStyle } from './viewer-style.js';
import { createToolbar } from './toolbar.js';
import { createPanel } from './panel.js';
import { canFullscreen, readingMode } from './reading-mode.js';
import { BOOK_HEIGHT } from './toolbar-room.js';

const ZOOM_STEP = 0.5;
const NARROW = 600;         // CSS px: below, icons only and panels as sheets from the bottom
const COMPACT = 800;        // CSS px: below, the panels' buttons show their icons only too
const SHEET_SHARE = 0.62;   // of the book's height, a sheet's (fine pointer, narrow book)
const COARSE = '(pointer: coarse)';  // a phone's finger: 44 px targets, sheets fixed to the screen, reading mode
const HIT_MARGIN = 12;      // CSS px kept between a hit shown and the sheet or the screen's edge
// Each panel's contents, imported when the first view is ready (or at the panel's first opening, if sooner).
const PANEL_KINDS = {
  thumbnails: () => import('./thumbnails-panel.js').then((module) => module.thumbnailsPanel),
  contents: () => import('./contents-panel.js').then((module) => module.contentsPanel),
  search: () => import('./search-panel.js').then((module) => module.searchPanel),
};

/**
 * Shows the toolbar and its panels with `book` (a Flipbook or StaticBook). `options.controls`: true or
 * the parts to show or hide; `options.labels`: texts by key; `options.pdf`: the book shows a PDF
 * (Download and Print are shown). Returns { element, toolbar, panels, remove() }.
 */
export function attachControls(book, { controls = true, labels = {}, pdf = false } = {}) {
  checkViewerOptions(controls, labels);
  const container = book.element.parentElement;
  const text = viewerLabels(labels);
  const parts = shownParts(controls, { pdf, downloadUrl: typeof book.options.download === 'string' });
  const viewer = document.createElement('div');
  viewer.className = 'conecurl-viewer';
  const removeStyle = installViewerStyle(container);
  const panels = {};
  const coarse = window.matchMedia?.(COARSE) ?? { matches: false };
  const fullscreenApi = canFullscreen(container);
  let reading = null;
  // Fullscreen: the Fullscreen API on a desktop; on a phone, or where there is no API (Read), reading mode.
  const fullscreen = () => {
    if (coarse.matches || !fullscreenApi) reading.toggle();
    else book.toggleFullscreen().catch(() => {});
  };
  const toolbar = createToolbar(text, parts, {
    previous: () => book.prev().catch(() => {}),
    next: () => book.next().catch(() => {}),
    page: (n) => book.flip(n - 1).catch(() => {}),
    zoomIn: () => { book.zoom = Math.min(MAX_ZOOM, book.zoom + ZOOM_STEP); },
    zoomOut: () => { book.zoom = Math.max(1, book.zoom - ZOOM_STEP); },
    fullscreen,
    exit: () => reading.leave(),
    download: () => book.download().catch(() => {}),
    print: () => book.print().catch(() => {}),
    thumbnails: () => toggle('thumbnails'),
    contents: () => toggle('contents'),
    search: () => toggle('search'),
    readAloud: () => readAloud.press(),
    readAloudSettings: () => readAloud.toggleMenu(),
    keepOffline: () => keepOffline?.then((part) => part?.press()),
  }, { fullscreenKey: fullscreenApi ? 'fullscreen' : 'read' });
  viewer.append(toolbar.element, toolbar.menu.element);
  let removed = false;
  const readAloud = parts.readAloud ? readAloudPart() : null;
  let keepOffline = null;
  // Keep offline's module loads only once a service worker controls the page: on a site's first visit
  // after the first spread (the reader registers it then), never for a book without one.
  const workers = globalThis.navigator?.serviceWorker;
  const loadKeepOffline = () => {
    if (keepOffline || !workers?.controller) return;
    keepOffline = import('./keep-offline.js')
      .then(({ keepOfflinePart }) => (removed ? null : keepOfflinePart(book, toolbar, text, viewer)), () => null);
  };
  if (parts.keepOffline) {
    workers?.addEventListener?.('controllerchange', loadKeepOffline);
    loadKeepOffline();
  }
  const contents = {};  // kind -> the promise of its contents ({ remove }), once asked for
  for (const kind of Object.keys(PANEL_KINDS)) {
    if (!parts[kind]) continue;
    panels[kind] = createPanel(text, text[kind], toolbar.buttons[kind], () => toolbar.focusTarget(kind));
    viewer.append(panels[kind].element);
  }
  const panelContents = (kind) => (contents[kind] ??= PANEL_KINDS[kind]().then((make) => {
    if (removed) return null;
    return make(book, panels[kind], text, { revealHit });
  }));
  // After the first view: a book still being built has no surface yet, and says `ready` once it is on screen.
  const startLater = () => {
    if (removed) return;
    for (const kind of Object.keys(panels)) panelContents(kind);
  };
  if (book.surface) startLater();
  else book.addEventListener('ready', startLater, { once: true });
  const openPanel = () => Object.values(panels).find((panel) => panel.isOpen());
  reading = readingMode(book, {
    container, viewer, toolbar,
    busy: () => Boolean(openPanel()) || toolbar.menu.isOpen() || Boolean(readAloud?.menu?.isOpen()),
    changed: () => { layout(); show(); },
  });

  async function toggle(kind) {
    const panel = panels[kind];
    if (panel.isOpen()) {
      panel.close();
      return;
    }
    await panelContents(kind);  // at once once loaded
    if (removed || panel.isOpen()) return;
    for (const other of Object.values(panels)) other.close();
    panel.open();
  }

  // The book and the open panel side by side: on a wide book the panel takes the left of the book's
  // box and the book the rest; on a narrow one (icons only) the panel is a sheet over the toolbar and
  // the book takes what is above it. On a coarse pointer (a phone) the panels are sheets fixed to the
  // screen, whatever the page around the book: from the bottom, 45% of the screen's height, when the
  // screen stands; from the left, min(360 px, 45% of its width), when it lies; the book gives way to a
  // side sheet, and in reading mode to either. The book fits itself to its new box (its size watch).
  const given = book.element.style;
  const bookStyle = { height: given.height, width: given.width, marginLeft: given.marginLeft, marginBottom: given.marginBottom };
  function layout() {
    const width = viewer.clientWidth;
    const narrow = width < NARROW;
    const phone = coarse.matches;
    const landscape = window.innerWidth > window.innerHeight;
    const inReading = reading?.active() ?? false;
    viewer.toggleAttribute('data-narrow', narrow);
    viewer.toggleAttribute('data-compact', width < COMPACT);
    viewer.toggleAttribute('data-coarse', phone);
    viewer.toggleAttribute('data-landscape', phone && landscape);
    const open = openPanel();
    if (phone) {
      for (const panel of Object.values(panels)) panel.element.style.height = '';
      const sheet = open?.element.getBoundingClientRect();
      const box = container.getBoundingClientRect();
      const beside = sheet && landscape ? Math.max(0, Math.round(sheet.right - box.left)) : 0;
      const below = sheet && !landscape && inReading ? Math.max(0, Math.round(box.bottom - sheet.top)) : 0;
      Object.assign(book.element.style, {
        height: inReading ? (below ? `calc(100% - ${below}px)` : '100%') : BOOK_HEIGHT,
        width: beside ? `calc(100% - ${beside}px)` : (inReading ? '100%' : bookStyle.width),
        marginLeft: beside ? `${beside}px` : (inReading ? '0px' : bookStyle.marginLeft),
        marginBottom: inReading ? '0px' : bookStyle.marginBottom,
      });
    } else {
      const space = container.getBoundingClientRect().height - (inReading ? 0 : viewer.getBoundingClientRect().height);
      const sheet = Math.round(space * SHEET_SHARE);
      for (const panel of Object.values(panels)) panel.element.style.height = `${Math.max(0, narrow ? sheet : space)}px`;
      const beside = open && !narrow ? open.element.getBoundingClientRect().width : 0;
      const full = inReading ? '100%' : BOOK_HEIGHT;
      Object.assign(book.element.style, {
        height: open && narrow ? `calc(${full} - ${sheet}px)` : full,
        width: beside ? `calc(100% - ${beside}px)` : (inReading ? '100%' : bookStyle.width),
        marginLeft: beside ? `${beside}px` : (inReading ? '0px' : bookStyle.marginLeft),
        marginBottom: open && narrow && !inReading ? `${sheet}px` : (inReading ? '0px' : bookStyle.marginBottom),
      });
    }
    toolbar.fit();
    readAloud?.menu?.place();
  }

  // Read aloud: its two buttons shown once the book says it can read aloud. Read aloud starts reading
  // with the popup's voice and speed, pauses and resumes; it follows the book's readaloud* events, so
  // it says what the reading does whoever started or paused it. The popup's choices change the reading
  // under way at once.
  function readAloudPart() {
    const button = toolbar.buttons.readAloud;
    const live = () => {
      const now = book.readingAloud;
      return now && now.state !== 'ended' ? now : null;
    };
    // A call whose failure the viewer has nothing to say about (the book's events say what happened).
    const quietly = (call) => {
      try {
        Promise.resolve(call()).catch(() => {});
      } catch { /* the reading had ended */ }
    };
    // The Voice and speed popup, imported once the book can read aloud (the button shows at once; a press
    // before it came reads with the book's own choice).
    let menu = null;
    let menuLoading = null;
    const makeMenu = () => (menuLoading ??= import('./read-aloud-menu.js').then(({ createReadAloudMenu }) => {
      if (removed) return;
      menu = createReadAloudMenu(text, toolbar.buttons.readAloudSettings, {
        anchorOf: () => toolbar.focusTarget('readAloudSettings'),
        voices: () => book.readAloudVoices(),
        lang: () => (typeof book.pageLanguage === 'function' ? book.pageLanguage() : languageOf(book.element)),  // the reading's own
        memory: () => book.options?.readAloudMemory,  // engine/voice-choice.js: undefined is its default key
        changed: (change) => {
          const now = live();
          if (now) quietly(() => now.update(change));
        },
      });
      viewer.append(menu.element);
    }));
    const showState = (state) => {  // 'reading' (or waiting), 'paused' or 'ended'
      const on = state === 'reading' || state === 'waiting';
      // A play/pause button as media players have it: its name says what a press does (no aria-pressed
      // beside a name that changes); `data-on` shows it lit while the book reads.
      button.dataset.on = String(on);
      toolbar.relabel('readAloud', on ? 'pauseReading' : 'readAloud', on ? 'pauseReading' : 'readAloud');
    };
    const showNow = () => showState(live()?.state ?? 'ended');
    const events = {
      readaloudstart: () => showState('reading'),
      readaloudresume: () => showState('reading'),
      readaloudpause: () => showState('paused'),
      // Ended; and once the book's own work for that end is done, what it reads now (a reading stopped
      // by a new readAloud() may say it ended after the new one started).
      readaloudend: () => {
        showState('ended');
        queueMicrotask(showNow);
      },
    };
    for (const [type, listener] of Object.entries(events)) book.addEventListener(type, listener);
    // Shown once the book can read aloud: asked now, and again when voices come late (`readaloudvoices`).
    const ask = () => Promise.resolve().then(() => book.canReadAloud()).then((can) => {
      if (can !== true || removed) return;
      toolbar.setPresent('readAloud', true);
      showNow();
      makeMenu().catch(() => {});
    }, () => {});
    if (typeof book.canReadAloud === 'function') {
      events.readaloudvoices = ask;
      book.addEventListener('readaloudvoices', ask);
      ask();
    }
    return {
      get menu() { return menu; },
      press() {
        const now = live();
        if (now?.state === 'paused') quietly(() => now.resume());
        else if (now) quietly(() => now.pause());
        else {
          // Called within the press (speech may want the reader's gesture); a refusal leaves the button as it was.
          let started;
          try {
            started = book.readAloud(menu?.choice());
          } catch (error) {
            started = Promise.reject(error);
          }
          Promise.resolve(started).then(showNow, showNow);
        }
        showNow();
      },
      toggleMenu: () => (menu?.isOpen() ? menu.close(false) : makeMenu().then(() => menu?.open())),
      remove() {
        for (const [type, listener] of Object.entries(events)) book.removeEventListener(type, listener);
        menu?.remove();
      },
    };
  }

  // A search hit shown while a sheet covers part of the screen: when its place on the page lies under
  // the sheet or off the screen, the page scrolls it into the part left free (above a bottom sheet).
  function revealHit(hit) {
    const sheet = openPanel()?.element;
    if (!coarse.matches || !sheet) return;
    const place = book.openPagePlaces().find((p) => p.page === hit.page);
    if (!place) return;
    const at = book.element.getBoundingClientRect();  // the canvas fills the book's box
    const top = at.top + place.y + Math.min(...hit.rects.map((r) => r[1])) * place.height;
    const bottom = at.top + place.y + Math.max(...hit.rects.map((r) => r[1] + r[3])) * place.height;
    const cover = sheet.getBoundingClientRect();
    const freeBottom = window.innerWidth > window.innerHeight ? window.innerHeight : cover.top;
    if (top >= HIT_MARGIN && bottom <= freeBottom - HIT_MARGIN) return;
    window.scrollBy({ top: (top + bottom) / 2 - freeBottom / 2, behavior: 'instant' });
  }
  for (const panel of Object.values(panels)) panel.onToggle(layout);

  const show = () => toolbar.show({
    pages: [...new Set([Math.min(...book.openPages) + 1, Math.max(...book.openPages) + 1])].join('\u2013'),
    pageCount: book.pageCount,
    atStart: book.page <= 0,
    atEnd: Math.max(...book.openPages) >= book.pageCount - 1,
    zoom: book.zoom,
    maxZoom: MAX_ZOOM,
    fullscreen: Boolean(book.fullscreen),
  });
  const resized = () => {
    layout();
    show();
  };
  window.addEventListener('resize', resized);
  coarse.addEventListener?.('change', resized);
  // Escape anywhere in the viewer closes the open panel and gives focus back to its button.
  const onKey = (event) => {
    if (event.key !== 'Escape' || event.defaultPrevented) return;
    const open = openPanel();
    if (!open) return;
    event.preventDefault();
    open.close(true);
  };
  viewer.addEventListener('keydown', onKey);
  const events = { turned: show, pageschange: show, zoom: show, fullscreenchange: show, ready: show, resize: resized };
  for (const [type, listener] of Object.entries(events)) book.addEventListener(type, listener);

  // The book's box gives the toolbar its height: the book fits itself to the rest.
  container.append(viewer);
  layout();
  show();

  return {
    /** The viewer's element: the toolbar and the panels. */
    element: viewer,
    /** The toolbar (role="toolbar"). */
    toolbar: toolbar.element,
    /** The panels' elements by kind (thumbnails, contents, search), those shown. */
    panels: Object.fromEntries(Object.entries(panels).map(([kind, panel]) => [kind, panel.element])),
    /** Takes the viewer away; the book gets its whole box back. */
    remove() {
      removed = true;
      book.removeEventListener('ready', startLater);
      reading.leave();
      window.removeEventListener('resize', resized);
      coarse.removeEventListener?.('change', resized);
      for (const [type, listener] of Object.entries(events)) book.removeEventListener(type, listener);
      for (const part of Object.values(contents)) part.then((made) => made?.remove());
      readAloud?.remove();
      workers?.removeEventListener?.('controllerchange', loadKeepOffline);
      keepOffline?.then((part) => part?.remove());
      for (const panel of Object.values(panels)) panel.close();
      toolbar.remove();
      viewer.remove();
      removeStyle();
      Object.assign(book.element.style, bookStyle);
    },
  };
}
