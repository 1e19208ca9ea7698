// A document's selectable text (a PDF's, a published one's): transparent spans over the words, laid
// out from the page's text record (document/format.js) as pdf.js's TextLayer lays them, over each
// open page while it lies flat, so a reader selects and copies text with mouse or touch and a screen
// reader reads the page in order; a press on text selects and never turns (the spans sit above the
// canvas, whose listeners never see it), and a selection offers "Copy link to this passage".
// Loaded (a dynamic import) only for PDF and published books with the `textLayer` option on.
import { measureText as measure } from './text-measure.js';
/** The passage button's text (the viewer's labels may replace it later). */
export const PASSAGE_LINK_LABEL = 'Copy link to this passage';
const PASSAGE_MAX_CHARS = 300;  // a link carries at most this much of the selection (search finds its start)

// pdf.js's own rules for its text layer (pdfjs-dist web/pdf_viewer.css, `.textLayer`), as facts under
// our class (the spans are ours, placed as pdf.js places its own): spans placed in % of the page,
// sized by --total-scale-factor (CSS px per PDF unit) times
// the item's --font-height, stretched by --scale-x to the word's width, transparent, selectable. Our
// additions: --min-font-size is set a page (legibleFactor below: every span's font at least 12 CSS px,
// scaled back down by its transform, so its box stays where it was and tools that judge legibility by
// the font size, Lighthouse's among them, find no illegible text); the layer takes no presses itself
// (only its spans, and the whole page while a selection is being dragged, so the drag never lands on the canvas), and the passage button.
const TEXT_LAYER_CSS = `
.conecurl-text-layer {
  color-scheme: only light; position: absolute; text-align: initial; overflow: clip; opacity: 1;
  line-height: 1; letter-spacing: normal; word-spacing: normal; -webkit-text-size-adjust: none;
  text-size-adjust: none; forced-color-adjust: none; transform-origin: 0 0; caret-color: CanvasText;
  z-index: 0; pointer-events: none;
  --min-font-size: 1;
  --text-scale-factor: calc(var(--total-scale-factor) * var(--min-font-size));
  --min-font-size-inv: calc(1 / var(--min-font-size));
}
.conecurl-text-layer :is(span, br) {
  color: transparent; position: absolute; white-space: pre; cursor: text; transform-origin: 0% 0%;
  -webkit-user-select: text; user-select: text; pointer-events: auto;
}
.conecurl-text-layer > :not(.markedContent), .conecurl-text-layer .markedContent span:not(.markedContent) {
  z-index: 1; --font-height: 0; font-size: calc(var(--text-scale-factor) * var(--font-height));
  --scale-x: 1; --rotate: 0deg;
  transform: rotate(var(--rotate)) scaleX(var(--scale-x)) scale(var(--min-font-size-inv));
}
.conecurl-text-layer .markedContent { display: contents; }
.conecurl-text-layer ::selection { background: rgba(0 0 255 / 0.25); background: color-mix(in srgb, AccentColor, transparent 50%); color: transparent; }
.conecurl-text-layer br::selection { background: transparent; }
.conecurl-text-layer .endOfContent {
  display: block; position: absolute; inset: 100% 0 0; z-index: 0; cursor: default; -webkit-user-select: none; user-select: none;
}
.conecurl-text-layer.selecting { pointer-events: auto; }
.conecurl-text-layer.selecting .endOfContent { top: 0; }
.conecurl-passage-link {
  position: absolute; pointer-events: auto; z-index: 2; font: 13px/1.2 system-ui, sans-serif; padding: 4px 8px;
  border: 1px solid #8a8a8a; border-radius: 4px; background: #ffffff; color: #1a1a1a; cursor: pointer;
  box-shadow: 0 1px 4px rgb(0 0 0 / 0.25); white-space: nowrap; -webkit-user-select: none; user-select: none;
}
.conecurl-passage-link:focus-visible { outline: var(--conecurl-focus-ring, 3px solid #1a5fd6); outline-offset: 1px; }`;

let sharedSheet = null;

