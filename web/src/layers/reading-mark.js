// The word read aloud now, over its page while the page lies flat: an element with `data-reading` (and
// `data-page`) over each line of the word, under it one with `data-reading="sentence"` over each line of
// the sentence said (lighter; where a voice reports no words, the only mark), laid over the open pages
// from the engine's page places as the search hits are (search-hits.js), removed while a leaf moves. While the leaf turns, the mark is
// drawn into the page's image instead (pages/marked-page.js), so it curls with the paper.
import { READING_FILL, SENTENCE_FILL } from '../pages/marked-page.js';
import { markBox } from './search-hits.js';

/**
 * An overlay layer (book-controller.js lays it over the open pages while the book rests).
 * @param {HTMLElement} root  the book's element (position: relative); the layer covers it
 * @param {() => Array<{ page: number, rects: number[][], sentence?: boolean }>} markNow  the sentence and the word
 *   marked now, under to over (rects as fractions of their page)
 */
export function createReadingMarkLayer(root, markNow) {
  const layer = document.createElement('div');
  layer.className = 'conecurl-reading';
  layer.style.cssText = 'position:absolute;inset:0;pointer-events:none;overflow:hidden';
  layer.setAttribute('aria-hidden', 'true');  // the words are heard; this is their picture
  root.append(layer);
  let shown = '';
  let places = [];

  const lay = () => {
    const marks = markNow().map((mark) => ({ ...mark, place: places.find((p) => p.page === mark.page) })).filter((mark) => mark.place);
    const key = JSON.stringify(marks);
    if (key === shown) return;
    shown = key;
    layer.replaceChildren(...marks.flatMap(({ page, rects, sentence, place }) => rects.map((rect) => {
      const element = document.createElement('div');
      element.dataset.reading = sentence ? 'sentence' : '';
      element.dataset.page = String(page);
      element.style.cssText = `position:absolute;box-sizing:border-box;border-radius:3px;mix-blend-mode:multiply;background:${sentence ? SENTENCE_FILL : READING_FILL};`
        + markBox(place, rect, Math.max(1, place.height * 0.002));
      return element;
    })));
  };

  return {
    /** Lays the mark over its page, if open (`places`: { page, x, y, width, height } in CSS px of the root). */
    place(given) {
      places = given;
      lay();
    },
    /** The word marked changed: laid again where the pages were last placed. */
    update() {
      if (places.length > 0) lay();
    },
    hide() {
      places = [];
      if (shown === '[]') return;
      shown = '[]';
      layer.replaceChildren();
    },
    remove() { layer.remove(); },
  };
}
