// Search hits over the open pages while they lie flat: an element with `data-search-hit` (and
// `data-page`; `data-current` on the hit shown now) over each line of each hit, laid over the open
// pages from the engine's page places like the links (link-layer.js), removed while a leaf moves.
// The yellow itself is in the page's image (pages/marked-page.js), so it is the same flat and curling;
// these elements outline the current hit, make the hits findable in the DOM, and carry the colour
// themselves only over a live HTML page, whose element covers its texture.

/**
 * Where a mark over `rect` ([x, y, w, h] fractions of the page placed at `place`: { x, y, width, height }
 * in CSS px of the book's element) lies, `pad` CSS px around it: its left, top, width and height as CSS.
 * The word read aloud (reading-mark.js) is laid by it too.
 */
export function markBox(place, [fx, fy, fw, fh], pad = 0) {
  return `left:${place.x + fx * place.width - pad}px;top:${place.y + fy * place.height - pad}px;`
    + `width:${fw * place.width + 2 * pad}px;height:${fh * place.height + 2 * pad}px;`;
}

/**
 * An overlay layer (book-controller.js lays it over the open pages while the book rests).
 * @param {HTMLElement} root  the book's element (position: relative); the layer covers it
 * @param {{ marksOn: (page: number) => Array<{ rect: number[], current: boolean }>, live: (page: number) => boolean }} book
 *   marksOn: the marks on a page (rects as fractions of it); live: the page is a live HTML page
 */
export function createSearchHitsLayer(root, { marksOn, live }) {
  const layer = document.createElement('div');
  layer.className = 'conecurl-search-hits';
  layer.style.cssText = 'position:absolute;inset:0;pointer-events:none;overflow:hidden';
  layer.setAttribute('aria-hidden', 'true');  // the results are announced by whoever searched; these are pictures
  root.append(layer);
  let shown = '';

  return {
    /** Lays the marks of the open pages over them (`places`: { page, x, y, width, height } in CSS px of the root). */
    place(places) {
      const placed = places.map((place) => ({ place, marks: marksOn(place.page) })).filter(({ marks }) => marks.length > 0);
      const key = JSON.stringify(placed);
      if (key === shown) return;
      shown = key;
      const elements = [];
      for (const { place, marks } of placed) {
        const tint = live(place.page);
        for (const { rect: [fx, fy, fw, fh], current } of marks) {
          const mark = document.createElement('div');
          mark.dataset.searchHit = '';
          mark.dataset.page = String(place.page);
          if (current) mark.dataset.current = '';
          mark.style.cssText = `position:absolute;box-sizing:border-box;border-radius:2px;${markBox(place, [fx, fy, fw, fh])}`
            + (tint ? `background:${current ? 'rgba(255,140,0,0.45)' : 'rgba(255,214,0,0.45)'};mix-blend-mode:multiply;` : '')
            + (current ? 'outline:2px solid rgba(220,110,0,0.9);outline-offset:1px;' : '');
          elements.push(mark);
        }
      }
      layer.replaceChildren(...elements);
    },
    hide() {
      if (shown === '') return;
      shown = '';
      layer.replaceChildren();
    },
    remove() { layer.remove(); },
  };
}