// The rules go in a constructed sheet adopted by the book's document or shadow root (works under a
// strict CSP), else a <style> before the layer (returned, to go with it).
function installStyles(root, layer) {
  const scope = root.getRootNode();
  if (typeof CSSStyleSheet === 'function' && 'replaceSync' in CSSStyleSheet.prototype && scope && 'adoptedStyleSheets' in scope) {
    if (!sharedSheet) {
      sharedSheet = new CSSStyleSheet();
      sharedSheet.replaceSync(TEXT_LAYER_CSS);
    }
    if (!scope.adoptedStyleSheets.includes(sharedSheet)) scope.adoptedStyleSheets = [...scope.adoptedStyleSheets, sharedSheet];
    return null;
  }
  const style = document.createElement('style');
  style.textContent = TEXT_LAYER_CSS;
  layer.before(style);
  return style;
}

/** A selection's text as a passage link carries it: white space folded, at most PASSAGE_MAX_CHARS. */
export function passageText(text) {
  const folded = String(text).replace(/\s+/g, ' ').trim();
  if (folded.length <= PASSAGE_MAX_CHARS) return folded;
  const cut = folded.slice(0, PASSAGE_MAX_CHARS);
  const space = cut.lastIndexOf(' ');
  return space > PASSAGE_MAX_CHARS / 2 ? cut.slice(0, space) : cut;
}

/** The least font size, CSS px, a span is given (Lighthouse's "legible font sizes" threshold). */
export const LEGIBLE_FONT_PX = 12;
/** At most this factor: a span under 12 / 32 px keeps a smaller font (no 1000 px fonts for a speck of text). */
const MAX_FONT_FACTOR = 32;

/**
 * The layer's --min-font-size for a page drawn `scale` CSS px a page unit whose smallest text is
 * `smallest` page units high: the factor that brings that text's font to LEGIBLE_FONT_PX (1 when it is
 * there already); each span's font is this much larger and its transform this much smaller.
 */
export function legibleFactor(smallest, scale) {
  const px = smallest * scale;
  if (!(px > 0)) return 1;
  return Math.min(MAX_FONT_FACTOR, Math.max(1, (LEGIBLE_FONT_PX * 1.001) / px));  // 1.001: never a rounding under 12
}

/**
 * The spans of a page's text record, as pdf.js's TextLayer makes them: each piece at its baseline less
 * its ascent, in % of the page; its font height in page units (the layer's --total-scale-factor turns
 * them into CSS px); stretched to its width on the page; turned with its baseline. A line's end is a <br>.
 * The array's `smallest` is the least font height among them.
 */
function spansOf(record) {
  const out = [];
  out.smallest = 0;  // the smallest font height of any span, page units (0: none)
  for (const item of record.items) {
    const [a, b, c, d, e, f] = item.tx;
    const angle = Math.atan2(b, a);
    const height = Math.hypot(c, d);
    const ascent = height * item.ascent;
    const left = angle === 0 ? e : e + ascent * Math.sin(angle);
    const top = angle === 0 ? f - ascent : f - ascent * Math.cos(angle);
    const span = document.createElement('span');
    span.textContent = item.str;
    span.setAttribute('role', 'presentation');
    span.style.left = `${(100 * left) / record.width}%`;
    span.style.top = `${(100 * top) / record.height}%`;
    span.style.fontFamily = item.family;
    span.style.setProperty('--font-height', `${height.toFixed(2)}px`);
    const rounded = Number(height.toFixed(2));
    if (rounded > 0 && (out.smallest === 0 || rounded < out.smallest)) out.smallest = rounded;
    if (angle !== 0) span.style.setProperty('--rotate', `${angle * (180 / Math.PI)}deg`);
    const natural = (measure(item.str, item.family) * height) / 100;
    if (natural > 0 && item.width > 0) span.style.setProperty('--scale-x', String(item.width / natural));
    out.push(span);
    if (record.text[item.end] === '\n') {
      const br = document.createElement('br');
      br.setAttribute('role', 'presentation');
      out.push(br);
    }
  }
  return out;
}

