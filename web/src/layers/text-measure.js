// How wide a piece of text is drawn in a font family, for the two places that fit text to a PDF's
// word boxes: the text layer's spans (text-layer.js) and search hits inside a text item (document/text-index.js).
let measurer = null;

/** The width of `text` in `family` (a generic one when none is given) at 100 px. */
export function measureText(text, family) {
  measurer ??= (typeof OffscreenCanvas === 'function' ? new OffscreenCanvas(1, 1) : document.createElement('canvas')).getContext('2d');
  measurer.font = `100px ${family || 'sans-serif'}`;
  return measurer.measureText(text).width;
}
