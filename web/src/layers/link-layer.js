// Links inside pages: real <a> elements laid over the open pages while they lie flat, so they are
// clickable (a pointer cursor), reachable with Tab and read by screen readers; clicking one never
// starts a turn (the anchors sit above the canvas, not in it). Hidden while any leaf moves.

/** Only links that go somewhere: http(s), mailto and relative URLs; never javascript: or data:. */
export function isSafeHref(href) {
  if (typeof href !== 'string' || href === '') return false;
  try {
    return ['http:', 'https:', 'mailto:'].includes(new URL(href, document.baseURI).protocol);
  } catch {
    return false;
  }
}

/**
 * An overlay layer (book-controller.js lays it over the open pages while the book rests).
 * @param {HTMLElement} root  the book's element (position: relative); the layer covers it
 * @param {{ linksOf: (page: number) => Array<{ rect: number[], href: string, toPage?: number, title?: string }> | undefined,
 *           onActivate: (link: { page: number, href: string, toPage?: number, title?: string }, event: MouseEvent) => void }} book
 */
export function createLinkLayer(root, { linksOf, onActivate }) {
  const layer = document.createElement('div');
  layer.className = 'conecurl-links';
  layer.style.cssText = 'position:absolute;inset:0;pointer-events:none;overflow:hidden';
  root.append(layer);
  let shown = '';

  return {
    /**
     * Lays the links of the open pages over them. `places`: for each open page, its rectangle in CSS
     * pixels of the root ({ page, x, y, width, height }); a link's rect is [x, y, width, height] as
     * fractions of its page.
     */
    place(places) {
      const placed = places.map((place) => ({ place, links: linksOf(place.page) ?? [] })).filter(({ links }) => links.length > 0);
      const key = JSON.stringify(placed);
      if (key === shown) return;
      shown = key;
      const anchors = [];
      for (const { place, links } of placed) {
        const { page } = place;
        for (const link of links) {
          if (link.toPage === undefined && !isSafeHref(link.href)) continue;  // javascript: and the like never
          const [fx, fy, fw, fh] = link.rect;
          const a = document.createElement('a');
          // Text and attributes only: hrefs and titles come from page authors and PDFs.
          a.href = link.toPage !== undefined ? '#' : link.href;
          if (link.title) a.title = link.title;
          a.textContent = link.title || (link.toPage !== undefined ? `Go to page ${link.toPage + 1}` : link.href);
          a.style.cssText = `position:absolute;pointer-events:auto;cursor:pointer;color:transparent;overflow:hidden;`
            + `left:${place.x + fx * place.width}px;top:${place.y + fy * place.height}px;`
            + `width:${fw * place.width}px;height:${fh * place.height}px`;
          a.dataset.page = String(page);
          a.addEventListener('click', (event) => onActivate({ page, ...link }, event));
          anchors.push(a);
        }
      }
      layer.replaceChildren(...anchors);
    },
    hide() {
      if (shown === '') return;
      shown = '';
      layer.replaceChildren();
    },
    get anchors() { return [...layer.children]; },
    /** The layer's element (other layers go in under it). */
    get element() { return layer; },
    remove() { layer.remove(); },
  };
}
