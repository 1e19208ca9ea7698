// The Thumbnails panel: a grid of page buttons ("Page N"), each with the page drawn small by
// book.pageThumbnail(). Virtualised: only the rows near the scroll position exist as elements, and
// thumbnails are asked for only as they come into view, a few at a time, the latest view first.
import { fill } from './viewer-labels.js';

const THUMB_WIDTH = 96;    // CSS px of a thumbnail's image
const CAPTION = 22;        // CSS px of its caption and padding under it
const GAP = 8;
const OVERSCAN_ROWS = 2;   // rows made beyond each side of the view
const IN_FLIGHT = 3;       // thumbnails drawn at once
const KEPT = 120;          // thumbnails kept (not in the page) for rows scrolled back to

/** The grid in `panel` (panel.js) for `book`; returns { remove }. */
export function thumbnailsPanel(book, panel, labels) {
  const grid = document.createElement('div');
  grid.className = 'conecurl-thumbs';
  panel.body.append(grid);
  const items = new Map();      // page -> its button, for the rows near the view
  const images = new Map();     // page -> its thumbnail canvas (least recently used first)
  const failed = new Set();
  const wanted = [];            // pages waiting for a thumbnail, in order of asking
  let inFlight = 0;
  let aspect = null;             // the pages' height over width, read when first shown
  let frame = 0;

  const geometry = () => {
    aspect ??= pageAspect(book);
    const width = panel.body.clientWidth;
    const columns = Math.max(1, Math.floor((width - GAP) / (THUMB_WIDTH + 8 + GAP)));
    const cell = (width - GAP) / columns;
    const rowHeight = Math.round(THUMB_WIDTH * aspect) + 8 + CAPTION + GAP;
    return { columns, cell, rowHeight, rows: Math.ceil(book.pageCount / columns) };
  };

  function render() {
    frame = 0;
    if (!panel.isOpen()) return;
    const { columns, cell, rowHeight, rows } = geometry();
    grid.style.height = `${rows * rowHeight + GAP}px`;
    const top = panel.body.scrollTop;
    const first = Math.max(0, Math.floor(top / rowHeight) - OVERSCAN_ROWS);
    const last = Math.min(rows - 1, Math.ceil((top + panel.body.clientHeight) / rowHeight) + OVERSCAN_ROWS);
    const from = first * columns;
    const to = Math.min(book.pageCount, (last + 1) * columns);
    for (const [page, item] of items) {
      if (page < from || page >= to) {
        item.remove();
        items.delete(page);
      }
    }
    const current = new Set(book.openPages);
    for (let page = from; page < to; page++) {
      let item = items.get(page);
      if (!item) {
        item = makeItem(page);
        items.set(page, item);
        grid.append(item);
      }
      item.style.left = `${GAP / 2 + (page % columns) * cell}px`;
      item.style.top = `${GAP + Math.floor(page / columns) * rowHeight}px`;
      item.style.width = `${cell - GAP}px`;
      markCurrent(item, current.has(page));
    }
    // The latest view first: pages out of it are no longer wanted.
    wanted.splice(0, wanted.length, ...[...items.keys()].filter((page) => !images.has(page) && !failed.has(page)));
    pump();
  }

  function makeItem(page) {
    const item = document.createElement('button');
    item.type = 'button';
    item.className = 'conecurl-thumb';
    item.dataset.page = String(page);
    const frameBox = document.createElement('span');
    frameBox.className = 'conecurl-thumb-frame';
    frameBox.style.width = `${THUMB_WIDTH}px`;
    frameBox.style.height = `${Math.round(THUMB_WIDTH * aspect)}px`;
    const image = images.get(page);
    if (image) {
      images.delete(page);  // most recently used last
      images.set(page, image);
      frameBox.append(image);
    }
    const caption = document.createElement('span');
    caption.textContent = fill(labels.thumbnail, { n: page + 1 });
    item.append(frameBox, caption);
    item.addEventListener('click', () => { book.flip(page).catch(() => {}); });
    return item;
  }

  function pump() {
    while (inFlight < IN_FLIGHT && wanted.length > 0) {
      const page = wanted.shift();
      inFlight++;
      const scale = globalThis.devicePixelRatio || 1;
      book.pageThumbnail(page, { width: Math.round(THUMB_WIDTH * scale) }).then((canvas) => {
        images.set(page, canvas);
        for (const old of images.keys()) {  // the least recently used first, never one in view
          if (images.size <= KEPT) break;
          if (!items.has(old)) images.delete(old);
        }
        canvas.setAttribute('aria-hidden', 'true');
        items.get(page)?.querySelector('.conecurl-thumb-frame').replaceChildren(canvas);
      }, () => failed.add(page)).finally(() => {
        inFlight--;
        if (!removed) pump();
      });
    }
  }

  function markCurrent(item, on) {
    if (on) item.setAttribute('aria-current', 'page');
    else item.removeAttribute('aria-current');
  }

  const schedule = () => { frame ||= requestAnimationFrame(render); };
  const followPage = () => {
    const current = new Set(book.openPages);
    for (const [page, item] of items) markCurrent(item, current.has(page));
  };
  const pagesChanged = () => {
    images.clear();
    failed.clear();
    for (const item of items.values()) item.remove();
    items.clear();
    aspect = null;
    schedule();
  };
  let removed = false;
  panel.body.addEventListener('scroll', schedule, { passive: true });
  book.addEventListener('turned', followPage);
  book.addEventListener('pageschange', pagesChanged);
  book.addEventListener('resize', schedule);
  panel.onToggle((open) => {
    if (!open) return;
    render();
    // The page being read in view.
    const { columns, rowHeight } = geometry();
    const row = Math.floor(book.page / columns);
    const top = row * rowHeight;
    if (top < panel.body.scrollTop || top + rowHeight > panel.body.scrollTop + panel.body.clientHeight) {
      panel.body.scrollTop = Math.max(0, top - panel.body.clientHeight / 2 + rowHeight / 2);
      render();
    }
  });
  return {
    remove() {
      removed = true;
      cancelAnimationFrame(frame);
      book.removeEventListener('turned', followPage);
      book.removeEventListener('pageschange', pagesChanged);
      book.removeEventListener('resize', schedule);
      images.clear();
    },
  };
}

// Height over width of a page, from where the open pages lie (1.414 before the book has any).
function pageAspect(book) {
  const place = book.openPagePlaces().find((p) => p.page >= 0 && p.width > 0);
  return place ? place.height / place.width : Math.SQRT2;
}
