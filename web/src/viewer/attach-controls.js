// attachControls(book, options): the viewer for a book, built on its public API alone (the `controls`
// option calls this; conecurl/viewer exports it). A toolbar below the book (the book's box gives up
// its height), the panels over the book's side, all in the book's container so fullscreen takes them.
import { MAX_ZOOM } from '../engine/layout.js';
import { viewerLabels } from './viewer-labels.js';
import { checkControls, checkLabels, shownParts } from './viewer-options.js';
import { installViewerStyle } from './viewer-style.js';
import { createToolbar } from './toolbar.js';
import { createPanel } from './panel.js';
import { thumbnailsPanel } from './thumbnails-panel.js';
import { contentsPanel } from './contents-panel.js';
import { searchPanel } from './search-panel.js';

const ZOOM_STEP = 0.5;
const NARROW = 600;         // CSS px: below, icons only and panels as sheets from the bottom
const COMPACT = 800;        // CSS px: below, the panels' buttons show their icons only too
const SHEET_SHARE = 0.62;   // of the book's height, a sheet's
const PANEL_KINDS = { thumbnails: thumbnailsPanel, contents: contentsPanel, search: searchPanel };

/**
 * Shows the toolbar and its panels with `book` (a Flipbook or StaticBook). `options.controls`: true or
 * the parts to show or hide; `options.labels`: texts by key; `options.pdf`: the book shows a PDF
 * (Download and Print are shown). Returns { element, toolbar, panels, remove() }.
 */
export function attachControls(book, { controls = true, labels = {}, pdf = false } = {}) {
  for (const [name, value, check] of [['controls', controls, checkControls], ['labels', labels, checkLabels]]) {
    const verdict = check(value);
    if (verdict !== true) throw new TypeError(`conecurl: attachControls option '${name}' must be ${verdict}`);
  }
  const container = book.element.parentElement;
  const text = viewerLabels(labels);
  const parts = shownParts(controls, { pdf, downloadUrl: typeof book.options.download === 'string' });
  const viewer = document.createElement('div');
  viewer.className = 'conecurl-viewer';
  const removeStyle = installViewerStyle(container);
  const panels = {};
  const toolbar = createToolbar(text, parts, {
    previous: () => book.prev().catch(() => {}),
    next: () => book.next().catch(() => {}),
    page: (n) => book.flip(n - 1).catch(() => {}),
    zoomIn: () => { book.zoom = Math.min(MAX_ZOOM, book.zoom + ZOOM_STEP); },
    zoomOut: () => { book.zoom = Math.max(1, book.zoom - ZOOM_STEP); },
    fullscreen: () => book.toggleFullscreen().catch(() => {}),
    download: () => book.download().catch(() => {}),
    print: () => book.print().catch(() => {}),
    thumbnails: () => toggle('thumbnails'),
    contents: () => toggle('contents'),
    search: () => toggle('search'),
  });
  viewer.append(toolbar.element);
  const contents = [];
  for (const [kind, make] of Object.entries(PANEL_KINDS)) {
    if (!parts[kind]) continue;
    panels[kind] = createPanel(text, text[kind], toolbar.buttons[kind]);
    viewer.append(panels[kind].element);
    contents.push(make(book, panels[kind], text));
  }

  function toggle(kind) {
    const panel = panels[kind];
    if (panel.isOpen()) {
      panel.close();
      return;
    }
    for (const other of Object.values(panels)) other.close();
    panel.open();
  }

  // The book and the open panel side by side: on a wide book the panel takes the left of the book's
  // box and the book the rest; on a narrow one (icons only) the panel is a sheet over the toolbar and
  // the book takes what is above it. The book fits itself to its new box (its size watch).
  const given = book.element.style;
  const bookStyle = { height: given.height, width: given.width, marginLeft: given.marginLeft, marginBottom: given.marginBottom };
  const BOOK_HEIGHT = 'calc(100% - var(--conecurl-toolbar-height, 44px))';
  function layout() {
    const width = viewer.clientWidth;
    const narrow = width < NARROW;
    viewer.toggleAttribute('data-narrow', narrow);
    viewer.toggleAttribute('data-compact', width < COMPACT);
    const space = container.getBoundingClientRect().height - viewer.getBoundingClientRect().height;
    const sheet = Math.round(space * SHEET_SHARE);
    for (const panel of Object.values(panels)) panel.element.style.height = `${Math.max(0, narrow ? sheet : space)}px`;
    const open = Object.values(panels).find((panel) => panel.isOpen());
    const beside = open && !narrow ? open.element.getBoundingClientRect().width : 0;
    Object.assign(book.element.style, {
      height: open && narrow ? `calc(100% - var(--conecurl-toolbar-height, 44px) - ${sheet}px)` : BOOK_HEIGHT,
      width: beside ? `calc(100% - ${beside}px)` : bookStyle.width,
      marginLeft: beside ? `${beside}px` : bookStyle.marginLeft,
      marginBottom: open && narrow ? `${sheet}px` : bookStyle.marginBottom,  // the toolbar stays where it was
    });
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
  // Escape anywhere in the viewer closes the open panel and gives focus back to its button.
  const onKey = (event) => {
    if (event.key !== 'Escape' || event.defaultPrevented) return;
    const open = Object.values(panels).find((panel) => panel.isOpen());
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
      for (const [type, listener] of Object.entries(events)) book.removeEventListener(type, listener);
      for (const part of contents) part.remove();
      for (const panel of Object.values(panels)) panel.close();
      toolbar.remove();
      viewer.remove();
      removeStyle();
      Object.assign(book.element.style, bookStyle);
    },
  };
}
