// The first view's poster (issue 38): the opening pages' placeholders as <img> elements, laid where the
// surface will draw those pages (layout.js, the engine's rules), from the moment the book knows its size.
// It lies under the canvas, which is clear until its first frame and then covers it with the same pages,
// opaque: a reader sees the cover while the engine, its context and its programs are still being made, and
// the page has a contentful element to paint first (a canvas is none), whenever its image is decoded.
import { openPagePlaces, positionOfPage } from '../engine/layout.js';

let posters = 0;  // posters laid on this page so far: their images' Element Timing names differ

/**
 * Lays the placeholders of the pages open at `opening` over `canvas` (in the book's element), or returns null when none of them names a placeholder by URL (a Blob, or no placeholder: nothing to show).
 * `book`: { entries, pageCount, display, direction, pageAspect, center, leafThickness, hardPages } (layout.js's book); `size`: the canvas's CSS size.
 * Returns { element, places, whenPainted, remove(), removeOncePainted() }: `places` as layout.js
 * openPagePlaces; `whenPainted` a promise, resolved once its images have been
 * painted (or failed, or the poster was removed); remove() may be called more than once; removeOncePainted()
 * resolves once it removed the poster.
 */
export function showFirstViewPoster(canvas, book, size, opening) {
  const position = positionOfPage(opening, book.pageCount, book.display);
  const places = openPagePlaces(position, book, size)
    .filter(({ page }) => page >= 0 && typeof book.entries[page]?.placeholder === 'string');
  if (places.length === 0) return null;
  posters += 1;
  const element = document.createElement('div');
  element.className = 'conecurl-poster';
  element.setAttribute('aria-hidden', 'true');  // the live region and the page text say what is open
  element.style.cssText = 'position:absolute;inset:0;pointer-events:none;overflow:hidden';
  for (const { page, x, y, width, height } of places) {
    const image = document.createElement('img');
    image.alt = '';
    image.decoding = 'async';
    image.dataset.page = String(page);
    image.setAttribute('elementtiming', `conecurl-poster-${posters}-${page}`);  // its paint time, for removeOncePainted
    image.style.cssText = `position:absolute;left:${x}px;top:${y}px;width:${width}px;height:${height}px;margin:0;border:0`;
    image.onerror = () => image.remove();  // the page's own image comes as without a placeholder; no broken-image mark meanwhile
    image.src = book.entries[page].placeholder;
    element.append(image);
  }
  canvas.before(element);  // under the canvas (positioned, book-shell.js) and every layer laid in later
  let removed;
  const whenRemoved = new Promise((resolve) => { removed = resolve; });
  const remove = () => {
    element.remove();
    removed();
  };
  const whenPainted = Promise.race([paintedImages(element), whenRemoved]);
  const removeOncePainted = () => whenPainted.then(remove);
  return { element, places, whenPainted, remove, removeOncePainted };
}

/**
 * Resolves once each of `element`'s images has loaded or failed and has been painted: where the browser
 * tells paint times (Element Timing: Chromium, whose largest contentful paint drops an image removed before
 * its frame was presented), once it told each image's; elsewhere two animation frames after decoding (the
 * first one's rendering paints them). At once where it cannot be painted now: a hidden page, the element not
 * rendered (checkVisibility) or outside the viewport. No timer stands in: where no frame is painted (a main
 * thread too busy to render) it waits, and the poster under the canvas with it, unseen.
 */
async function paintedImages(element) {
  if (!paintable(element)) return;
  const images = [...element.querySelectorAll('img')];
  await Promise.allSettled(images.map((image) => image.decode()));
  const shown = images.filter((image) => image.isConnected && image.naturalWidth > 0);  // a failed one removed itself
  const timed = typeof PerformanceObserver === 'function' && PerformanceObserver.supportedEntryTypes?.includes('element');
  if (shown.length > 0 && timed) await painted(shown.map((image) => image.getAttribute('elementtiming')));
  else await new Promise((resolve) => { requestAnimationFrame(() => requestAnimationFrame(resolve)); });
}

// Whether `element` can be painted now: the page shown, the element rendered and partly in the viewport.
function paintable(element) {
  if (document.visibilityState === 'hidden') return false;
  if (element.checkVisibility && !element.checkVisibility({ visibilityProperty: true })) return false;
  const r = element.getBoundingClientRect();
  return r.width > 0 && r.height > 0 && r.right > 0 && r.bottom > 0 && r.left < innerWidth && r.top < innerHeight;
}

// Resolves once Element Timing has reported each of `names` (elementtiming values) painted.
function painted(names) {
  const waiting = new Set(names);
  return new Promise((resolve) => {
    const observer = new PerformanceObserver((list) => {
      for (const entry of list.getEntries()) waiting.delete(entry.identifier);
      if (waiting.size > 0) return;
      observer.disconnect();
      resolve();
    });
    observer.observe({ type: 'element', buffered: true });
  });
}

/** Whether `places` (a surface's openPagePlaces) are where the poster lies: the same pages, within half a pixel. */
export function posterStillFits(poster, places) {
  const near = (a, b) => a.page === b.page && ['x', 'y', 'width', 'height'].every((k) => Math.abs(a[k] - b[k]) <= 0.5);
  return poster.places.every((laid) => places.some((place) => near(laid, place)));
}
