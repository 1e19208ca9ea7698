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
 * Returns { element, places, remove(), removeOncePainted() }: `places` as layout.js openPagePlaces; remove() may
 * be called more than once; removeOncePainted() resolves once it removed the poster.
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
  const remove = () => element.remove();
  return { element, places, remove, removeOncePainted: () => removeOncePainted(element, remove) };
}

/**
 * Removes the poster once each of its images has loaded or failed and has been painted: where the browser
 * tells paint times (Element Timing: Chromium, whose largest contentful paint drops an image removed before
 * its frame was presented), once it told each image's; elsewhere two animation frames after decoding (the
 * first one's rendering paints them). No timer stands in: where no frame is painted (a hidden tab, a main
 * thread too busy to render) the poster waits under the canvas, unseen.
 */
async function removeOncePainted(element, remove) {
  const images = [...element.querySelectorAll('img')];
  await Promise.allSettled(images.map((image) => image.decode()));
  const shown = images.filter((image) => image.isConnected && image.naturalWidth > 0);  // a failed one removed itself
  const timed = typeof PerformanceObserver === 'function' && PerformanceObserver.supportedEntryTypes?.includes('element');
  if (shown.length > 0 && timed) await painted(shown.map((image) => image.getAttribute('elementtiming')));
  else await new Promise((resolve) => { requestAnimationFrame(() => requestAnimationFrame(resolve)); });
  remove();
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
