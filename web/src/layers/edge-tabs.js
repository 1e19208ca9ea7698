// Buttons over the marks the engine draws on the page blocks' fore-edge: one per index tab, named by
// its section's title (a tooltip too) and labelled on the tab, and a small hit area over each search
// tick; a click riffles there. Laid out from the surface's edgeMarkPlaces() while the book rests,
// hidden while a leaf moves, like the other overlay layers.

const TICK_HIT_CSS_PX = 10;  // a tick is a line a pixel or two wide: its hit area is at least this wide

/**
 * An overlay layer (book-controller.js lays it out while the book rests).
 * @param {HTMLElement} root  the book's element (position: relative); the layer covers it
 * @param {{ marks: () => Array<{ page: number, kind: 'tab' | 'tick', label?: string }>,
 *           placesOf: () => Array<{ mark: number, page: number, kind: string, turned: boolean, x: number, y: number, width: number, height: number }>,
 *           onActivate: (mark: { page: number, kind: string, label?: string }) => void }} book
 */
export function createEdgeTabs(root, { marks, placesOf, onActivate }) {
  const layer = document.createElement('div');
  layer.className = 'conecurl-edge-tabs';
  layer.style.cssText = 'position:absolute;inset:0;pointer-events:none;overflow:hidden';
  root.append(layer);
  let shown = '';

  function button(mark, place) {
    const b = document.createElement('button');
    b.type = 'button';
    const tab = mark.kind === 'tab';
    const name = tab ? mark.label || `Page ${mark.page + 1}` : `Search hit on page ${mark.page + 1}${mark.label ? `: ${mark.label}` : ''}`;
    // Text only: titles and snippets come from PDFs and page authors.
    b.title = name;
    b.setAttribute('aria-label', name);
    b.dataset.edgeMark = mark.kind;
    b.dataset.page = String(mark.page);
    let { x, width } = place;
    if (!tab && width < TICK_HIT_CSS_PX) {
      x -= (TICK_HIT_CSS_PX - width) / 2;
      width = TICK_HIT_CSS_PX;
    }
    const label = tab ? name : '';
    // As large as lets the whole title fit across the tab (about 0.6 em a letter), from 8 to 11 px;
    // a longer one ends in an ellipsis.
    const fontPx = Math.max(8, Math.min(11, place.height * 0.5, (width - 4) / (0.62 * Math.max(1, name.length))));
    b.style.cssText = 'position:absolute;pointer-events:auto;cursor:pointer;margin:0;padding:0 2px;border:0;'
      + 'background:transparent;overflow:hidden;white-space:nowrap;'
      + `font:600 ${fontPx}px/1 system-ui,sans-serif;color:rgba(255,255,255,0.95);text-shadow:0 0 2px rgba(0,0,0,0.45);`
      + `text-align:${place.turned ? 'left' : 'right'};`
      + `left:${x}px;top:${place.y}px;width:${width}px;height:${place.height}px`;
    if (label) {
      // The title on the tab as far as it fits (the whole of it is the button's name and tooltip).
      const span = document.createElement('span');
      span.setAttribute('aria-hidden', 'true');
      span.style.cssText = 'display:block;overflow:hidden;text-overflow:ellipsis;white-space:nowrap';
      span.textContent = label.trim();
      b.append(span);
    }
    // Over the canvas, not in it: the book's own clicks and taps (on the canvas) never see this one.
    b.addEventListener('click', () => onActivate(mark));
    return b;
  }

  return {
    /** Lays the buttons over the marks that show now (the open page places are not needed: the marks say where). */
    place() {
      const given = marks();
      const places = given.length ? placesOf() : [];
      const key = JSON.stringify([given, places]);
      if (key === shown) return;
      shown = key;
      // Tabs last: over the ticks where they cross.
      const ordered = [...places].sort((a, b) => (a.kind === 'tab') - (b.kind === 'tab'));
      layer.replaceChildren(...ordered.map((place) => button(given[place.mark], place)));
    },
    hide() {
      if (shown === '') return;
      shown = '';
      layer.replaceChildren();
    },
    get buttons() { return [...layer.children]; },
    remove() { layer.remove(); },
  };
}