/**
 * The text layer: one element `data-text-layer` (and `data-page`) per open page, over its place.
 * Only the spans take presses: a mouse press on a word selects (the canvas never sees it; a touch on
 * one is handed to the canvas too, a finger selects by a long press), a press between words is the canvas's, where `turnArea` rules (a PDF book's default, 'edges', keeps the page's inside
 * for selecting). The wheel over a word is handed to the canvas (it zooms there).
 * @param {HTMLElement} root  the book's element; the layer goes in it, over the canvas, before `before`
 * @param {{ doc: { pageText: (index: number) => Promise<object> },
 *           canvas: HTMLCanvasElement, before?: Element|null, onPassage: (passage: { page: number, text: string }) => void }} book
 *   doc: the book's document, whose pageText(index) is the page's record (document/format.js)
 *   onPassage: the passage button was used on a selection of page `page`'s text
 */
export function createTextLayer(root, { doc, canvas, before = null, onPassage }) {
  const layer = document.createElement('div');
  layer.className = 'conecurl-text-layers';
  layer.style.cssText = 'position:absolute;inset:0;pointer-events:none;overflow:hidden';
  root.insertBefore(layer, before);
  const style = installStyles(root, layer);
  const button = document.createElement('button');
  button.type = 'button';
  button.className = 'conecurl-passage-link';
  button.dataset.passageLink = '';
  button.textContent = PASSAGE_LINK_LABEL;
  button.hidden = true;

  const pages = new Map();  // page index -> { element, place, size (the page in its record's units) }
  let shownKey = '';
  let removed = false;
  let passage = null;  // { page, text } the button offers

  // The wheel zooms over text as over the canvas (a press selects, a wheel never did anything else).
  layer.addEventListener('wheel', (event) => {
    event.stopPropagation();
    event.preventDefault();
    canvas.dispatchEvent(new WheelEvent(event.type, event));
  }, { passive: false });

  // A finger selects by a long press (the browser's own), never by a drag: so a touch on a word is
  // also the canvas's, as between the words, and a tap, swipe or drag over text turns as elsewhere.
  // Once a drag takes the pointer (the canvas captures it), its later events go to the canvas directly.
  for (const type of ['pointerdown', 'pointermove', 'pointerup', 'pointercancel']) {
    layer.addEventListener(type, (event) => {
      if (event.pointerType !== 'touch' || !event.isTrusted) return;
      // The same touch, at the time it happened (a tap, a long press and a fling are told apart by it).
      const handed = new PointerEvent(type, event);
      Object.defineProperty(handed, 'timeStamp', { value: event.timeStamp });
      canvas.dispatchEvent(handed);
    });
  }

  // While a selection is dragged, its page takes every press (pdf.js's `selecting`), so the drag
  // stays on text, never on the canvas under the gaps between words.
  // The passage button waits for the press to end (under a dragging pointer it would catch the drag).
  let dragging = false;
  const stopSelecting = () => {
    for (const { element } of pages.values()) element.classList.remove('selecting');
    if (!dragging) return;
    dragging = false;
    onSelection();
  };
  const onDown = (event) => {
    const element = event.target.closest?.('[data-text-layer]');
    if (!element || !layer.contains(element)) return;
    element.classList.add('selecting');
    dragging = true;
    hidePassageButton();
  };
  layer.addEventListener('pointerdown', onDown);
  document.addEventListener('pointerup', stopSelecting);
  document.addEventListener('pointercancel', stopSelecting);

  const pageOfNode = (node) => {
    const element = (node?.nodeType === 1 ? node : node?.parentElement)?.closest?.('[data-text-layer]');
    return element && layer.contains(element) ? Number(element.dataset.page) : null;
  };
  // A selection in the layer offers the passage button near its end; any other hides it.
  function onSelection() {
    if (dragging) return;
    const selection = document.getSelection();
    const page = selection && !selection.isCollapsed ? pageOfNode(selection.anchorNode) : null;
    const text = page === null ? '' : passageText(selection.toString());
    if (page === null || text === '' || !layer.contains(selection.focusNode)) {
      if (document.activeElement !== button) hidePassageButton();
      return;
    }
    passage = { page, text };
    const rects = [...selection.getRangeAt(0).getClientRects()].filter((r) => r.width > 0 && r.height > 0);
    const last = rects[rects.length - 1] ?? selection.getRangeAt(0).getBoundingClientRect();
    const box = root.getBoundingClientRect();
    button.hidden = false;
    const width = button.offsetWidth;
    const height = button.offsetHeight;
    const left = Math.max(0, Math.min(box.width - width, last.right - box.left - width / 2));
    const below = last.bottom - box.top + 6;
    const top = below + height <= box.height ? below : Math.max(0, last.top - box.top - height - 6);
    button.style.left = `${left}px`;
    button.style.top = `${top}px`;
  }
  document.addEventListener('selectionchange', onSelection);
  // A press on the button keeps the selection (and the focus where it is); a click or Enter uses it.
  button.addEventListener('pointerdown', (event) => event.preventDefault());
  button.addEventListener('click', () => { if (passage) onPassage({ ...passage }); });

  function hidePassageButton() {
    passage = null;
    button.hidden = true;
  }

  // Page `index`'s layer, built once it is open, from the page's text record.
  function pageLayer(index) {
    const element = document.createElement('div');
    element.className = 'conecurl-text-layer';
    element.dataset.textLayer = '';
    element.dataset.page = String(index);
    const entry = { element, place: null, size: null, smallest: 0 };
    Promise.resolve().then(() => doc.pageText(index)).then((record) => {
      if (removed) return;
      entry.size = { width: record.width, height: record.height };
      const spans = spansOf(record);
      entry.smallest = spans.smallest;
      element.append(...spans);
      const end = document.createElement('div');
      end.className = 'endOfContent';
      element.append(end);
      if (entry.place) fit(entry);
    }).catch(() => {
      // A page whose text cannot be read shows no text layer; the page itself still shows.
    });
    return entry;
  }

  function fit(entry) {
    const { element, place, size } = entry;
    element.style.left = `${place.x}px`;
    element.style.top = `${place.y}px`;
    element.style.width = `${place.width}px`;
    element.style.height = `${place.height}px`;
    if (size) {
      const scale = place.width / size.width;
      element.style.setProperty('--scale-factor', String(scale));
      element.style.setProperty('--total-scale-factor', String(scale));
      element.style.setProperty('--min-font-size', String(legibleFactor(entry.smallest, scale)));
    }
  }

  return {
    /** Lays the open pages' text over their places ({ page, x, y, width, height } in CSS px of the root). */
    place(places) {
      const key = JSON.stringify(places);
      if (key === shownKey) return;
      shownKey = key;
      const open = new Set(places.map((p) => p.page));
      for (const index of pages.keys()) if (!open.has(index)) pages.delete(index);
      const laid = [];
      for (const place of places) {
        let entry = pages.get(place.page);
        if (!entry) {
          entry = pageLayer(place.page);
          pages.set(place.page, entry);
        }
        entry.place = place;
        fit(entry);
        laid.push(entry.element);
      }
      // Page order is reading order; the button after the text (left in place if it is: it may have focus).
      const children = [...laid, button];
      if (children.some((child, i) => layer.children[i] !== child) || layer.children.length !== children.length) {
        layer.replaceChildren(...children);
      }
      if (passage && !open.has(passage.page)) hidePassageButton();
      else if (passage) onSelection();  // the selection moved with its page (zoom, pan)
    },
    /** A leaf moves: the text gives way to the page's texture (and a selection in it goes). */
    hide() {
      if (shownKey === '') return;
      shownKey = '';
      dragging = false;
      stopSelecting();
      hidePassageButton();
      layer.replaceChildren();
    },
    remove() {
      removed = true;
      pages.clear();
      document.removeEventListener('selectionchange', onSelection);
      document.removeEventListener('pointerup', stopSelecting);
      document.removeEventListener('pointercancel', stopSelecting);
      layer.remove();
      style?.remove();
    },
  };
}
